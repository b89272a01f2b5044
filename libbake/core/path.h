// Small path helpers shared by the readers and writers.
#pragma once

#include <filesystem>
#include <string>

namespace bake {

// ".png" for "Frame.PNG": file formats are chosen by extension, case-insensitively.
std::string lowercaseExtension(const std::filesystem::path& path);

}  // namespace bake
