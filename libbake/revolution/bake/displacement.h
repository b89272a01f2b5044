// The displacement map of seed 001 ("Shape and displacement map", Fig. 5): the partial derivatives
// dH/du and dH/dv of a height map H(u, v), by central differences with wrap-around in u (the angle
// goes round) and one-sided at the v ends, stored in RG with the scale that maps them to unorm16.
#pragma once

#include <cstdint>
#include <vector>

#include "bake/core/status.h"

namespace bake::revolution {

struct HeightMap {
  int width = 0, height = 0;
  std::vector<float> height01;  // row-major, values in [0, 1]
};

struct DisplacementMap {
  int width = 0, height = 0;
  double derivativeScale = 1;       // largest |dH/du|, |dH/dv| (height units per texture unit)
  std::vector<float> dHdu, dHdv;    // per texel, in height units per texture unit (u, v in [0, 1])
  std::vector<std::uint8_t> bytes;  // RG unorm16: 0.5 + 0.5 x / derivativeScale
};

// `heightScale` multiplies H (object units per unit of H).
DisplacementMap buildDisplacementMap(const HeightMap& height, double heightScale);

}  // namespace bake::revolution
