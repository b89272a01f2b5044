// The TAM and its threshold texture as KTX2 files (formats/tam.md). Texel values are paper
// brightness quantised to 8 bits (round(255 v)). The TAM is a 2D array, one layer per tone, light to
// dark, with the full mip chain (levels below the stroke levels are the builder's box-filtered ones).
// Black ink gives R8; coloured ink gives RGBA8 with RGB the composited colour (the builder's colour
// images) and A the brightness (its one-channel images: the ink as if black, whose darkness is what
// the tones target). The `BAKE_tam` key/value entry carries the tone values and the
// construction's parameters as JSON.
#include <algorithm>
#include <cmath>

#include "bake_formats/tam.h"
#include "core/json_read.h"
#include "hatching/bake/bake_stages.h"

namespace bake::hatching {
namespace {

namespace fmt = format::tam;
using nlohmann::json;

std::uint8_t quantise(float v) {
  const float clamped = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
  return std::uint8_t(std::lround(clamped * 255.0f));
}

Status checkImage(const stroke::Raster& image, int side, int channels, int tone, int mip) {
  if (image.width != side || image.height != side || image.channels != channels ||
      image.values.size() != std::size_t(side) * side * std::size_t(channels))
    return internalError("the TAM image of tone " + std::to_string(tone) + ", mip " + std::to_string(mip) + " is " +
                         std::to_string(image.width) + " x " + std::to_string(image.height) + " x " +
                         std::to_string(image.channels) + ", expected " + std::to_string(side) + " x " +
                         std::to_string(side) + " x " + std::to_string(channels));
  return {};
}

}  // namespace

json tamMetadata(const Tam& tam, const Style& style, bool threshold) {
  json metadata = {{"version", fmt::kVersion},
                   {"tones", tam.targets},
                   {"strokeLevels", tam.strokeLevels},
                   {"style", strokeKindName(style.stroke.kind)},
                   {"seed", style.seed},
                   {"colour", tam.coloured}};
  if (threshold) metadata["threshold"] = true;
  return metadata;
}

Result<ktx2::Texture> tamTexture(const Tam& tam, const Style& style) {
  if (tam.tones < 1 || int(tam.images.size()) != tam.tones || tam.resolution < 1 ||
      tam.mipLevels != int(ktx2::fullMipCount(tam.resolution, tam.resolution)))
    return internalError("the TAM's tones, resolution or mip chain are inconsistent");
  ktx2::Texture texture;
  texture.format = tam.coloured ? ktx2::Format::RGBA8 : ktx2::Format::R8;
  texture.width = texture.height = std::uint32_t(tam.resolution);
  texture.layers = std::uint32_t(tam.tones);
  if (tam.coloured && tam.colourImages.size() != tam.images.size()) return internalError("the coloured TAM lacks its colour images");
  for (int mip = 0; mip < tam.mipLevels; ++mip) {
    const int side = std::max(1, tam.resolution >> mip);
    const std::size_t texels = std::size_t(side) * side;
    std::vector<std::uint8_t> level;
    level.reserve(texels * tam.tones * (tam.coloured ? 4 : 1));
    for (int tone = 0; tone < tam.tones; ++tone) {
      if (int(tam.images[tone].size()) != tam.mipLevels) return internalError("tone " + std::to_string(tone) + " lacks mip levels");
      const stroke::Raster& image = tam.images[tone][mip];
      BAKE_RETURN_IF_ERROR(checkImage(image, side, 1, tone, mip));
      if (!tam.coloured) {
        for (std::size_t i = 0; i < texels; ++i) level.push_back(quantise(image.values[i]));
        continue;
      }
      if (int(tam.colourImages[tone].size()) != tam.mipLevels) return internalError("tone " + std::to_string(tone) + " lacks colour mip levels");
      const stroke::Raster& colour = tam.colourImages[tone][mip];
      BAKE_RETURN_IF_ERROR(checkImage(colour, side, 3, tone, mip));
      for (std::size_t i = 0; i < texels; ++i) {
        for (int c = 0; c < 3; ++c) level.push_back(quantise(colour.values[i * 3 + c]));
        level.push_back(quantise(image.values[i]));
      }
    }
    texture.levels.push_back(std::move(level));
  }
  texture.setText(fmt::kMetadataKey, tamMetadata(tam, style, false).dump());
  BAKE_RETURN_IF_ERROR(ktx2::validate(texture));
  return texture;
}

std::vector<double> storedDarkness(const ktx2::Texture& texture, std::uint32_t level) {
  const std::size_t texels = std::size_t(texture.levelWidth(level)) * texture.levelHeight(level);
  const std::size_t stride = texture.format == ktx2::Format::RGBA8 ? 4 : 1;
  const std::size_t offset = stride - 1;  // R of R8, A of RGBA8
  std::vector<double> darkness;
  const std::vector<std::uint8_t>& bytes = texture.levels[level];
  for (std::uint32_t layer = 0; layer < texture.layerCount(); ++layer) {
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < texels; ++i) sum += bytes[(layer * texels + i) * stride + offset];
    darkness.push_back(1.0 - double(sum) / (255.0 * double(texels)));
  }
  return darkness;
}

Result<ktx2::Texture> thresholdKtx(const Tam& tam, const Style& style) {
  const std::vector<stroke::Raster> thresholds = thresholdTexture(tam);
  if (int(thresholds.size()) != tam.mipLevels) return internalError("the threshold texture lacks mip levels");
  ktx2::Texture texture;
  texture.format = ktx2::Format::R8;
  texture.width = texture.height = std::uint32_t(tam.resolution);
  texture.layers = 0;
  for (int mip = 0; mip < tam.mipLevels; ++mip) {
    const int side = std::max(1, tam.resolution >> mip);
    const stroke::Raster& image = thresholds[mip];
    BAKE_RETURN_IF_ERROR(checkImage(image, side, 1, 0, mip));
    std::vector<std::uint8_t> level(std::size_t(side) * side);
    for (std::size_t i = 0; i < level.size(); ++i) level[i] = quantise(image.values[i]);
    texture.levels.push_back(std::move(level));
  }
  texture.setText(fmt::kMetadataKey, tamMetadata(tam, style, true).dump());
  BAKE_RETURN_IF_ERROR(ktx2::validate(texture));
  return texture;
}

Status dropFinestLevels(ktx2::Texture& texture, int count) {
  if (count <= 0) return {};
  if (count >= int(texture.levels.size()))
    return usageError("--skip-levels " + std::to_string(count) + ": the TAM has only " +
                      std::to_string(texture.levels.size()) + " mip levels (at least one must remain)");
  texture.width = texture.levelWidth(std::uint32_t(count));
  texture.height = texture.levelHeight(std::uint32_t(count));
  texture.levels.erase(texture.levels.begin(), texture.levels.begin() + count);
  BAKE_ASSIGN_OR_RETURN(json metadata, parseJsonText(texture.text(fmt::kMetadataKey), "the TAM's metadata"));
  metadata["skippedLevels"] = count;
  metadata["strokeLevels"] = std::max(0, metadata["strokeLevels"].get<int>() - count);
  texture.setText(fmt::kMetadataKey, metadata.dump());
  return {};
}

}  // namespace bake::hatching
