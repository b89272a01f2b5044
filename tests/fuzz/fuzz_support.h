// Shared by the fuzz targets: a scratch file for readers that only take a path.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include <unistd.h>

namespace bake::fuzz {

// Writes the input to `<temp dir>/bake-fuzz-<pid>/<name>` (one directory per process, so parallel
// fuzzing jobs never share a file) and returns the path.
inline std::filesystem::path writeInput(const std::uint8_t* data, std::size_t size, const std::string& name) {
  static const std::filesystem::path dir = [] {
    std::filesystem::path d = std::filesystem::temp_directory_path() / ("bake-fuzz-" + std::to_string(::getpid()));
    std::error_code ec;
    std::filesystem::create_directories(d, ec);
    return d;
  }();
  const std::filesystem::path path = dir / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

inline std::string asText(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

}  // namespace bake::fuzz
