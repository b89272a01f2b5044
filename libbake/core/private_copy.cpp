#include "core/private_copy.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "core/temporaries.h"

namespace bake {

PrivateCopy::~PrivateCopy() {
  if (path_.empty()) return;
  ::unlink(path_.c_str());
  unregisterTemporary(path_);
}

Status PrivateCopy::write(std::span<const std::uint8_t> bytes, const std::string& stem, const std::string& suffix,
                          const std::string& name) {
  std::string pattern = (std::filesystem::temp_directory_path() / ("bake-" + stem + ".XXXXXX" + suffix)).string();
  const int fd = createRegisteredTemporary(pattern, int(suffix.size()));
  if (fd < 0) return ioError(std::string("cannot create a temporary file: ") + std::strerror(errno), {name, ""});
  path_ = pattern;
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n <= 0) break;
    written += std::size_t(n);
  }
  ::close(fd);
  if (written != bytes.size()) return ioError("cannot write a temporary file", {name, ""});
  return {};
}

}  // namespace bake
