// KTX 2.0 reader for bake::ktx2 (io/ktx2.h): decodeHeader(), decode() and read().
// Source: the Khronos KTX File Format Specification 2.0, sections "File Structure", "Index", "Level
// Index", "Data Format Descriptor" (with the Khronos Data Format Specification 1.3 basic descriptor
// block), "Key/Value Data", "Mip Level Array" / "mipPadding", "supercompressionScheme" (Zstandard
// notes) and "Texture Type". Every byte-level constant is in bake_formats/ktx2.h.
// The reader treats its input as untrusted: each offset and length is checked against the file before
// use, and nothing is allocated that the file's size (or, for Zstandard, its actual output) does not
// justify.

#include <zstd.h>

#include <algorithm>
#include <limits>
#include <memory>

#include "bake/core/atomic_file.h"
#include "bake/core/limits.h"
#include "bake_formats/ktx2.h"
#include "io/ktx2.h"
#include "io/ktx2_layout.h"

namespace bake::ktx2 {
namespace fmt = bake::format::ktx2;

using layout::alignUp;
using layout::describeLevelSize;
using layout::levelElement;
using layout::levelSize;
using layout::maxLevels;

namespace {

// ---- Formats ------------------------------------------------------------------------------------------

Format formatOf(const fmt::FormatInfo& info) { return Format(&info - fmt::kFormats.data()); }

std::string supportedFormatList() {
  std::string list;
  for (const fmt::FormatInfo& info : fmt::kFormats) {
    if (!list.empty()) list += ", ";
    list += std::string(info.name) + " (" + std::to_string(info.vkFormat) + ")";
  }
  return list;
}

// ---- Little-endian bytes ----------------------------------------------------------------------------------

// Readers: the caller has checked that [at, at + width) lies inside `bytes`.
std::uint8_t get8(std::span<const std::uint8_t> bytes, std::size_t at) { return bytes[at]; }

std::uint16_t get16(std::span<const std::uint8_t> bytes, std::size_t at) {
  return std::uint16_t(bytes[at] | bytes[at + 1] << 8);
}

std::uint32_t get32(std::span<const std::uint8_t> bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = value << 8 | bytes[at + i];
  return value;
}

std::uint64_t get64(std::span<const std::uint8_t> bytes, std::size_t at) {
  std::uint64_t value = 0;
  for (int i = 7; i >= 0; --i) value = value << 8 | bytes[at + i];
  return value;
}

// ---- Reader -------------------------------------------------------------------------------------------------

// The Index: where the DFD, KVD and SGD sections lie.
struct Index {
  std::uint32_t dfdOffset = 0, dfdLength = 0;
  std::uint32_t kvdOffset = 0, kvdLength = 0;
  std::uint64_t sgdOffset = 0, sgdLength = 0;
};

struct LevelEntry {
  std::uint64_t byteOffset = 0, byteLength = 0, uncompressedByteLength = 0;
};

// True when [offset, offset + length) lies inside a file of `fileSize` bytes, without overflowing.
bool fitsInFile(std::uint64_t offset, std::uint64_t length, std::uint64_t fileSize) {
  return offset <= fileSize && length <= fileSize - offset;
}

std::string rangeText(std::uint64_t offset, std::uint64_t length) {
  return "(offset " + std::to_string(offset) + ", " + std::to_string(length) + " bytes)";
}

// Keys in messages: anything but printable ASCII is shown as '?' so that error text stays readable.
std::string printableKey(const std::string& key) {
  std::string text;
  for (const char c : key.substr(0, 64)) text += (c >= 0x20 && c < 0x7F) ? c : '?';
  return key.size() > 64 ? text + "..." : text;
}

const char* supercompressionName(std::uint32_t scheme) {
  switch (scheme) {
    case 1: return "BasisLZ";
    case 3: return "ZLIB";
    default: return "unknown";
  }
}

// Checks whether decode can handle the header; returns the format's entry.
Result<const fmt::FormatInfo*> checkSupported(const Header& header, const std::string& name) {
  const Location where{name, "header"};
  if (header.supercompression != fmt::kSupercompressionNone && header.supercompression != fmt::kSupercompressionZstd) {
    return unsupported("supercompressionScheme " + std::to_string(header.supercompression) + " (" +
                           supercompressionName(header.supercompression) +
                           ") is not supported; we read none (0) and Zstandard (2)",
                       where);
  }
  const fmt::FormatInfo* info = fmt::findFormat(header.vkFormat);
  if (!info) {
    return unsupported("vkFormat " + std::to_string(header.vkFormat) + " is not supported; we read " +
                           supportedFormatList(),
                       where);
  }
  if (header.faces == 6) return unsupported("cubemaps (faceCount 6) are not supported", where);
  if (header.depth != 0) {
    return unsupported("3D textures (pixelDepth " + std::to_string(header.depth) + ") are not supported", where);
  }
  if (header.height == 0) return unsupported("1D textures (pixelHeight 0) are not supported", where);
  if (header.typeSize != info->typeSize) {
    return invalidInput("typeSize " + std::to_string(header.typeSize) + " does not match vkFormat " + info->name +
                            " (typeSize " + std::to_string(info->typeSize) + ")",
                        where);
  }
  return info;
}

Index readIndex(std::span<const std::uint8_t> bytes) {
  Index index;
  index.dfdOffset = get32(bytes, fmt::kOffsetDfdByteOffset);
  index.dfdLength = get32(bytes, fmt::kOffsetDfdByteLength);
  index.kvdOffset = get32(bytes, fmt::kOffsetKvdByteOffset);
  index.kvdLength = get32(bytes, fmt::kOffsetKvdByteLength);
  index.sgdOffset = get64(bytes, fmt::kOffsetSgdByteOffset);
  index.sgdLength = get64(bytes, fmt::kOffsetSgdByteLength);
  return index;
}

// A section named `what` must lie inside the file, after the level index, on a 4-byte boundary.
Status checkSection(const char* what, std::uint64_t offset, std::uint64_t length, std::uint64_t levelIndexEnd,
                    std::uint64_t fileSize, const std::string& name) {
  const Location where{name, "index"};
  if (!fitsInFile(offset, length, fileSize)) {
    return invalidInput(std::string(what) + " " + rangeText(offset, length) + " runs past the end of the file (" +
                            std::to_string(fileSize) + " bytes)",
                        where);
  }
  if (offset < levelIndexEnd) {
    return invalidInput(std::string(what) + " " + rangeText(offset, length) +
                            " overlaps the header or level index, which end at " + std::to_string(levelIndexEnd),
                        where);
  }
  if (offset % 4 != 0) {
    return invalidInput(std::string(what) + " offset " + std::to_string(offset) + " is not a multiple of 4", where);
  }
  return Status::ok();
}

Status checkIndex(const Index& index, std::uint64_t levelIndexEnd, std::uint64_t fileSize, const std::string& name) {
  const Location where{name, "index"};
  if (index.dfdLength < fmt::kDfdTotalSizeFieldSize + fmt::kDfdBlockHeaderSize) {
    return invalidInput("dfdByteLength " + std::to_string(index.dfdLength) +
                            " is too small for a descriptor block (at least " +
                            std::to_string(fmt::kDfdTotalSizeFieldSize + fmt::kDfdBlockHeaderSize) + ")",
                        where);
  }
  BAKE_RETURN_IF_ERROR(checkSection("the data format descriptor", index.dfdOffset, index.dfdLength, levelIndexEnd,
                                    fileSize, name));
  if (index.kvdLength == 0) {
    if (index.kvdOffset != 0) {
      return invalidInput("kvdByteOffset is " + std::to_string(index.kvdOffset) + " but kvdByteLength is 0", where);
    }
  } else {
    BAKE_RETURN_IF_ERROR(
        checkSection("the key/value data", index.kvdOffset, index.kvdLength, levelIndexEnd, fileSize, name));
    // The specification ties the DFD size to the KVD position: the KVD follows the DFD directly.
    if (std::uint64_t(index.kvdOffset) != std::uint64_t(index.dfdOffset) + index.dfdLength) {
      return invalidInput("the key/value data (offset " + std::to_string(index.kvdOffset) +
                              ") does not directly follow the data format descriptor, which ends at " +
                              std::to_string(std::uint64_t(index.dfdOffset) + index.dfdLength),
                          where);
    }
  }
  // Neither "none" nor Zstandard has global data.
  if (index.sgdLength != 0 || index.sgdOffset != 0) {
    return invalidInput("supercompression global data " + rangeText(index.sgdOffset, index.sgdLength) +
                            " is present, but the supercompression scheme has none",
                        where);
  }
  return Status::ok();
}

// Checks that the first descriptor block is the basic block our vkFormat implies: RGBSDA, one sample
// per channel with the format's bit layout. Colour primaries, transfer function and sample bounds are
// informative and not checked; the LINEAR qualifier may differ (the specification allows it).
Status checkDataFormatDescriptor(std::span<const std::uint8_t> dfd, const fmt::FormatInfo& info, bool supercompressed,
                                 const std::string& name) {
  const Location where{name, "data format descriptor"};
  const std::uint32_t totalSize = get32(dfd, 0);
  if (totalSize != dfd.size()) {
    return invalidInput("dfdTotalSize " + std::to_string(totalSize) + " differs from dfdByteLength " +
                            std::to_string(dfd.size()),
                        where);
  }
  const std::span<const std::uint8_t> block = dfd.subspan(fmt::kDfdTotalSizeFieldSize);
  const std::uint32_t vendorAndType = get32(block, fmt::kDfdOffsetVendorAndType);
  const std::uint32_t vendor = vendorAndType & fmt::kDfdVendorIdMask;
  const std::uint32_t type = vendorAndType >> fmt::kDfdDescriptorTypeShift;
  if (vendor != fmt::kDfdVendorKhronos || type != fmt::kDfdDescriptorTypeBasic) {
    return invalidInput("the first descriptor block is not a Khronos basic block (vendorId " + std::to_string(vendor) +
                            ", descriptorType " + std::to_string(type) + ")",
                        where);
  }
  const std::uint32_t blockSize = get32(block, fmt::kDfdOffsetVersionAndSize) >> fmt::kDfdBlockSizeShift;
  if (blockSize < fmt::kDfdBlockHeaderSize || blockSize > block.size() ||
      (blockSize - fmt::kDfdBlockHeaderSize) % fmt::kDfdSampleSize != 0) {
    return invalidInput("descriptorBlockSize " + std::to_string(blockSize) +
                            " is not 24 + 16 x samples within the descriptor's " + std::to_string(block.size()) +
                            " bytes",
                        where);
  }
  const std::uint8_t model = get8(block, fmt::kDfdOffsetColorModel);
  if (model != fmt::kDfdModelRgbsda) {
    return invalidInput("colorModel " + std::to_string(model) + " is not RGBSDA (" +
                            std::to_string(fmt::kDfdModelRgbsda) + ") as vkFormat " + info.name + " requires",
                        where);
  }
  for (std::size_t i = 0; i < 4; ++i) {
    if (get8(block, fmt::kDfdOffsetTexelBlockDimension + i) != 0) {
      return invalidInput("texelBlockDimension" + std::to_string(i) + " is not 0 (1 texel) for an uncompressed format",
                          where);
    }
  }
  const std::uint8_t bytesPlane0 = get8(block, fmt::kDfdOffsetBytesPlane);
  const bool bytesPlane0Ok = bytesPlane0 == fmt::texelSize(info) || (supercompressed && bytesPlane0 == 0);
  if (!bytesPlane0Ok) {
    return invalidInput("bytesPlane0 " + std::to_string(bytesPlane0) + " does not match the " +
                            std::to_string(fmt::texelSize(info)) + "-byte texels of " + info.name,
                        where);
  }
  const std::uint32_t samples = (blockSize - fmt::kDfdBlockHeaderSize) / fmt::kDfdSampleSize;
  if (samples != info.channels) {
    return invalidInput("the descriptor has " + std::to_string(samples) + " samples but " + info.name + " has " +
                            std::to_string(info.channels) + " channels",
                        where);
  }
  const std::uint32_t bits = info.typeSize * 8;
  const std::uint8_t checkedTypeBits = fmt::kDfdChannelIdMask | fmt::kDfdSampleFloat | fmt::kDfdSampleSigned;
  for (std::uint32_t c = 0; c < samples; ++c) {
    const std::size_t sample = fmt::kDfdOffsetSamples + c * fmt::kDfdSampleSize;
    const std::uint8_t expectedType =
        fmt::kChannelOrder[c] | (info.isFloat ? fmt::kDfdSampleFloat | fmt::kDfdSampleSigned : 0);
    const bool matches = get16(block, sample + fmt::kDfdSampleOffsetBitOffset) == c * bits &&
                         get8(block, sample + fmt::kDfdSampleOffsetBitLength) == bits - 1 &&
                         (get8(block, sample + fmt::kDfdSampleOffsetChannelType) & checkedTypeBits) == expectedType;
    if (!matches) {
      return invalidInput("sample " + std::to_string(c) + " (bitOffset " +
                              std::to_string(get16(block, sample + fmt::kDfdSampleOffsetBitOffset)) + ", bitLength " +
                              std::to_string(get8(block, sample + fmt::kDfdSampleOffsetBitLength) + 1) +
                              ", channelType " +
                              std::to_string(get8(block, sample + fmt::kDfdSampleOffsetChannelType)) +
                              ") does not match channel " + std::to_string(c) + " of " + info.name,
                          where);
    }
  }
  return Status::ok();
}

// Parses key/value entries; the entries with their padding must fill kvdByteLength exactly, keys must be
// NUL-terminated, non-empty, unique and sorted.
Result<std::map<std::string, std::vector<std::uint8_t>>> parseKeyValueData(std::span<const std::uint8_t> kvd,
                                                                            const std::string& name) {
  std::map<std::string, std::vector<std::uint8_t>> entries;
  std::string previousKey;
  std::size_t pos = 0;
  for (std::uint32_t number = 0; pos < kvd.size(); ++number) {
    std::string element = "key/value entry " + std::to_string(number);
    const std::size_t left = kvd.size() - pos;
    if (left < 4) {
      return invalidInput("only " + std::to_string(left) + " bytes remain, too few for keyAndValueByteLength",
                          {name, element});
    }
    const std::uint32_t length = get32(kvd, pos);
    pos += 4;
    if (length < 2) {
      return invalidInput("keyAndValueByteLength " + std::to_string(length) +
                              " is below 2 (a 1-byte key and its NUL terminator)",
                          {name, element});
    }
    if (alignUp(length, fmt::kKeyValueAlignment) > kvd.size() - pos) {
      return invalidInput("the entry (" + std::to_string(length) + " bytes and its padding) runs past the end of " +
                              "the key/value data (" + std::to_string(kvd.size() - pos) + " bytes left)",
                          {name, element});
    }
    const std::span<const std::uint8_t> entry = kvd.subspan(pos, length);
    const auto nul = std::find(entry.begin(), entry.end(), std::uint8_t{0});
    if (nul == entry.end()) return invalidInput("the key has no NUL terminator", {name, element});
    if (nul == entry.begin()) return invalidInput("the key is empty", {name, element});
    std::string key(entry.begin(), nul);
    element += " ('" + printableKey(key) + "')";
    if (!entries.empty() && key == previousKey) return invalidInput("the key appears twice", {name, element});
    if (!entries.empty() && key < previousKey) {
      return invalidInput("keys are not sorted: this key follows '" + printableKey(previousKey) + "'",
                          {name, element});
    }
    entries.emplace(key, std::vector<std::uint8_t>(nul + 1, entry.end()));
    previousKey = std::move(key);
    pos += alignUp(length, fmt::kKeyValueAlignment);
  }
  return entries;
}

// Zstandard never expands data more than this: its best case is an RLE block, 4 bytes (3-byte block
// header + the byte) for at most 128 KiB of output. A level that claims more is corrupt.
constexpr std::uint64_t kZstdMaxExpansion = 32768;

struct ZstdContextDeleter {
  void operator()(ZSTD_DCtx* context) const { ZSTD_freeDCtx(context); }
};

// Inflates one level. Output is appended chunk by chunk, so memory grows with what the data actually
// produces, never with what the header claims; producing more than `expected` bytes is an error.
Result<std::vector<std::uint8_t>> inflateLevel(std::span<const std::uint8_t> compressed, std::uint64_t expected,
                                               const Location& where) {
  if (expected / kZstdMaxExpansion >= compressed.size()) {
    return invalidInput("uncompressedByteLength " + std::to_string(expected) + " cannot come from " +
                            std::to_string(compressed.size()) + " bytes of Zstandard data",
                        where);
  }
  const std::unique_ptr<ZSTD_DCtx, ZstdContextDeleter> context(ZSTD_createDCtx());
  if (!context) return internalError("cannot create a Zstandard decompression context", where);
  std::vector<std::uint8_t> chunk(ZSTD_DStreamOutSize());
  std::vector<std::uint8_t> level;
  ZSTD_inBuffer input{compressed.data(), compressed.size(), 0};
  // ZSTD_decompressStream returns 0 once a frame is decoded and fully flushed. Keep calling while input
  // remains (a level may hold several frames) or the current frame is unfinished. Stopping on "input
  // consumed" alone would be wrong: a full output chunk may still hide buffered bytes, and calling again
  // after a finished frame with no input would start reading a next frame that does not exist.
  std::size_t pending = 1;
  while (input.pos < input.size || pending != 0) {
    ZSTD_outBuffer output{chunk.data(), chunk.size(), 0};
    const std::size_t inputBefore = input.pos;
    const std::size_t result = ZSTD_decompressStream(context.get(), &output, &input);
    if (ZSTD_isError(result)) {
      return invalidInput(std::string("the Zstandard data is corrupt: ") + ZSTD_getErrorName(result), where);
    }
    if (output.pos > expected - level.size()) {
      return invalidInput("the Zstandard data inflates to more than uncompressedByteLength (" +
                              std::to_string(expected) + " bytes)",
                          where);
    }
    level.insert(level.end(), chunk.begin(), chunk.begin() + std::ptrdiff_t(output.pos));
    if (output.pos == 0 && input.pos == inputBefore) {
      // No progress: with all input read, the last frame is cut short.
      return invalidInput(input.pos == input.size ? "the Zstandard data ends inside a frame"
                                                  : "the Zstandard data makes no progress",
                          where);
    }
    pending = result;
  }
  if (level.size() != expected) {
    return invalidInput("the Zstandard data inflates to " + std::to_string(level.size()) +
                            " bytes, but uncompressedByteLength is " + std::to_string(expected),
                        where);
  }
  return level;
}

struct LevelLayout {
  std::uint32_t width, height, layerCount, texelBytes;
  bool supercompressed;
  std::uint64_t metadataEnd;  // end of the header, level index, DFD and KVD: level data starts after it
};

// Checks one level's index entry against the file, the format and the level stored after it (levels
// are stored smallest first, so level p follows level p + 1), then reads or inflates its data.
Result<std::vector<std::uint8_t>> readLevel(std::span<const std::uint8_t> bytes, const LevelEntry& entry,
                                            std::uint32_t level, const LevelLayout& layout,
                                            std::uint64_t followsEnd, const std::string& name) {
  const Location where{name, levelElement(level)};
  const auto expected = levelSize(layout.width, layout.height, layout.layerCount, layout.texelBytes, level);
  if (!expected) {
    return invalidInput("the level size (" +
                            describeLevelSize(layout.width, layout.height, layout.layerCount, layout.texelBytes,
                                              level) +
                            ") does not fit in 64 bits",
                        where);
  }
  if (!fitsInFile(entry.byteOffset, entry.byteLength, bytes.size())) {
    return invalidInput(levelElement(level) + " data " + rangeText(entry.byteOffset, entry.byteLength) +
                            " runs past the end of the file (" + std::to_string(bytes.size()) + " bytes)",
                        where);
  }
  if (entry.byteOffset < layout.metadataEnd) {
    return invalidInput(levelElement(level) + " data " + rangeText(entry.byteOffset, entry.byteLength) +
                            " overlaps the header, level index, descriptor or key/value data, which end at " +
                            std::to_string(layout.metadataEnd),
                        where);
  }
  if (entry.byteOffset < followsEnd) {
    return invalidInput(levelElement(level) + " data " + rangeText(entry.byteOffset, entry.byteLength) +
                            " starts before the end of level " + std::to_string(level + 1) + " data (" +
                            std::to_string(followsEnd) + "); levels are stored smallest first",
                        where);
  }
  const std::span<const std::uint8_t> data = bytes.subspan(entry.byteOffset, entry.byteLength);
  if (layout.supercompressed) {
    if (entry.uncompressedByteLength != *expected) {
      return invalidInput("uncompressedByteLength " + std::to_string(entry.uncompressedByteLength) + " differs from " +
                              std::to_string(*expected) + " (" +
                              describeLevelSize(layout.width, layout.height, layout.layerCount,
                                                layout.texelBytes, level) +
                              ")",
                          where);
    }
    return inflateLevel(data, *expected, where);
  }
  if (entry.byteLength != *expected) {
    return invalidInput(levelElement(level) + " holds " + std::to_string(entry.byteLength) + " bytes, but " +
                            describeLevelSize(layout.width, layout.height, layout.layerCount, layout.texelBytes,
                                              level) +
                            " need " + std::to_string(*expected),
                        where);
  }
  if (entry.uncompressedByteLength != entry.byteLength) {
    return invalidInput("uncompressedByteLength " + std::to_string(entry.uncompressedByteLength) +
                            " differs from byteLength " + std::to_string(entry.byteLength) +
                            " without supercompression",
                        where);
  }
  const std::uint32_t alignment = fmt::uncompressedLevelAlignment(layout.texelBytes);
  if (entry.byteOffset % alignment != 0) {
    return invalidInput(levelElement(level) + " data offset " + std::to_string(entry.byteOffset) +
                            " is not a multiple of " + std::to_string(alignment) + " (lcm(texel size, 4))",
                        where);
  }
  return std::vector<std::uint8_t>(data.begin(), data.end());
}

}  // namespace

// ---- Public API -------------------------------------------------------------------------------------------

Result<Header> decodeHeader(std::span<const std::uint8_t> bytes, const std::string& name) {
  if (bytes.size() < fmt::kIdentifierSize ||
      !std::equal(fmt::kIdentifier.begin(), fmt::kIdentifier.end(), bytes.begin())) {
    return invalidInput("not a KTX 2.0 file: the 12-byte KTX2 identifier is missing", {name, "identifier"});
  }
  const Location where{name, "header"};
  if (bytes.size() < fmt::kHeaderSize) {
    return invalidInput("the file is " + std::to_string(bytes.size()) + " bytes, shorter than the " +
                            std::to_string(fmt::kHeaderSize) + "-byte KTX2 header and index",
                        where);
  }
  Header header;
  header.vkFormat = get32(bytes, fmt::kOffsetVkFormat);
  header.typeSize = get32(bytes, fmt::kOffsetTypeSize);
  header.width = get32(bytes, fmt::kOffsetPixelWidth);
  header.height = get32(bytes, fmt::kOffsetPixelHeight);
  header.depth = get32(bytes, fmt::kOffsetPixelDepth);
  header.layers = get32(bytes, fmt::kOffsetLayerCount);
  header.faces = get32(bytes, fmt::kOffsetFaceCount);
  header.levels = get32(bytes, fmt::kOffsetLevelCount);
  header.supercompression = get32(bytes, fmt::kOffsetSupercompressionScheme);

  // What the specification requires of any KTX2 file ("Texture Type", "levelCount").
  if (header.width == 0) return invalidInput("pixelWidth is 0", where);
  if (header.faces != 1 && header.faces != 6) {
    return invalidInput("faceCount " + std::to_string(header.faces) + " is neither 1 nor 6 (a cubemap)", where);
  }
  if (header.faces == 6 && (header.height != header.width || header.depth != 0)) {
    return invalidInput("a cubemap must have square faces and pixelDepth 0", where);
  }
  if (header.depth != 0 && header.height == 0) return invalidInput("pixelDepth is set but pixelHeight is 0", where);
  const std::uint32_t maxCount = maxLevels(std::max({header.width, header.height, header.depth}));
  if (header.levels > maxCount) {
    return invalidInput("levelCount " + std::to_string(header.levels) + " exceeds the " + std::to_string(maxCount) +
                            " levels of a full mip chain for this size",
                        where);
  }
  return header;
}

Result<Texture> decode(std::span<const std::uint8_t> bytes, const std::string& name) {
  BAKE_ASSIGN_OR_RETURN(const Header header, decodeHeader(bytes, name));
  BAKE_ASSIGN_OR_RETURN(const fmt::FormatInfo* info, checkSupported(header, name));
  const bool supercompressed = header.supercompression == fmt::kSupercompressionZstd;

  // levelCount 0 means "base level only; generate the rest at load time".
  const std::uint32_t levelCount = std::max<std::uint32_t>(1, header.levels);
  const std::uint64_t levelIndexEnd = fmt::kLevelIndexOffset + std::uint64_t(levelCount) * fmt::kLevelIndexEntrySize;
  if (levelIndexEnd > bytes.size()) {
    return invalidInput("the level index (" + std::to_string(levelCount) + " entries, bytes " +
                            std::to_string(fmt::kLevelIndexOffset) + " to " + std::to_string(levelIndexEnd) +
                            ") runs past the end of the file (" + std::to_string(bytes.size()) + " bytes)",
                        {name, "level index"});
  }

  const Index index = readIndex(bytes);
  BAKE_RETURN_IF_ERROR(checkIndex(index, levelIndexEnd, bytes.size(), name));
  BAKE_RETURN_IF_ERROR(
      checkDataFormatDescriptor(bytes.subspan(index.dfdOffset, index.dfdLength), *info, supercompressed, name));

  Texture texture;
  texture.format = formatOf(*info);
  texture.width = header.width;
  texture.height = header.height;
  texture.layers = header.layers;
  BAKE_ASSIGN_OR_RETURN(texture.metadata, parseKeyValueData(bytes.subspan(index.kvdOffset, index.kvdLength), name));

  const LevelLayout layout{header.width,
                           header.height,
                           texture.layerCount(),
                           fmt::texelSize(*info),
                           supercompressed,
                           std::max({levelIndexEnd, std::uint64_t(index.dfdOffset) + index.dfdLength,
                                     std::uint64_t(index.kvdOffset) + index.kvdLength})};
  // Before any level is read or inflated: what the whole chain would take in memory. A few kilobytes
  // of Zstandard data can claim gigabytes (a decompression bomb).
  std::uint64_t decodedTotal = 0;
  for (std::uint32_t level = 0; level < levelCount; ++level) {
    const auto size = levelSize(layout.width, layout.height, layout.layerCount, layout.texelBytes, level);
    if (!size || *size > std::numeric_limits<std::uint64_t>::max() - decodedTotal) {
      decodedTotal = std::numeric_limits<std::uint64_t>::max();
      break;
    }
    decodedTotal += *size;
  }
  BAKE_RETURN_IF_ERROR(checkBudget(Budget::DecodedBytes, decodedTotal,
                                   "bytes of decoded texture levels (" + std::to_string(layout.width) + "x" +
                                       std::to_string(layout.height) + ", " + std::to_string(layout.layerCount) +
                                       " layers, " + std::to_string(levelCount) + " levels)",
                                   {name, "level index"}));
  texture.levels.resize(levelCount);
  std::uint64_t followsEnd = 0;  // end of the previously stored (next smaller) level
  for (std::uint32_t level = levelCount; level-- > 0;) {
    const std::size_t at = fmt::kLevelIndexOffset + level * fmt::kLevelIndexEntrySize;
    const LevelEntry entry{get64(bytes, at + fmt::kLevelEntryByteOffset), get64(bytes, at + fmt::kLevelEntryByteLength),
                           get64(bytes, at + fmt::kLevelEntryUncompressedByteLength)};
    BAKE_ASSIGN_OR_RETURN(texture.levels[level], readLevel(bytes, entry, level, layout, followsEnd, name));
    followsEnd = entry.byteOffset + entry.byteLength;
  }
  return texture;
}

Result<Texture> read(const std::filesystem::path& path) {
  BAKE_ASSIGN_OR_RETURN(const std::vector<std::uint8_t> bytes, readFileBytes(path));
  return decode(bytes, path.string());
}

}  // namespace bake::ktx2
