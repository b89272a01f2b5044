// Inputs the fuzz targets (tests/fuzz) found crashing the io readers, kept under
// tests/fuzz/regressions/<surface>/ and replayed here: each must read or fail with a Status. Under
// scripts/test.sh --sanitize a memory error in the reader fails these tests too.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <string>
#include <vector>

#include "bake/io/glb.h"
#include "bake/io/mesh.h"
#include "grooves/package/package.h"
#include "io/ktx2.h"

namespace bake {
namespace {
namespace fs = std::filesystem;

const fs::path kRegressions = fs::path(BAKE_SOURCE_DIR) / "tests" / "fuzz" / "regressions";

std::vector<fs::path> regressionFiles(const std::string& surface) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(kRegressions / surface, ec))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::uint8_t> bytesOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(FuzzRegressions, MeshInputsReadOrFailWithAStatus) {
  for (const fs::path& path : regressionFiles("mesh")) {
    SCOPED_TRACE(path.string());
    MeshReadOptions options;
    options.weld = true;
    options.weldTolerance = 1e-6;
    const Result<TriangleMesh> mesh = readMesh(path, options);
    if (!mesh.isOk()) EXPECT_NE(mesh.status().code(), ExitCode::Internal) << mesh.status().describe();
  }
}

// Corners that disagree with a vertex already split once: the reader kept a pointer into the list of
// split variants across a push_back that moved it (heap-use-after-free).
TEST(FuzzRegressions, ObjVertexSplitForSeveralCornersKeepsEachCornersTexcoord) {
  MeshReadStats stats;
  const Result<TriangleMesh> mesh = readMesh(kRegressions / "mesh" / "split-corner-of-a-split-vertex.obj", {}, &stats);
  ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
  EXPECT_EQ(mesh->triangleCount(), 4u);
  EXPECT_EQ(mesh->vertexCount(), 8u);
  EXPECT_EQ(stats.verticesSplit, 2u);
  // The second quad's corners carry texture coordinates (0,0) (1,0) (1,1) (0,1), in that order.
  const std::vector<Vec2f> expected = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const Triangle& first = mesh->triangles[2];
  const Triangle& second = mesh->triangles[3];
  EXPECT_EQ(mesh->texcoords[first[0]], expected[0]);
  EXPECT_EQ(mesh->texcoords[first[1]], expected[1]);
  EXPECT_EQ(mesh->texcoords[first[2]], expected[2]);
  EXPECT_EQ(mesh->texcoords[second[2]], expected[3]);
  EXPECT_EQ(mesh->positions[first[0]], (Vec3f{1, 0, 0}));
  EXPECT_EQ(mesh->positions[second[2]], (Vec3f{1, 1, 0}));
}

// A PLY format line whose version is not a number: OpenMesh's reader looped forever on it, so the
// pre-scan refuses any version but 1.0.
TEST(FuzzRegressions, PlyWithAnUnreadableVersionIsAnInputError) {
  const Result<TriangleMesh> mesh = readMesh(kRegressions / "mesh" / "unreadable-version.ply");
  ASSERT_FALSE(mesh.isOk());
  EXPECT_EQ(mesh.status().code(), ExitCode::InvalidInput);
  EXPECT_NE(mesh.status().message().find("unknown PLY version"), std::string::npos) << mesh.status().describe();
  EXPECT_EQ(mesh.status().where().element, "line 2");
}

TEST(FuzzRegressions, GlbInputsDecodeOrFailWithAStatus) {
  for (const fs::path& path : regressionFiles("glb")) {
    SCOPED_TRACE(path.string());
    const std::vector<std::uint8_t> bytes = bytesOf(path);
    const Result<glb::Package> package = glb::decode(std::span<const std::uint8_t>(bytes), path.string());
    if (!package.isOk()) {
      EXPECT_NE(package.status().code(), ExitCode::Internal) << package.status().describe();
      continue;
    }
    // The BAKE_grooves reader: its extension JSON may hold any type anywhere (a number as "grid").
    const auto grooves = grooves::decodeGroovePackage(*package, path.string());
    if (!grooves.isOk()) EXPECT_NE(grooves.status().code(), ExitCode::Internal) << grooves.status().describe();
  }
}

TEST(FuzzRegressions, Ktx2InputsDecodeOrFailWithAStatus) {
  for (const fs::path& path : regressionFiles("ktx2")) {
    SCOPED_TRACE(path.string());
    const std::vector<std::uint8_t> bytes = bytesOf(path);
    const std::span<const std::uint8_t> span(bytes);
    (void)ktx2::decodeHeader(span, path.string());
    const Result<ktx2::Texture> texture = ktx2::decode(span, path.string());
    if (!texture.isOk()) EXPECT_NE(texture.status().code(), ExitCode::Internal) << texture.status().describe();
  }
}

}  // namespace
}  // namespace bake
