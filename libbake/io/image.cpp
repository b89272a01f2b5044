// Image input and output (io/image.h). The decoding and encoding are OpenImageIO's, in the codec
// module loaded on first use (io/image_codec.h, io/oiio/codec.cpp); what must hold whatever the codec
// lives here: inputs are read once and bounded, the header's size is checked against the budgets
// before any pixel is allocated, and writes stay atomic. The codec writes a temporary file beside the
// target (with the same extension, since OIIO chooses its writer by name), which is flushed and
// renamed over the target only when complete. Images embedded in packages are read from memory where
// the format's reader takes it, else through a private temporary file, with the same conversions.
#include "bake/io/image.h"

#include "bake/core/atomic_file.h"
#include "bake/core/limits.h"
#include "core/output_plan.h"
#include "core/path.h"
#include "core/private_copy.h"
#include "core/temporaries.h"
#include "io/image_codec.h"

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

// The decoder `opened` holds, closed whatever happens.
class OpenedImage {
 public:
  OpenedImage(const ImageCodecTable& codec, void* decoder) : codec_(codec), decoder_(decoder) {}
  ~OpenedImage() { codec_.close(decoder_); }
  OpenedImage(const OpenedImage&) = delete;
  OpenedImage& operator=(const OpenedImage&) = delete;

  ImageHeader header() const {
    ImageHeader header;
    codec_.header(decoder_, &header);
    return header;
  }
  Status readPixels(Image& image, const std::string& name) {
    CodecFailure failure;
    if (!codec_.readPixels(decoder_, image.pixels.data(), &failure)) return statusOf(failure, name);
    return {};
  }

 private:
  const ImageCodecTable& codec_;
  void* decoder_;
};

// Reads the opened image; `name` is the file (or the embedded image) errors name.
Result<Image> readOpened(OpenedImage& opened, const std::string& name) {
  const ImageHeader header = opened.header();
  if (header.deep) return unsupported("deep images are not supported", {name, ""});
  if (header.depth > 1) return unsupported("volume images are not supported", {name, ""});
  if (header.width <= 0 || header.height <= 0 || header.channels <= 0) {
    return invalidInput("the image has no pixels", {name, ""});
  }

  // Before any pixel is allocated: the header alone can claim billions of texels.
  BAKE_RETURN_IF_ERROR(checkBudget(Budget::TextureSide, std::uint64_t(std::max(header.width, header.height)),
                                   "texels on the longer side (" + std::to_string(header.width) + "x" +
                                       std::to_string(header.height) + ")",
                                   {name, ""}));
  const std::uint64_t decoded = std::uint64_t(header.width) * std::uint64_t(header.height) *
                                std::uint64_t(header.channels) * sizeof(float);
  BAKE_RETURN_IF_ERROR(checkBudget(Budget::DecodedBytes, decoded,
                                   "bytes of decoded pixels (" + std::to_string(header.width) + "x" +
                                       std::to_string(header.height) + ", " + std::to_string(header.channels) +
                                       " channels as floats)",
                                   {name, ""}));
  Image image;
  image.width = header.width;
  image.height = header.height;
  image.channels = header.channels;
  image.sourceType = header.storedType;
  try {
    image.pixels.resize(std::size_t(header.width) * std::size_t(header.height) * std::size_t(header.channels));
  } catch (const std::bad_alloc&) {
    return unsupported("the image is too large to hold in memory (" + std::to_string(header.width) + "x" +
                           std::to_string(header.height) + ")",
                       {name, ""});
  }
  BAKE_RETURN_IF_ERROR(opened.readPixels(image, name));
  return image;
}

// Reading a file by its name: only for the private temporaries below, never for an input (inputs are
// read once, bounded, by readFileBytes).
Result<Image> readImageByName(const ImageCodecTable& codec, const fs::path& path) {
  BAKE_RETURN_IF_ERROR(checkReadable(path));
  CodecFailure failure;
  void* decoder = codec.openFile(path.c_str(), &failure);
  if (!decoder) return statusOf(failure, path.string());
  OpenedImage opened(codec, decoder);
  return readOpened(opened, path.string());
}

// For readers that cannot read from memory (OIIO 2.4's PNG reader): the bytes go through a private
// temporary file, removed again whatever happens.
Result<Image> readThroughFile(const ImageCodecTable& codec, std::span<const std::uint8_t> bytes,
                              const std::string& name, const std::string& extension) {
  PrivateCopy copy;
  BAKE_RETURN_IF_ERROR(copy.write(bytes, "image", extension, name));
  Result<Image> image = readImageByName(codec, copy.path());
  if (!image.isOk()) return Status(image.status().code(), image.status().message(), {name, ""});
  return image;
}

}  // namespace

Result<Image> readImageFromMemory(std::span<const std::uint8_t> bytes, const std::string& name,
                                  const std::string& extension) {
  if (bytes.empty()) return invalidInput("the image holds no bytes", {name, ""});
  BAKE_ASSIGN_OR_RETURN(const ImageCodecTable* codec, imageCodec());
  CodecFailure failure;
  void* decoder = codec->openMemory(bytes.data(), bytes.size(), extension.c_str(), &failure);
  if (!decoder && failure.kind == CodecFailureKind::NeedsFile) return readThroughFile(*codec, bytes, name, extension);
  if (!decoder) return statusOf(failure, name);
  OpenedImage opened(*codec, decoder);
  return readOpened(opened, name);
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

  BAKE_ASSIGN_OR_RETURN(const ImageCodecTable* codec, imageCodec());

  TemporaryFile temporary;
  BAKE_RETURN_IF_ERROR(temporary.create(path, path.extension().string()));
  CodecFailure failure;
  if (!codec->write(temporary.path().c_str(), temporary.file(), &image, type, extension.c_str(), &failure)) {
    return statusOf(failure, path.string());
  }
  BAKE_RETURN_IF_ERROR(temporary.finish(path));
  return temporary.renameOver(path);
}

}  // namespace bake
