// Exact geodesic distances (window propagation) against analytic answers: Euclidean distance on flat
// grids with perturbed triangulations, the unfolded straight line across a cube's edge, the unrolled
// distance on a cylinder side, unfolded pages of a non-manifold book, other components unreachable,
// and the combined field of several sources equal to the minimum of the single fields.
#include "geodesic/bake/exact.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bake::geodesic {
namespace {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

// An n x n grid of cells in the z = 0 plane (size 1), interior vertices jittered deterministically and
// diagonals alternating, so that rays cross edges at every angle.
Surface jitteredGrid(int n, double jitter) {
  std::vector<Vec3d> positions;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double x = double(i) / n, y = double(j) / n;
      if (i > 0 && i < n && j > 0 && j < n) {
        x += jitter / n * std::sin(12.9898 * i + 78.233 * j);
        y += jitter / n * std::cos(39.3468 * i + 11.135 * j);
      }
      positions.push_back({x, y, 0.0});
    }
  Triangles triangles;
  auto at = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if ((i + j) % 2 == 0) {
        triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      } else {
        triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  return makeSurface(std::move(positions), std::move(triangles));
}

double planar(const Vec3d& a, const Vec3d& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }

SurfacePoint atVertex(const Surface& s, std::uint32_t v) {
  SurfacePoint p;
  p.face = s.facesOfVertex(v).front();
  p.barycentric = {0.0, 0.0, 0.0};
  p.barycentric[s.cornerOf(p.face, v)] = 1.0;
  return p;
}

TEST(GeodesicExact, FlatGridVertexSourceIsEuclidean) {
  const Surface s = jitteredGrid(16, 0.3);
  const std::uint32_t source = 5 * 17 + 7;
  const std::vector<SurfacePoint> sources{atVertex(s, source)};
  ExactStats stats;
  const auto d = exactDistances(s, sources, {}, &stats);
  for (std::uint32_t v = 0; v < s.vertexCount(); ++v)
    EXPECT_NEAR(d[v], planar(s.positions[v], s.positions[source]), 1e-12) << "vertex " << v;
  EXPECT_GT(stats.windowsPropagated, 0u);
}

TEST(GeodesicExact, FlatGridFacePointAndEdgePointSources) {
  const Surface s = jitteredGrid(12, 0.25);
  for (const std::array<double, 3> weights : {std::array<double, 3>{0.2, 0.3, 0.5}, {0.0, 0.4, 0.6}}) {
    SurfacePoint p;
    p.face = 77;
    p.barycentric = weights;
    const Vec3d origin = p.position(s);
    const auto d = exactDistances(s, std::vector<SurfacePoint>{p});
    for (std::uint32_t v = 0; v < s.vertexCount(); ++v)
      EXPECT_NEAR(d[v], planar(s.positions[v], origin), 1e-12) << "vertex " << v;
  }
}

TEST(GeodesicExact, SeveralSourcesGiveTheMinimumField) {
  const Surface s = jitteredGrid(12, 0.3);
  std::vector<SurfacePoint> sources;
  for (std::uint32_t v : {3u, 40u, 100u, 150u}) sources.push_back(atVertex(s, v));
  SurfacePoint inside;
  inside.face = 200;
  inside.barycentric = {0.1, 0.6, 0.3};
  sources.push_back(inside);
  const auto combined = exactDistances(s, sources);
  for (std::uint32_t v = 0; v < s.vertexCount(); ++v) {
    double expected = kUnreachable;
    for (const auto& p : sources) expected = std::min(expected, planar(s.positions[v], p.position(s)));
    EXPECT_NEAR(combined[v], expected, 1e-12) << "vertex " << v;
  }
}

// A unit cube, each face an n x n grid; the source at the centre of the bottom face (z = 0).
Surface subdividedCube(int n) {
  std::vector<Vec3d> positions;
  Triangles triangles;
  auto addFace = [&](Vec3d origin, Vec3d u, Vec3d v) {
    const auto base = std::uint32_t(positions.size());
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const double a = double(i) / n, b = double(j) / n;
        positions.push_back({origin[0] + a * u[0] + b * v[0], origin[1] + a * u[1] + b * v[1],
                             origin[2] + a * u[2] + b * v[2]});
      }
    auto at = [&](int i, int j) { return base + std::uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  };
  addFace({0, 0, 0}, {0, 1, 0}, {1, 0, 0});  // bottom
  addFace({0, 0, 1}, {1, 0, 0}, {0, 1, 0});  // top
  addFace({0, 0, 0}, {1, 0, 0}, {0, 0, 1});  // y = 0
  addFace({0, 1, 0}, {0, 0, 1}, {1, 0, 0});  // y = 1
  addFace({0, 0, 0}, {0, 0, 1}, {0, 1, 0});  // x = 0
  addFace({1, 0, 0}, {0, 1, 0}, {0, 0, 1});  // x = 1
  TriangleMesh mesh;
  for (const auto& p : positions) mesh.positions.push_back({float(p[0]), float(p[1]), float(p[2])});
  for (const auto& t : triangles) mesh.triangles.push_back({t[0], t[1], t[2]});
  return buildSurface(mesh).surface;  // welds the shared cube edges
}

TEST(GeodesicExact, CubeAdjacentFacesUnfoldToAStraightLine) {
  const Surface s = subdividedCube(6);
  std::uint32_t centre = 0;
  for (std::uint32_t v = 0; v < s.vertexCount(); ++v)
    if (planar(s.positions[v], {0.0, 0.0, 0.0}) + std::fabs(s.positions[v][2] + 0.5) < 1e-6) centre = v;
  const auto d = exactDistances(s, std::vector<SurfacePoint>{atVertex(s, centre)});
  const Vec3d c = s.positions[centre];
  int checked = 0;
  for (std::uint32_t v = 0; v < s.vertexCount(); ++v) {
    const Vec3d p = s.positions[v];
    const double lo = -0.5 + 1e-9, hi = 0.5 - 1e-9;  // surface centred on its bounding box
    double expected = -1.0;
    if (p[2] < lo) {
      expected = planar(p, c);
    } else if (p[2] < hi && p[1] < lo) {  // side y = min: unfold about the bottom edge
      expected = std::hypot(p[0] - c[0], (c[1] - p[1]) + (p[2] - c[2]));
    } else if (p[2] < hi && p[0] > hi) {  // side x = max
      expected = std::hypot(p[1] - c[1], (p[0] - c[0]) + (p[2] - c[2]));
    }
    if (expected < 0.0) continue;
    EXPECT_NEAR(d[v], expected, 1e-6) << "vertex " << v;
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(GeodesicExact, OpenCylinderSideUnrolls) {
  const int segments = 24, rows = 8;
  const double radius = 1.0, height = 0.3;
  std::vector<Vec3d> positions;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i < segments; ++i) {
      const double a = 2.0 * std::numbers::pi * i / segments;
      positions.push_back({radius * std::cos(a), radius * std::sin(a), height * j});
    }
  Triangles triangles;
  auto at = [&](int i, int j) { return std::uint32_t(j * segments + (i % segments)); };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < segments; ++i) {
      triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  const Surface s = makeSurface(positions, triangles);
  const double chord = 2.0 * radius * std::sin(std::numbers::pi / segments);
  for (int row : {1, 0}) {  // inside, then on the boundary rim
    const std::uint32_t source = at(3, row);
    ExactStats stats;
    const auto d = exactDistances(s, std::vector<SurfacePoint>{atVertex(s, source)}, {}, &stats);
    EXPECT_FALSE(stats.windowLimitReached);
    for (int j = 0; j <= rows; ++j)
      for (int i = 0; i < segments; ++i) {
        const int around = std::abs(i - 3);
        const double expected = std::hypot(std::min(around, segments - around) * chord, (j - row) * height);
        EXPECT_NEAR(d[at(i, j)], expected, 1e-9) << i << "," << j;
      }
  }
}

TEST(GeodesicExact, NonManifoldBookPagesUnfoldThroughTheSpine) {
  // Three square pages (n x n cells) sharing the spine x = 0..0 along z; page k at angle 120k degrees.
  const int n = 6;
  std::vector<Vec3d> positions;
  Triangles triangles;
  auto spine = [&](int j) { return std::uint32_t(j); };
  for (int j = 0; j <= n; ++j) positions.push_back({0.0, 0.0, double(j) / n});
  for (int page = 0; page < 3; ++page) {
    const double a = 2.0 * std::numbers::pi * page / 3.0;
    const auto base = std::uint32_t(positions.size());
    for (int j = 0; j <= n; ++j)
      for (int i = 1; i <= n; ++i) {
        const double u = double(i) / n;
        positions.push_back({u * std::cos(a), u * std::sin(a), double(j) / n});
      }
    auto at = [&](int i, int j) { return i == 0 ? spine(j) : base + std::uint32_t(j * n + (i - 1)); };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  }
  const Surface s = makeSurface(positions, triangles);
  // Source on page 0 at u = 4/6, z = 2/6; pages unfold flat against each other across the spine.
  const std::uint32_t source = std::uint32_t(n + 1 + 2 * n + 3);
  const auto d = exactDistances(s, std::vector<SurfacePoint>{atVertex(s, source)});
  const double su = 4.0 / n, sz = 2.0 / n;
  for (int page = 0; page < 3; ++page)
    for (int j = 0; j <= n; ++j)
      for (int i = 1; i <= n; ++i) {
        const std::uint32_t v = std::uint32_t(n + 1 + page * (n + 1) * n + j * n + (i - 1));
        const double u = double(i) / n, z = double(j) / n;
        const double expected = page == 0 ? std::hypot(u - su, z - sz) : std::hypot(u + su, z - sz);
        EXPECT_NEAR(d[v], expected, 1e-9) << "page " << page << " " << i << "," << j;
      }
}

TEST(GeodesicExact, OtherComponentsAreUnreachableAndMaxDistanceStops) {
  Surface grid = jitteredGrid(6, 0.2);
  std::vector<Vec3d> positions = grid.positions;
  Triangles triangles = grid.triangles;
  const auto offset = std::uint32_t(positions.size());
  for (std::size_t i = 0; i < grid.positions.size(); ++i)
    positions.push_back({grid.positions[i][0] + 5.0, grid.positions[i][1], 1.0});
  for (const auto& t : grid.triangles) triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const Surface s = makeSurface(positions, triangles);
  const auto d = exactDistances(s, std::vector<SurfacePoint>{atVertex(s, 0)});
  for (std::uint32_t v = 0; v < offset; ++v) EXPECT_TRUE(std::isfinite(d[v]));
  for (std::uint32_t v = offset; v < s.vertexCount(); ++v) EXPECT_EQ(d[v], kUnreachable);

  ExactOptions options;
  options.maxDistance = 0.5;
  const auto near = exactDistances(s, std::vector<SurfacePoint>{atVertex(s, 0)}, options);
  for (std::uint32_t v = 0; v < offset; ++v) {
    if (d[v] <= 0.5) EXPECT_NEAR(near[v], d[v], 1e-12);
    if (d[v] > 0.5 + 1e-9) EXPECT_EQ(near[v], kUnreachable);
  }
}

TEST(GeodesicExact, WindowLimitIsReportedAndLeavesUpperBounds) {
  // Cut short after a few windows, the propagation must say so, and what it returns must still be
  // path lengths: never below the exact distance, finite wherever a path exists.
  const Surface s = jitteredGrid(12, 0.3);
  const std::vector<SurfacePoint> source{atVertex(s, 0)};
  ExactStats full;
  const auto exact = exactDistances(s, source, {}, &full);
  EXPECT_FALSE(full.windowLimitReached);
  ExactOptions options;
  options.maxWindows = 20;
  ExactStats limited;
  const auto bounds = exactDistances(s, source, options, &limited);
  EXPECT_TRUE(limited.windowLimitReached);
  EXPECT_LE(limited.windowsCreated + limited.windowsSplit, 20u);
  std::size_t above = 0;
  for (std::uint32_t v = 0; v < s.vertexCount(); ++v) {
    ASSERT_TRUE(std::isfinite(bounds[v])) << v;
    EXPECT_GE(bounds[v], exact[v] - 1e-12) << v;
    if (bounds[v] > exact[v] + 1e-9) ++above;
  }
  EXPECT_GT(above, 0u);  // the limit did cut something short
}

TEST(GeodesicExact, ZeroAreaFacePassesWindowsThrough) {
  // A flat grid whose middle cell holds a sliver: vertex m sits on the segment a-b.
  const Surface base = jitteredGrid(8, 0.0);
  std::vector<Vec3d> positions = base.positions;
  Triangles triangles;
  const std::uint32_t m = std::uint32_t(positions.size());
  const auto at = [](int i, int j) { return std::uint32_t(j * 9 + i); };
  positions.push_back({4.5 / 8, 4.0 / 8, 0.0});  // midpoint of the edge (4,4)-(5,4)
  for (const auto& t : base.triangles) {
    const bool lower = t == std::array<std::uint32_t, 3>{at(4, 3), at(5, 3), at(5, 4)};
    const bool upper = t == std::array<std::uint32_t, 3>{at(4, 4), at(5, 4), at(5, 5)};
    if (lower) {  // split through m: a sliver (4,4)-(m)-(5,4) and the cell's real triangles
      triangles.push_back({at(4, 3), at(5, 3), at(5, 4)});
    } else if (upper) {
      triangles.push_back({at(4, 4), m, at(5, 5)});
      triangles.push_back({m, at(5, 4), at(5, 5)});
    } else {
      triangles.push_back(t);
    }
  }
  triangles.push_back({at(4, 4), at(5, 4), m});  // zero area: m lies on the segment
  const Surface s = makeSurface(positions, triangles);
  for (std::uint32_t source : {at(2, 1), at(6, 7), m}) {
    const auto d = exactDistances(s, std::vector<SurfacePoint>{atVertex(s, source)});
    for (std::uint32_t v = 0; v < s.vertexCount(); ++v)
      EXPECT_NEAR(d[v], planar(s.positions[v], s.positions[source]), 1e-9) << source << " -> " << v;
  }
}

TEST(GeodesicExact, DegenerateInputNeverGivesNaN) {
  // Repeated positions (zero-length edges) and a collapsed face next to a normal one.
  const Surface s = makeSurface({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0.5, 0.5, 0}},
                                {{0, 1, 2}, {1, 3, 4}, {1, 4, 2}, {2, 4, 5}, {3, 4, 5}});
  const auto d = exactDistances(s, std::vector<SurfacePoint>{atVertex(s, 0)});
  for (double x : d) EXPECT_FALSE(std::isnan(x));
  EXPECT_NEAR(d[4], std::sqrt(2.0), 1e-9);
}

}  // namespace
}  // namespace bake::geodesic
