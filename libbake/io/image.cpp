// Image input and output through OpenImageIO (io/image.h). Reading converts whatever OIIO can read to
// interleaved floats (8/16-bit values k become exactly k/255, k/65535); writing picks the format from the
// extension and stays atomic: OIIO writes a temporary file beside the target (with the same extension, since
// OIIO chooses its writer by name), which is flushed and renamed over the target only when complete. OIIO
// writes through a proxy on the temporary's open descriptor, not by its name (but for the few writers
// without proxy support): a signal that removes the temporary (core/temporaries.h) while another thread
// writes cannot see it created again.
//
// Two OIIO defaults would break exact round trips of data images (normal maps, masks) and are turned
// off: PNG alpha is kept unassociated (OIIO would premultiply on read and divide on write), and EXR
// compression is pinned so the bytes do not depend on OIIO's default. Nothing time-dependent is
// written (no DateTime, no Software), so equal images give equal files. Images embedded in packages are
// read from memory through OIIO's IOMemReader proxy where the format's reader takes one, else through a
// private temporary file, with the same conversions.
#include "io/image.h"

#include "core/atomic_file.h"
#include "core/limits.h"
#include "core/output_plan.h"
#include "core/path.h"
#include "core/private_copy.h"
#include "core/temporaries.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <system_error>

namespace bake {
namespace fs = std::filesystem;

namespace {

const char* pixelTypeName(PixelType type) {
  switch (type) {
    case PixelType::U8: return "8-bit";
    case PixelType::U16: return "16-bit";
    case PixelType::Half: return "half-float";
    case PixelType::Float: return "float";
  }
  return "unknown";
}

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
  if (format.basetype == OIIO::TypeDesc::UINT8 || format.basetype == OIIO::TypeDesc::INT8) {
    return PixelType::U8;
  }
  if (format.basetype == OIIO::TypeDesc::UINT16 || format.basetype == OIIO::TypeDesc::INT16) {
    return PixelType::U16;
  }
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

Status checkReadable(const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) return ioError("cannot open: no such file", {path.string(), ""});
  if (fs::is_directory(status)) return ioError("is a directory, not a file", {path.string(), ""});
  if (::access(path.c_str(), R_OK) != 0) {
    return ioError(std::string("cannot open: ") + std::strerror(errno), {path.string(), ""});
  }
  return {};
}

Status checkImageShape(const Image& image, const fs::path& path) {
  if (image.width <= 0 || image.height <= 0 || image.channels <= 0) {
    return internalError("image has no pixels (" + std::to_string(image.width) + "x" +
                             std::to_string(image.height) + ", " + std::to_string(image.channels) +
                             " channels)",
                         {path.string(), ""});
  }
  const std::size_t expected =
      std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels);
  if (image.pixels.size() != expected) {
    return internalError("image holds " + std::to_string(image.pixels.size()) + " values, its size needs " +
                             std::to_string(expected),
                         {path.string(), ""});
  }
  return {};
}

Status checkFormatAllows(const std::string& extension, PixelType type, int channels, const fs::path& path) {
  if (extension.empty()) {
    return unsupported("no file extension to choose the image format by", {path.string(), ""});
  }
  if (extension == ".png") {
    if (type != PixelType::U8 && type != PixelType::U16) {
      return unsupported(std::string("PNG stores 8- or 16-bit integers, not ") + pixelTypeName(type),
                         {path.string(), ""});
    }
    if (channels > 4) {
      return unsupported("PNG holds 1 to 4 channels, not " + std::to_string(channels), {path.string(), ""});
    }
  }
  if (extension == ".exr" && type != PixelType::Half && type != PixelType::Float) {
    return unsupported(std::string("EXR stores half or float pixels here, not ") + pixelTypeName(type),
                       {path.string(), ""});
  }
  return {};
}

// A fresh file beside `target` whose name ends with the target's extension; removed again unless
// released.
class TemporaryFile {
 public:
  ~TemporaryFile() {
    if (file_) std::fclose(file_);
    if (path_.empty()) return;
    ::unlink(path_.c_str());
    unregisterTemporary(path_);
  }

  Status create(const fs::path& target, const std::string& extension) {
    const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    std::string pattern = temporaryPatternFor(target.parent_path() / target.stem(), extension);
    const int fd = createRegisteredTemporary(pattern, int(extension.size()));
    if (fd < 0) {
      return ioError("cannot create a file in " + dir.string() + ": " + std::strerror(errno),
                     {target.string(), ""});
    }
    path_ = pattern;
    file_ = ::fdopen(fd, "w+b");
    if (!file_) {
      const int err = errno;
      ::close(fd);
      return ioError(std::string("cannot open the temporary image file: ") + std::strerror(err), {target.string(), ""});
    }
    return {};
  }

  // Flushed to disk and closed; mkstemps makes the file private, so it gets the permissions a plain
  // new file would get.
  Status finish(const fs::path& target) {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    const int fd = ::fileno(file_);
    const bool ok = std::fflush(file_) == 0 && ::fchmod(fd, 0666 & ~mask) == 0 && ::fsync(fd) == 0;
    const int err = errno;
    const bool closed = std::fclose(file_) == 0;
    file_ = nullptr;
    if (!ok || !closed) {
      return ioError(std::string("cannot flush the written image: ") + std::strerror(ok ? errno : err),
                     {target.string(), ""});
    }
    return {};
  }

  FILE* file() const { return file_; }

  Status renameOver(const fs::path& target) {
    std::error_code ec;
    fs::rename(path_, target, ec);
    if (ec) return ioError("cannot replace the file: " + ec.message(), {target.string(), ""});
    unregisterTemporary(path_);
    path_.clear();
    return {};
  }

  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
  FILE* file_ = nullptr;
};

OIIO::ImageSpec outputSpec(const Image& image, PixelType type, const std::string& extension) {
  OIIO::ImageSpec spec(image.width, image.height, image.channels, typeDescOf(type));
  spec.attribute("oiio:UnassociatedAlpha", 1);  // write the given values, no alpha division
  if (extension == ".exr") spec.attribute("compression", "zip");
  return spec;
}

// Writes the image into `file` (FILE* on the temporary's descriptor; the name picks the writer).
Status writeWithOiio(const fs::path& name, FILE* file, const Image& image, PixelType type, const std::string& extension,
                     const fs::path& target) {
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(name.string());
  if (!out) {
    return unsupported("no image writer for '" + extension + "': " + globalOiioError(),
                       {target.string(), ""});
  }
  // The few writers without proxy support (SGI, ICO, HEIF in OIIO 2.4) write the same file by name.
  OIIO::Filesystem::IOFile proxy(file, OIIO::Filesystem::IOProxy::Write);
  if (out->supports("ioproxy") && !out->set_ioproxy(&proxy)) {
    return ioError("cannot write the image: " + oiioErrorOf(*out), {target.string(), ""});
  }
  const OIIO::ImageSpec spec = outputSpec(image, type, extension);
  if (!out->open(name.string(), spec)) {
    return ioError("cannot write the image: " + oiioErrorOf(*out), {target.string(), ""});
  }
  if (!out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data())) {
    const std::string message = oiioErrorOf(*out);
    out->close();
    return ioError("cannot write the image: " + message, {target.string(), ""});
  }
  if (!out->close()) return ioError("cannot write the image: " + oiioErrorOf(*out), {target.string(), ""});
  return {};
}

// 8- and 16-bit data is fetched as stored and divided here, so a value k reads as exactly k/255
// (k/65535) rounded once; OIIO's own conversion multiplies by the reciprocal, one ulp off for some k.
template <class Stored>
bool readNormalised(OIIO::ImageInput& in, Image& image, OIIO::TypeDesc type) {
  std::vector<Stored> stored(image.pixels.size());
  if (!in.read_image(0, 0, 0, image.channels, type, stored.data())) return false;
  const float scale = float(std::numeric_limits<Stored>::max());
  for (std::size_t i = 0; i < stored.size(); ++i) image.pixels[i] = float(stored[i]) / scale;
  return true;
}

Status readPixels(OIIO::ImageInput& in, Image& image, const fs::path& path) {
  const OIIO::TypeDesc::BASETYPE stored = OIIO::TypeDesc::BASETYPE(in.spec().format.basetype);
  bool ok = false;
  if (stored == OIIO::TypeDesc::UINT8) {
    ok = readNormalised<std::uint8_t>(in, image, OIIO::TypeDesc::UINT8);
  } else if (stored == OIIO::TypeDesc::UINT16) {
    ok = readNormalised<std::uint16_t>(in, image, OIIO::TypeDesc::UINT16);
  } else {
    ok = in.read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, image.pixels.data());
  }
  if (!ok) return invalidInput("cannot read the image: " + oiioErrorOf(in), {path.string(), ""});
  return {};
}

// Reads the opened image; `name` is the file (or the embedded image) errors name.
Result<Image> readOpened(std::unique_ptr<OIIO::ImageInput> in, const fs::path& name) {
  if (!in) return invalidInput("cannot read the image: " + globalOiioError(), {name.string(), ""});
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.deep) return unsupported("deep images are not supported", {name.string(), ""});
  if (spec.depth > 1) return unsupported("volume images are not supported", {name.string(), ""});
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
    return invalidInput("the image has no pixels", {name.string(), ""});
  }

  // Before any pixel is allocated: the header alone can claim billions of texels.
  BAKE_RETURN_IF_ERROR(checkBudget(Budget::TextureSide, std::uint64_t(std::max(spec.width, spec.height)),
                                   "texels on the longer side (" + std::to_string(spec.width) + "x" +
                                       std::to_string(spec.height) + ")",
                                   {name.string(), ""}));
  const std::uint64_t decoded = std::uint64_t(spec.width) * std::uint64_t(spec.height) *
                                std::uint64_t(spec.nchannels) * sizeof(float);
  BAKE_RETURN_IF_ERROR(checkBudget(Budget::DecodedBytes, decoded,
                                   "bytes of decoded pixels (" + std::to_string(spec.width) + "x" +
                                       std::to_string(spec.height) + ", " + std::to_string(spec.nchannels) +
                                       " channels as floats)",
                                   {name.string(), ""}));
  Image image;
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.nchannels;
  image.sourceType = pixelTypeOf(spec.format);
  try {
    image.pixels.resize(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
  } catch (const std::bad_alloc&) {
    return unsupported("the image is too large to hold in memory (" + std::to_string(spec.width) + "x" +
                           std::to_string(spec.height) + ")",
                       {name.string(), ""});
  }
  BAKE_RETURN_IF_ERROR(readPixels(*in, image, name));
  in->close();
  return image;
}

OIIO::ImageSpec readConfig() {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);  // keep PNG colour as stored, not premultiplied
  return config;
}

// OIIO reading a file by its name: only for the private temporaries below, never for an input
// (inputs are read once, bounded, by readFileBytes).
Result<Image> readImageByName(const fs::path& path) {
  BAKE_RETURN_IF_ERROR(checkReadable(path));
  const OIIO::ImageSpec config = readConfig();
  return readOpened(OIIO::ImageInput::open(path.string(), &config), path);
}

// For readers without proxy support (OIIO 2.4's PNG reader): the bytes go through a private
// temporary file, removed again whatever happens.
Result<Image> readThroughFile(std::span<const std::uint8_t> bytes, const std::string& name,
                              const std::string& extension) {
  PrivateCopy copy;
  BAKE_RETURN_IF_ERROR(copy.write(bytes, "image", extension, name));
  Result<Image> image = readImageByName(copy.path());
  if (!image.isOk()) return Status(image.status().code(), image.status().message(), {name, ""});
  return image;
}

}  // namespace

Result<Image> readImageFromMemory(std::span<const std::uint8_t> bytes, const std::string& name,
                                  const std::string& extension) {
  if (bytes.empty()) return invalidInput("the image holds no bytes", {name, ""});
  // OIIO picks its reader by the name's extension, then reads through the proxy, not the file system.
  OIIO::Filesystem::IOMemReader reader(bytes.data(), bytes.size());
  const std::string pseudoName = "memory" + extension;
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::create(pseudoName);
  if (!in || !in->supports("ioproxy") || !in->set_ioproxy(&reader)) {
    (void)OIIO::geterror();  // a failed create leaves a message behind
    return readThroughFile(bytes, name, extension);
  }
  OIIO::ImageSpec spec;
  if (!in->open(pseudoName, spec, readConfig())) {
    return invalidInput("cannot read the image: " + oiioErrorOf(*in), {name, ""});
  }
  return readOpened(std::move(in), name);
}

Result<Image> readImage(const fs::path& path) {
  BAKE_ASSIGN_OR_RETURN(const std::vector<std::uint8_t> bytes, readFileBytes(path));
  return readImageFromMemory(bytes, path.string(), lowercaseExtension(path));
}

Status writeImage(const fs::path& path, const Image& image, PixelType type) {
  BAKE_RETURN_IF_ERROR(checkImageShape(image, path));
  const std::string extension = lowercaseExtension(path);
  BAKE_RETURN_IF_ERROR(checkFormatAllows(extension, type, image.channels, path));
  BAKE_RETURN_IF_ERROR(checkReplaceable(path));

  TemporaryFile temporary;
  BAKE_RETURN_IF_ERROR(temporary.create(path, path.extension().string()));
  BAKE_RETURN_IF_ERROR(writeWithOiio(temporary.path(), temporary.file(), image, type, extension, path));
  BAKE_RETURN_IF_ERROR(temporary.finish(path));
  return temporary.renameOver(path);
}

}  // namespace bake
