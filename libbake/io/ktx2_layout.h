// Helpers that more than one KTX2 stage needs: the Format <-> bake_formats/ktx2.h lookup, level
// dimensions, sizes and alignment (Khronos KTX 2.0 specification, "Level Index", "Mip Level Array" /
// "mipPadding", "Key/Value Data"), the metadata limits both validate() and the writer enforce, and the
// element names their errors use. Defined in io/ktx2_texture.cpp; used by ktx2_write.cpp and
// ktx2_read.cpp. Internal to io/, not part of the library's API.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bake/core/status.h"
#include "bake_formats/ktx2.h"
#include "io/ktx2.h"

namespace bake::ktx2::layout {

bool isKnownFormat(Format format);
// The format's entry in bake_formats/ktx2.h; only for formats that passed isKnownFormat.
const bake::format::ktx2::FormatInfo& infoOf(Format format);

// Size of one dimension at a mip level: halved per level, never below 1.
std::uint32_t levelDimension(std::uint32_t base, std::uint32_t level);
// Bytes of one level holding every layer, or nullopt when that does not fit in 64 bits.
std::optional<std::uint64_t> levelSize(std::uint32_t width, std::uint32_t height, std::uint32_t layerCount,
                                       std::uint32_t texelBytes, std::uint32_t level);
// Number of levels of a full chain for the largest dimension.
std::uint32_t maxLevels(std::uint32_t largestDimension);
std::uint64_t alignUp(std::uint64_t value, std::uint64_t alignment);

// For messages: how a level size was derived, and the element name of a level.
std::string describeLevelSize(std::uint32_t width, std::uint32_t height, std::uint32_t layerCount,
                              std::uint32_t texelBytes, std::uint32_t level);
std::string levelElement(std::uint32_t level);

// Keys non-empty and NUL-free, entries small enough for a 32-bit keyAndValueByteLength.
Status validateMetadata(const std::map<std::string, std::vector<std::uint8_t>>& metadata);

}  // namespace bake::ktx2::layout
