// Descriptions of our packages for bakeinfo: a .glb/.gltf (glTF summary, attributes and their value
// ranges, extensions and their versions, Draco use) or a .ktx2 (format, size, layers, levels,
// supercompression, metadata). The file kind is recognised by its magic bytes, not its name.
// The JSON form is for programs (docs/tools/bakeinfo.md), the text form for people.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "bake/core/status.h"

namespace bake::info {

// Reads and fully decodes the file (so a damaged one is reported), then describes it.
Result<nlohmann::json> describeFile(const std::filesystem::path& path);

std::string formatText(const nlohmann::json& description);

// Pieces of the text form, also for the lines a technique adds (techniques/registry.h).
std::string numberText(const nlohmann::json& value);          // 6 significant digits; "-" for null
std::string vectorText(const nlohmann::json& values);         // "(x, y, z)"
std::string plural(std::size_t n, const std::string& word);  // "1 stroke", "3 strokes", "2 meshes"

}  // namespace bake::info
