#include "bake/mesh/shapes.h"

#include <gtest/gtest.h>

#include <cmath>

#include "mesh/mesh_stats.h"

namespace bake {
namespace {

// Signed volume by the divergence theorem: positive when the triangles face outward.
double signedVolume(const TriangleMesh& mesh) {
  double volume = 0.0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3f &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
    volume += (double(a[0]) * (double(b[1]) * c[2] - double(b[2]) * c[1]) -
               double(a[1]) * (double(b[0]) * c[2] - double(b[2]) * c[0]) +
               double(a[2]) * (double(b[0]) * c[1] - double(b[1]) * c[0])) / 6.0;
  }
  return volume;
}

struct Expected {
  const char* name;
  long genus;
  double volume;
};

TEST(Shapes, ClosedOrientedWithTheirGenusAndVolume) {
  const double pi = std::acos(-1.0);
  for (const Expected& e : {Expected{"sphere", 0, 4.0 / 3.0 * pi}, Expected{"torus", 1, 2 * pi * pi * 1.0 * 0.16}}) {
    Result<TriangleMesh> mesh = makeShape({e.name, 40});
    ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
    const MeshStats stats = computeMeshStats(mesh.value());
    EXPECT_EQ(stats.boundaryEdges, 0u) << e.name;
    EXPECT_EQ(stats.nonManifoldEdges, 0u) << e.name;
    EXPECT_EQ(stats.components, 1u) << e.name;
    const long euler = long(mesh.value().vertexCount()) - long(mesh.value().triangleCount()) / 2;
    EXPECT_EQ((2 - euler) / 2, e.genus) << e.name;
    // Inscribed polygonisation: slightly less than the true volume, within 2 %.
    EXPECT_NEAR(signedVolume(mesh.value()), e.volume, 0.02 * e.volume) << e.name;
  }
}

TEST(Shapes, RingsGiveHigherGenus) {
  for (const auto& [name, genus] : {std::pair{"double-torus", 2L}, std::pair{"pretzel", 3L}}) {
    Result<TriangleMesh> mesh = makeShape({name, 48});
    ASSERT_TRUE(mesh.isOk());
    const MeshStats stats = computeMeshStats(mesh.value());
    EXPECT_EQ(stats.boundaryEdges, 0u) << name;
    const long euler = long(mesh.value().vertexCount()) - long(mesh.value().triangleCount()) / 2;
    EXPECT_EQ((2 - euler) / 2, genus) << name;
    EXPECT_GT(signedVolume(mesh.value()), 0.0) << name;
  }
}

TEST(Shapes, UnknownNameAndBadResolutionAreUsageErrors) {
  EXPECT_EQ(makeShape({"cube", 32}).status().code(), ExitCode::Usage);
  EXPECT_EQ(makeShape({"sphere", 2}).status().code(), ExitCode::Usage);
}

}  // namespace
}  // namespace bake
