// The image codec module (io/image_codec.h): OpenImageIO behind a table of plain functions, built as
// libbake_image_oiio.so and loaded by libbake only when a run touches an image.
//
// Two OIIO defaults would break exact round trips of data images (normal maps, masks) and are turned
// off: PNG alpha is kept unassociated (OIIO would premultiply on read and divide on write), and EXR
// compression is pinned so the bytes do not depend on OIIO's default. Nothing time-dependent is
// written (no DateTime, no Software), so equal images give equal files. Writers go through a proxy on
// the temporary's open descriptor, not its name (but for the few without proxy support), so a signal
// that removes the temporary while another thread writes cannot see it created again.
#include "io/image_codec.h"
#include "io/image_compare.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <limits>
#include <memory>
#include <vector>

namespace bake {
namespace {

OIIO::TypeDesc typeDescOf(PixelType type) {
  switch (type) {
    case PixelType::U8: return OIIO::TypeDesc::UINT8;
    case PixelType::U16: return OIIO::TypeDesc::UINT16;
    case PixelType::Half: return OIIO::TypeDesc::HALF;
    case PixelType::Float: return OIIO::TypeDesc::FLOAT;
  }
  return OIIO::TypeDesc::FLOAT;
}

// The nearest of our storage types for what a file holds: small integers as 8-bit, other 16-bit
// integers as 16-bit, half as half, anything wider as float.
PixelType pixelTypeOf(OIIO::TypeDesc format) {
  if (format.basetype == OIIO::TypeDesc::HALF) return PixelType::Half;
  if (format.basetype == OIIO::TypeDesc::UINT8 || format.basetype == OIIO::TypeDesc::INT8) return PixelType::U8;
  if (format.basetype == OIIO::TypeDesc::UINT16 || format.basetype == OIIO::TypeDesc::INT16) return PixelType::U16;
  return PixelType::Float;
}

// OIIO keeps its last error per thread (global) or per ImageInput/Output; reading it also clears it,
// so no stale message turns up on a later call.
std::string globalOiioError() {
  std::string message = OIIO::geterror();
  return message.empty() ? "unknown OpenImageIO error" : message;
}

template <class ImageIO>
std::string oiioErrorOf(ImageIO& io) {
  std::string message = io.geterror();
  return message.empty() ? globalOiioError() : message;
}

bool fail(CodecFailure* failure, CodecFailureKind kind, std::string message) {
  failure->kind = kind;
  failure->message = std::move(message);
  return false;
}

// An opened image and, when it reads from memory, the proxy it reads through.
struct Decoder {
  std::unique_ptr<OIIO::Filesystem::IOMemReader> memory;
  std::unique_ptr<OIIO::ImageInput> input;
};

OIIO::ImageSpec readConfig() {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);  // keep PNG colour as stored, not premultiplied
  return config;
}

void* openMemory(const std::uint8_t* bytes, std::size_t size, const char* extension, CodecFailure* failure) {
  // OIIO picks its reader by the name's extension, then reads through the proxy, not the file system.
  auto decoder = std::make_unique<Decoder>();
  decoder->memory = std::make_unique<OIIO::Filesystem::IOMemReader>(bytes, size);
  const std::string pseudoName = std::string("memory") + extension;
  decoder->input = OIIO::ImageInput::create(pseudoName);
  if (!decoder->input || !decoder->input->supports("ioproxy") ||
      !decoder->input->set_ioproxy(decoder->memory.get())) {
    (void)OIIO::geterror();  // a failed create leaves a message behind
    fail(failure, CodecFailureKind::NeedsFile, "the reader cannot read from memory");
    return nullptr;
  }
  OIIO::ImageSpec spec;
  if (!decoder->input->open(pseudoName, spec, readConfig())) {
    fail(failure, CodecFailureKind::Invalid, "cannot read the image: " + oiioErrorOf(*decoder->input));
    return nullptr;
  }
  return decoder.release();
}

void* openFile(const char* path, CodecFailure* failure) {
  auto decoder = std::make_unique<Decoder>();
  const OIIO::ImageSpec config = readConfig();
  decoder->input = OIIO::ImageInput::open(path, &config);
  if (!decoder->input) {
    fail(failure, CodecFailureKind::Invalid, "cannot read the image: " + globalOiioError());
    return nullptr;
  }
  return decoder.release();
}

void header(void* opaque, ImageHeader* header) {
  const OIIO::ImageSpec& spec = static_cast<Decoder*>(opaque)->input->spec();
  header->width = spec.width;
  header->height = spec.height;
  header->channels = spec.nchannels;
  header->depth = spec.depth;
  header->deep = spec.deep;
  header->storedType = pixelTypeOf(spec.format);
}

// 8- and 16-bit data is fetched as stored and divided here, so a value k reads as exactly k/255
// (k/65535) rounded once; OIIO's own conversion multiplies by the reciprocal, one ulp off for some k.
template <class Stored>
bool readNormalised(OIIO::ImageInput& in, float* pixels, std::size_t count, int channels, OIIO::TypeDesc type) {
  std::vector<Stored> stored(count);
  if (!in.read_image(0, 0, 0, channels, type, stored.data())) return false;
  const float scale = float(std::numeric_limits<Stored>::max());
  for (std::size_t i = 0; i < count; ++i) pixels[i] = float(stored[i]) / scale;
  return true;
}

bool readPixels(void* opaque, float* pixels, CodecFailure* failure) {
  OIIO::ImageInput& in = *static_cast<Decoder*>(opaque)->input;
  const OIIO::ImageSpec& spec = in.spec();
  const std::size_t count = std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels);
  const auto stored = OIIO::TypeDesc::BASETYPE(spec.format.basetype);
  bool ok = false;
  if (stored == OIIO::TypeDesc::UINT8) {
    ok = readNormalised<std::uint8_t>(in, pixels, count, spec.nchannels, OIIO::TypeDesc::UINT8);
  } else if (stored == OIIO::TypeDesc::UINT16) {
    ok = readNormalised<std::uint16_t>(in, pixels, count, spec.nchannels, OIIO::TypeDesc::UINT16);
  } else {
    ok = in.read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels);
  }
  if (!ok) return fail(failure, CodecFailureKind::Invalid, "cannot read the image: " + oiioErrorOf(in));
  return true;
}

void close(void* opaque) {
  std::unique_ptr<Decoder> decoder(static_cast<Decoder*>(opaque));
  if (decoder->input) decoder->input->close();
}

OIIO::ImageSpec outputSpec(const Image& image, PixelType type, const std::string& extension) {
  OIIO::ImageSpec spec(image.width, image.height, image.channels, typeDescOf(type));
  spec.attribute("oiio:UnassociatedAlpha", 1);  // write the given values, no alpha division
  if (extension == ".exr") {
    spec.attribute("compression", "zip");
    // OpenEXR's writer stamps the current time (capDate) unless the image has one: a fixed empty
    // stamp keeps equal images byte-identical.
    spec.attribute("DateTime", "");
  }
  return spec;
}

bool write(const char* name, std::FILE* file, const Image* image, PixelType type, const char* extension,
           CodecFailure* failure) {
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(name);
  if (!out) {
    return fail(failure, CodecFailureKind::Unsupported,
                std::string("no image writer for '") + extension + "': " + globalOiioError());
  }
  // The few writers without proxy support (SGI, ICO, HEIF in OIIO 2.4) write the same file by name.
  OIIO::Filesystem::IOFile proxy(file, OIIO::Filesystem::IOProxy::Write);
  if (out->supports("ioproxy") && !out->set_ioproxy(&proxy)) {
    return fail(failure, CodecFailureKind::Io, "cannot write the image: " + oiioErrorOf(*out));
  }
  if (!out->open(name, outputSpec(*image, type, extension))) {
    return fail(failure, CodecFailureKind::Io, "cannot write the image: " + oiioErrorOf(*out));
  }
  if (!out->write_image(OIIO::TypeDesc::FLOAT, image->pixels.data())) {
    const std::string message = oiioErrorOf(*out);
    out->close();
    return fail(failure, CodecFailureKind::Io, "cannot write the image: " + message);
  }
  if (!out->close()) return fail(failure, CodecFailureKind::Io, "cannot write the image: " + oiioErrorOf(*out));
  return true;
}

OIIO::ImageBuf toImageBuf(const Image& image) {
  OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf buffer(spec);
  buffer.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, image.pixels.data());
  return buffer;
}

bool compare(const Image* actual, const Image* expected, double threshold, ImageDifference* difference,
             CodecFailure* failure) {
  const OIIO::ImageBuf a = toImageBuf(*actual), b = toImageBuf(*expected);
  const OIIO::ImageBufAlgo::CompareResults result =
      OIIO::ImageBufAlgo::compare(a, b, float(threshold), float(threshold), OIIO::ROI::All(), 1);
  // OIIO 2.4 sets `error` whenever a pixel fails the threshold, so only its message tells a real error.
  if (const std::string message = OIIO::geterror(); !message.empty()) {
    return fail(failure, CodecFailureKind::Internal, "image comparison failed: " + message);
  }
  difference->rmse = result.rms_error;
  difference->maxError = result.maxerror;
  difference->worstX = result.maxx;
  difference->worstY = result.maxy;
  difference->threshold = threshold;
  const double pixels = double(actual->width) * double(actual->height);
  difference->percentOver = pixels > 0 ? 100.0 * double(result.nfail) / pixels : 0.0;
  return true;
}

constexpr ImageCodecTable kTable = {kImageCodecAbi, openMemory, openFile, header, readPixels, close, write, compare};

}  // namespace
}  // namespace bake

extern "C" __attribute__((visibility("default"))) const bake::ImageCodecTable* bake_image_codec(int abi) {
  return abi == bake::kImageCodecAbi ? &bake::kTable : nullptr;
}
