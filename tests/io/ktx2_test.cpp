// Tests for the KTX 2.0 writer and reader (libbake/io/ktx2.h): round trips of every format as 2D and
// 2D-array textures with full mip chains (plain and Zstandard), metadata, determinism, validation, the
// reader's handling of truncated and corrupted files, a byte-exact golden file, and an independent parse
// of our output by ktx-parse (tests/js/check_ktx2.mjs, run with node).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <functional>
#include <numeric>
#include <random>
#include <sstream>

#include "bake/core/atomic_file.h"
#include "bake/core/limits.h"
#include "bake/core/version.h"
#include "bake_formats/ktx2.h"
#include "io/ktx2.h"
#include "support/golden.h"
#include "support/node_check.h"

namespace bake::ktx2 {
namespace {
namespace fs = std::filesystem;
namespace fmt = bake::format::ktx2;

constexpr Format kAllFormats[] = {Format::R8,  Format::RG8,    Format::RGBA8,   Format::R16,
                                  Format::RG16, Format::RGBA16, Format::RGBA16F, Format::R32F};

const std::string kDefaultWriter = std::string("bake ") + kToolkitVersion;

// A texture with deterministic pseudo-random texels (std::mt19937's sequence is fixed by the standard).
Texture makeTexture(Format format, std::uint32_t width, std::uint32_t height, std::uint32_t layers,
                    std::uint32_t seed = 1) {
  Texture texture;
  texture.format = format;
  texture.width = width;
  texture.height = height;
  texture.layers = layers;
  std::mt19937 random(seed);
  const std::uint32_t levels = fullMipCount(width, height);
  for (std::uint32_t level = 0; level < levels; ++level) {
    std::vector<std::uint8_t> bytes(texture.levelByteSize(level));
    for (auto& byte : bytes) byte = std::uint8_t(random() >> 24);
    texture.levels.push_back(std::move(bytes));
  }
  return texture;
}

std::uint32_t read32(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  return std::uint32_t(bytes[at]) | std::uint32_t(bytes[at + 1]) << 8 | std::uint32_t(bytes[at + 2]) << 16 |
         std::uint32_t(bytes[at + 3]) << 24;
}

std::uint64_t read64(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  return std::uint64_t(read32(bytes, at)) | std::uint64_t(read32(bytes, at + 4)) << 32;
}

void write32(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes[at + i] = std::uint8_t(value >> (8 * i));
}

void write64(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) bytes[at + i] = std::uint8_t(value >> (8 * i));
}

std::size_t levelEntry(std::uint32_t level) { return fmt::kLevelIndexOffset + level * fmt::kLevelIndexEntrySize; }

std::vector<std::uint8_t> encodeOrDie(const Texture& texture, const WriteOptions& options = {}) {
  auto bytes = encode(texture, options);
  EXPECT_TRUE(bytes.isOk()) << bytes.status().describe();
  return bytes.isOk() ? *bytes : std::vector<std::uint8_t>{};
}

void expectSameTexture(const Texture& actual, const Texture& expected) {
  EXPECT_EQ(actual.format, expected.format);
  EXPECT_EQ(actual.width, expected.width);
  EXPECT_EQ(actual.height, expected.height);
  EXPECT_EQ(actual.layers, expected.layers);
  ASSERT_EQ(actual.levels.size(), expected.levels.size());
  for (std::size_t level = 0; level < expected.levels.size(); ++level) {
    EXPECT_TRUE(actual.levels[level] == expected.levels[level]) << "level " << level << " differs";
  }
}

// ---- Round trips --------------------------------------------------------------------------------------------

TEST(Ktx2, RoundTripsEveryFormatAs2DAndArrayWithFullMipChains) {
  for (const Format format : kAllFormats) {
    for (const std::uint32_t layers : {0u, 1u, 3u}) {
      for (const bool zstd : {false, true}) {
        SCOPED_TRACE(std::string(formatName(format)) + " layers " + std::to_string(layers) +
                     (zstd ? " zstd" : " plain"));
        // 13x6 is neither square nor a power of two: levels 13x6, 6x3, 3x1, 1x1.
        Texture texture = makeTexture(format, 13, 6, layers, 7 + layers);
        ASSERT_EQ(texture.levels.size(), 4u);
        WriteOptions options;
        options.zstd = zstd;
        options.zstdLevel = 3;
        const auto bytes = encodeOrDie(texture, options);
        auto decoded = decode(bytes, "round-trip");
        ASSERT_TRUE(decoded.isOk()) << decoded.status().describe();
        expectSameTexture(*decoded, texture);

        auto header = decodeHeader(bytes);
        ASSERT_TRUE(header.isOk()) << header.status().describe();
        EXPECT_EQ(header->vkFormat, vkFormatOf(format));
        EXPECT_EQ(header->width, 13u);
        EXPECT_EQ(header->height, 6u);
        EXPECT_EQ(header->depth, 0u);
        EXPECT_EQ(header->layers, layers);
        EXPECT_EQ(header->faces, 1u);
        EXPECT_EQ(header->levels, 4u);
        EXPECT_EQ(header->supercompression, zstd ? 2u : 0u);
      }
    }
  }
}

TEST(Ktx2, RoundTripsLargeArrayWithZstd) {
  const Texture texture = makeTexture(Format::RGBA16F, 300, 200, 2, 3);
  const auto bytes = encodeOrDie(texture, {.zstd = true, .zstdLevel = 1});
  auto decoded = decode(bytes);
  ASSERT_TRUE(decoded.isOk()) << decoded.status().describe();
  expectSameTexture(*decoded, texture);
}

TEST(Ktx2, RoundTripsZstdLevelsOfWholeStreamingBlocks) {
  // 128x128 RGBA16F is 128 KiB, zstd's block and streaming-output size; 256x256 spans 4 such chunks.
  for (const std::uint32_t size : {128u, 256u}) {
    const Texture texture = makeTexture(Format::RGBA16F, size, size, 0, size);
    const auto bytes = encodeOrDie(texture, {.zstd = true, .zstdLevel = 1});
    auto decoded = decode(bytes);
    ASSERT_TRUE(decoded.isOk()) << decoded.status().describe();
    expectSameTexture(*decoded, texture);
  }
}

TEST(Ktx2, RoundTripsPartialMipChainAndFiles) {
  Texture texture = makeTexture(Format::RG16, 16, 8, 2, 5);
  texture.levels.resize(2);
  const fs::path dir = test::freshTempDir("ktx2_files");
  ASSERT_TRUE(write(dir / "partial.ktx2", texture).isOk());
  auto decoded = read(dir / "partial.ktx2");
  ASSERT_TRUE(decoded.isOk()) << decoded.status().describe();
  expectSameTexture(*decoded, texture);

  auto missing = read(dir / "missing.ktx2");
  ASSERT_FALSE(missing.isOk());
  EXPECT_EQ(missing.status().code(), ExitCode::Io);

  // Errors in a file name the file.
  std::vector<std::uint8_t> broken = test::readAll(dir / "partial.ktx2");
  broken.resize(broken.size() - 1);
  ASSERT_TRUE(writeFileAtomic(dir / "broken.ktx2", broken).isOk());
  auto brokenRead = read(dir / "broken.ktx2");
  ASSERT_FALSE(brokenRead.isOk());
  EXPECT_EQ(brokenRead.status().where().file, (dir / "broken.ktx2").string());
}

TEST(Ktx2, LevelCountZeroReadsTheBaseLevel) {
  Texture texture = makeTexture(Format::R8, 8, 8, 0);
  texture.levels.resize(1);
  auto bytes = encodeOrDie(texture);
  write32(bytes, fmt::kOffsetLevelCount, 0);
  auto decoded = decode(bytes);
  ASSERT_TRUE(decoded.isOk()) << decoded.status().describe();
  expectSameTexture(*decoded, texture);
}

// ---- Layout -----------------------------------------------------------------------------------------------

TEST(Ktx2, LayoutFollowsTheSpecification) {
  for (const Format format : kAllFormats) {
    for (const bool zstd : {false, true}) {
      SCOPED_TRACE(std::string(formatName(format)) + (zstd ? " zstd" : " plain"));
      const Texture texture = makeTexture(format, 5, 3, 0);
      const auto bytes = encodeOrDie(texture, {.zstd = zstd});
      ASSERT_GE(bytes.size(), fmt::kHeaderSize);
      EXPECT_TRUE(std::equal(fmt::kIdentifier.begin(), fmt::kIdentifier.end(), bytes.begin()));
      EXPECT_EQ(read32(bytes, fmt::kOffsetPixelDepth), 0u);
      EXPECT_EQ(read32(bytes, fmt::kOffsetLayerCount), 0u) << "a plain 2D texture has layerCount 0";
      EXPECT_EQ(read32(bytes, fmt::kOffsetFaceCount), 1u);
      EXPECT_EQ(read64(bytes, fmt::kOffsetSgdByteOffset), 0u);
      EXPECT_EQ(read64(bytes, fmt::kOffsetSgdByteLength), 0u);
      const std::uint32_t levels = read32(bytes, fmt::kOffsetLevelCount);
      ASSERT_EQ(levels, 3u);
      // The DFD directly follows the level index; the KVD directly follows the DFD.
      const std::uint32_t dfdOffset = read32(bytes, fmt::kOffsetDfdByteOffset);
      EXPECT_EQ(dfdOffset, levelEntry(levels));
      EXPECT_EQ(read32(bytes, fmt::kOffsetKvdByteOffset), dfdOffset + read32(bytes, fmt::kOffsetDfdByteLength));
      EXPECT_EQ(read32(bytes, dfdOffset), read32(bytes, fmt::kOffsetDfdByteLength)) << "dfdTotalSize";
      // Levels are stored smallest first, aligned, and the last (base) level ends the file.
      const std::uint64_t alignment = zstd ? 1 : std::lcm<std::uint64_t>(bytesPerTexel(format), 4);
      std::uint64_t previousEnd = read32(bytes, fmt::kOffsetKvdByteOffset) + read32(bytes, fmt::kOffsetKvdByteLength);
      for (std::uint32_t level = levels; level-- > 0;) {
        const std::uint64_t offset = read64(bytes, levelEntry(level));
        const std::uint64_t length = read64(bytes, levelEntry(level) + 8);
        EXPECT_EQ(offset % alignment, 0u) << "level " << level;
        EXPECT_GE(offset, previousEnd) << "level " << level;
        EXPECT_LT(offset - previousEnd, alignment) << "padding is minimal";
        EXPECT_EQ(read64(bytes, levelEntry(level) + 16), texture.levels[level].size());
        if (!zstd) EXPECT_EQ(length, texture.levels[level].size());
        previousEnd = offset + length;
      }
      EXPECT_EQ(previousEnd, bytes.size());
    }
  }
}

// ---- Metadata ---------------------------------------------------------------------------------------------

TEST(Ktx2, MetadataRoundTrips) {
  Texture texture = makeTexture(Format::RGBA8, 4, 4, 2);
  texture.setText("KTXorientation", "rd");
  texture.setText("bake.source", "unit test ✓");
  texture.metadata["bake.binary"] = {0x00, 0x01, 0x00, 0xFF, 0x7F};  // not text: embedded NULs, no terminator
  texture.metadata["bake.empty"] = {};
  texture.setText("KTXwriter", "someone else");  // replaced: only the latest writer is named
  EXPECT_EQ(texture.text("bake.source"), "unit test ✓");
  EXPECT_EQ(texture.text("absent"), "");
  for (const bool zstd : {false, true}) {
    const auto bytes = encodeOrDie(texture, {.zstd = zstd});
    auto decoded = decode(bytes);
    ASSERT_TRUE(decoded.isOk()) << decoded.status().describe();
    auto expected = texture.metadata;
    expected["KTXwriter"] = std::vector<std::uint8_t>(kDefaultWriter.begin(), kDefaultWriter.end());
    expected["KTXwriter"].push_back(0);
    EXPECT_EQ(decoded->metadata, expected);
    EXPECT_EQ(decoded->text("KTXwriter"), kDefaultWriter);
    EXPECT_EQ(decoded->text("KTXorientation"), "rd");
    EXPECT_EQ(decoded->metadata.at("bake.source").back(), 0) << "text values keep their NUL";
  }
  // A pinned writer replaces the default one.
  auto pinned = decode(encodeOrDie(texture, {.writer = "bake golden"}));
  ASSERT_TRUE(pinned.isOk());
  EXPECT_EQ(pinned->text("KTXwriter"), "bake golden");
}

// ---- Determinism ---------------------------------------------------------------------------------------------

TEST(Ktx2, EncodingIsDeterministic) {
  for (const bool zstd : {false, true}) {
    Texture texture = makeTexture(Format::RGBA16, 9, 7, 3);
    texture.setText("b", "2");
    texture.setText("a", "1");
    const auto first = encodeOrDie(texture, {.zstd = zstd});
    const auto second = encodeOrDie(texture, {.zstd = zstd});
    EXPECT_EQ(first, second);
    // Decoding and re-encoding reproduces the file too.
    auto decoded = decode(first);
    ASSERT_TRUE(decoded.isOk());
    EXPECT_EQ(encodeOrDie(*decoded, {.zstd = zstd}), first);
  }
}

// ---- Validation ------------------------------------------------------------------------------------------------

TEST(Ktx2, ValidateCatchesInconsistentTextures) {
  const Texture good = makeTexture(Format::RG8, 8, 4, 2);
  EXPECT_TRUE(validate(good).isOk());

  Texture shortLevel = good;
  shortLevel.levels[2].pop_back();
  Status status = validate(shortLevel);
  EXPECT_EQ(status.code(), ExitCode::InvalidInput);
  EXPECT_EQ(status.where().element, "level 2");
  EXPECT_NE(status.message().find("2x1 texels x 2 layers x 2 bytes need 8"), std::string::npos) << status.message();
  EXPECT_EQ(encode(shortLevel).status().code(), ExitCode::InvalidInput) << "encode validates first";

  Texture tooManyLevels = good;
  tooManyLevels.levels.push_back({0, 0, 0, 0});
  EXPECT_EQ(validate(tooManyLevels).code(), ExitCode::InvalidInput);

  Texture noLevels = good;
  noLevels.levels.clear();
  EXPECT_EQ(validate(noLevels).code(), ExitCode::InvalidInput);

  Texture empty = good;
  empty.height = 0;
  EXPECT_EQ(validate(empty).code(), ExitCode::InvalidInput);

  Texture badFormat = good;
  badFormat.format = Format(42);
  EXPECT_EQ(validate(badFormat).code(), ExitCode::InvalidInput);

  Texture emptyKey = good;
  emptyKey.metadata[""] = {1};
  EXPECT_EQ(validate(emptyKey).code(), ExitCode::InvalidInput);

  // An array texture's levels hold every layer.
  Texture layersMissing = good;
  layersMissing.layers = 3;
  EXPECT_EQ(validate(layersMissing).code(), ExitCode::InvalidInput);

  EXPECT_EQ(encode(good, {.zstd = true, .zstdLevel = 99}).status().code(), ExitCode::Usage);
}

TEST(Ktx2, FullMipCount) {
  EXPECT_EQ(fullMipCount(0, 0), 0u);
  EXPECT_EQ(fullMipCount(1, 1), 1u);
  EXPECT_EQ(fullMipCount(2, 1), 2u);
  EXPECT_EQ(fullMipCount(1, 3), 2u);
  EXPECT_EQ(fullMipCount(4, 4), 3u);
  EXPECT_EQ(fullMipCount(13, 6), 4u);
  EXPECT_EQ(fullMipCount(1024, 768), 11u);
  EXPECT_EQ(fullMipCount(1025, 1), 11u);
  EXPECT_EQ(fullMipCount(0xFFFFFFFFu, 1), 32u);
}

TEST(Ktx2, FormatFacts) {
  EXPECT_EQ(vkFormatOf(Format::R8), 9u);
  EXPECT_EQ(vkFormatOf(Format::RG8), 16u);
  EXPECT_EQ(vkFormatOf(Format::RGBA8), 37u);
  EXPECT_EQ(vkFormatOf(Format::R16), 70u);
  EXPECT_EQ(vkFormatOf(Format::RG16), 77u);
  EXPECT_EQ(vkFormatOf(Format::RGBA16), 91u);
  EXPECT_EQ(vkFormatOf(Format::RGBA16F), 97u);
  EXPECT_EQ(vkFormatOf(Format::R32F), 100u);
  EXPECT_STREQ(formatName(Format::RGBA16F), "R16G16B16A16_SFLOAT");
  EXPECT_EQ(bytesPerTexel(Format::RGBA16F), 8u);
  EXPECT_EQ(bytesPerTexel(Format::RG8), 2u);
  EXPECT_EQ(channelCount(Format::R32F), 1u);
  EXPECT_EQ(channelCount(Format::RGBA16), 4u);
  const Texture texture = makeTexture(Format::R8, 5, 2, 0);
  EXPECT_EQ(texture.levelWidth(2), 1u);
  EXPECT_EQ(texture.levelHeight(1), 1u);
  EXPECT_EQ(texture.levelByteSize(1), 2u);
}

// ---- Untrusted input --------------------------------------------------------------------------------------

// Decoding must fail cleanly; a crash or hang fails the whole test binary.
void expectCleanFailure(std::span<const std::uint8_t> bytes, const std::string& what) {
  auto decoded = decode(bytes, "fuzz.ktx2");
  if (decoded.isOk()) return;
  const ExitCode code = decoded.status().code();
  EXPECT_TRUE(code == ExitCode::InvalidInput || code == ExitCode::Unsupported)
      << what << ": " << decoded.status().describe();
  EXPECT_EQ(decoded.status().where().file, "fuzz.ktx2") << what;
}

std::vector<std::vector<std::uint8_t>> sampleFiles() {
  Texture texture = makeTexture(Format::RGBA16F, 7, 5, 2);
  texture.setText("KTXorientation", "rd");
  texture.setText("bake.note", "x");
  return {encodeOrDie(texture), encodeOrDie(texture, {.zstd = true}),
          encodeOrDie(makeTexture(Format::R8, 3, 3, 0))};
}

TEST(Ktx2, EveryTruncatedPrefixIsAnError) {
  for (const auto& file : sampleFiles()) {
    for (std::size_t size = 0; size < file.size(); ++size) {
      const std::span<const std::uint8_t> prefix(file.data(), size);
      auto decoded = decode(prefix, "cut.ktx2");
      ASSERT_FALSE(decoded.isOk()) << "a prefix of " << size << " of " << file.size() << " bytes decoded";
      EXPECT_EQ(decoded.status().code(), ExitCode::InvalidInput) << decoded.status().describe();
      if (size < fmt::kHeaderSize) EXPECT_FALSE(decodeHeader(prefix).isOk());
    }
  }
}

TEST(Ktx2, CorruptedHeaderIndexAndMetadataNeverCrash) {
  for (const auto& file : sampleFiles()) {
    // Every byte before the level data: header, index, level index, DFD, key/value data.
    const std::size_t metadataEnd = read32(file, fmt::kOffsetKvdByteOffset) + read32(file, fmt::kOffsetKvdByteLength);
    for (std::size_t at = 0; at < metadataEnd; ++at) {
      for (const std::uint8_t change : {0xFF, 0x01, 0x80}) {
        std::vector<std::uint8_t> corrupt = file;
        corrupt[at] ^= change;
        expectCleanFailure(corrupt, "byte " + std::to_string(at) + " ^ " + std::to_string(change));
      }
    }
    // Random damage anywhere, including compressed level data.
    std::mt19937 random(99);
    for (int round = 0; round < 400; ++round) {
      std::vector<std::uint8_t> corrupt = file;
      for (int hit = 0; hit < 1 + round % 4; ++hit) corrupt[random() % corrupt.size()] = std::uint8_t(random());
      expectCleanFailure(corrupt, "round " + std::to_string(round));
    }
  }
}

TEST(Ktx2, HeaderFieldsThatMustBeRejected) {
  const auto file = sampleFiles()[0];
  const auto expectError = [&](std::size_t at, std::uint32_t value, ExitCode code, const std::string& element) {
    std::vector<std::uint8_t> bytes = file;
    write32(bytes, at, value);
    auto decoded = decode(bytes, "t.ktx2");
    ASSERT_FALSE(decoded.isOk()) << "field at " << at << " = " << value;
    EXPECT_EQ(decoded.status().code(), code) << decoded.status().describe();
    EXPECT_EQ(decoded.status().where().element, element) << decoded.status().describe();
  };
  expectError(fmt::kOffsetVkFormat, 43, ExitCode::Unsupported, "header");  // R8G8B8A8_SRGB
  expectError(fmt::kOffsetVkFormat, 0, ExitCode::Unsupported, "header");
  expectError(fmt::kOffsetSupercompressionScheme, 1, ExitCode::Unsupported, "header");  // BasisLZ
  expectError(fmt::kOffsetSupercompressionScheme, 3, ExitCode::Unsupported, "header");  // ZLIB
  expectError(fmt::kOffsetTypeSize, 1, ExitCode::InvalidInput, "header");
  expectError(fmt::kOffsetPixelWidth, 0, ExitCode::InvalidInput, "header");
  expectError(fmt::kOffsetPixelHeight, 0, ExitCode::Unsupported, "header");  // a 1D texture
  expectError(fmt::kOffsetPixelDepth, 4, ExitCode::Unsupported, "header");   // a 3D texture
  expectError(fmt::kOffsetFaceCount, 0, ExitCode::InvalidInput, "header");
  expectError(fmt::kOffsetFaceCount, 6, ExitCode::InvalidInput, "header");  // 7x5 faces are not square
  expectError(fmt::kOffsetLevelCount, 4, ExitCode::InvalidInput, "header");  // 7x5 has 3 levels
  expectError(fmt::kOffsetLayerCount, 3, ExitCode::InvalidInput, "level 2");
  // 2^32 - 1 layers claim terabytes: the decoded-bytes budget stops it at the level index, before any level.
  expectError(fmt::kOffsetLayerCount, 0xFFFFFFFF, ExitCode::InvalidInput, "level index");
  expectError(fmt::kOffsetDfdByteLength, 0xFFFFFFF0, ExitCode::InvalidInput, "index");
  expectError(fmt::kOffsetKvdByteOffset, 3, ExitCode::InvalidInput, "index");
}

TEST(Ktx2, WrongIdentifierIsInvalidInput) {
  auto bytes = sampleFiles()[0];
  bytes[5] = '1';  // "KTX 10": a KTX 1 file
  auto decoded = decode(bytes, "old.ktx");
  ASSERT_FALSE(decoded.isOk());
  EXPECT_EQ(decoded.status().code(), ExitCode::InvalidInput);
  EXPECT_EQ(decoded.status().where().file, "old.ktx");
  EXPECT_EQ(decoded.status().where().element, "identifier");
  EXPECT_EQ(decodeHeader(bytes).status().code(), ExitCode::InvalidInput);
  const std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  EXPECT_EQ(decode(png).status().code(), ExitCode::InvalidInput);
}

TEST(Ktx2, UnknownVkFormatIsUnsupported) {
  auto bytes = sampleFiles()[2];
  write32(bytes, fmt::kOffsetVkFormat, 131);  // VK_FORMAT_BC1_RGB_UNORM_BLOCK
  auto decoded = decode(bytes);
  ASSERT_FALSE(decoded.isOk());
  EXPECT_EQ(decoded.status().code(), ExitCode::Unsupported);
  EXPECT_NE(decoded.status().message().find("vkFormat 131"), std::string::npos) << decoded.status().message();
  // The header alone still describes the file.
  auto header = decodeHeader(bytes);
  ASSERT_TRUE(header.isOk()) << header.status().describe();
  EXPECT_EQ(header->vkFormat, 131u);
}

TEST(Ktx2, LevelErrorsNameTheLevel) {
  auto bytes = sampleFiles()[0];
  const std::uint64_t fileSize = bytes.size();
  write64(bytes, levelEntry(1), fileSize - 4);  // level 1 now starts 4 bytes before the end
  auto decoded = decode(bytes, "t.ktx2");
  ASSERT_FALSE(decoded.isOk());
  EXPECT_EQ(decoded.status().where().file, "t.ktx2");
  EXPECT_EQ(decoded.status().where().element, "level 1");
  const std::uint64_t length = read64(bytes, levelEntry(1) + 8);
  EXPECT_EQ(decoded.status().message(), "level 1 data (offset " + std::to_string(fileSize - 4) + ", " +
                                            std::to_string(length) + " bytes) runs past the end of the file (" +
                                            std::to_string(fileSize) + " bytes)");
  // Offsets near 2^64 must not wrap around the bounds check.
  bytes = sampleFiles()[0];
  write64(bytes, levelEntry(0), ~std::uint64_t{0} - 2);
  EXPECT_EQ(decode(bytes).status().where().element, "level 0");
  // A level size that disagrees with the format and dimensions.
  bytes = sampleFiles()[0];
  write64(bytes, levelEntry(2) + 8, read64(bytes, levelEntry(2) + 8) - 8);
  write64(bytes, levelEntry(2) + 16, read64(bytes, levelEntry(2) + 16) - 8);
  auto wrongSize = decode(bytes);
  EXPECT_EQ(wrongSize.status().where().element, "level 2");
  EXPECT_EQ(wrongSize.status().code(), ExitCode::InvalidInput);
}

TEST(Ktx2, ZstdSizeClaimsAreCheckedBeforeInflating) {
  const auto file = sampleFiles()[1];
  // uncompressedByteLength must match the level size the header implies.
  auto bytes = file;
  write64(bytes, levelEntry(0) + 16, std::uint64_t{1} << 40);
  auto decoded = decode(bytes);
  EXPECT_EQ(decoded.status().code(), ExitCode::InvalidInput);
  EXPECT_EQ(decoded.status().where().element, "level 0");
  // Cut-short Zstandard data (level 0 is last in the file, so shortening it overlaps nothing).
  for (const std::uint64_t cut : {1, 5, 20}) {
    bytes = file;
    write64(bytes, levelEntry(0) + 8, read64(bytes, levelEntry(0) + 8) - cut);
    decoded = decode(bytes);
    EXPECT_EQ(decoded.status().code(), ExitCode::InvalidInput);
    EXPECT_EQ(decoded.status().where().element, "level 0") << decoded.status().describe();
  }
  // A header claiming an enormous array whose level sizes agree: rejected, not allocated.
  bytes = file;
  write32(bytes, fmt::kOffsetLayerCount, 0x7FFFFFFF);
  for (std::uint32_t level = 0; level < 3; ++level) {
    const std::uint64_t texels = std::uint64_t(std::max(1u, 7u >> level)) * std::max(1u, 5u >> level);
    write64(bytes, levelEntry(level) + 16, texels * 0x7FFFFFFF * 8);
  }
  decoded = decode(bytes);
  EXPECT_EQ(decoded.status().code(), ExitCode::InvalidInput);
  EXPECT_NE(decoded.status().message().find("--budget decoded-bytes"), std::string::npos) << decoded.status().message();
  // With the budget raised out of the way, the expansion bound still refuses it before inflating.
  const Budgets saved = budgets();
  Budgets unlimited = saved;
  unlimited.decodedBytes = ~std::uint64_t(0);
  setBudgets(unlimited);
  decoded = decode(bytes);
  setBudgets(saved);
  EXPECT_EQ(decoded.status().code(), ExitCode::InvalidInput);
  EXPECT_NE(decoded.status().message().find("cannot come from"), std::string::npos) << decoded.status().message();
}

TEST(Ktx2, DecompressionBombIsRefusedBeforeInflating) {
  // A level index claiming far more decoded bytes than the budget: refused at the index, whatever the
  // Zstandard data would inflate to.
  std::vector<std::uint8_t> bytes = sampleFiles()[0];
  write32(bytes, fmt::kOffsetLayerCount, 10000000);  // about 1.7 GB of 7x5 levels
  const auto decoded = decode(bytes, "bomb.ktx2");
  ASSERT_FALSE(decoded.isOk());
  EXPECT_EQ(decoded.status().code(), ExitCode::InvalidInput);
  EXPECT_EQ(decoded.status().where().element, "level index");
  EXPECT_NE(decoded.status().message().find("--budget decoded-bytes"), std::string::npos);
}

TEST(Ktx2, KeyValueDataIsChecked) {
  Texture texture = makeTexture(Format::R8, 2, 2, 0);
  texture.setText("a", "1");
  texture.setText("b", "2");
  const auto file = encodeOrDie(texture, {.writer = "w"});
  const std::size_t kvd = read32(file, fmt::kOffsetKvdByteOffset);
  // Entries: "KTXwriter\0w\0" (12 bytes), "a\01\0" (4), "b\02\0" (4); each with a 4-byte length.
  ASSERT_EQ(read32(file, kvd), 12u);
  const auto expectKvdError = [&](const std::function<void(std::vector<std::uint8_t>&)>& damage,
                                  const std::string& text) {
    auto bytes = file;
    damage(bytes);
    auto decoded = decode(bytes);
    ASSERT_FALSE(decoded.isOk()) << text;
    EXPECT_EQ(decoded.status().code(), ExitCode::InvalidInput);
    EXPECT_NE(decoded.status().message().find(text), std::string::npos) << decoded.status().describe();
  };
  expectKvdError([&](auto& b) { b[kvd + 16 + 4] = 'c'; }, "not sorted");           // "c" before "b"
  expectKvdError([&](auto& b) { b[kvd + 24 + 4] = 'a'; }, "appears twice");        // "a", "a"
  expectKvdError([&](auto& b) { write32(b, kvd + 16, 1); }, "below 2");
  expectKvdError([&](auto& b) { write32(b, kvd + 16, 0x10000); }, "runs past the end");
  expectKvdError([&](auto& b) { b[kvd + 16 + 5] = b[kvd + 16 + 7] = 'x'; }, "no NUL");  // "a\01\0" -> "ax1x"
  expectKvdError([&](auto& b) { b[kvd + 16 + 4] = 0; }, "key is empty");
}

// ---- Golden file ------------------------------------------------------------------------------------------

// A tiny fixed texture: 4x4, 2 layers, full mip chain (3 levels), RGBA8, two metadata keys. Texel bytes
// encode their own position so that a diff of the golden is readable.
Texture goldenTexture() {
  Texture texture;
  texture.format = Format::RGBA8;
  texture.width = 4;
  texture.height = 4;
  texture.layers = 2;
  for (std::uint32_t level = 0; level < 3; ++level) {
    std::vector<std::uint8_t> bytes;
    for (std::uint32_t layer = 0; layer < 2; ++layer) {
      for (std::uint32_t y = 0; y < texture.levelHeight(level); ++y) {
        for (std::uint32_t x = 0; x < texture.levelWidth(level); ++x) {
          bytes.insert(bytes.end(), {std::uint8_t(x * 60), std::uint8_t(y * 60), std::uint8_t(layer * 200),
                                     std::uint8_t(255 - level * 100)});
        }
      }
    }
    texture.levels.push_back(std::move(bytes));
  }
  texture.setText("KTXorientation", "rd");
  texture.setText("bake.source", "golden");
  return texture;
}

constexpr const char* kGoldenName = "io/ktx2/array_rgba8.ktx2-v1.ktx2";
constexpr const char* kGoldenWriter = "bake golden";  // pinned: a toolkit version bump must not move bytes

TEST(Ktx2, GoldenArrayRgba8) {
  const auto bytes = encodeOrDie(goldenTexture(), {.writer = kGoldenWriter});
  EXPECT_TRUE(test::matchesGolden(kGoldenName, bytes));
}

TEST(Ktx2, CommittedGoldenStillDecodes) {
  auto decoded = read(test::goldenPath(kGoldenName));
  ASSERT_TRUE(decoded.isOk()) << decoded.status().describe();
  const Texture expected = goldenTexture();
  expectSameTexture(*decoded, expected);
  EXPECT_EQ(decoded->text("KTXorientation"), "rd");
  EXPECT_EQ(decoded->text("bake.source"), "golden");
  EXPECT_EQ(decoded->text("KTXwriter"), kGoldenWriter);
  EXPECT_EQ(decoded->metadata.size(), 3u);
}

// ---- Independent parser: ktx-parse ----------------------------------------------------------------------------

std::string toHex(const std::vector<std::uint8_t>& bytes) {
  static const char* digits = "0123456789abcdef";
  std::string hex;
  for (const std::uint8_t b : bytes) {
    hex += digits[b >> 4];
    hex += digits[b & 15];
  }
  return hex;
}

// What each format's DFD must say, written out independently of bake_formats/ktx2.h.
struct ExpectedFormat {
  Format format;
  std::uint32_t vkFormat, typeSize, channels;
  bool isFloat;
};
constexpr ExpectedFormat kExpectedFormats[] = {
    {Format::R8, 9, 1, 1, false},       {Format::RG8, 16, 1, 2, false},   {Format::RGBA8, 37, 1, 4, false},
    {Format::R16, 70, 2, 1, false},     {Format::RG16, 77, 2, 2, false},  {Format::RGBA16, 91, 2, 4, false},
    {Format::RGBA16F, 97, 2, 4, true},  {Format::R32F, 100, 4, 1, true},
};

TEST(Ktx2, KtxParseReadsWhatWeWrite) {
  const fs::path dir = test::freshTempDir("ktx2_ktx_parse");
  for (const ExpectedFormat& expected : kExpectedFormats) {
    for (const bool zstd : {false, true}) {
      SCOPED_TRACE(std::string(formatName(expected.format)) + (zstd ? " zstd" : " plain"));
      Texture texture = makeTexture(expected.format, 6, 4, 3, expected.vkFormat);
      texture.setText("KTXorientation", "rd");
      texture.setText("bake.note", "checked by ktx-parse");
      const fs::path file = dir / (std::string(formatName(expected.format)) + (zstd ? "-zstd" : "") + ".ktx2");
      ASSERT_TRUE(write(file, texture, {.zstd = zstd}).isOk());
      const std::vector<std::uint8_t> bytes = test::readAll(file);

      const nlohmann::json s = test::runNodeChecker("check_ktx2.mjs", {file.string()});
      ASSERT_TRUE(s.is_object());
      EXPECT_EQ(s["vkFormat"], expected.vkFormat);
      EXPECT_EQ(s["typeSize"], expected.typeSize);
      EXPECT_EQ(s["pixelWidth"], 6);
      EXPECT_EQ(s["pixelHeight"], 4);
      EXPECT_EQ(s["pixelDepth"], 0);
      EXPECT_EQ(s["layerCount"], 3);
      EXPECT_EQ(s["faceCount"], 1);
      EXPECT_EQ(s["levelCount"], 3);
      EXPECT_EQ(s["supercompressionScheme"], zstd ? 2 : 0);
      EXPECT_EQ(s["keyValue"], (nlohmann::json{{"KTXorientation", "rd"},
                                               {"KTXwriter", kDefaultWriter},
                                               {"bake.note", "checked by ktx-parse"}}));

      const nlohmann::json& dfd = s["dfd"];
      const std::uint32_t texelBytes = expected.typeSize * expected.channels;
      EXPECT_EQ(dfd["vendorId"], 0);
      EXPECT_EQ(dfd["descriptorType"], 0);
      EXPECT_EQ(dfd["versionNumber"], 2);
      EXPECT_EQ(dfd["colorModel"], 1);        // RGBSDA
      EXPECT_EQ(dfd["colorPrimaries"], 1);    // BT709
      EXPECT_EQ(dfd["transferFunction"], 1);  // linear
      EXPECT_EQ(dfd["flags"], 0);
      EXPECT_EQ(dfd["texelBlockDimension"], nlohmann::json({0, 0, 0, 0}));
      EXPECT_EQ(dfd["bytesPlane"], nlohmann::json({zstd ? 0u : texelBytes, 0u, 0u, 0u, 0u, 0u, 0u, 0u}));
      ASSERT_EQ(dfd["samples"].size(), expected.channels);
      const std::uint32_t channelIds[] = {0, 1, 2, 15};
      for (std::uint32_t c = 0; c < expected.channels; ++c) {
        const nlohmann::json& sample = dfd["samples"][c];
        const std::uint32_t bits = expected.typeSize * 8;
        EXPECT_EQ(sample["bitOffset"], c * bits);
        EXPECT_EQ(sample["bitLength"], bits - 1);
        EXPECT_EQ(sample["channelType"], channelIds[c] | (expected.isFloat ? 0xC0u : 0u));
        EXPECT_EQ(sample["samplePosition"], nlohmann::json({0, 0, 0, 0}));
        EXPECT_EQ(sample["sampleLower"], expected.isFloat ? 0xBF800000u : 0u);
        EXPECT_EQ(sample["sampleUpper"], expected.isFloat ? 0x3F800000u : (bits == 8 ? 255u : 65535u));
      }

      ASSERT_EQ(s["levels"].size(), texture.levels.size());
      for (std::uint32_t level = 0; level < texture.levels.size(); ++level) {
        const nlohmann::json& parsed = s["levels"][level];
        EXPECT_EQ(parsed["uncompressedByteLength"], texture.levels[level].size()) << "level " << level;
        if (zstd) {
          // ktx-parse hands back the Zstandard frames: their length must match our level index.
          EXPECT_EQ(parsed["byteLength"], read64(bytes, levelEntry(level) + 8)) << "level " << level;
        } else {
          EXPECT_EQ(parsed["byteLength"], texture.levels[level].size()) << "level " << level;
          ASSERT_TRUE(parsed.contains("hex"));
          EXPECT_EQ(parsed["hex"], toHex(texture.levels[level])) << "level " << level;
        }
      }
    }
  }
}

}  // namespace
}  // namespace bake::ktx2
