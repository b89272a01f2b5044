// tambake: a style file to a tonal art map (formats/tam.md): a KTX2 2D array, one layer per tone, the
// full mip chain (R8, or RGBA8 for coloured ink), the tone values in its metadata; optionally the
// threshold texture and a glTF package applying the TAM to a mesh as a BAKE_hatching material. The
// report gives the quality figures of hatching/bake/quality.h next to the construction time.
#pragma once

#include <array>
#include <string>

#include "bake/core/cache.h"
#include "bake/core/diagnostics.h"
#include "bake/core/options.h"
#include "bake/core/status.h"
#include "bake_formats/tam.h"

namespace bake::hatching {

struct MaterialSettings {
  std::string mesh;                   // mesh to apply the TAM to (.obj .ply .off .stl .gltf .glb); empty: none
  std::string package;                // the .glb to write with it
  double tilesPerUnit = 1;            // hatching parameter scale: TAM tiles per object unit
  double rotationDegrees = 0;         // rotation of the hatching parameters about N
  std::array<double, 2> translation{0, 0};  // shift along T and B, in tiles
  std::string orientation = format::tam::kOrientationTowardLight;  // or kOrientationAcrossLight
  std::array<double, 3> baseColour{1, 1, 1};  // colour material the TAM is combined with
  std::array<double, 3> position{0, 0, 0};    // node translation
  double scale = 1;                           // uniform node scale
};

struct Settings {
  std::string style;            // STYLE.json
  std::string output;           // OUT.ktx2
  std::string threshold;        // optional OUT.ktx2 of the threshold texture
  bool zstd = false;            // Zstandard supercompression of the KTX2 levels
  // Overrides of the style file (unset when < 0 / empty).
  int candidates = -1;
  int resolution = -1;
  long long seed = -1;
  // Leave the N finest mip levels out of the written TAM and threshold texture (the base level
  // becomes level N): a scene whose closest view never samples them does not need them
  // (formats/scene.md). The TAM is built in full first, so the levels kept are the full bake's.
  int skipLevels = 0;
  MaterialSettings material;
  CommonOptions common;         // --report, --depfile, --threads, --quiet
};

// The option checks (usage errors), also made by run().
Status check(const Settings& settings);

// The files a bake of these settings reads and writes (for --print-inputs, the output plan and the
// cache).
Result<RunFiles> inputs(const Settings& settings);

// Builds, writes every output atomically, the --report and the --depfile.
Status run(const Settings& settings, Diagnostics& diagnostics);

}  // namespace bake::hatching
