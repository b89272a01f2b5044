// Loading the image codec module (io/image_codec.h) on first use. It is looked for beside the
// executable as installed (bin/ → lib/bake/), then where the build tree put it; the first that loads
// and offers this ABI wins. dlopen's own search (LD_LIBRARY_PATH, the system folders) is not used, so a
// stray copy elsewhere cannot stand in for the one built with this library.
#include "io/image_codec.h"

#include "io/image_codec_paths.h"  // generated: kImageCodecInstalled, kImageCodecBuilt

#include <dlfcn.h>

#include <filesystem>
#include <vector>

namespace bake {
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> candidatePaths() {
  std::vector<fs::path> paths;
  std::error_code ec;
  const fs::path executable = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) paths.push_back(executable.parent_path() / kImageCodecInstalled);
  paths.emplace_back(kImageCodecBuilt);
  return paths;
}

Result<const ImageCodecTable*> load() {
  std::string tried;
  for (const fs::path& path : candidatePaths()) {
    std::error_code ec;
    if (!fs::exists(path, ec)) {
      tried += "\n  " + path.string() + ": not there";
      continue;
    }
    // Never closed: the table and OIIO's state live as long as the process.
    void* module = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!module) {
      tried += "\n  " + path.string() + ": " + ::dlerror();
      continue;
    }
    using Entry = const ImageCodecTable* (*)(int);
    auto entry = reinterpret_cast<Entry>(::dlsym(module, kImageCodecSymbol));
    const ImageCodecTable* table = entry ? entry(kImageCodecAbi) : nullptr;
    if (table) return table;
    tried += "\n  " + path.string() + ": built for another version of the library";
  }
  return internalError(std::string("image support is not available: cannot load ") + kImageCodecFile + tried);
}

}  // namespace

Result<const ImageCodecTable*> imageCodec() {
  static const Result<const ImageCodecTable*> codec = load();  // a thread-safe one-time load
  return codec;
}

Status statusOf(const CodecFailure& failure, const std::string& where) {
  const Location location{where, ""};
  switch (failure.kind) {
    case CodecFailureKind::Unsupported: return unsupported(failure.message, location);
    case CodecFailureKind::Io: return ioError(failure.message, location);
    case CodecFailureKind::Invalid:
    case CodecFailureKind::NeedsFile: return invalidInput(failure.message, location);
    case CodecFailureKind::Internal:
    case CodecFailureKind::None: break;
  }
  return internalError(failure.message.empty() ? "image codec failed" : failure.message, location);
}

}  // namespace bake
