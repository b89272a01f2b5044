// Make-syntax dependency files (--depfile) for Make, Ninja and CMake's DEPFILE: every output is a
// target, every file read is a prerequisite, all as absolute normalised paths escaped the way GNU Make
// and Ninja both read them (core/build_syntax.h); a path neither can hold is a usage error.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "bake/core/status.h"

namespace bake {

Result<std::string> escapeDepfilePath(const std::string& path);

Result<std::string> formatDepfile(const std::vector<std::filesystem::path>& outputs,
                          const std::vector<std::filesystem::path>& inputs);

// Formats and writes the depfile atomically.
Status writeDepfile(const std::filesystem::path& depfile,
                    const std::vector<std::filesystem::path>& outputs,
                    const std::vector<std::filesystem::path>& inputs);

}  // namespace bake
