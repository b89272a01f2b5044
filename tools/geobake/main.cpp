// geobake: bakes per-vertex geodesic distance fields into a glTF package (formats/geodesic.md).
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

#include "bake/core/huge_pages.h"
#include "bake/core/session.h"
#include "bake/core/vector_text.h"
#include "bake/geodesic/bake.h"
#include "common/cli.h"

int main(int argc, char** argv) {
  using namespace bake::geodesic;
  Settings settings;
  std::vector<std::string> points;
  bake::Diagnostics diagnostics("geobake");
  CLI::App app{"Bakes per-vertex geodesic distance fields from feature sources (GeoTextures) into a glTF\n"
               "package: attributes _GEODESIC_0, _GEODESIC_1, ... normalised to [0, 1], described by the\n"
               "BAKE_geodesic extension.",
               "geobake"};
  app.add_option("mesh", settings.input, "Input mesh (.obj .ply .off .stl .gltf .glb)")->required();
  app.add_option("-o,--output", settings.output, "Package to write (.glb)")->required();

  auto* sources = app.add_option_group("Sources", "At least one kind is needed");
  sources->add_option("--source-vertex", settings.sourceVertices, "Source at this input vertex index (repeatable)");
  sources->add_option("--source-point", points, "Source at the surface point nearest to X,Y,Z (repeatable)")
      ->type_name("X,Y,Z");
  sources->add_option("--source-node", settings.sourceNodes, "Source at the named glTF node (repeatable)")->type_name("NAME");
  sources->add_option("--sources", settings.sourcesFile,
                      "JSON file of fields: {\"fields\": [{\"name\": ..., \"sources\": [{\"vertex\": i} | "
                      "{\"point\": [x, y, z]} | {\"node\": \"name\"}]}]}");
  sources->add_option("--fields", settings.onlyFields,
                      "Bake only these fields of the --sources file, by name (comma-separated or repeated)")
      ->type_name("NAME")
      ->delimiter(',');
  sources->add_option("--auto-sources", settings.autoSources, "Add N sources by farthest-point sampling");
  app.add_flag("--combine", settings.combine,
               "One field of all command-line sources (distance to the nearest) instead of one field each");

  const std::map<std::string, Method> methods{{"exact", Method::Exact}, {"heat", Method::Heat}, {"fmm", Method::FastMarching}};
  app.add_option("--method", settings.method,
                 "exact: window propagation (exact polyhedral distances); heat: robust heat method; fmm: fast marching")
      ->transform(CLI::CheckedTransformer(methods))
      ->default_str("exact");
  const std::map<std::string, Normalization> normalizations{
      {"per-field", Normalization::PerField}, {"global", Normalization::Global}, {"none", Normalization::None}};
  app.add_option("--normalize", settings.normalization,
                 "per-field: each field / its largest distance; global: / the largest of all; none: model units")
      ->transform(CLI::CheckedTransformer(normalizations))
      ->default_str("per-field");
  const std::map<std::string, Encoding> encodings{{"float", Encoding::Float}, {"unorm16", Encoding::Unorm16}};
  app.add_option("--encoding", settings.encoding, "float (32-bit) or unorm16 (normalized 16-bit)")
      ->transform(CLI::CheckedTransformer(encodings))
      ->default_str("float");
  app.add_option("--verify", settings.verifySamples,
                 "Measure the error against exact distances at K sampled vertices (report and stderr). Heat and FMM "
                 "fields: one exact run per field gives the reference at K vertices. Exact fields: at most 8 vertices, "
                 "each checked by its own independent exact run (about the cost of the bake per vertex)");
  app.add_option("--weld-tolerance", settings.weldTolerance,
                 "Weld positions closer than this fraction of the bounding-box diagonal (0: identical only)")
      ->default_str("0");
  app.add_option("--heat-time", settings.heat.timeFactor,
                 "Heat method: time step t = m h^2 with this m (0: chosen from the mesh)")
      ->default_str("0");
  app.add_option("--geotexture", settings.geotexture,
                 "Add a material choosing this GeoTexture preset for bakeplay (formats/geodesic-material.md)")
      ->type_name("PRESET");
  app.add_flag("--draco", settings.draco, "Compress the mesh with Draco (KHR_draco_mesh_compression)");
  bake::addCommonOptions(app, settings.common, {.cacheDir = true});

  return bake::runBaker("geobake", app, settings, diagnostics, argc, argv, [&]() -> bake::Status {
    // A large mesh's bake touches hundreds of megabytes of fresh memory (the heat method's factors,
    // the exact method's edge records): 2 MiB pages fault far less often, and the propagation's
    // scattered reads miss the TLB less (core/huge_pages.h).
    bake::reexecWithHugePagesForInput(argv, "geobake", settings.input);
    for (const std::string& text : points) {
      BAKE_ASSIGN_OR_RETURN(const auto point, bake::parseTriple(text, "--source-point"));
      settings.sourcePoints.push_back(point);
    }
    return {};
  });
}
