#include "geodesic/input/snap.h"

#include <gtest/gtest.h>

namespace bake::geodesic {
namespace {

// A unit square in z = 0 made of two triangles, placed far from the origin.
TriangleMesh square(float offset) {
  TriangleMesh mesh;
  mesh.positions = {{offset, offset, 0}, {offset + 1, offset, 0}, {offset + 1, offset + 1, 0}, {offset, offset + 1, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

TEST(Snap, PointAboveAFaceKeepsItsBarycentricPosition) {
  const SurfaceBuild build = buildSurface(square(0.0f));
  const SnappedPoint snapped = snapToSurface(build.surface, {0.75, 0.25, 0.5});
  EXPECT_EQ(snapped.point.face, 0u);
  EXPECT_DOUBLE_EQ(snapped.distance, 0.5);
  EXPECT_EQ(snapped.point.vertex(build.surface), -1);
  const Vec3d p = snapped.point.position(build.surface);
  EXPECT_NEAR(p[0] + build.surface.origin[0], 0.75, 1e-15);
  EXPECT_NEAR(p[1] + build.surface.origin[1], 0.25, 1e-15);
}

TEST(Snap, PointsBeyondACornerBecomeThatVertexExactly) {
  const SurfaceBuild build = buildSurface(square(0.0f));
  const SnappedPoint snapped = snapToSurface(build.surface, {2.0, 2.0, 0.0});
  EXPECT_EQ(snapped.point.vertex(build.surface), 2);
  EXPECT_DOUBLE_EQ(snapped.distance, std::sqrt(2.0));
}

TEST(Snap, PointsBesideAnEdgeLandOnTheEdge) {
  const SurfaceBuild build = buildSurface(square(0.0f));
  const SnappedPoint snapped = snapToSurface(build.surface, {0.5, -3.0, 0.0});
  EXPECT_DOUBLE_EQ(snapped.distance, 3.0);
  const auto& w = snapped.point.barycentric;
  // On edge 0-1 of face 0: the third weight is exactly 0.
  EXPECT_EQ(snapped.point.face, 0u);
  EXPECT_EQ(w[2], 0.0);
  EXPECT_DOUBLE_EQ(w[0], 0.5);
}

TEST(Snap, FarFromTheOriginStaysExact) {
  const SurfaceBuild build = buildSurface(square(1.0e7f));
  const SnappedPoint snapped = snapToSurface(build.surface, {1.0e7 + 0.75, 1.0e7 + 0.25, 2.0});
  EXPECT_DOUBLE_EQ(snapped.distance, 2.0);
  const Vec3d p = snapped.point.position(build.surface);
  EXPECT_DOUBLE_EQ(p[0] + build.surface.origin[0], 1.0e7 + 0.75);
}

}  // namespace
}  // namespace bake::geodesic
