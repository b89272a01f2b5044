// bakeshape: generates the example and test shapes (sphere, torus, double torus, pretzel) as meshes.
#include "bake/core/session.h"
#include "bake/mesh/patterns.h"
#include "bake/mesh/shape_tool.h"
#include "common/cli.h"

int main(int argc, char** argv) {
  bake::ShapeToolSettings settings;
  bake::Diagnostics diagnostics("bakeshape");
  std::string names;
  for (const std::string& name : bake::shapeNames()) names += (names.empty() ? "" : ", ") + name;
  std::string patterns;
  for (const std::string& name : bake::patternNames()) patterns += (patterns.empty() ? "" : ", ") + name;
  CLI::App app{"Generates closed example shapes by polygonising signed distance fields (marching tetrahedra),\n"
               "UV-mapped shapes for texture-space techniques (column, globe: parametric, with TEXCOORD_0),\n"
               "and tileable example images (colour textures, height maps) when the output ends in .png.",
               "bakeshape"};
  app.add_option("shape", settings.shape.name, "A shape: " + names + "; or, with a .png or .exr output, a pattern: " + patterns)
      ->type_name("NAME")
      ->required();
  app.add_option("-o,--output", settings.output, "Mesh to write (.glb or .obj), or pattern image (.png, or .exr for the sky's radiance)")->required();
  app.add_option("--resolution", settings.shape.resolution,
                 "Grid cells along the longest side (shapes, default 64) or pixels per side (patterns)")
      ->default_str("64");
  bake::addCommonOptions(app, settings.common, {.version = true, .report = true, .depfile = true, .threads = false,
                                                .printInputs = false, .cacheDir = true});
  return bake::runTool(app, diagnostics, argc, argv, [&] {
    diagnostics.setQuiet(settings.common.quiet);
    const auto files = [&]() -> bake::Result<bake::RunFiles> { return bake::RunFiles{{}, {settings.output}}; };
    return bake::runCachedBake("bakeshape", app, settings.common, diagnostics, files,
                               [&] { return bake::runShapeTool(settings, diagnostics); });
  });
}
