#include "core/hash.h"

#include <sys/stat.h>
#include <xxhash.h>

#include <cstdio>
#include <fstream>
#include <memory>
#include <vector>

#include "bake/core/input_file.h"

namespace bake {

namespace {
std::string formatHash(XXH128_hash_t h) {
  char text[64];
  std::snprintf(text, sizeof text, "xxh3-128:%016llx%016llx", static_cast<unsigned long long>(h.high64),
                static_cast<unsigned long long>(h.low64));
  return text;
}
}  // namespace

std::string hashBytes(std::span<const std::uint8_t> bytes) {
  return formatHash(XXH3_128bits(bytes.data(), bytes.size()));
}

Result<std::string> hashFile(const std::filesystem::path& path) {
  // An input read through readFileBytes is never opened again (a pipe cannot be read twice).
  if (std::optional<std::string> known = hashOfReadInput(path)) return *known;
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode)) {
    return ioError("not a regular file, and not read by this run: no content hash", {path.string(), ""});
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return ioError("cannot open for hashing", {path.string(), ""});
  std::unique_ptr<XXH3_state_t, decltype(&XXH3_freeState)> state(XXH3_createState(), &XXH3_freeState);
  XXH3_128bits_reset(state.get());
  std::vector<char> buffer(1 << 20);
  while (in) {
    in.read(buffer.data(), std::streamsize(buffer.size()));
    XXH3_128bits_update(state.get(), buffer.data(), std::size_t(in.gcount()));
  }
  if (in.bad()) return ioError("read failed while hashing", {path.string(), ""});
  return formatHash(XXH3_128bits_digest(state.get()));
}

}  // namespace bake
