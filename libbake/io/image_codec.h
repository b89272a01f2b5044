// The boundary between libbake and its image codec module. OpenImageIO pulls in some 260 shared
// libraries (OpenCV, ffmpeg, GStreamer, ...) whose loading took 0.4 s of every tool's start-up, though
// most runs never touch an image. So OIIO lives in a module of its own (libbake_image_oiio.so, source
// in io/oiio/), loaded with dlopen the first time an image is read, written or compared
// (io/image_codec_load.cpp). The table below is everything the module offers; it passes plain data
// (no Status, no libbake code on the module's side), and kImageCodecAbi changes whenever it does.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "bake/core/status.h"
#include "bake/io/image.h"

namespace bake {

constexpr int kImageCodecAbi = 1;
// The symbol the module exports: `const ImageCodecTable* bake_image_codec(int abi)`, null when the
// module was built for another ABI.
constexpr const char* kImageCodecSymbol = "bake_image_codec";
constexpr const char* kImageCodecFile = "libbake_image_oiio.so";

// How a codec call failed; libbake turns it into a Status naming the file.
enum class CodecFailureKind { None, Unsupported, Io, Invalid, Internal, NeedsFile };

struct CodecFailure {
  CodecFailureKind kind = CodecFailureKind::None;
  std::string message;
};

// What an opened image's header says, before any pixel is decoded (so the caller can check budgets).
struct ImageHeader {
  int width = 0, height = 0, channels = 0, depth = 1;
  bool deep = false;
  PixelType storedType = PixelType::Float;
};

struct ImageDifference;

struct ImageCodecTable {
  int abi;
  // An image held in memory, its reader chosen by `extension` (".png"). Null on failure; the kind is
  // NeedsFile when that format's reader cannot read from memory (the caller then goes through a file).
  void* (*openMemory)(const std::uint8_t* bytes, std::size_t size, const char* extension, CodecFailure* failure);
  // A private temporary file by name (never a user's input: inputs are read once, bounded).
  void* (*openFile)(const char* path, CodecFailure* failure);
  void (*header)(void* decoder, ImageHeader* header);
  // Decodes width·height·channels interleaved floats; 8/16-bit values k become exactly k/255, k/65535.
  bool (*readPixels)(void* decoder, float* pixels, CodecFailure* failure);
  void (*close)(void* decoder);
  // Encodes into `file` (open on a fresh temporary named `name`, whose extension picks the writer).
  bool (*write)(const char* name, std::FILE* file, const Image* image, PixelType type, const char* extension,
                CodecFailure* failure);
  // Differences of two images of equal shape (io/image_compare.h).
  bool (*compare)(const Image* actual, const Image* expected, double threshold, ImageDifference* difference,
                  CodecFailure* failure);
};

// The module's table, loaded on the first call and kept for the life of the process; or why it could
// not be loaded (the paths tried and the loader's message). Thread-safe.
Result<const ImageCodecTable*> imageCodec();

// A codec failure as a Status naming `where`.
Status statusOf(const CodecFailure& failure, const std::string& where);

}  // namespace bake
