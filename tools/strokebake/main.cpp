// strokebake: bakes a stroke list (formats/paintstroke-input.md) or strokes grown on a mesh into a
// BAKE_paintstrokes package (formats/paintstrokes.md): 3D paintstrokes of seed 002, quantised per
// stroke, with baked self-shadowing per light direction.
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "bake/core/session.h"
#include "bake/core/vector_text.h"
#include "bake/paintstrokes/bake.h"
#include "common/cli.h"

int main(int argc, char** argv) {
  using namespace bake::paintstrokes;
  Settings settings;
  bake::Diagnostics diagnostics("strokebake");
  CLI::App app{"Bakes 3D paintstrokes (generalized cylinders whose path and radius are Catmull-Rom splines\n"
               "through control points, with colour, opacity and reflectance varying along them) into a\n"
               "glTF package whose BAKE_paintstrokes material holds the strokes quantised per stroke, their\n"
               "styles and a baked self-shadowing table per light direction. INPUT is a stroke list (.json\n"
               "or .csv) or a mesh (.obj .ply .off .stl .gltf .glb) to grow fur on.",
               "strokebake"};
  std::vector<std::string> lightDirs;
  std::string bendDirection;
  app.add_option("input", settings.input, "Stroke list (.json, .csv) or mesh to grow strokes on")->required();
  app.add_option("-o,--output", settings.output, "Package to write (.glb)")->required();
  app.add_option("--light-dir", lightDirs, "Direction towards a light, x,y,z (repeatable, at most 16; default: the "
                                           "runtime's light 0.4,0.8,0.45)")
      ->type_name("X,Y,Z");
  app.add_option("--shadow-density", settings.shadow.density, "Extinction per unit of relative depth along the light path")
      ->default_str(std::to_string(settings.shadow.density));
  app.add_option("--shadow-minimum", settings.shadow.minimum, "Reflectance scale of a point the light cannot reach, [0, 1]")
      ->default_str(std::to_string(settings.shadow.minimum));
  app.add_flag("--no-shadows{false}", settings.shadow.enabled, "Bake no shadow table (strokes unshadowed)");
  app.add_flag("--drop-unused-styles", settings.dropUnusedStyles,
               "Pack only the styles some stroke uses (the report's stylesDropped names the others)");
  GrowSettings& grow = settings.grow;
  auto* growGroup = app.add_option_group("grow", "Growing strokes on a mesh (when INPUT is a mesh)");
  growGroup->add_option("--count", grow.count, "Strokes to grow")->default_str(std::to_string(grow.count));
  growGroup->add_option("--length", grow.length, "Stroke length, model units")->default_str(std::to_string(grow.length));
  growGroup->add_option("--radius", grow.radius, "Root radius, model units")->default_str(std::to_string(grow.radius));
  growGroup->add_option("--tip-radius", grow.tipRadius, "Tip radius / root radius")->default_str(std::to_string(grow.tipRadius));
  growGroup->add_option("--bend", grow.bend, "Bend towards --bend-direction (0 straight, 1: tip displaced by the length)")
      ->default_str(std::to_string(grow.bend));
  growGroup->add_option("--bend-direction", bendDirection, "Bend direction x,y,z")->type_name("X,Y,Z")->default_str("0,-1,0");
  growGroup->add_option("--points", grow.pointsPerStroke, "Control points per stroke (>= 2)")
      ->default_str(std::to_string(grow.pointsPerStroke));
  growGroup->add_option("--seed", grow.seed, "Random seed")->default_str(std::to_string(grow.seed));
  growGroup->add_option("--length-from", grow.lengthFrom, "Scale lengths by vertex:NAME (a scalar attribute) or texture:PATH")
      ->type_name("SOURCE");
  growGroup->add_option("--color-from,--colour-from", grow.colourFrom, "Colours from vertex (COLOR_0 / vertex colours) or texture:PATH")
      ->type_name("SOURCE");
  bake::addCommonOptions(app, settings.common, {.cacheDir = true});

  return bake::runBaker("strokebake", app, settings, diagnostics, argc, argv, [&]() -> bake::Status {
    for (const std::string& text : lightDirs) {
      BAKE_ASSIGN_OR_RETURN(const bake::Vec3d d, bake::parseTriple(text, "--light-dir"));
      settings.shadow.directions.push_back(d);
    }
    if (!bendDirection.empty()) { BAKE_ASSIGN_OR_RETURN(grow.bendDirection, bake::parseTriple(bendDirection, "--bend-direction")); }
    return {};
  });
}
