// The CGAL peers (peers/cgal_geodesic.h) against analytic distances: on a flat grid the geodesic
// distance is the Euclidean distance in the plane; on a regular tetrahedron adjacent vertices are one
// edge length apart. Non-manifold input must come back as an error, other components as +infinity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cgal_geodesic.h"

namespace bake::peers {
namespace {

struct PeerInput {
  PeerPositions positions;
  PeerTriangles triangles;
};

// (n+1) x (n+1) vertices in the z = 0 plane, unit spacing, two triangles per cell.
PeerInput flatGrid(std::uint32_t n) {
  PeerInput grid;
  for (std::uint32_t j = 0; j <= n; ++j)
    for (std::uint32_t i = 0; i <= n; ++i) grid.positions.push_back({double(i), double(j), 0.0});
  auto at = [n](std::uint32_t i, std::uint32_t j) { return j * (n + 1) + i; };
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i) {
      grid.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      grid.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return grid;
}

PeerInput regularTetrahedron() {
  return {{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}, {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}};
}

double planarDistance(const PeerInput& grid, std::uint32_t a, std::uint32_t b) {
  return std::hypot(grid.positions[a][0] - grid.positions[b][0], grid.positions[a][1] - grid.positions[b][1]);
}

TEST(CgalPeer, ExactOnFlatGridIsPlanarDistanceToNearestSource) {
  const PeerInput grid = flatGrid(6);
  const std::vector<std::uint32_t> sources{0, 48};  // opposite corners
  auto distances = cgalExactDistances(grid.positions, grid.triangles, sources);
  ASSERT_TRUE(distances.isOk()) << distances.status().describe();
  for (std::uint32_t v = 0; v < grid.positions.size(); ++v) {
    const double expected = std::min(planarDistance(grid, v, 0), planarDistance(grid, v, 48));
    EXPECT_NEAR(distances.value()[v], expected, 1e-9) << "vertex " << v;
  }
}

TEST(CgalPeer, ExactOnTetrahedronIsEdgeLength) {
  const PeerInput tetrahedron = regularTetrahedron();
  auto distances = cgalExactDistances(tetrahedron.positions, tetrahedron.triangles, {0});
  ASSERT_TRUE(distances.isOk()) << distances.status().describe();
  EXPECT_EQ(distances.value()[0], 0.0);
  for (int v = 1; v < 4; ++v) EXPECT_NEAR(distances.value()[v], std::sqrt(8.0), 1e-12);
}

TEST(CgalPeer, HeatOnFlatGridIsCloseToPlanarDistance) {
  const PeerInput grid = flatGrid(8);
  auto solver = CgalHeatSolver::build(grid.positions, grid.triangles);
  ASSERT_TRUE(solver.isOk()) << solver.status().describe();
  const std::uint32_t centre = 4 * 9 + 4;
  auto distances = solver.value().distances({centre});
  ASSERT_TRUE(distances.isOk()) << distances.status().describe();
  // The heat method is smooth but approximate: within 10 % of the largest distance everywhere.
  const double largest = planarDistance(grid, centre, 0);
  for (std::uint32_t v = 0; v < grid.positions.size(); ++v)
    EXPECT_NEAR(distances.value()[v], planarDistance(grid, v, centre), 0.1 * largest) << "vertex " << v;
  // A second field from the same factorisation.
  auto corner = solver.value().distances({0});
  ASSERT_TRUE(corner.isOk());
  EXPECT_NEAR(corner.value()[80], planarDistance(grid, 0, 80), 0.1 * planarDistance(grid, 0, 80));
}

TEST(CgalPeer, OtherComponentIsUnreachable) {
  PeerInput two = regularTetrahedron();
  for (const auto& p : regularTetrahedron().positions) two.positions.push_back({p[0] + 10, p[1], p[2]});
  for (const auto& t : regularTetrahedron().triangles) two.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
  auto exact = cgalExactDistances(two.positions, two.triangles, {0});
  ASSERT_TRUE(exact.isOk()) << exact.status().describe();
  auto solver = CgalHeatSolver::build(two.positions, two.triangles);
  ASSERT_TRUE(solver.isOk()) << solver.status().describe();
  auto heat = solver.value().distances({0});
  ASSERT_TRUE(heat.isOk()) << heat.status().describe();
  for (int v = 4; v < 8; ++v) {
    EXPECT_TRUE(std::isinf(exact.value()[v]));
    EXPECT_TRUE(std::isinf(heat.value()[v]));
  }
  EXPECT_NEAR(exact.value()[1], std::sqrt(8.0), 1e-12);
}

TEST(CgalPeer, NonManifoldInputIsAnErrorNotACrash) {
  // Three triangles on the edge 0-1.
  const PeerPositions positions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  const PeerTriangles triangles{{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  EXPECT_FALSE(cgalExactDistances(positions, triangles, {0}).isOk());
  EXPECT_FALSE(CgalHeatSolver::build(positions, triangles).isOk());
  const PeerTriangles badIndex{{0, 1, 7}};
  EXPECT_FALSE(cgalExactDistances(positions, badIndex, {0}).isOk());
  EXPECT_FALSE(cgalExactDistances(positions, {{0, 1, 2}}, {9}).isOk());
}

}  // namespace
}  // namespace bake::peers
