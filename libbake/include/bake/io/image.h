// Images through OpenImageIO: PNG (8/16-bit), EXR (half/float) and whatever else OIIO reads. Pixels
// are held as interleaved 32-bit floats (8/16-bit integer data normalised to 0..1); the storage type
// is chosen when writing. Writes are atomic like every output.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "bake/core/status.h"

namespace bake {

enum class PixelType { U8, U16, Half, Float };

struct Image {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<float> pixels;  // row-major, top row first, interleaved channels
  PixelType sourceType = PixelType::Float;  // what the file stored (set by readImage)

  float& at(int x, int y, int c) { return pixels[(std::size_t(y) * width + x) * channels + c]; }
  float at(int x, int y, int c) const { return pixels[(std::size_t(y) * width + x) * channels + c]; }
};

Result<Image> readImage(const std::filesystem::path& path);
// An encoded image held in memory (e.g. a PNG embedded in a glTF package); `extension` (".png")
// chooses the decoder, `name` is what errors name.
Result<Image> readImageFromMemory(std::span<const std::uint8_t> bytes, const std::string& name,
                                  const std::string& extension);
// The file format follows the extension (.png, .exr, ...). PNG accepts U8/U16, EXR Half/Float.
Status writeImage(const std::filesystem::path& path, const Image& image, PixelType type);

}  // namespace bake
