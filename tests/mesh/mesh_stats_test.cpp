// Mesh statistics on tiny inline meshes whose answers can be counted by hand.
#include "mesh/mesh_stats.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bake {
namespace {

TriangleMesh tetrahedron() {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  return mesh;
}

TEST(MeshStats, SingleTriangleIsAllBoundary) {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}};
  mesh.triangles = {{0, 1, 2}};
  const MeshStats stats = computeMeshStats(mesh);
  EXPECT_EQ(stats.components, 1u);
  EXPECT_EQ(stats.boundaryEdges, 3u);
  EXPECT_EQ(stats.nonManifoldEdges, 0u);
  EXPECT_EQ(stats.degenerateTriangles, 0u);
  EXPECT_EQ(stats.unreferencedVertices, 0u);
  EXPECT_FALSE(stats.bounds.empty);
  EXPECT_EQ(stats.bounds.min, (Vec3f{0, 0, 0}));
  EXPECT_EQ(stats.bounds.max, (Vec3f{2, 3, 0}));
  EXPECT_DOUBLE_EQ(stats.bounds.diagonal(), std::sqrt(13.0));
}

TEST(MeshStats, ClosedTetrahedronHasNoBoundary) {
  const MeshStats stats = computeMeshStats(tetrahedron());
  EXPECT_EQ(stats.components, 1u);
  EXPECT_EQ(stats.boundaryEdges, 0u);
  EXPECT_EQ(stats.nonManifoldEdges, 0u);
}

TEST(MeshStats, ComponentsIgnoreUnreferencedVertices) {
  TriangleMesh mesh = tetrahedron();
  const std::uint32_t base = std::uint32_t(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), {{5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {9, 9, 9}});
  mesh.triangles.push_back({base, base + 1, base + 2});
  const MeshStats stats = computeMeshStats(mesh);
  EXPECT_EQ(stats.components, 2u);
  EXPECT_EQ(stats.unreferencedVertices, 1u);
  EXPECT_EQ(stats.boundaryEdges, 3u);
  EXPECT_EQ(stats.bounds.max, (Vec3f{9, 9, 9}));
}

TEST(MeshStats, TrianglesTouchingAtOneVertexAreOneComponent) {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 3, 4}};
  EXPECT_EQ(computeMeshStats(mesh).components, 1u);
}

TEST(MeshStats, ThreeTrianglesOnOneEdgeAreNonManifold) {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {0.5f, -1, 0}, {0.5f, 0, 1}};
  mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const MeshStats stats = computeMeshStats(mesh);
  EXPECT_EQ(stats.nonManifoldEdges, 1u);
  EXPECT_EQ(stats.boundaryEdges, 6u);
  EXPECT_EQ(stats.components, 1u);
}

TEST(MeshStats, DegenerateTrianglesOfEveryKind) {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 1, 0}, {2, 2, 0}, {1, 1, 0}, {0, 1, 0}, {1e-6f, 0, 0}};
  mesh.triangles = {
      {0, 1, 2},  // collinear
      {0, 1, 3},  // two corners at one position
      {0, 0, 4},  // repeated index
      {0, 5, 4},  // tiny but not zero
  };
  EXPECT_EQ(computeMeshStats(mesh).degenerateTriangles, 3u);
}

TEST(MeshStats, EmptyMesh) {
  const MeshStats stats = computeMeshStats(TriangleMesh{});
  EXPECT_TRUE(stats.bounds.empty);
  EXPECT_EQ(stats.bounds.diagonal(), 0.0);
  EXPECT_EQ(stats.components, 0u);
  EXPECT_EQ(stats.boundaryEdges, 0u);
}

}  // namespace
}  // namespace bake
