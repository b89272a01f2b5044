// The readers' early budget checks (core/limits.h): a mesh header or an image header that claims
// more than the budget is refused before anything is allocated for it, with the file and the place
// named, and the same input passes once the budget is raised.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "bake/core/limits.h"
#include "bake/io/image.h"
#include "bake/io/mesh.h"
#include "support/golden.h"

namespace bake {
namespace {
namespace fs = std::filesystem;

class ReaderBudgets : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::freshTempDir("reader_budgets"); }
  void TearDown() override { setBudgets(Budgets{}); }

  fs::path write(const std::string& name, const std::string& bytes) {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  fs::path dir_;
};

std::string bigEndian32(std::uint32_t value) {
  return {char(value >> 24), char(value >> 16), char(value >> 8), char(value)};
}

std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (unsigned char byte : bytes) {
    crc ^= byte;
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xFFFFFFFFu;
}

std::string pngChunk(const std::string& type, const std::string& data) {
  return bigEndian32(std::uint32_t(data.size())) + type + data + bigEndian32(crc32(type + data));
}

// A well-formed PNG whose IHDR claims width x height 8-bit grey pixels, with one tiny (stored, empty)
// zlib stream as its only IDAT: the header is all a reader needs to see for the size to be wrong.
std::string pngHeaderClaiming(std::uint32_t width, std::uint32_t height) {
  const std::string header = bigEndian32(width) + bigEndian32(height) + std::string{8, 0, 0, 0, 0};
  const std::string emptyZlib{0x78, 0x01, 0x01, 0x00, 0x00, char(0xFF), char(0xFF), 0x00, 0x00, 0x00, 0x01};
  return std::string("\x89PNG\r\n\x1a\n", 8) + pngChunk("IHDR", header) + pngChunk("IDAT", emptyZlib) +
         pngChunk("IEND", "");
}

TEST_F(ReaderBudgets, PlyHeaderFaceCountIsCheckedBeforeParsing) {
  const fs::path ply = write("two.ply",
                             "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
                             "0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n");
  ASSERT_TRUE(readMesh(ply).isOk());
  ASSERT_TRUE(applyBudgetSetting("triangles=1").isOk());
  const auto refused = readMesh(ply);
  ASSERT_FALSE(refused.isOk());
  EXPECT_EQ(refused.status().code(), ExitCode::InvalidInput);
  EXPECT_EQ(refused.status().where().file, ply.string());
  EXPECT_EQ(refused.status().where().element, "line 7") << "the header line that declares the faces";
  EXPECT_NE(refused.status().message().find("2 faces exceed the budget of 1"), std::string::npos)
      << refused.status().message();
}

TEST_F(ReaderBudgets, ObjPolygonsCountAfterTriangulationToo) {
  // One face line under a budget of 1, but a quad makes two triangles.
  const fs::path obj = write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  ASSERT_TRUE(applyBudgetSetting("triangles=1").isOk());
  const auto refused = readMesh(obj);
  ASSERT_FALSE(refused.isOk());
  EXPECT_NE(refused.status().message().find("2 triangles exceed the budget of 1"), std::string::npos)
      << refused.status().message();
  ASSERT_TRUE(applyBudgetSetting("triangles=2").isOk());
  EXPECT_TRUE(readMesh(obj).isOk());
}

TEST_F(ReaderBudgets, ImageHeaderClaimingBillionsOfTexelsIsRefusedBeforeAllocation) {
  const fs::path huge = write("huge.png", pngHeaderClaiming(100000, 100000));
  const auto refused = readImage(huge);
  ASSERT_FALSE(refused.isOk());
  EXPECT_EQ(refused.status().code(), ExitCode::InvalidInput);
  EXPECT_NE(refused.status().message().find("100000 texels on the longer side (100000x100000) exceed the budget of 16384"),
            std::string::npos)
      << refused.status().message();
}

TEST_F(ReaderBudgets, ImageWithinARaisedBudgetReads) {
  Image image;
  image.width = 40;
  image.height = 20;
  image.channels = 1;
  image.pixels.assign(800, 0.5f);
  const fs::path file = dir_ / "small.png";
  ASSERT_TRUE(writeImage(file, image, PixelType::U8).isOk());
  ASSERT_TRUE(applyBudgetSetting("texture-side=39").isOk());
  EXPECT_EQ(readImage(file).status().code(), ExitCode::InvalidInput);
  ASSERT_TRUE(applyBudgetSetting("texture-side=40").isOk());
  EXPECT_TRUE(readImage(file).isOk());
}

}  // namespace
}  // namespace bake
