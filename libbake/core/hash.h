// Content hashes of inputs and outputs for reports and caches: XXH3-128 (libxxhash), written as
// "xxh3-128:<32 hex digits>". Not cryptographic; it identifies content, it does not authenticate it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "bake/core/status.h"

namespace bake {

std::string hashBytes(std::span<const std::uint8_t> bytes);
// Streams the file, so large inputs are not held in memory twice.
Result<std::string> hashFile(const std::filesystem::path& path);

}  // namespace bake
