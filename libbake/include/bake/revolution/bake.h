// revolbake: a profile (vector polyline/arcs, SVG path, coverage image or a mesh of revolution) to a
// BAKE_revolution package (formats/revolution.md): the signed shape map, the displacement map, the
// measured projection choice, the safety margin, the proxy bands and the iteration budget that the
// CPU march (identical to the shader) finds for the requested silhouette error.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "bake/core/cache.h"
#include "bake/core/diagnostics.h"
#include "bake/core/options.h"
#include "bake/core/status.h"
#include "bake/revolution/projection.h"
#include "bake/revolution/shape_map.h"
#include "bake_formats/revolution.h"

namespace bake::revolution {

enum class ProfileKind { Auto, Json, Csv, Svg, Image, Mesh };

struct Settings {
  std::string input;
  std::string output;
  ProfileKind kind = ProfileKind::Auto;  // Auto: by extension
  std::string svgPathId;
  double imageTexelSize = 0;  // image inputs: object units per pixel (0: 1 / image height)
  int resolution = 1024;      // texels on the larger side of the shape map
  int paddingTexels = 4;
  DistanceEncoding encoding = DistanceEncoding::Unorm16;
  std::string heightMap;      // optional image for the displacement map
  double heightScale = 0.01;  // object units for H = 1
  std::optional<Projection> projection;  // unset: measured choice
  double repeatU = 0, repeatV = 0;       // 0: from the projection's recommended ratio
  double targetError = 0.005;            // silhouette mismatch the iteration budget must reach
  int proxyBands = 32;
  double overRelaxation = format::revolution::kDefaultOverRelaxation;
  std::string baseColorTexture;  // optional PNG embedded as the material's base colour
  std::array<double, 3> position{0, 0, 0};  // node translation (where the object stands in a scene)
  // Copies of the object in one shape box (seed 001 Eq. 9, Fig. 13; formats/revolution.md,
  // "Replicas"): a grid, or a ring round +y; not both.
  std::array<int, 3> grid{1, 1, 1};            // copies along x, y, z
  std::array<double, 3> gridSpacing{0, 0, 0};  // object units; 0: the shape box's extent on that axis
  std::string mirror;                          // axes among "xyz" whose odd copies are reflected
  int ring = 0;                                // copies round +y (0: no ring)
  double ringRadius = 0;                       // 0: the smallest that keeps the copies apart
  bool selfShadow = true;                      // the runtime marches a shadow ray toward the light
  CommonOptions common;  // --report, --depfile, --threads, --quiet
};

// The option checks (usage errors), also made by run().
Status check(const Settings& settings);

// The files a bake of these settings reads and writes (for --print-inputs, the output plan and the
// cache).
Result<RunFiles> inputs(const Settings& settings);

// Bakes, writes the package (atomically), the --report and the --depfile.
Status run(const Settings& settings, Diagnostics& diagnostics);

}  // namespace bake::revolution
