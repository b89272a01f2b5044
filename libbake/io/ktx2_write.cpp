// KTX 2.0 writer for bake::ktx2 (io/ktx2.h): encode() and write().
// Source: the Khronos KTX File Format Specification 2.0, sections "File Structure", "Index", "Level
// Index", "Data Format Descriptor" (with the Khronos Data Format Specification 1.3 basic descriptor
// block), "Key/Value Data", "Mip Level Array" / "mipPadding", "supercompressionScheme" (Zstandard
// notes) and "KTXwriter". Every byte-level constant is in bake_formats/ktx2.h.
// The writer is deterministic: zero padding, keys sorted, levels stored smallest first. Level sizes,
// alignment and the metadata limits come from io/ktx2_layout.h, shared with validate() and the reader.

#include <zstd.h>

#include <algorithm>
#include <cstring>
#include <limits>

#include "bake/core/atomic_file.h"
#include "bake/core/version.h"
#include "bake_formats/ktx2.h"
#include "io/ktx2.h"
#include "io/ktx2_layout.h"

namespace bake::ktx2 {
namespace fmt = bake::format::ktx2;

using layout::alignUp;
using layout::infoOf;
using layout::levelElement;
using layout::validateMetadata;

namespace {

// ---- Little-endian bytes ----------------------------------------------------------------------------------

void put8(std::vector<std::uint8_t>& out, std::size_t at, std::uint8_t value) { out[at] = value; }

void put16(std::vector<std::uint8_t>& out, std::size_t at, std::uint16_t value) {
  for (int i = 0; i < 2; ++i) out[at + i] = std::uint8_t(value >> (8 * i));
}

void put32(std::vector<std::uint8_t>& out, std::size_t at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) out[at + i] = std::uint8_t(value >> (8 * i));
}

void put64(std::vector<std::uint8_t>& out, std::size_t at, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) out[at + i] = std::uint8_t(value >> (8 * i));
}

// ---- Writer -----------------------------------------------------------------------------------------------

std::string writerValue(const WriteOptions& options) {
  return options.writer.empty() ? std::string(fmt::kWriterName) + " " + kToolkitVersion : options.writer;
}

// The basic descriptor block for an unpacked RGBSDA format: one sample per channel, R G B A order.
std::vector<std::uint8_t> encodeDataFormatDescriptor(const fmt::FormatInfo& info, bool supercompressed) {
  const std::size_t blockSize = fmt::kDfdBlockHeaderSize + info.channels * fmt::kDfdSampleSize;
  std::vector<std::uint8_t> dfd(fmt::kDfdTotalSizeFieldSize + blockSize, 0);
  put32(dfd, 0, std::uint32_t(dfd.size()));

  const std::size_t block = fmt::kDfdTotalSizeFieldSize;
  put32(dfd, block + fmt::kDfdOffsetVendorAndType,
        fmt::kDfdVendorKhronos | fmt::kDfdDescriptorTypeBasic << fmt::kDfdDescriptorTypeShift);
  put32(dfd, block + fmt::kDfdOffsetVersionAndSize,
        fmt::kDfdVersion1_3 | std::uint32_t(blockSize) << fmt::kDfdBlockSizeShift);
  put8(dfd, block + fmt::kDfdOffsetColorModel, fmt::kDfdModelRgbsda);
  put8(dfd, block + fmt::kDfdOffsetColorPrimaries, fmt::kDfdPrimariesBt709);
  put8(dfd, block + fmt::kDfdOffsetTransferFunction, fmt::kDfdTransferLinear);
  put8(dfd, block + fmt::kDfdOffsetFlags, fmt::kDfdFlagsAlphaStraight);
  // texelBlockDimension stays 0 ("1 texel" in each dimension). bytesPlane0 is 0 for supercompressed
  // data ("unsized"), as KTX2 document revisions before 5 require; readers must accept both forms.
  put8(dfd, block + fmt::kDfdOffsetBytesPlane, supercompressed ? 0 : std::uint8_t(fmt::texelSize(info)));

  const std::uint32_t bits = info.typeSize * 8;
  for (std::uint32_t c = 0; c < info.channels; ++c) {
    const std::size_t sample = block + fmt::kDfdOffsetSamples + c * fmt::kDfdSampleSize;
    std::uint8_t channelType = fmt::kChannelOrder[c];
    if (info.isFloat) channelType |= fmt::kDfdSampleFloat | fmt::kDfdSampleSigned;
    put16(dfd, sample + fmt::kDfdSampleOffsetBitOffset, std::uint16_t(c * bits));
    put8(dfd, sample + fmt::kDfdSampleOffsetBitLength, std::uint8_t(bits - 1));
    put8(dfd, sample + fmt::kDfdSampleOffsetChannelType, channelType);
    // samplePosition stays 0: every channel is at the texel's origin.
    put32(dfd, sample + fmt::kDfdSampleOffsetLower, info.isFloat ? fmt::kDfdFloatLower : fmt::kDfdUnormLower);
    put32(dfd, sample + fmt::kDfdSampleOffsetUpper,
          info.isFloat ? fmt::kDfdFloatUpper : (bits == 8 ? fmt::kDfdUnorm8Upper : fmt::kDfdUnorm16Upper));
  }
  return dfd;
}

// Entries in std::map order, which is the byte order of the UTF-8 keys (char_traits<char> compares as
// unsigned char), i.e. the Unicode code point order the specification asks for.
std::vector<std::uint8_t> encodeKeyValueData(const std::map<std::string, std::vector<std::uint8_t>>& entries) {
  std::vector<std::uint8_t> kvd;
  for (const auto& [key, value] : entries) {
    const std::size_t length = key.size() + 1 + value.size();
    const std::size_t at = kvd.size();
    kvd.resize(at + 4 + alignUp(length, fmt::kKeyValueAlignment), 0);
    put32(kvd, at, std::uint32_t(length));
    std::memcpy(kvd.data() + at + 4, key.data(), key.size());
    // The key's NUL terminator and the valuePadding are the zeros resize() wrote.
    if (!value.empty()) std::memcpy(kvd.data() + at + 4 + key.size() + 1, value.data(), value.size());
  }
  return kvd;
}

Result<std::vector<std::uint8_t>> compressLevel(std::span<const std::uint8_t> level, int zstdLevel,
                                                std::uint32_t index) {
  std::vector<std::uint8_t> compressed(ZSTD_compressBound(level.size()));
  const std::size_t size = ZSTD_compress(compressed.data(), compressed.size(), level.data(), level.size(), zstdLevel);
  if (ZSTD_isError(size)) {
    return internalError(std::string("Zstandard compression failed: ") + ZSTD_getErrorName(size),
                         {"", levelElement(index)});
  }
  compressed.resize(size);
  return compressed;
}

}  // namespace

// ---- Public API -------------------------------------------------------------------------------------------

Result<std::vector<std::uint8_t>> encode(const Texture& texture, const WriteOptions& options) {
  BAKE_RETURN_IF_ERROR(validate(texture));
  if (options.zstd && (options.zstdLevel < ZSTD_minCLevel() || options.zstdLevel > ZSTD_maxCLevel())) {
    return Status(ExitCode::Usage, "zstd level " + std::to_string(options.zstdLevel) + " is outside " +
                                       std::to_string(ZSTD_minCLevel()) + ".." + std::to_string(ZSTD_maxCLevel()));
  }
  const fmt::FormatInfo& info = infoOf(texture.format);
  const std::uint32_t levelCount = std::uint32_t(texture.levels.size());

  // Level payloads: the texture's own bytes, or their Zstandard frames.
  std::vector<std::vector<std::uint8_t>> compressed;
  std::vector<std::span<const std::uint8_t>> payloads;
  for (std::uint32_t level = 0; level < levelCount; ++level) {
    if (options.zstd) {
      BAKE_ASSIGN_OR_RETURN(auto frame, compressLevel(texture.levels[level], options.zstdLevel, level));
      compressed.push_back(std::move(frame));
    }
  }
  for (std::uint32_t level = 0; level < levelCount; ++level) {
    payloads.push_back(options.zstd ? std::span<const std::uint8_t>(compressed[level])
                                    : std::span<const std::uint8_t>(texture.levels[level]));
  }

  // Our KTXwriter replaces any earlier writer's: only the most recent writer is identified.
  auto metadata = texture.metadata;
  const std::string writer = writerValue(options);
  metadata[fmt::kKeyWriter] = std::vector<std::uint8_t>(writer.begin(), writer.end());
  metadata[fmt::kKeyWriter].push_back(0);
  BAKE_RETURN_IF_ERROR(validateMetadata(metadata));

  const std::vector<std::uint8_t> dfd = encodeDataFormatDescriptor(info, options.zstd);
  const std::vector<std::uint8_t> kvd = encodeKeyValueData(metadata);
  const std::uint64_t dfdOffset = fmt::kLevelIndexOffset + std::uint64_t(levelCount) * fmt::kLevelIndexEntrySize;
  const std::uint64_t kvdOffset = dfdOffset + dfd.size();
  const std::uint64_t kvdEnd = kvdOffset + kvd.size();
  if (kvdEnd > std::numeric_limits<std::uint32_t>::max()) {
    return invalidInput("the key/value data (" + std::to_string(kvd.size()) +
                            " bytes) does not fit the 32-bit KTX2 index",
                        {"", "metadata"});
  }

  // Place the levels, smallest first, each on its alignment boundary.
  const std::uint64_t alignment =
      options.zstd ? fmt::kSupercompressedLevelAlignment : fmt::uncompressedLevelAlignment(fmt::texelSize(info));
  std::vector<std::uint64_t> offsets(levelCount);
  std::uint64_t end = kvdEnd;
  for (std::uint32_t level = levelCount; level-- > 0;) {
    offsets[level] = alignUp(end, alignment);
    end = offsets[level] + payloads[level].size();
  }

  std::vector<std::uint8_t> file(end, 0);  // every byte not written below is padding, and zero
  std::copy(fmt::kIdentifier.begin(), fmt::kIdentifier.end(), file.begin());
  put32(file, fmt::kOffsetVkFormat, info.vkFormat);
  put32(file, fmt::kOffsetTypeSize, info.typeSize);
  put32(file, fmt::kOffsetPixelWidth, texture.width);
  put32(file, fmt::kOffsetPixelHeight, texture.height);
  put32(file, fmt::kOffsetPixelDepth, 0);
  put32(file, fmt::kOffsetLayerCount, texture.layers);
  put32(file, fmt::kOffsetFaceCount, 1);
  put32(file, fmt::kOffsetLevelCount, levelCount);
  put32(file, fmt::kOffsetSupercompressionScheme,
        options.zstd ? fmt::kSupercompressionZstd : fmt::kSupercompressionNone);
  put32(file, fmt::kOffsetDfdByteOffset, std::uint32_t(dfdOffset));
  put32(file, fmt::kOffsetDfdByteLength, std::uint32_t(dfd.size()));
  put32(file, fmt::kOffsetKvdByteOffset, std::uint32_t(kvdOffset));
  put32(file, fmt::kOffsetKvdByteLength, std::uint32_t(kvd.size()));
  put64(file, fmt::kOffsetSgdByteOffset, 0);
  put64(file, fmt::kOffsetSgdByteLength, 0);
  for (std::uint32_t level = 0; level < levelCount; ++level) {
    const std::size_t entry = fmt::kLevelIndexOffset + level * fmt::kLevelIndexEntrySize;
    put64(file, entry + fmt::kLevelEntryByteOffset, offsets[level]);
    put64(file, entry + fmt::kLevelEntryByteLength, payloads[level].size());
    put64(file, entry + fmt::kLevelEntryUncompressedByteLength, texture.levels[level].size());
  }
  std::copy(dfd.begin(), dfd.end(), file.begin() + std::ptrdiff_t(dfdOffset));
  std::copy(kvd.begin(), kvd.end(), file.begin() + std::ptrdiff_t(kvdOffset));
  for (std::uint32_t level = 0; level < levelCount; ++level) {
    std::copy(payloads[level].begin(), payloads[level].end(), file.begin() + std::ptrdiff_t(offsets[level]));
  }
  return file;
}

Status write(const std::filesystem::path& path, const Texture& texture, const WriteOptions& options) {
  auto bytes = encode(texture, options);
  if (!bytes.isOk()) {
    Status status = bytes.takeStatus();
    status.inFile(path.string());
    return status;
  }
  return writeFileAtomic(path, *bytes);
}

}  // namespace bake::ktx2
