// The displacement map of seed 001 ("Shape and displacement map", Fig. 5): the shader perturbs the
// normal with the partial derivatives of a height map H(u, v) (Blinn 1978, seed Eq. 1 and 4-5), so
// the bake stores dH/du and dH/dv instead of H. They are central differences on the texel grid,
// converted to height units per texture unit (u, v in [0, 1]): a step of one texel is 1/width in u,
// so dH/du = (H[i+1] - H[i-1]) * width / 2 * heightScale. u is the angle around the axis, so the
// differences wrap around in u (the seam is invisible); v ends are open, so they are one-sided there.
// Both are stored as RG unorm16 0.5 + 0.5 x / derivativeScale, the scale being the largest slope.
#include "revolution/bake/displacement.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace bake::revolution {
namespace {

std::size_t texelIndex(const HeightMap& map, int i, int j) { return std::size_t(j) * map.width + i; }

double heightAt(const HeightMap& map, int i, int j) { return map.height01[texelIndex(map, i, j)]; }

// Central difference across the column, wrapping: column -1 is column width-1.
double derivativeU(const HeightMap& map, int i, int j) {
  const int left = (i + map.width - 1) % map.width;
  const int right = (i + 1) % map.width;
  return (heightAt(map, right, j) - heightAt(map, left, j)) * map.width / 2.0;
}

// Central difference along the row inside, one-sided at the first and last row.
double derivativeV(const HeightMap& map, int i, int j) {
  if (map.height < 2) return 0;
  if (j == 0) return (heightAt(map, i, 1) - heightAt(map, i, 0)) * map.height;
  if (j == map.height - 1) return (heightAt(map, i, j) - heightAt(map, i, j - 1)) * map.height;
  return (heightAt(map, i, j + 1) - heightAt(map, i, j - 1)) * map.height / 2.0;
}

void appendUnorm16(std::vector<std::uint8_t>& bytes, double value01) {
  const double clamped = std::clamp(value01, 0.0, 1.0);
  const auto v = static_cast<std::uint16_t>(std::lround(clamped * 65535.0));
  bytes.push_back(static_cast<std::uint8_t>(v & 0xff));  // little-endian
  bytes.push_back(static_cast<std::uint8_t>(v >> 8));
}

}  // namespace

DisplacementMap buildDisplacementMap(const HeightMap& height, double heightScale) {
  DisplacementMap out;
  if (height.width <= 0 || height.height <= 0 ||
      height.height01.size() != std::size_t(height.width) * height.height)
    return out;
  out.width = height.width;
  out.height = height.height;
  const std::size_t count = height.height01.size();
  out.dHdu.resize(count);
  out.dHdv.resize(count);
  double largest = 0;
  for (int j = 0; j < height.height; ++j)
    for (int i = 0; i < height.width; ++i) {
      const std::size_t k = texelIndex(height, i, j);
      const double du = derivativeU(height, i, j) * heightScale;
      const double dv = derivativeV(height, i, j) * heightScale;
      out.dHdu[k] = static_cast<float>(du);
      out.dHdv[k] = static_cast<float>(dv);
      largest = std::max({largest, std::abs(du), std::abs(dv)});
    }
  // A flat map has no slope; scale 1 keeps the encoding finite (everything maps to 0.5).
  out.derivativeScale = largest > 0 ? largest : 1.0;
  out.bytes.reserve(count * 4);
  for (std::size_t k = 0; k < count; ++k) {
    appendUnorm16(out.bytes, 0.5 + 0.5 * out.dHdu[k] / out.derivativeScale);
    appendUnorm16(out.bytes, 0.5 + 0.5 * out.dHdv[k] / out.derivativeScale);
  }
  return out;
}

}  // namespace bake::revolution
