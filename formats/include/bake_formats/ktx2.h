// KTX 2.0 byte-level constants (Khronos KTX 2.0 specification; the Data Format Descriptor follows the
// Khronos Data Format Specification 1.3, "basic" descriptor block). One definition for every number
// in a .ktx2 file we write or read: libbake's writer and reader (libbake/io/ktx2.cpp) and the GL
// runtime's loader include this header. Spec page: formats/ktx2.md. All fields are little-endian.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <numeric>

namespace bake::format::ktx2 {

// ---- File identifier: «KTX 20»\r\n\x1A\n -------------------------------------------------------------
inline constexpr std::size_t kIdentifierSize = 12;
inline constexpr std::array<std::uint8_t, kIdentifierSize> kIdentifier = {
    0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32, 0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};

// ---- Header: nine UInt32 fields right after the identifier (byte offsets from the file start) ----------
inline constexpr std::size_t kOffsetVkFormat = 12;
inline constexpr std::size_t kOffsetTypeSize = 16;
inline constexpr std::size_t kOffsetPixelWidth = 20;
inline constexpr std::size_t kOffsetPixelHeight = 24;
inline constexpr std::size_t kOffsetPixelDepth = 28;
inline constexpr std::size_t kOffsetLayerCount = 32;
inline constexpr std::size_t kOffsetFaceCount = 36;
inline constexpr std::size_t kOffsetLevelCount = 40;
inline constexpr std::size_t kOffsetSupercompressionScheme = 44;

// ---- Index: where the DFD, key/value data and supercompression global data lie ---------------------------
inline constexpr std::size_t kOffsetDfdByteOffset = 48;  // UInt32
inline constexpr std::size_t kOffsetDfdByteLength = 52;  // UInt32
inline constexpr std::size_t kOffsetKvdByteOffset = 56;  // UInt32
inline constexpr std::size_t kOffsetKvdByteLength = 60;  // UInt32
inline constexpr std::size_t kOffsetSgdByteOffset = 64;  // UInt64
inline constexpr std::size_t kOffsetSgdByteLength = 72;  // UInt64

// Identifier + header + index; the level index starts here.
inline constexpr std::size_t kHeaderSize = 80;

// ---- Level index: max(1, levelCount) entries of three UInt64, base level (level 0) first -----------------
inline constexpr std::size_t kLevelIndexOffset = kHeaderSize;
inline constexpr std::size_t kLevelIndexEntrySize = 24;
inline constexpr std::size_t kLevelEntryByteOffset = 0;
inline constexpr std::size_t kLevelEntryByteLength = 8;
inline constexpr std::size_t kLevelEntryUncompressedByteLength = 16;

// ---- VkFormat values (Vulkan VkFormat enum) --------------------------------------------------------------
inline constexpr std::uint32_t kVkFormatUndefined = 0;
inline constexpr std::uint32_t kVkFormatR8Unorm = 9;
inline constexpr std::uint32_t kVkFormatR8G8Unorm = 16;
inline constexpr std::uint32_t kVkFormatR8G8B8A8Unorm = 37;
inline constexpr std::uint32_t kVkFormatR16Unorm = 70;
inline constexpr std::uint32_t kVkFormatR16G16Unorm = 77;
inline constexpr std::uint32_t kVkFormatR16G16B16A16Unorm = 91;
inline constexpr std::uint32_t kVkFormatR16G16B16A16Sfloat = 97;
inline constexpr std::uint32_t kVkFormatR32Sfloat = 100;

// ---- supercompressionScheme ----------------------------------------------------------------------------
inline constexpr std::uint32_t kSupercompressionNone = 0;
inline constexpr std::uint32_t kSupercompressionZstd = 2;  // each level is one or more Zstandard frames

// ---- Alignment -----------------------------------------------------------------------------------------
inline constexpr std::uint32_t kKeyValueAlignment = 4;  // every keyAndValueByteLength field is 4-aligned
// Uncompressed levels start on a multiple of lcm(texel block size, 4) ("mipPadding"); supercompressed
// levels are packed with no padding.
inline constexpr std::uint32_t kSupercompressedLevelAlignment = 1;
constexpr std::uint32_t uncompressedLevelAlignment(std::uint32_t texelBlockSize) {
  return std::lcm(texelBlockSize, std::uint32_t{4});
}

// ---- Data Format Descriptor (KDF 1.3 basic descriptor block) --------------------------------------------
// The DFD is a UInt32 dfdTotalSize (which counts itself) followed by descriptor blocks; we write one
// basic block: a 24-byte block header, then one 16-byte sample per channel.
inline constexpr std::size_t kDfdTotalSizeFieldSize = 4;
inline constexpr std::size_t kDfdBlockHeaderSize = 24;
inline constexpr std::size_t kDfdSampleSize = 16;

// Block header words/bytes, as offsets from the start of the descriptor block.
inline constexpr std::size_t kDfdOffsetVendorAndType = 0;     // UInt32: vendorId (17 bits) | descriptorType << 17
inline constexpr std::size_t kDfdOffsetVersionAndSize = 4;    // UInt32: versionNumber | descriptorBlockSize << 16
inline constexpr std::size_t kDfdOffsetColorModel = 8;        // UInt8
inline constexpr std::size_t kDfdOffsetColorPrimaries = 9;    // UInt8
inline constexpr std::size_t kDfdOffsetTransferFunction = 10; // UInt8
inline constexpr std::size_t kDfdOffsetFlags = 11;            // UInt8
inline constexpr std::size_t kDfdOffsetTexelBlockDimension = 12;  // 4 x UInt8, each "size - 1"
inline constexpr std::size_t kDfdOffsetBytesPlane = 16;       // 8 x UInt8
inline constexpr std::size_t kDfdOffsetSamples = kDfdBlockHeaderSize;

// Sample fields, as offsets from the start of a sample.
inline constexpr std::size_t kDfdSampleOffsetBitOffset = 0;    // UInt16
inline constexpr std::size_t kDfdSampleOffsetBitLength = 2;    // UInt8, "bits - 1"
inline constexpr std::size_t kDfdSampleOffsetChannelType = 3;  // UInt8: channel id (low 4 bits) | qualifiers
inline constexpr std::size_t kDfdSampleOffsetPosition = 4;     // 4 x UInt8
inline constexpr std::size_t kDfdSampleOffsetLower = 8;        // UInt32
inline constexpr std::size_t kDfdSampleOffsetUpper = 12;       // UInt32

inline constexpr std::uint32_t kDfdVendorKhronos = 0;
inline constexpr std::uint32_t kDfdVendorIdMask = 0x1FFFF;
inline constexpr std::uint32_t kDfdDescriptorTypeShift = 17;
inline constexpr std::uint32_t kDfdDescriptorTypeBasic = 0;
inline constexpr std::uint32_t kDfdVersion1_3 = 2;
inline constexpr std::uint32_t kDfdBlockSizeShift = 16;

inline constexpr std::uint8_t kDfdModelRgbsda = 1;
inline constexpr std::uint8_t kDfdPrimariesBt709 = 1;
inline constexpr std::uint8_t kDfdTransferLinear = 1;
inline constexpr std::uint8_t kDfdFlagsAlphaStraight = 0;

// RGBSDA channel ids.
inline constexpr std::uint8_t kDfdChannelRed = 0;
inline constexpr std::uint8_t kDfdChannelGreen = 1;
inline constexpr std::uint8_t kDfdChannelBlue = 2;
inline constexpr std::uint8_t kDfdChannelAlpha = 15;
inline constexpr std::uint8_t kDfdChannelIdMask = 0x0F;

// Sample qualifier bits in channelType.
inline constexpr std::uint8_t kDfdSampleFloat = 0x80;
inline constexpr std::uint8_t kDfdSampleSigned = 0x40;

// sampleLower / sampleUpper: the integer range of UNORM channels, and -1.0f / 1.0f (as IEEE-754 bits) for
// float channels, as the KDF specification's examples use.
inline constexpr std::uint32_t kDfdUnormLower = 0;
inline constexpr std::uint32_t kDfdUnorm8Upper = 255;
inline constexpr std::uint32_t kDfdUnorm16Upper = 65535;
inline constexpr std::uint32_t kDfdFloatLower = 0xBF800000u;
inline constexpr std::uint32_t kDfdFloatUpper = 0x3F800000u;

// ---- Key/value data ------------------------------------------------------------------------------------
inline constexpr const char* kKeyWriter = "KTXwriter";  // value: "bake <toolkit version>", NUL-terminated
inline constexpr const char* kWriterName = "bake";

// ---- The formats we write and read ------------------------------------------------------------------------
// All are unpacked: `channels` components of `typeSize` bytes each, in R, G, B, A order.
struct FormatInfo {
  std::uint32_t vkFormat;
  const char* name;       // the VkFormat name without the VK_FORMAT_ prefix
  std::uint32_t typeSize; // bytes per component (the header's typeSize)
  std::uint32_t channels;
  bool isFloat;           // SFLOAT; otherwise UNORM
};

inline constexpr std::array<FormatInfo, 8> kFormats = {{
    {kVkFormatR8Unorm, "R8_UNORM", 1, 1, false},
    {kVkFormatR8G8Unorm, "R8G8_UNORM", 1, 2, false},
    {kVkFormatR8G8B8A8Unorm, "R8G8B8A8_UNORM", 1, 4, false},
    {kVkFormatR16Unorm, "R16_UNORM", 2, 1, false},
    {kVkFormatR16G16Unorm, "R16G16_UNORM", 2, 2, false},
    {kVkFormatR16G16B16A16Unorm, "R16G16B16A16_UNORM", 2, 4, false},
    {kVkFormatR16G16B16A16Sfloat, "R16G16B16A16_SFLOAT", 2, 4, true},
    {kVkFormatR32Sfloat, "R32_SFLOAT", 4, 1, true},
}};

// Channel ids in storage order for a format with 1, 2 or 4 channels (index: channel number).
inline constexpr std::array<std::uint8_t, 4> kChannelOrder = {kDfdChannelRed, kDfdChannelGreen, kDfdChannelBlue,
                                                              kDfdChannelAlpha};

constexpr std::uint32_t texelSize(const FormatInfo& format) { return format.typeSize * format.channels; }

// The entry for a vkFormat value, or nullptr when we do not support it.
constexpr const FormatInfo* findFormat(std::uint32_t vkFormat) {
  for (const FormatInfo& format : kFormats) {
    if (format.vkFormat == vkFormat) return &format;
  }
  return nullptr;
}

}  // namespace bake::format::ktx2
