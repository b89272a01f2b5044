// Meshes with known geodesic distances for the heat method's tests: a planar grid (distance =
// Euclidean distance in the plane) and a geodesic sphere (distance = R * angle), plus 1:4 midpoint
// subdivision to make large meshes from the shared ones.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "bake/geodesic/surface.h"

namespace bake::geodesic::testing {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

// Splits every triangle into four at its edge midpoints; `project` moves each new vertex (e.g. onto a
// sphere).
template <class Project>
void subdivide(std::vector<Vec3d>& positions, Triangles& triangles, Project project) {
  std::unordered_map<std::uint64_t, std::uint32_t> midpoints;
  const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
    const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
    const auto [it, inserted] = midpoints.try_emplace(key, 0u);
    if (inserted) {
      Vec3d m{};
      for (int k = 0; k < 3; ++k) m[k] = 0.5 * (positions[a][k] + positions[b][k]);
      it->second = static_cast<std::uint32_t>(positions.size());
      positions.push_back(project(m));
    }
    return it->second;
  };
  Triangles out;
  out.reserve(4 * triangles.size());
  for (const auto& t : triangles) {
    const std::uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
    out.push_back({t[0], ab, ca});
    out.push_back({ab, t[1], bc});
    out.push_back({ca, bc, t[2]});
    out.push_back({ab, bc, ca});
  }
  triangles = std::move(out);
}

inline Surface geodesicSphere(int levels, double radius) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3d> p{{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                       {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  Triangles t{{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
              {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
              {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  const auto onSphere = [radius](Vec3d v) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (double& x : v) x *= radius / n;
    return v;
  };
  for (auto& v : p) v = onSphere(v);
  for (int i = 0; i < levels; ++i) subdivide(p, t, onSphere);
  return makeSurface(std::move(p), std::move(t));
}

// A size x size square of (n+1)^2 vertices, each cell split along alternating diagonals.
inline Surface planarGrid(int n, double size) {
  std::vector<Vec3d> p;
  Triangles t;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) p.push_back({size * i / n, size * j / n, 0.0});
  const auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if ((i + j) % 2 == 0) {
        t.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        t.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      } else {
        t.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        t.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  return makeSurface(std::move(p), std::move(t));
}

// Mean and maximum of |field - reference| over reachable vertices, relative to the reference's
// largest value.
struct FieldError {
  double mean = 0.0;
  double max = 0.0;
};
inline FieldError errorRelativeTo(const std::vector<double>& field, const std::vector<double>& reference, double length);
inline FieldError relativeError(const std::vector<double>& field, const std::vector<double>& reference) {
  double range = 0.0;
  for (double r : reference)
    if (std::isfinite(r)) range = std::max(range, r);
  return errorRelativeTo(field, reference, range);
}

// Mean and maximum of |field - reference| over reachable vertices, divided by `length`.
inline FieldError errorRelativeTo(const std::vector<double>& field, const std::vector<double>& reference, double length) {
  FieldError error;
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t v = 0; v < field.size(); ++v) {
    if (!std::isfinite(reference[v])) continue;
    const double e = std::abs(field[v] - reference[v]);
    sum += e;
    error.max = std::max(error.max, e);
    ++count;
  }
  if (count == 0 || length <= 0.0) return error;
  error.mean = sum / static_cast<double>(count) / length;
  error.max /= length;
  return error;
}

}  // namespace bake::geodesic::testing
