// groovebake: bakes a groove scene (formats/groove-scene.md) into a BAKE_grooves package
// (formats/grooves.md): the groove grid of seed 000 §4.1-§4.2, packed for the GPU.
#include <cstdio>
#include <string>

#include "bake/core/huge_pages.h"
#include "bake/core/session.h"
#include "bake/grooves/bake/bake.h"
#include "common/cli.h"

int main(int argc, char** argv) {
  using namespace bake::grooves;
  Settings settings;
  bake::Diagnostics diagnostics("groovebake");
  CLI::App app{"Bakes a groove scene (paths in UV, polyline cross-sections, perturbations, materials) into\n"
               "a glTF package whose BAKE_grooves material holds the groove grid: a uniform grid of\n"
               "per-cell primitive lists (CSR), the special-case records (intersections, ends, corners),\n"
               "and the primitives, grooves, profiles and materials in cell-local fp32, laid out for\n"
               "direct GPU upload. A preview plane covers the domain, or --apply-to draws the grooves on a\n"
               "UV-mapped mesh (its UV [0,1]^2 spans the domain; tangent frames computed where missing).",
               "groovebake"};
  app.add_option("scene", settings.scene, "Scene file (.json, formats/groove-scene.schema.json)")->required();
  app.add_option("-o,--output", settings.output, "Package to write (.glb)")->required();
  app.add_option("--cell-size", settings.cellSize, "Grid cell size in texture units (0: the mean groove width)")
      ->default_str("0");
  app.add_option("--max-cells", settings.maxCells, "Largest cell count; the automatic cell size grows to fit")
      ->default_str(std::to_string(settings.maxCells));
  app.add_flag("--no-special-cases{false}", settings.specialCases,
               "Write no special-case records: every footprint is line-sampled (for patterns seen only from far)");
  app.add_option("--apply-to", settings.applyTo,
                 "Mesh to draw the grooves on instead of the preview plane (.obj .ply .off .stl .gltf .glb, with UVs)");
  app.add_option("--max-stretch", settings.maxStretch,
                 "Warn where the mesh's UV layout stretches the pattern (or scales it from the median) beyond this ratio")
      ->default_str("1.5");
  bake::addCommonOptions(app, settings.common, {.cacheDir = true});

  return bake::runBaker("groovebake", app, settings, diagnostics, argc, argv, [&]() -> bake::Status {
    // A large pattern's bake touches hundreds of megabytes of fresh memory: 2 MiB pages fault ten
    // times less (core/huge_pages.h). Its size follows the grooves, which a small scene can generate,
    // so every bake restarts (once the command line is read: --help and --version do not).
    bake::reexecWithHugePages(argv, "groovebake");
    return {};
  });
}
