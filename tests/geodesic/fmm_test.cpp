// Fast marching (libbake/geodesic/fmm.cpp) against analytic distances: on a flat grid the geodesic
// distance is the planar Euclidean distance, on a sphere it is R times the angle. Fast marching is first
// order, so the tests bound the error relative to the edge length and check that it falls when the
// mesh is refined. Data tests run on the shared planar stress grids.
#include <gtest/gtest.h>

#include "support/data.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>

#include "bake/geodesic/sources.h"
#include "bake/io/mesh.h"
#include "geodesic/bake/fmm.h"

namespace bake::geodesic {
namespace {

// (n+1)^2 vertices on [0,1]^2, cells split along alternating diagonals (a "union jack" pattern,
// so the front meets every direction of diagonal).
Surface flatGrid(std::uint32_t n) {
  std::vector<Vec3d> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (std::uint32_t j = 0; j <= n; ++j)
    for (std::uint32_t i = 0; i <= n; ++i) positions.push_back({double(i) / n, double(j) / n, 0.0});
  auto at = [n](std::uint32_t i, std::uint32_t j) { return j * (n + 1) + i; };
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i) {
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

// An icosahedron subdivided `levels` times (1:4) with vertices pushed onto the unit sphere.
Surface unitSphere(int levels) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3d> p{{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                       {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  std::vector<std::array<std::uint32_t, 3>> t{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                              {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                              {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                              {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  auto normalise = [](Vec3d v) {
    const double r = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return Vec3d{v[0] / r, v[1] / r, v[2] / r};
  };
  for (auto& v : p) v = normalise(v);
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto found = midpoints.find(key);
      if (found != midpoints.end()) return found->second;
      p.push_back(normalise({p[a][0] + p[b][0], p[a][1] + p[b][1], p[a][2] + p[b][2]}));
      return midpoints[key] = static_cast<std::uint32_t>(p.size() - 1);
    };
    std::vector<std::array<std::uint32_t, 3>> finer;
    for (const auto& [a, b, c] : t) {
      const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    t = std::move(finer);
  }
  return makeSurface(std::move(p), std::move(t));
}

double planar(const Surface& s, std::uint32_t v, const Vec3d& from) {
  return std::hypot(s.positions[v][0] - from[0], s.positions[v][1] - from[1]);
}

// Largest |fmm - expected| over all vertices.
template <class Expected>
double maxError(const Surface& s, const std::vector<double>& d, Expected expected) {
  double worst = 0.0;
  for (std::uint32_t v = 0; v < s.vertexCount(); ++v) worst = std::max(worst, std::abs(d[v] - expected(v)));
  return worst;
}

TEST(Fmm, FlatGridFromCornerIsCloseToPlanarDistanceAndConverges) {
  double previous = 0.0;
  for (std::uint32_t n : {8u, 16u, 32u}) {
    const Surface s = flatGrid(n);
    const SurfacePoint source = vertexPoint(s, 0);
    const auto d = fastMarchingDistances(s, std::span(&source, 1));
    EXPECT_EQ(d[0], 0.0);
    const double error = maxError(s, d, [&](std::uint32_t v) { return planar(s, v, {0, 0, 0}); });
    EXPECT_LT(error, 1.0 / n) << "n = " << n;  // within one edge length
    if (previous > 0.0) {
      EXPECT_LT(error, 0.8 * previous) << "n = " << n;
    }
    previous = error;
  }
}

TEST(Fmm, AxisAlignedFrontIsExactOnFlatGrid) {
  // Sources along the whole left side: the front is planar, which fast marching reproduces exactly.
  const Surface s = flatGrid(10);
  std::vector<SurfacePoint> sources;
  for (std::uint32_t j = 0; j <= 10; ++j) sources.push_back(vertexPoint(s, j * 11));
  const auto d = fastMarchingDistances(s, sources);
  EXPECT_LT(maxError(s, d, [&](std::uint32_t v) { return s.positions[v][0]; }), 1e-12);
}

TEST(Fmm, SeveralSourcesGiveTheNearest) {
  const Surface s = flatGrid(16);
  const std::vector<SurfacePoint> sources{vertexPoint(s, 0), vertexPoint(s, 16 * 17 + 16)};
  const auto d = fastMarchingDistances(s, sources);
  EXPECT_EQ(d[0], 0.0);
  EXPECT_EQ(d[16 * 17 + 16], 0.0);
  const double error = maxError(s, d, [&](std::uint32_t v) {
    return std::min(planar(s, v, {0, 0, 0}), planar(s, v, {1, 1, 0}));
  });
  EXPECT_LT(error, 1.0 / 16);
}

TEST(Fmm, FaceInteriorSourceStartsFromItsCorners) {
  const Surface s = flatGrid(16);
  SurfacePoint source;
  source.face = 100;
  source.barycentric = {0.2, 0.3, 0.5};
  const Vec3d at = source.position(s);
  const auto d = fastMarchingDistances(s, std::span(&source, 1));
  for (std::uint32_t v : s.triangles[source.face]) EXPECT_NEAR(d[v], planar(s, v, at), 1e-12);
  EXPECT_LT(maxError(s, d, [&](std::uint32_t v) { return planar(s, v, at); }), 1.0 / 16);
}

TEST(Fmm, SphereIsRadiusTimesAngleAndConverges) {
  double previous = 0.0;
  for (int levels : {2, 3, 4}) {
    const Surface s = unitSphere(levels);
    const SurfacePoint source = vertexPoint(s, 0);
    const auto d = fastMarchingDistances(s, std::span(&source, 1));
    const Vec3d pole = s.positions[0];
    const double error = maxError(s, d, [&](std::uint32_t v) {
      const auto& q = s.positions[v];
      return std::acos(std::clamp(q[0] * pole[0] + q[1] * pole[1] + q[2] * pole[2], -1.0, 1.0));
    });
    EXPECT_LT(error, 0.1 * std::numbers::pi) << "levels = " << levels;
    if (previous > 0.0) {
      EXPECT_LT(error, 0.8 * previous) << "levels = " << levels;
    }
    previous = error;
  }
}

TEST(Fmm, ObtuseTrianglesAreSplitByUnfolding) {
  // A strip of flat, very obtuse triangles: without unfolding the front would zig-zag along edges.
  std::vector<Vec3d> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  const std::uint32_t columns = 40;
  for (std::uint32_t i = 0; i <= columns; ++i) {
    positions.push_back({double(i), 0.0, 0.0});
    positions.push_back({double(i) + 0.5, 0.1, 0.0});
  }
  for (std::uint32_t i = 0; i < columns; ++i) {
    triangles.push_back({2 * i, 2 * i + 2, 2 * i + 1});
    triangles.push_back({2 * i + 1, 2 * i + 2, 2 * i + 3});
  }
  const Surface s = makeSurface(std::move(positions), std::move(triangles));
  const SurfacePoint source = vertexPoint(s, 0);
  const auto d = fastMarchingDistances(s, std::span(&source, 1));
  // The strip is convex, so the distance is planar; the split corners keep the front straight.
  EXPECT_LT(maxError(s, d, [&](std::uint32_t v) { return planar(s, v, {0, 0, 0}); }), 0.01);
}

TEST(Fmm, NonManifoldEdgeReachesEveryPage) {
  // Three unit squares ("pages") hinged on the edge from (0, 0, 0) to (0, 1, 0).
  const std::vector<Vec3d> positions{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0},
                                     {-1, 0, 0.0001}, {-1, 1, 0.0001}, {0, 0, 1}, {0, 1, 1}};
  std::vector<std::array<std::uint32_t, 3>> triangles{{0, 2, 3}, {0, 3, 1}, {0, 1, 5}, {0, 5, 4},
                                                      {0, 1, 7}, {0, 7, 6}};
  const Surface s = makeSurface(positions, triangles);
  const SurfacePoint source = vertexPoint(s, 3);  // far corner of the first page
  const auto d = fastMarchingDistances(s, std::span(&source, 1));
  // Unfolded into the first page's plane, both other pages continue it past the hinge.
  EXPECT_NEAR(d[5], 2.0, 0.1);
  EXPECT_NEAR(d[7], 2.0, 0.1);
  EXPECT_NEAR(d[4], std::sqrt(5.0), 0.1);
  EXPECT_NEAR(d[6], std::sqrt(5.0), 0.1);
}

TEST(Fmm, OtherComponentsAreUnreachable) {
  const Surface s = makeSurface({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {9, 9, 9}},
                                {{0, 1, 2}, {3, 4, 5}});
  const SurfacePoint source = vertexPoint(s, 0);
  const auto d = fastMarchingDistances(s, std::span(&source, 1));
  EXPECT_DOUBLE_EQ(d[1], 1.0);
  EXPECT_DOUBLE_EQ(d[2], 1.0);
  for (std::uint32_t v : {3u, 4u, 5u, 6u}) EXPECT_EQ(d[v], kUnreachable);
}

TEST(DataFmm, StressGridsAreCloseToPlanarDistance) {
  BAKE_SKIP_WITHOUT_DATA();
  const std::filesystem::path dir = test::dataDir() / "meshes" / "stress";
  // Sheared grids have long obtuse triangles (edges up to 0.1 long on a 7 x 1 grid): a looser bound.
  const std::vector<std::pair<const char*, double>> grids{
      {"grid_flat_64.off", 0.01}, {"grid_needles.off", 0.02}, {"grid_obtuse.off", 0.08}};
  for (const auto& [name, tolerance] : grids) {
    auto mesh = readMesh(dir / name);
    ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
    const Surface s = buildSurface(mesh.value()).surface;
    // The source is the vertex nearest the grid's centre; distances are planar (z = 0).
    std::uint32_t centre = 0;
    for (std::uint32_t v = 0; v < s.vertexCount(); ++v)
      if (std::hypot(s.positions[v][0], s.positions[v][1]) <
          std::hypot(s.positions[centre][0], s.positions[centre][1]))
        centre = v;
    const SurfacePoint source = vertexPoint(s, centre);
    const auto d = fastMarchingDistances(s, std::span(&source, 1));
    double largest = 0.0;
    for (double x : d) largest = std::max(largest, x);
    const double error = maxError(s, d, [&](std::uint32_t v) { return planar(s, v, s.positions[centre]); });
    EXPECT_LT(error, tolerance * largest) << name;
  }
}

}  // namespace
}  // namespace bake::geodesic
