// Vertex welding on tiny inline meshes: exact and tolerance modes, attributes that block a merge,
// removal of collapsed triangles, and the lowest-index rule that makes the result deterministic.
#include "mesh/weld.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace bake {
namespace {

// Two triangles sharing the edge (1,0,0)-(0,1,0), stored as a soup of six vertices.
TriangleMesh squareSoup() {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  return mesh;
}

TEST(Weld, ExactMergesIdenticalPositions) {
  TriangleMesh mesh = squareSoup();
  const WeldStats stats = weldVertices(mesh);
  EXPECT_EQ(stats.verticesWelded, 2u);
  EXPECT_EQ(stats.degenerateTrianglesRemoved, 0u);
  ASSERT_EQ(mesh.vertexCount(), 4u);
  // Survivors keep their order; the merged ones map onto the earlier copies.
  EXPECT_EQ(mesh.positions[3], (Vec3f{1, 1, 0}));
  EXPECT_EQ(mesh.triangles[1], (Triangle{1, 3, 2}));
}

TEST(Weld, ExactTreatsBothZerosAsEqualButNothingElse) {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {-0.0f, 0, 0}, {1e-30f, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 3, 4}, {1, 3, 4}, {2, 3, 4}};
  const WeldStats stats = weldVertices(mesh);
  EXPECT_EQ(stats.verticesWelded, 1u);
  EXPECT_EQ(stats.degenerateTrianglesRemoved, 0u);
  EXPECT_EQ(mesh.vertexCount(), 4u);
  EXPECT_EQ(mesh.triangleCount(), 3u);
}

TEST(Weld, DifferentAttributesKeepVerticesApart) {
  TriangleMesh mesh = squareSoup();
  mesh.texcoords = {{0, 0}, {1, 0}, {0, 1}, {1, 0}, {1, 1}, {0.5f, 1}};  // a seam at vertex 5
  const WeldStats stats = weldVertices(mesh);
  EXPECT_EQ(stats.verticesWelded, 1u);
  EXPECT_EQ(mesh.vertexCount(), 5u);
  EXPECT_EQ(mesh.texcoords.size(), 5u);
  EXPECT_EQ(mesh.texcoords[4], (Vec2f{0.5f, 1}));

  TriangleMesh withNormals = squareSoup();
  withNormals.normals.assign(6, Vec3f{0, 0, 1});
  withNormals.normals[3] = {0, 0, -1};
  EXPECT_EQ(weldVertices(withNormals).verticesWelded, 1u);
  EXPECT_EQ(withNormals.normals.size(), 5u);
}

TEST(Weld, CollapsedTrianglesAreRemovedAndCounted) {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 1, 3}};  // the second one has two copies of (1,0,0)
  const WeldStats stats = weldVertices(mesh);
  EXPECT_EQ(stats.verticesWelded, 1u);
  EXPECT_EQ(stats.degenerateTrianglesRemoved, 1u);
  ASSERT_EQ(mesh.triangleCount(), 1u);
  EXPECT_EQ(mesh.triangles[0], (Triangle{0, 1, 2}));
}

TEST(Weld, UnreferencedVerticesSurviveUnlessMerged) {
  TriangleMesh mesh = squareSoup();
  mesh.positions.push_back({7, 7, 7});
  mesh.positions.push_back({0, 0, 0});
  weldVertices(mesh);
  EXPECT_EQ(mesh.vertexCount(), 5u);
  EXPECT_EQ(mesh.positions[4], (Vec3f{7, 7, 7}));
}

TEST(Weld, ToleranceIsRelativeToTheBoundingBoxDiagonal) {
  // The box is about 6 x 8 (diagonal about 10.2): tolerance 0.01 reaches about 0.1.
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {6, 0, 0}, {0, 8, 0}, {6.05f, 0, 0}, {0, 8.2f, 0}, {6, 8, 0}};
  mesh.triangles = {{0, 1, 2}, {3, 5, 4}};
  const WeldStats stats = weldVertices(mesh, 0.01);
  EXPECT_EQ(stats.verticesWelded, 1u);  // 3 joins 1; 4 is 0.2 away from 2
  EXPECT_EQ(mesh.vertexCount(), 5u);
  EXPECT_EQ(mesh.triangles[1], (Triangle{1, 4, 3}));
  EXPECT_EQ(mesh.positions[1], (Vec3f{6, 0, 0}));  // the survivor keeps its own position
}

TEST(Weld, ChainsResolveToTheLowestIndexedSurvivor) {
  // Along x, 0.6 reach apart: 1 joins 0; 2 is 1.2 reach from 0 and may not join 1 (merged), so it
  // survives; 3 is within reach of both 0 and 2 and joins the lower one, 0.
  const float reach = 1.0f;  // diagonal 10 below, tolerance 0.1
  TriangleMesh mesh;
  mesh.positions = {
      {0, 0, 0}, {0.6f * reach, 0, 0}, {1.2f * reach, 0, 0}, {0.55f * reach, 0.1f, 0}, {8, 6, 0}};
  mesh.triangles = {{1, 4, 2}, {2, 4, 3}};
  weldVertices(mesh, 0.1);
  ASSERT_EQ(mesh.vertexCount(), 3u);
  EXPECT_EQ(mesh.positions[0], (Vec3f{0, 0, 0}));
  EXPECT_EQ(mesh.positions[1], (Vec3f{1.2f, 0, 0}));
  ASSERT_EQ(mesh.triangleCount(), 2u);
  EXPECT_EQ(mesh.triangles[0], (Triangle{0, 2, 1}));
  EXPECT_EQ(mesh.triangles[1], (Triangle{1, 2, 0}));
}

TEST(Weld, ResultDoesNotDependOnTheOrderOfDuplicates) {
  // The same soup with its triangles (and so its vertices) listed in another order welds to the same
  // set of positions and triangles.
  TriangleMesh forward = squareSoup();
  TriangleMesh backward;
  backward.positions = {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  backward.triangles = {{0, 1, 2}, {3, 4, 5}};
  weldVertices(forward, 1e-6);
  weldVertices(backward, 1e-6);
  auto geometry = [](const TriangleMesh& mesh) {
    std::set<std::array<Vec3f, 3>> triangles;
    for (const Triangle& t : mesh.triangles) {
      std::array<Vec3f, 3> corners{mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]};
      std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
      triangles.insert(corners);
    }
    return triangles;
  };
  EXPECT_EQ(forward.vertexCount(), 4u);
  EXPECT_EQ(backward.vertexCount(), 4u);
  EXPECT_EQ(geometry(forward), geometry(backward));
}

TEST(Weld, EmptyAndSinglePointMeshes) {
  TriangleMesh empty;
  EXPECT_EQ(weldVertices(empty, 0.5).verticesWelded, 0u);
  TriangleMesh point;
  point.positions = {{1, 2, 3}, {1, 2, 3}};
  EXPECT_EQ(weldVertices(point, 0.5).verticesWelded, 1u);  // zero diagonal: exact mode
}

}  // namespace
}  // namespace bake
