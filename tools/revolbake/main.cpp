// revolbake: bakes the profile of a surface of revolution into a shape-map package for revolution
// mapping (formats/revolution.md).
#include <cmath>
#include <cstdio>
#include <map>

#include "bake/core/session.h"
#include "bake/core/vector_text.h"
#include "bake/revolution/bake.h"
#include "common/cli.h"

int main(int argc, char** argv) {
  using namespace bake::revolution;
  Settings settings;
  bake::Diagnostics diagnostics("revolbake");
  CLI::App app{"Bakes the profile of a surface of revolution into a glTF package for revolution mapping:\n"
               "a signed RGBA shape map over the (r, h) half-plane, an optional displacement map, the\n"
               "texture projection chosen by measured distortion, and the ray-march budget that reaches\n"
               "a target silhouette error (BAKE_revolution extension).",
               "revolbake"};
  app.add_option("profile", settings.input,
                 "Profile: polyline .json/.csv of (r, h) with optional arc bulges, an .svg path, a coverage image\n"
                 "(.png/.exr: column 0 at the axis, up = +h), or a mesh of revolution (.obj .ply .off .stl .gltf .glb)")
      ->required();
  app.add_option("-o,--output", settings.output, "Package to write (.glb)")->required();
  const std::map<std::string, ProfileKind> kinds{{"json", ProfileKind::Json}, {"csv", ProfileKind::Csv},
                                                 {"svg", ProfileKind::Svg},   {"image", ProfileKind::Image},
                                                 {"mesh", ProfileKind::Mesh}};
  app.add_option("--input-kind", settings.kind, "Kind of profile when the extension does not say it")
      ->transform(CLI::CheckedTransformer(kinds));
  app.add_option("--svg-path", settings.svgPathId, "SVG input: the id of the <path> to use (default: the first)")
      ->type_name("ID");
  app.add_option("--texel-size", settings.imageTexelSize,
                 "Image input: object units per pixel (default: 1 / image height)");
  app.add_option("--resolution", settings.resolution, "Texels on the larger side of the shape map (vector and mesh inputs)")
      ->default_str("1024");
  app.add_option("--padding", settings.paddingTexels, "Empty texels around the profile")->default_str("4");
  const std::map<std::string, DistanceEncoding> encodings{
      {"float", DistanceEncoding::Float}, {"unorm16", DistanceEncoding::Unorm16}, {"sqrt8", DistanceEncoding::Sqrt8}};
  app.add_option("--encoding", settings.encoding,
                 "float (RGBA32F), unorm16 (RGBA16) or sqrt8 (RGBA8, square-root distance encoding)")
      ->transform(CLI::CheckedTransformer(encodings))
      ->default_str("unorm16");
  app.add_option("--height-map", settings.heightMap, "Height map image for the displacement map (u = angle, v = up)");
  app.add_option("--height-scale", settings.heightScale, "Object units of relief for height 1")->default_str("0.01");
  const std::map<std::string, Projection> projections{{"cylindrical", Projection::Cylindrical},
                                                      {"spherical", Projection::Spherical},
                                                      {"arc-length", Projection::ArcLength}};
  Projection projection = Projection::Cylindrical;
  auto* projectionOption = app.add_option("--projection", projection,
                 "Texture projection instead of the measured choice: cylindrical, spherical or arc-length")
      ->transform(CLI::CheckedTransformer(projections));
  app.add_option("--repeat-u", settings.repeatU, "Texture repeats around the axis (default: from the measured u:v ratio)");
  app.add_option("--repeat-v", settings.repeatV, "Texture repeats along the projection's v (default: 1)");
  app.add_option("--base-color", settings.baseColorTexture, "PNG embedded as the material's base colour texture");
  std::string position;
  app.add_option("--position", position, "Where the object stands in a scene: X,Y,Z (node translation; axis along +y)")
      ->type_name("X,Y,Z");
  std::string grid, gridSpacing;
  app.add_option("--grid", grid, "Copies of the object along x, y and z in one shape box (seed 001 Eq. 9)")
      ->type_name("NX,NY,NZ");
  app.add_option("--grid-spacing", gridSpacing,
                 "Object units between neighbouring copies (default, or 0: the shape box's extent on that axis)")
      ->type_name("SX,SY,SZ");
  app.add_option("--mirror", settings.mirror, "Axes of the grid whose odd copies are mirrored, e.g. y (seed 001 Fig. 13)")
      ->type_name("AXES");
  app.add_option("--ring", settings.ring, "Copies turned round +y on a ring, instead of a grid")->type_name("N");
  app.add_option("--ring-radius", settings.ringRadius, "Ring radius (default: the smallest that keeps copies apart)");
  app.add_flag("!--no-self-shadow", settings.selfShadow,
               "Do not ask the runtime to march shadow rays toward the light (on by default)");
  app.add_option("--target-error", settings.targetError,
                 "Silhouette mismatch the recorded iteration budget must reach (fraction of rays)")
      ->default_str("0.005");
  app.add_option("--proxy-bands", settings.proxyBands, "Stacked bands of the bounding proxy the march starts from")
      ->default_str("32");
  app.add_option("--over-relaxation", settings.overRelaxation, "Sphere-tracing over-relaxation in [1, 2)")
      ->default_str("1.6");
  bake::addCommonOptions(app, settings.common, {.cacheDir = true});

  return bake::runBaker("revolbake", app, settings, diagnostics, argc, argv, [&]() -> bake::Status {
    if (projectionOption->count() > 0) settings.projection = projection;
    if (!position.empty()) { BAKE_ASSIGN_OR_RETURN(settings.position, bake::parseTriple(position, "--position")); }
    if (!grid.empty()) {
      BAKE_ASSIGN_OR_RETURN(const auto counts, bake::parseTriple(grid, "--grid", "NX,NY,NZ"));
      for (std::size_t a = 0; a < 3; ++a) {
        if (counts[a] != std::floor(counts[a]) || counts[a] < 1 || counts[a] > 1e6)
          return bake::usageError("--grid " + grid + ": the counts must be whole numbers >= 1");
        settings.grid[a] = int(counts[a]);
      }
    }
    if (!gridSpacing.empty()) {
      BAKE_ASSIGN_OR_RETURN(settings.gridSpacing, bake::parseTriple(gridSpacing, "--grid-spacing", "SX,SY,SZ"));
    }
    return {};
  });
}
