// One shape-map fetch as the GPU performs it (formats/revolution.md, "Sampling and marching"; the
// OpenGL 4.5 specification, section 8.14.2 "Coordinate wrapping and texel selection"): the texel
// coordinate is x = r / texelSize - 0.5 across (texel centres at i + 0.5), the two taps floor(x) and
// floor(x) + 1 are wrapped, and the four encoded B values are filtered with the bilinear weights
// before decoding, exactly as a linear sampler filters normalised integers. The r axis is mirrored at
// its lower edge (tap -1 - i reads texel i: GL_MIRROR_CLAMP_TO_EDGE, the distance field's own symmetry
// about the axis) and clamped at the outer edge; the h axis is clamped at both ends.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "revolution/oracle/march.h"

namespace bake::revolution {
namespace {

constexpr int kDistanceChannel = 2;  // B

int mirrorClamp(int i, int size) {
  if (i < 0) i = -1 - i;
  return std::min(i, size - 1);
}

int clampToEdge(int j, int size) { return std::clamp(j, 0, size - 1); }

// The B channel of texel (i, j) as the sampler's filter sees it: unorm values in [0, 1], floats as is.
double encodedB(const EncodedShapeMap& map, const ShapeGrid& grid, int i, int j) {
  const std::size_t texel = std::size_t(j) * grid.width + i;
  switch (map.encoding) {
    case DistanceEncoding::Float: {
      float v;
      std::memcpy(&v, &map.bytes[(texel * 4 + kDistanceChannel) * 4], sizeof v);
      return v;
    }
    case DistanceEncoding::Unorm16: {
      const std::size_t at = (texel * 4 + kDistanceChannel) * 2;
      return (map.bytes[at] | (unsigned(map.bytes[at + 1]) << 8)) / 65535.0;
    }
    case DistanceEncoding::Sqrt8:
      return map.bytes[texel * 4 + kDistanceChannel] / 255.0;
  }
  return 0;
}

// The shader's decoding of a filtered B value (bake_formats/revolution.h).
double decodeB(const EncodedShapeMap& map, double b) {
  switch (map.encoding) {
    case DistanceEncoding::Float: return b;
    case DistanceEncoding::Unorm16: return (2 * b - 1) * map.distanceScale;
    case DistanceEncoding::Sqrt8: {
      const double e = 2 * b - 1;
      return (e < 0 ? -e * e : e * e) * map.distanceScale;
    }
  }
  return b;
}

}  // namespace

double sampleDistance(const EncodedShapeMap& encoded, const ShapeGrid& grid, double r, double h) {
  if (grid.width <= 0 || grid.height <= 0 || !(grid.texelSize > 0)) return std::numeric_limits<double>::infinity();
  const double x = std::abs(r) / grid.texelSize - 0.5;
  const double y = (h - grid.hMin) / grid.texelSize - 0.5;
  // Far outside, the clamp makes every tap the edge texel; keep the floor in int range (NaN: the
  // first texel, so a broken ray still reads a finite value).
  const double xc = std::isnan(x) ? 0.0 : std::clamp(x, -2.0, double(grid.width) + 1);
  const double yc = std::isnan(y) ? 0.0 : std::clamp(y, -2.0, double(grid.height) + 1);
  const double x0 = std::floor(xc), y0 = std::floor(yc);
  const double fx = xc - x0, fy = yc - y0;
  const int i0 = mirrorClamp(int(x0), grid.width), i1 = mirrorClamp(int(x0) + 1, grid.width);
  const int j0 = clampToEdge(int(y0), grid.height), j1 = clampToEdge(int(y0) + 1, grid.height);
  const double bottom = (1 - fx) * encodedB(encoded, grid, i0, j0) + fx * encodedB(encoded, grid, i1, j0);
  const double top = (1 - fx) * encodedB(encoded, grid, i0, j1) + fx * encodedB(encoded, grid, i1, j1);
  return decodeB(encoded, (1 - fy) * bottom + fy * top);
}

}  // namespace bake::revolution
