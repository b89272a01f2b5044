// tambake: builds a tonal art map from a style file (formats/tam.md): a KTX2 2D array of tones with
// its full mip chain, optionally the threshold texture and a package applying it to a mesh.
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "bake/core/session.h"
#include "bake/core/vector_text.h"
#include "bake/hatching/bake.h"
#include "bake/hatching/style.h"
#include "common/cli.h"

int main(int argc, char** argv) {
  using namespace bake::hatching;
  Settings settings;
  bake::Diagnostics diagnostics("tambake");
  CLI::App app{"Builds a tonal art map (Praun et al. 2001) from a style file: one image per tone, light to\n"
               "dark, each level drawn with strokes at the same pixel width, nested across tones and\n"
               "resolutions, tiling seamlessly. Writes a KTX2 2D array (one layer per tone, full mip chain,\n"
               "tone values in its metadata), optionally the threshold texture, and optionally a glTF\n"
               "package that applies the TAM to a mesh as a BAKE_hatching material for bakeplay.",
               "tambake"};
  app.add_option("style", settings.style, "Style file (.json, formats/tam-style.schema.json)")->required();
  app.add_option("-o,--output", settings.output, "TAM to write (.ktx2)")->required();
  app.add_option("--threshold", settings.threshold, "Also write the threshold texture (.ktx2): per texel, the first inked tone");
  app.add_flag("--zstd", settings.zstd, "Zstandard-supercompress the KTX2 levels");
  app.add_option("--candidates", settings.candidates, "Override the style's candidate strokes per step (K)");
  app.add_option("--resolution", settings.resolution, "Override the style's finest level side (power of two)");
  app.add_option("--seed", settings.seed, "Override the style's random seed");
  app.add_option("--skip-levels", settings.skipLevels,
                 "Leave out the N finest mip levels (the base level becomes level N), for scenes never seen close enough to sample them")
      ->check(CLI::NonNegativeNumber);
  MaterialSettings& material = settings.material;
  app.add_option("--apply-to", material.mesh, "Mesh to apply the TAM to (.obj .ply .off .stl .gltf .glb)");
  app.add_option("--package", material.package, "Package to write with --apply-to (.glb, BAKE_hatching material)");
  app.add_option("--tiles-per-unit", material.tilesPerUnit, "Hatching scale: TAM tiles per object unit")->default_str("1");
  app.add_option("--rotation", material.rotationDegrees, "Rotation of the strokes about the normal, degrees")->default_str("0");
  std::string translation;
  app.add_option("--translation", translation, "Shift of the hatching along T and B, in tiles: U,V")
      ->type_name("U,V")
      ->default_str("0,0");
  app.add_option("--orientation", material.orientation, "Strokes toward-light (along the projected light) or across-light")
      ->check(CLI::IsMember({bake::format::tam::kOrientationTowardLight, bake::format::tam::kOrientationAcrossLight}))
      ->default_str(bake::format::tam::kOrientationTowardLight);
  std::string baseColour, position;
  app.add_option("--base-color,--base-colour", baseColour, "Colour material the TAM is combined with: R,G,B in [0, 1]")
      ->type_name("R,G,B");
  app.add_option("--position", position, "Where the object stands in a scene: X,Y,Z (node translation)")->type_name("X,Y,Z");
  app.add_option("--scale", material.scale, "Uniform scale of the object's node")->default_str("1");
  bake::addCommonOptions(app, settings.common, {.cacheDir = true});

  return bake::runBaker("tambake", app, settings, diagnostics, argc, argv, [&]() -> bake::Status {
    if (!baseColour.empty()) { BAKE_ASSIGN_OR_RETURN(material.baseColour, bake::parseTriple(baseColour, "--base-color", "R,G,B")); }
    if (!position.empty()) { BAKE_ASSIGN_OR_RETURN(material.position, bake::parseTriple(position, "--position")); }
    if (!translation.empty()) { BAKE_ASSIGN_OR_RETURN(material.translation, bake::parsePair(translation, "--translation")); }
    return {};
  });
}
