// Tangent frames and UV stretch (mesh/tangent_frames.h) against closed forms: the column's side has
// the tangent d/da (R sin a, y, R cos a) normalised and v up (w = +1); a mirrored UV island splits the
// vertices it shares; a flat quad whose UV is squeezed twice in u has stretch exactly 2.
#include "mesh/tangent_frames.h"

#include <gtest/gtest.h>

#include <cmath>

#include "bake/mesh/shapes.h"

namespace bake {
namespace {

// A flat strip in the z = 0 plane, 3 x 2 vertices (x = 0, 1, 2; y = 0, 1), two quads, facing +z.
TriangleMesh strip(const std::vector<Vec2f>& uv) {
  TriangleMesh mesh;
  for (float y : {0.0f, 1.0f})
    for (float x : {0.0f, 1.0f, 2.0f}) mesh.positions.push_back({x, y, 0});
  mesh.texcoords = uv;
  mesh.triangles = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}};
  return mesh;
}

TEST(TangentFrames, ColumnSideFollowsTheCircumference) {
  Result<TriangleMesh> made = makeShape({"column", 32});
  ASSERT_TRUE(made.isOk());
  TriangleMesh mesh = std::move(made).value();
  Result<TangentFrames> frames = computeTangentFrames(mesh);
  ASSERT_TRUE(frames.isOk()) << frames.status().describe();
  EXPECT_EQ(frames->splitVertices, 0u);
  EXPECT_EQ(frames->fallbackVertices, 0u);
  EXPECT_EQ(frames->normalsComputed, 0u);
  std::size_t side = 0;
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
    const Vec3f& n = mesh.normals[v];
    if (std::abs(n[1]) > 0.5f) continue;  // a cap
    const double a = std::atan2(double(mesh.positions[v][0]), double(mesh.positions[v][2]));
    const auto& t = frames->tangents[v];
    EXPECT_NEAR(t[0], std::cos(a), 2e-3) << "vertex " << v;
    EXPECT_NEAR(t[1], 0, 2e-3) << "vertex " << v;
    EXPECT_NEAR(t[2], -std::sin(a), 2e-3) << "vertex " << v;
    EXPECT_EQ(t[3], 1.0f) << "vertex " << v << ": v runs up the column";
    ++side;
  }
  EXPECT_EQ(side, std::size_t(33 * 9));
}

TEST(TangentFrames, MirroredIslandSplitsTheSharedVertices) {
  // u runs 0 -> 1 over the left quad and back 1 -> 0 over the right one: a mirror at x = 1.
  TriangleMesh mesh = strip({{0, 0}, {1, 0}, {0, 0}, {0, 1}, {1, 1}, {0, 1}});
  Result<TangentFrames> frames = computeTangentFrames(mesh);
  ASSERT_TRUE(frames.isOk());
  EXPECT_EQ(frames->splitVertices, 2u);
  ASSERT_EQ(mesh.vertexCount(), 8u);
  ASSERT_EQ(frames->tangents.size(), 8u);
  EXPECT_EQ(frames->normalsComputed, 6u);
  // Left quad: +u along +x, right-handed; right quad: +u along -x, so w = -1 keeps v along +y.
  for (std::uint32_t v : mesh.triangles[0]) {
    EXPECT_NEAR(frames->tangents[v][0], 1, 1e-6);
    EXPECT_EQ(frames->tangents[v][3], 1.0f);
  }
  for (std::uint32_t v : mesh.triangles[2]) {
    EXPECT_NEAR(frames->tangents[v][0], -1, 1e-6);
    EXPECT_EQ(frames->tangents[v][3], -1.0f);
  }
  EXPECT_NE(mesh.triangles[1][1], mesh.triangles[3][2]) << "vertex 4 must be split between the quads";
  for (const Vec3f& n : mesh.normals) EXPECT_NEAR(n[2], 1, 1e-6);
}

TEST(TangentFrames, NormalsAreSmoothAcrossAUvSeam) {
  Result<TriangleMesh> made = makeShape({"column", 16});
  ASSERT_TRUE(made.isOk());
  TriangleMesh mesh = std::move(made).value();
  mesh.normals.clear();
  Result<TangentFrames> frames = computeTangentFrames(mesh);
  ASSERT_TRUE(frames.isOk());
  EXPECT_GT(frames->normalsComputed, 0u);
  // The seam's two copies of a side vertex (same position, u = 0 and u = 1) share one normal.
  std::size_t seams = 0;
  for (std::size_t a = 0; a < mesh.vertexCount(); ++a)
    for (std::size_t b = a + 1; b < mesh.vertexCount(); ++b)
      if (mesh.positions[a] == mesh.positions[b] && std::abs(mesh.positions[a][1]) < 0.99f) {
        EXPECT_EQ(mesh.normals[a], mesh.normals[b]) << "vertices " << a << " and " << b;
        ++seams;
      }
  EXPECT_GT(seams, 0u);
}

TEST(TangentFrames, TrianglesWithoutUvAreaFallBack) {
  TriangleMesh mesh = strip(std::vector<Vec2f>(6, Vec2f{0.5f, 0.5f}));
  Result<TangentFrames> frames = computeTangentFrames(mesh);
  ASSERT_TRUE(frames.isOk());
  EXPECT_EQ(frames->degenerateTriangles, 4u);
  EXPECT_EQ(frames->fallbackVertices, 6u);
  for (const auto& t : frames->tangents) EXPECT_NEAR(std::hypot(t[0], t[1], t[2]), 1, 1e-6);
  TriangleMesh noUv = strip({});
  EXPECT_FALSE(computeTangentFrames(noUv).isOk());
}

TEST(TangentFrames, UsableTangentsAreCheckedNotTrusted) {
  TriangleMesh mesh = strip({{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}});
  std::string problem;
  EXPECT_TRUE(usableTangents(mesh, problem).empty());
  EXPECT_TRUE(problem.empty()) << "no TANGENT is no problem: " << problem;
  std::vector<float> values;
  for (int v = 0; v < 6; ++v) values.insert(values.end(), {1, 0, 0, 1});
  mesh.extraAttributes.push_back(glb::Attribute::fromFloats("TANGENT", 4, values));
  EXPECT_EQ(usableTangents(mesh, problem).size(), 6u);
  values[4 * 3 + 3] = 0.5f;  // w neither +1 nor -1
  mesh.extraAttributes.back() = glb::Attribute::fromFloats("TANGENT", 4, values);
  EXPECT_TRUE(usableTangents(mesh, problem).empty());
  EXPECT_NE(problem.find("vertex 3"), std::string::npos) << problem;
}

TEST(UvStretch, SqueezedQuadHasStretchTwo) {
  TriangleMesh mesh = strip({{0, 0}, {0.5f, 0}, {1, 0}, {0, 1}, {0.5f, 1}, {1, 1}});
  const double unitsPerUv[2] = {1, 1};
  const UvStretch s = measureUvStretch(mesh, unitsPerUv, 1.5);
  EXPECT_NEAR(s.maxStretch, 2, 1e-9);
  EXPECT_NEAR(s.medianScale, std::sqrt(2.0), 1e-9);  // sqrt(2 x 1) world units per texture unit
  EXPECT_EQ(s.trianglesOver, 4u);
  EXPECT_NEAR(s.areaShareOver, 1, 1e-12);
  // Texture units that undo the squeeze: a domain twice as long in u.
  const double undo[2] = {2, 1};
  const UvStretch none = measureUvStretch(mesh, undo, 1.5);
  EXPECT_NEAR(none.maxStretch, 1, 1e-9);
  EXPECT_EQ(none.trianglesOver, 0u);
}

TEST(UvStretch, ColumnIsEvenAndTheGlobeStretchesAtThePoles) {
  Result<TriangleMesh> column = makeShape({"column", 64});
  ASSERT_TRUE(column.isOk());
  const double circumference = 2 * kPi * 0.35, unitsPerUv[2] = {circumference, 2.0};
  const UvStretch even = measureUvStretch(column.value(), unitsPerUv, 1.5);
  EXPECT_NEAR(even.medianScale, 1, 0.01);  // one texture unit is one unit of the mesh
  EXPECT_LT(even.maxStretch, 1.05);
  EXPECT_EQ(even.trianglesOver, 0u);
  EXPECT_EQ(even.noUvArea, 0u);
  Result<TriangleMesh> globe = makeShape({"globe", 64});
  ASSERT_TRUE(globe.isOk());
  const double globeUnits[2] = {2 * kPi, kPi};
  const UvStretch poles = measureUvStretch(globe.value(), globeUnits, 1.5);
  EXPECT_GT(poles.maxStretch, 5);
  EXPECT_GT(poles.trianglesOver, 0u);
  EXPECT_GT(poles.areaShareOver, 0.01);
  EXPECT_LT(poles.areaShareOver, 0.5);
}

}  // namespace
}  // namespace bake
