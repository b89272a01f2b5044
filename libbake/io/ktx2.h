// KTX 2.0 textures (Khronos KTX 2.0 specification): 2D and 2D-array textures with full or partial mip
// chains, uncompressed formats R8 ... RGBA16F / R32F, key/value metadata, and optional Zstandard
// supercompression (libzstd). Debian 12 has no libktx, so this is our own writer and reader; the
// byte-level constants live in formats/include/bake_formats/ktx2.h, shared with the runtime.
// The reader treats its input as untrusted: every offset and length is checked, never asserted.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "bake/core/status.h"

namespace bake::ktx2 {

enum class Format { R8, RG8, RGBA8, R16, RG16, RGBA16, RGBA16F, R32F };

std::uint32_t vkFormatOf(Format format);
const char* formatName(Format format);      // "R8_UNORM", ...
std::uint32_t bytesPerTexel(Format format);
std::uint32_t channelCount(Format format);

struct Texture {
  Format format = Format::R8;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t layers = 0;  // 0: a plain 2D texture; >= 1: a 2D array with that many layers
  // levels[0] is the base level. Each holds all layers of that level, layer after layer, rows tightly
  // packed (no padding), texels little-endian.
  std::vector<std::vector<std::uint8_t>> levels;
  // Key/value metadata (written sorted by key, as KTX2 requires). Text values are stored with their
  // terminating NUL as the specification asks; setText/text handle that.
  std::map<std::string, std::vector<std::uint8_t>> metadata;

  void setText(const std::string& key, const std::string& value);
  std::string text(const std::string& key) const;  // "" when absent

  std::uint32_t levelWidth(std::uint32_t level) const;
  std::uint32_t levelHeight(std::uint32_t level) const;
  std::size_t levelByteSize(std::uint32_t level) const;  // all layers
  std::uint32_t layerCount() const { return layers == 0 ? 1 : layers; }
};

// Number of levels of a full mip chain for a base size: floor(log2(max(w, h))) + 1 (0 when both are 0).
std::uint32_t fullMipCount(std::uint32_t width, std::uint32_t height);

struct WriteOptions {
  bool zstd = false;
  int zstdLevel = 19;
  // The KTXwriter value; empty means "bake <toolkit version>". Golden tests pin it so that a version
  // bump does not change their bytes.
  std::string writer;
};

// Checks the texture's own consistency (sizes of every level, counts) before encoding.
Status validate(const Texture& texture);

Result<std::vector<std::uint8_t>> encode(const Texture& texture, const WriteOptions& options = {});
// `name` is used in error messages (usually the file path).
Result<Texture> decode(std::span<const std::uint8_t> bytes, const std::string& name = "<memory>");

// Facts about a file that a describer wants even when the payload is not decoded. decodeHeader checks
// the identifier and the header's own consistency (InvalidInput), not whether decode supports the
// format, so it also describes files that decode rejects as Unsupported.
struct Header {
  std::uint32_t vkFormat = 0;
  std::uint32_t typeSize = 0;
  std::uint32_t width = 0, height = 0, depth = 0;
  std::uint32_t layers = 0, faces = 0, levels = 0;
  std::uint32_t supercompression = 0;
};
Result<Header> decodeHeader(std::span<const std::uint8_t> bytes, const std::string& name = "<memory>");

Status write(const std::filesystem::path& path, const Texture& texture, const WriteOptions& options = {});
Result<Texture> read(const std::filesystem::path& path);

}  // namespace bake::ktx2
