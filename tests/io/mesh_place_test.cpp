// MeshReadOptions::nearOrigin (io/mesh_place.h): far-off meshes are stored relative to their centre,
// chosen in double; meshes near the origin are read bit for bit as without the option.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "bake/io/mesh.h"
#include "io/mesh_place.h"

namespace bake {
namespace {

namespace fs = std::filesystem;

fs::path writeObj(const std::string& stem, const std::vector<Vec3d>& points) {
  const fs::path path = fs::path(BAKE_TEST_TMP) / (stem + ".obj");
  fs::create_directories(path.parent_path());
  std::ofstream out(path);
  char line[128];
  for (const Vec3d& p : points) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
    out << line;
  }
  out << "f 1 2 3\nf 1 3 4\n";
  return path;
}

TEST(MeshPlace, FarMeshIsStoredRelativeToItsCentreInDouble) {
  const double x = 1.0e7 + 0.123456789, y = -3.0e6 - 0.5, z = 0.25;
  const std::vector<Vec3d> points = {{x, y, z}, {x + 0.01, y, z}, {x + 0.01, y + 0.02, z}, {x, y + 0.02, z + 0.003}};
  MeshReadOptions options;
  options.nearOrigin = true;
  Result<TriangleMesh> mesh = readMesh(writeObj("place-far", points), options);
  ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
  EXPECT_NEAR(mesh.value().origin[0], x + 0.005, 1e-8);
  EXPECT_NEAR(mesh.value().origin[1], y + 0.01, 1e-8);
  EXPECT_NEAR(mesh.value().origin[2], z + 0.0015, 1e-8);
  for (std::size_t v = 0; v < points.size(); ++v)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(double(mesh.value().positions[v][k]) + mesh.value().origin[k], points[v][k], 1e-9)
          << "vertex " << v << " axis " << k;
  // Without the option the float positions lose the 1 cm square entirely at this distance.
  Result<TriangleMesh> plain = readMesh(writeObj("place-far", points));
  ASSERT_TRUE(plain.isOk());
  EXPECT_EQ(plain.value().origin, Vec3d{});
  EXPECT_EQ(plain.value().positions[0][0], plain.value().positions[1][0]);
}

TEST(MeshPlace, NearMeshIsReadBitForBit) {
  const std::vector<Vec3d> points = {{0.1, 0.2, 0.3}, {1.7, 0.2, 0.3}, {1.7, 1.9, 0.3}, {0.1, 1.9, 0.31}};
  MeshReadOptions options;
  options.nearOrigin = true;
  Result<TriangleMesh> near = readMesh(writeObj("place-near", points), options);
  Result<TriangleMesh> plain = readMesh(writeObj("place-near", points));
  ASSERT_TRUE(near.isOk() && plain.isOk());
  EXPECT_EQ(near.value().origin, Vec3d{});
  ASSERT_EQ(near.value().positions.size(), plain.value().positions.size());
  EXPECT_EQ(std::memcmp(near.value().positions.data(), plain.value().positions.data(),
                        plain.value().positions.size() * sizeof(Vec3f)),
            0);
}

TEST(MeshPlace, OriginIsZeroUnlessTheCentreIsFartherThanTheDiagonal) {
  EXPECT_EQ(nearOriginFor({{0, 0, 0}, {1, 1, 1}}), Vec3d{});
  EXPECT_EQ(nearOriginFor({{1, 1, 1}, {2, 2, 2}}), Vec3d{});  // centre 1.5 from 0 per axis, diagonal 1.73
  EXPECT_EQ(nearOriginFor({{4, 0, 0}, {5, 1, 1}}), (Vec3d{4.5, 0.5, 0.5}));
  EXPECT_EQ(nearOriginFor({{7, 8, 9}}), (Vec3d{7, 8, 9}));  // a single point
  EXPECT_EQ(nearOriginFor({}), Vec3d{});
}

}  // namespace
}  // namespace bake
