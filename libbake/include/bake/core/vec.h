// The small fixed-size vectors the library passes around (positions, directions, texture
// coordinates) and the few operations every module needs on them. Plain std::array, so they copy
// into glTF buffers and JSON as they are.
#pragma once

#include <array>
#include <cmath>
#include <numbers>

namespace bake {

inline constexpr double kPi = std::numbers::pi;

using Vec2f = std::array<float, 2>;
using Vec3f = std::array<float, 3>;
using Vec2d = std::array<double, 2>;
using Vec3d = std::array<double, 3>;

namespace vec {

inline Vec3d add(const Vec3d& a, const Vec3d& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3d sub(const Vec3d& a, const Vec3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3d scale(const Vec3d& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double length(const Vec3d& a) { return std::sqrt(dot(a, a)); }
// `a` scaled to unit length, or `fallback` when it has none.
inline Vec3d unit(const Vec3d& a, const Vec3d& fallback) {
  const double l = length(a);
  return l > 1e-300 ? scale(a, 1 / l) : fallback;
}

}  // namespace vec
}  // namespace bake
