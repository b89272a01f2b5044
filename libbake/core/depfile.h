// Make-syntax dependency files (--depfile) for Make, Ninja and CMake's DEPFILE: every output is a
// target, every file read is a prerequisite, all as absolute normalised paths with spaces, '#', '$'
// and backslashes escaped the way GNU Make and Ninja both read them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/status.h"

namespace bake {

std::string escapeDepfilePath(const std::string& path);

std::string formatDepfile(const std::vector<std::filesystem::path>& outputs,
                          const std::vector<std::filesystem::path>& inputs);

// Formats and writes the depfile atomically.
Status writeDepfile(const std::filesystem::path& depfile,
                    const std::vector<std::filesystem::path>& outputs,
                    const std::vector<std::filesystem::path>& inputs);

}  // namespace bake
