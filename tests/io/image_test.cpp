// Image input and output: exact round trips for every storage type, PNG alpha kept as stored,
// byte-identical repeated writes, atomic replacement, and clear errors for bad files and requests.
#include "bake/io/image.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/golden.h"

namespace bake {
namespace {
namespace fs = std::filesystem;

// A w x h image whose channel values are `value(i)` for i = 0, 1, 2, ... in memory order.
template <class ValueOf>
Image makeImage(int width, int height, int channels, ValueOf value) {
  Image image;
  image.width = width;
  image.height = height;
  image.channels = channels;
  image.pixels.resize(std::size_t(width) * height * channels);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = value(i);
  return image;
}

std::size_t entriesIn(const fs::path& dir) {
  return std::size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

void expectSamePixels(const Image& expected, const Image& actual) {
  ASSERT_EQ(actual.width, expected.width);
  ASSERT_EQ(actual.height, expected.height);
  ASSERT_EQ(actual.channels, expected.channels);
  for (std::size_t i = 0; i < expected.pixels.size(); ++i) {
    ASSERT_EQ(actual.pixels[i], expected.pixels[i]) << "value " << i;
  }
}

struct RoundTrip {
  const char* file;
  PixelType type;
  int channels;
  float (*value)(std::size_t);
};

// Values each storage type represents exactly.
float eightBit(std::size_t i) { return float((i * 37) % 256) / 255.0f; }
float sixteenBit(std::size_t i) { return float((i * 7919) % 65536) / 65535.0f; }
float halfValues(std::size_t i) {
  const float values[] = {0.0f, 1.0f, 0.5f, -2.0f, 1024.0f, 0.099975586f, 65504.0f, 0.000061035156f};
  return values[i % 8];
}
float floatValues(std::size_t i) {
  const float values[] = {0.1f, -1e-7f, 12345.678f, 3.0e38f, 1.0f / 3.0f, -0.0f, 2.5f};
  return values[i % 7];
}

TEST(ImageIo, RoundTripsAreExact) {
  const fs::path dir = test::freshTempDir("image_round_trips");
  const RoundTrip cases[] = {
      {"gray8.png", PixelType::U8, 1, eightBit},        {"rgb8.png", PixelType::U8, 3, eightBit},
      {"rgba16.png", PixelType::U16, 4, sixteenBit},    {"gray16.png", PixelType::U16, 1, sixteenBit},
      {"half.exr", PixelType::Half, 4, halfValues},     {"float.exr", PixelType::Float, 3, floatValues},
      {"float1.exr", PixelType::Float, 1, floatValues},
  };
  for (const RoundTrip& c : cases) {
    SCOPED_TRACE(c.file);
    const Image image = makeImage(5, 3, c.channels, c.value);
    ASSERT_TRUE(writeImage(dir / c.file, image, c.type).isOk());
    const Result<Image> read = readImage(dir / c.file);
    ASSERT_TRUE(read.isOk()) << read.status().describe();
    EXPECT_EQ(read->sourceType, c.type);
    expectSamePixels(image, *read);
  }
}

TEST(ImageIo, PngAlphaIsNeitherPremultipliedNorDivided) {
  // Colour under low alpha would change if OIIO associated alpha on read or divided on write.
  const fs::path dir = test::freshTempDir("image_alpha");
  Image image = makeImage(2, 1, 4, eightBit);
  image.pixels = {200 / 255.0f, 10 / 255.0f, 1.0f, 0.0f, 0.2f, 0.6f, 0.8f, 51 / 255.0f};
  ASSERT_TRUE(writeImage(dir / "alpha.png", image, PixelType::U8).isOk());
  const Result<Image> read = readImage(dir / "alpha.png");
  ASSERT_TRUE(read.isOk()) << read.status().describe();
  expectSamePixels(image, *read);
}

TEST(ImageIo, IntegerFormatsClampAndRound) {
  const fs::path dir = test::freshTempDir("image_clamp");
  Image image = makeImage(4, 1, 1, [](std::size_t) { return 0.0f; });
  image.pixels = {-0.5f, 1.5f, 0.5f, 0.2f};
  ASSERT_TRUE(writeImage(dir / "clamp.png", image, PixelType::U8).isOk());
  const Result<Image> read = readImage(dir / "clamp.png");
  ASSERT_TRUE(read.isOk()) << read.status().describe();
  EXPECT_EQ(read->pixels[0], 0.0f);
  EXPECT_EQ(read->pixels[1], 1.0f);
  EXPECT_EQ(read->pixels[2], 128 / 255.0f);
  EXPECT_EQ(read->pixels[3], 51 / 255.0f);
}

TEST(ImageIo, RepeatedWritesAreByteIdentical) {
  const fs::path dir = test::freshTempDir("image_determinism");
  const struct {
    const char* extension;
    PixelType type;
  } formats[] = {{".png", PixelType::U8},
                 {".png", PixelType::U16},
                 {".exr", PixelType::Half},
                 {".exr", PixelType::Float}};
  for (const auto& format : formats) {
    SCOPED_TRACE(std::string(format.extension) + " " + std::to_string(int(format.type)));
    const fs::path first = dir / (std::string("first") + format.extension);
    const fs::path second = dir / (std::string("second") + format.extension);
    ASSERT_TRUE(writeImage(first, makeImage(16, 9, 4, eightBit), format.type).isOk());
    ASSERT_TRUE(writeImage(second, makeImage(16, 9, 4, eightBit), format.type).isOk());
    const std::vector<std::uint8_t> bytes = test::readAll(first);
    EXPECT_EQ(bytes, test::readAll(second));
    // No timestamp or tool version that would differ between runs or machines.
    const std::string text(bytes.begin(), bytes.end());
    for (const char* stamp : {"DateTime", "tIME", "Software", "OpenImageIO"}) {
      EXPECT_EQ(text.find(stamp), std::string::npos) << stamp;
    }
  }
}

TEST(ImageIo, WritesReplaceAtomically) {
  const fs::path dir = test::freshTempDir("image_atomic");
  const fs::path target = dir / "out.png";
  ASSERT_TRUE(writeImage(target, makeImage(2, 2, 1, eightBit), PixelType::U8).isOk());
  ASSERT_TRUE(writeImage(target, makeImage(3, 3, 1, eightBit), PixelType::U16).isOk());
  EXPECT_EQ(readImage(target)->width, 3);
  EXPECT_EQ(entriesIn(dir), 1u) << "no temporary file may remain";

  // A rejected request leaves the earlier output as it was.
  const std::vector<std::uint8_t> before = test::readAll(target);
  EXPECT_EQ(writeImage(target, makeImage(2, 2, 1, eightBit), PixelType::Float).code(), ExitCode::Unsupported);
  EXPECT_EQ(test::readAll(target), before);
  // A target that cannot be replaced (a non-empty directory) fails after writing: the temporary goes.
  fs::create_directories(dir / "busy.png" / "child");
  EXPECT_EQ(writeImage(dir / "busy.png", makeImage(2, 2, 1, eightBit), PixelType::U8).code(), ExitCode::Io);
  EXPECT_EQ(writeImage(dir / "missing" / "out.png", makeImage(2, 2, 1, eightBit), PixelType::U8).code(),
            ExitCode::Io);
  EXPECT_EQ(entriesIn(dir), 2u);
  EXPECT_FALSE(fs::exists(dir / "missing"));
}

TEST(ImageIo, RejectsTypesAFormatCannotStore) {
  const fs::path dir = test::freshTempDir("image_types");
  const Image image = makeImage(2, 2, 3, eightBit);
  for (PixelType type : {PixelType::Half, PixelType::Float}) {
    const Status status = writeImage(dir / "x.png", image, type);
    EXPECT_EQ(status.code(), ExitCode::Unsupported);
    EXPECT_NE(status.message().find("PNG"), std::string::npos) << status.describe();
  }
  for (PixelType type : {PixelType::U8, PixelType::U16}) {
    EXPECT_EQ(writeImage(dir / "x.exr", image, type).code(), ExitCode::Unsupported);
  }
  EXPECT_EQ(writeImage(dir / "x.png", makeImage(2, 2, 5, eightBit), PixelType::U8).code(),
            ExitCode::Unsupported);
  EXPECT_EQ(writeImage(dir / "x.nosuchformat", image, PixelType::U8).code(), ExitCode::Unsupported);
  EXPECT_EQ(writeImage(dir / "noextension", image, PixelType::U8).code(), ExitCode::Unsupported);
  Image broken = image;
  broken.pixels.pop_back();
  EXPECT_EQ(writeImage(dir / "x.png", broken, PixelType::U8).code(), ExitCode::Internal);
  EXPECT_EQ(entriesIn(dir), 0u);
}

// Images embedded in packages are decoded from their bytes, exactly as from a file; errors name the
// given name.
TEST(ImageIo, ReadsFromMemoryLikeFromAFile) {
  const fs::path dir = test::freshTempDir("image_memory");
  const fs::path file = dir / "rgba16.png";
  ASSERT_TRUE(writeImage(file, makeImage(13, 7, 4, sixteenBit), PixelType::U16).isOk());
  const Result<Image> fromFile = readImage(file);
  ASSERT_TRUE(fromFile.isOk());
  const std::vector<std::uint8_t> bytes = test::readAll(file);
  const Result<Image> fromMemory = readImageFromMemory(bytes, "package.glb image 0", ".png");
  ASSERT_TRUE(fromMemory.isOk()) << fromMemory.status().describe();
  expectSamePixels(*fromFile, *fromMemory);
  EXPECT_EQ(fromMemory->sourceType, PixelType::U16);

  const std::string text = "this is not a PNG file at all, just text that goes on for a while";
  const Result<Image> corrupt =
      readImageFromMemory({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()}, "bad image", ".png");
  EXPECT_EQ(corrupt.status().code(), ExitCode::InvalidInput) << corrupt.status().describe();
  EXPECT_EQ(corrupt.status().where().file, "bad image");
  EXPECT_FALSE(readImageFromMemory({}, "empty image", ".png").isOk());
}

TEST(ImageIo, UnreadableFilesGiveErrorsWithThePath) {
  const fs::path dir = test::freshTempDir("image_read_errors");
  const Result<Image> missing = readImage(dir / "absent.png");
  EXPECT_EQ(missing.status().code(), ExitCode::Io);
  EXPECT_EQ(missing.status().where().file, (dir / "absent.png").string());

  fs::create_directories(dir / "folder.png");
  EXPECT_EQ(readImage(dir / "folder.png").status().code(), ExitCode::Io);

  const fs::path garbage = dir / "garbage.png";
  std::ofstream(garbage) << "this is not a PNG file at all, just text that goes on for a while";
  const Result<Image> corrupt = readImage(garbage);
  EXPECT_EQ(corrupt.status().code(), ExitCode::InvalidInput) << corrupt.status().describe();
  EXPECT_EQ(corrupt.status().where().file, garbage.string());

  // A valid EXR cut in half: the header reads, the pixels do not. (Not tried with PNG: OIIO 2.4's PNG
  // reader leaks a string when libpng longjmps out of its read callback at the end of the file, which
  // fails sanitizer builds; the corrupted PNG below covers that reader.)
  for (const char* name : {"whole.exr"}) {
    SCOPED_TRACE(name);
    const fs::path whole = dir / name;
    const PixelType type = fs::path(name).extension() == ".exr" ? PixelType::Half : PixelType::U16;
    ASSERT_TRUE(writeImage(whole, makeImage(64, 64, 3, sixteenBit), type).isOk());
    std::vector<std::uint8_t> bytes = test::readAll(whole);
    bytes.resize(bytes.size() / 2);
    const fs::path cut = dir / ("cut" + fs::path(name).extension().string());
    std::ofstream(cut, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    const Result<Image> truncated = readImage(cut);
    EXPECT_EQ(truncated.status().code(), ExitCode::InvalidInput) << truncated.status().describe();
  }

  // A PNG whose compressed pixel data is overwritten: the checksum no longer matches.
  const fs::path png = dir / "damaged.png";
  ASSERT_TRUE(writeImage(png, makeImage(64, 64, 3, sixteenBit), PixelType::U16).isOk());
  std::vector<std::uint8_t> bytes = test::readAll(png);
  for (std::size_t i = bytes.size() / 2; i < bytes.size() / 2 + 64; ++i) bytes[i] ^= 0x5a;
  std::ofstream(png, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  const Result<Image> damaged = readImage(png);
  EXPECT_EQ(damaged.status().code(), ExitCode::InvalidInput) << damaged.status().describe();

  const fs::path empty = dir / "empty.exr";
  std::ofstream{empty};
  EXPECT_EQ(readImage(empty).status().code(), ExitCode::InvalidInput);
}

}  // namespace
}  // namespace bake
