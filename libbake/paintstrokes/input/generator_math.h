// Small vector helpers, setting checks and the portable random numbers shared by the stroke generators
// (grow.cpp, tree.cpp). The uniform deviates are built from std::mt19937_64's raw output by hand, because the
// standard distributions may differ between library versions and the generators promise identical
// strokes for a given seed everywhere.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>

#include "bake/core/status.h"
#include "bake/core/vec.h"
#include "bake/paintstrokes/model.h"

namespace bake::paintstrokes::detail {

using vec::add;
using vec::cross;
using vec::dot;
using vec::length;
using vec::scale;
using vec::sub;
inline Vec3d mul(const Vec3d& a, const Vec3d& b) { return {a[0] * b[0], a[1] * b[1], a[2] * b[2]}; }
inline Vec3d lerp(const Vec3d& a, const Vec3d& b, double t) { return add(a, scale(sub(b, a), t)); }
// `a` scaled to unit length, or `fallback` when it is (nearly) zero or not finite.
inline Vec3d normalized(const Vec3d& a, const Vec3d& fallback) {
  const double l = length(a);
  return (l > 1e-300 && std::isfinite(l)) ? scale(a, 1 / l) : fallback;
}

// A generator setting the reader refuses, named by its field.
inline Status badSetting(const std::string& field, const std::string& message) {
  return invalidInput(message, {"", field});
}

// Each component of a colour finite and within [0, 1].
inline bool isUnit(const Vec3d& c) {
  return std::all_of(c.begin(), c.end(), [](double x) { return std::isfinite(x) && x >= 0 && x <= 1; });
}

// A unit vector orthogonal to unit `n`.
inline Vec3d anyOrthogonal(const Vec3d& n) {
  const Vec3d other = std::abs(n[0]) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
  return normalized(cross(n, other), {0, 0, 1});
}

// `v` rotated by `angle` radians about unit `axis` (Rodrigues).
inline Vec3d rotate(const Vec3d& v, const Vec3d& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return add(add(scale(v, c), scale(cross(axis, v), s)), scale(axis, dot(axis, v) * (1 - c)));
}

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  // Uniform in [0, 1): the top 53 bits of one draw.
  double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform in the unit ball (rejection; about two tries on average).
  Vec3d inBall() {
    for (;;) {
      const Vec3d v{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
      if (dot(v, v) <= 1) return v;
    }
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace bake::paintstrokes::detail
