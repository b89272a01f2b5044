// KTX 2.0 texture facts for bake::ktx2 (io/ktx2.h): the supported formats, Texture's methods,
// fullMipCount and validate(), and the helpers that the writer (io/ktx2_write.cpp) and the reader
// (io/ktx2_read.cpp) share, declared in io/ktx2_layout.h.
// Source: the Khronos KTX File Format Specification 2.0, sections "Level Index" (level sizes),
// "levelCount" / "Texture Type" (the mip chain), "Mip Level Array" / "mipPadding" (alignment) and
// "Key/Value Data" (entry limits). Every byte-level constant is in bake_formats/ktx2.h.

#include <algorithm>
#include <bit>
#include <limits>
#include <optional>

#include "bake_formats/ktx2.h"
#include "io/ktx2.h"
#include "io/ktx2_layout.h"

namespace bake::ktx2 {
namespace fmt = bake::format::ktx2;

// ---- Formats ------------------------------------------------------------------------------------------

// The Format enum indexes fmt::kFormats directly; these pin that correspondence.
static_assert(fmt::kFormats.size() == 8);
static_assert(fmt::kFormats[std::size_t(Format::R8)].vkFormat == fmt::kVkFormatR8Unorm);
static_assert(fmt::kFormats[std::size_t(Format::RG8)].vkFormat == fmt::kVkFormatR8G8Unorm);
static_assert(fmt::kFormats[std::size_t(Format::RGBA8)].vkFormat == fmt::kVkFormatR8G8B8A8Unorm);
static_assert(fmt::kFormats[std::size_t(Format::R16)].vkFormat == fmt::kVkFormatR16Unorm);
static_assert(fmt::kFormats[std::size_t(Format::RG16)].vkFormat == fmt::kVkFormatR16G16Unorm);
static_assert(fmt::kFormats[std::size_t(Format::RGBA16)].vkFormat == fmt::kVkFormatR16G16B16A16Unorm);
static_assert(fmt::kFormats[std::size_t(Format::RGBA16F)].vkFormat == fmt::kVkFormatR16G16B16A16Sfloat);
static_assert(fmt::kFormats[std::size_t(Format::R32F)].vkFormat == fmt::kVkFormatR32Sfloat);

namespace layout {

bool isKnownFormat(Format format) { return std::size_t(format) < fmt::kFormats.size(); }

// Only for formats that passed isKnownFormat (a cast integer may not name one).
const fmt::FormatInfo& infoOf(Format format) { return fmt::kFormats[std::size_t(format)]; }

}  // namespace layout

// ---- Overflow-safe sizes --------------------------------------------------------------------------------

namespace {

std::optional<std::uint64_t> checkedMul(std::uint64_t a, std::uint64_t b) {
  std::uint64_t product = 0;
  if (__builtin_mul_overflow(a, b, &product)) return std::nullopt;
  return product;
}

}  // namespace

namespace layout {

// Size of one dimension at a mip level: halved per level, never below 1.
std::uint32_t levelDimension(std::uint32_t base, std::uint32_t level) {
  if (level >= 32) return 1;  // shifting a 32-bit value by 32 or more is undefined
  return std::max<std::uint32_t>(1, base >> level);
}

// Bytes of one level holding every layer, or nullopt when that does not fit in 64 bits (only an
// absurd header can ask for that).
std::optional<std::uint64_t> levelSize(std::uint32_t width, std::uint32_t height, std::uint32_t layerCount,
                                       std::uint32_t texelBytes, std::uint32_t level) {
  auto size = checkedMul(levelDimension(width, level), levelDimension(height, level));
  if (size) size = checkedMul(*size, layerCount);
  if (size) size = checkedMul(*size, texelBytes);
  return size;
}

// Number of levels of a full chain for the largest dimension: floor(log2(n)) + 1.
std::uint32_t maxLevels(std::uint32_t largestDimension) { return std::uint32_t(std::bit_width(largestDimension)); }

std::uint64_t alignUp(std::uint64_t value, std::uint64_t alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

// "r x c texels x L layers x B bytes": how a level size was derived, for messages.
std::string describeLevelSize(std::uint32_t width, std::uint32_t height, std::uint32_t layerCount,
                              std::uint32_t texelBytes, std::uint32_t level) {
  return std::to_string(levelDimension(width, level)) + "x" + std::to_string(levelDimension(height, level)) +
         " texels x " + std::to_string(layerCount) + (layerCount == 1 ? " layer" : " layers") + " x " +
         std::to_string(texelBytes) + " bytes";
}

std::string levelElement(std::uint32_t level) { return "level " + std::to_string(level); }

// ---- Metadata ------------------------------------------------------------------------------------------------

Status validateMetadata(const std::map<std::string, std::vector<std::uint8_t>>& metadata) {
  for (const auto& [key, value] : metadata) {
    const std::string element = "metadata key '" + key + "'";
    if (key.empty()) return invalidInput("metadata keys must not be empty", {"", "metadata"});
    if (key.find('\0') != std::string::npos) return invalidInput("the key contains a NUL byte", {"", element});
    if (key.size() + 1 + value.size() > std::numeric_limits<std::uint32_t>::max() - 8) {
      return invalidInput("the entry is too large for KTX2 key/value data", {"", element});
    }
  }
  return Status::ok();
}

}  // namespace layout

// ---- Public API -------------------------------------------------------------------------------------------

using layout::describeLevelSize;
using layout::infoOf;
using layout::isKnownFormat;
using layout::levelDimension;
using layout::levelElement;
using layout::levelSize;
using layout::maxLevels;
using layout::validateMetadata;

std::uint32_t vkFormatOf(Format format) { return isKnownFormat(format) ? infoOf(format).vkFormat : 0; }

const char* formatName(Format format) { return isKnownFormat(format) ? infoOf(format).name : "unknown"; }

std::uint32_t bytesPerTexel(Format format) { return isKnownFormat(format) ? fmt::texelSize(infoOf(format)) : 0; }

std::uint32_t channelCount(Format format) { return isKnownFormat(format) ? infoOf(format).channels : 0; }

void Texture::setText(const std::string& key, const std::string& value) {
  std::vector<std::uint8_t> bytes(value.begin(), value.end());
  bytes.push_back(0);  // the specification asks text values to carry their NUL terminator
  metadata[key] = std::move(bytes);
}

std::string Texture::text(const std::string& key) const {
  const auto found = metadata.find(key);
  if (found == metadata.end()) return "";
  const auto& bytes = found->second;
  // Readers must not rely on the NUL being there; stop at the first one when it is.
  return std::string(bytes.begin(), std::find(bytes.begin(), bytes.end(), std::uint8_t{0}));
}

std::uint32_t Texture::levelWidth(std::uint32_t level) const { return levelDimension(width, level); }

std::uint32_t Texture::levelHeight(std::uint32_t level) const { return levelDimension(height, level); }

std::size_t Texture::levelByteSize(std::uint32_t level) const {
  const auto size = levelSize(width, height, layerCount(), bytesPerTexel(format), level);
  return size ? std::size_t(*size) : std::numeric_limits<std::size_t>::max();  // saturates; validate() reports it
}

std::uint32_t fullMipCount(std::uint32_t width, std::uint32_t height) { return maxLevels(std::max(width, height)); }

Status validate(const Texture& texture) {
  const Location where{"", "texture"};
  if (!isKnownFormat(texture.format)) {
    return invalidInput("format value " + std::to_string(int(texture.format)) + " is not a ktx2::Format", where);
  }
  if (texture.width == 0 || texture.height == 0) {
    return invalidInput("the size " + std::to_string(texture.width) + "x" + std::to_string(texture.height) +
                            " is empty",
                        where);
  }
  const std::uint32_t maxCount = fullMipCount(texture.width, texture.height);
  if (texture.levels.empty() || texture.levels.size() > maxCount) {
    return invalidInput("the texture has " + std::to_string(texture.levels.size()) + " levels; a " +
                            std::to_string(texture.width) + "x" + std::to_string(texture.height) +
                            " texture has 1 to " + std::to_string(maxCount),
                        where);
  }
  const std::uint32_t texelBytes = bytesPerTexel(texture.format);
  for (std::uint32_t level = 0; level < texture.levels.size(); ++level) {
    const auto expected = levelSize(texture.width, texture.height, texture.layerCount(), texelBytes, level);
    if (!expected || *expected != texture.levels[level].size()) {
      return invalidInput(
          "the level holds " + std::to_string(texture.levels[level].size()) + " bytes, but " +
              describeLevelSize(texture.width, texture.height, texture.layerCount(), texelBytes, level) + " need " +
              (expected ? std::to_string(*expected) : std::string("more than 2^64")),
          {"", levelElement(level)});
    }
  }
  return validateMetadata(texture.metadata);
}

}  // namespace bake::ktx2
