// strokebake: a stroke list (formats/paintstroke-input.md: JSON or CSV control points, optionally
// with generators) or a mesh to grow strokes on, to a BAKE_paintstrokes package
// (formats/paintstrokes.md): read, validate and repair (validate.cpp), bake the self-shadowing of
// seed 002 per control point and light direction (shadow.cpp), quantise and pack (package.cpp), write
// atomically. The report gives the counts, the repairs, the quantisation errors against the input and
// the stage times.
#pragma once

#include <string>
#include <vector>

#include "bake/core/cache.h"
#include "bake/core/diagnostics.h"
#include "bake/core/options.h"
#include "bake/core/status.h"
#include "bake/paintstrokes/generators.h"

namespace bake::paintstrokes {

struct ShadowSettings {
  std::vector<Vec3d> directions;  // towards the light; empty: one, the default light of bakeplay
  bool enabled = true;            // --no-shadows: no table (strokes unshadowed)
  double density = 2.5;           // extinction per unit depth along the light path
  double minimum = 0.15;          // reflectance scale of a point the light cannot reach
};

struct Settings {
  std::string input;              // .json / .csv stroke list, or a mesh (grow on it with `grow`)
  std::string output;             // OUT.glb
  GrowSettings grow;              // used when the input is a mesh (grow.mesh = input)
  ShadowSettings shadow;
  bool dropUnusedStyles = false;  // --drop-unused-styles: styles no stroke uses are not packed
  CommonOptions common;           // --report, --depfile, --threads, --quiet, --print-inputs, --budget
};

// The option checks (usage errors), also made by run().
Status check(const Settings& settings);

// The files a bake of these settings reads and writes (for --print-inputs, the output plan and the
// cache).
Result<RunFiles> inputs(const Settings& settings);

// Bakes, writes the package atomically, the --report and the --depfile.
Status run(const Settings& settings, Diagnostics& diagnostics);

}  // namespace bake::paintstrokes
