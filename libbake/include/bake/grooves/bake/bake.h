// groovebake: a groove scene (formats/groove-scene.md) to a BAKE_grooves package (formats/grooves.md):
// read and validate the scene, build the groove grid and its special-case records (seed 000 §4.1,
// §4.2), pack it for the GPU in cell-local fp32, and write it atomically. The report gives the grid's
// size and load, the record counts, the bytes per buffer, the stage times and the largest error of the
// stored fp32 geometry against the scene's double geometry. With --apply-to, the package draws the
// grooves on the given mesh (tangent frames computed where it has none) and the report states the
// texture-space scale and how much the mesh's UV layout stretches the pattern.
#pragma once

#include <cstdint>
#include <string>

#include "bake/core/cache.h"
#include "bake/core/diagnostics.h"
#include "bake/core/options.h"
#include "bake/core/status.h"

namespace bake::grooves {

struct Settings {
  std::string scene;                  // SCENE.json
  std::string output;                 // OUT.glb
  double cellSize = 0;                // texture units; 0 = automatic (mean groove width)
  std::uint64_t maxCells = 1u << 22;  // the automatic cell size grows until the grid fits
  bool specialCases = true;           // false: no special-case records (line sampling everywhere)
  // --apply-to: the mesh the grooves are drawn on (its TEXCOORD_0 maps UV [0, 1]^2 to the domain),
  // written into the package with its normals and tangent frames instead of the preview plane.
  std::string applyTo;
  double maxStretch = 1.5;            // warn where the UV layout stretches the pattern beyond this ratio
  CommonOptions common;               // --report, --depfile, --threads, --quiet, --print-inputs
};

// The option checks (usage errors), also made by run().
Status check(const Settings& settings);

// The files a bake of these settings reads and writes (for --print-inputs, the output plan and the
// cache).
Result<RunFiles> inputs(const Settings& settings);

// Bakes, writes the package atomically, the --report and the --depfile.
Status run(const Settings& settings, Diagnostics& diagnostics);

}  // namespace bake::grooves
