#include "bake/core/atomic_file.h"

#include "bake/core/limits.h"
#include "core/output_plan.h"
#include "core/temporaries.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace bake {
namespace fs = std::filesystem;

namespace {

std::string systemMessage(int err) { return std::strerror(err); }

void removeTemporary(const fs::path& temporary) {
  ::unlink(temporary.c_str());
  unregisterTemporary(temporary);
}

// Writes `bytes` to a fresh temporary file in the target's directory; returns its path.
Result<fs::path> writeTemporary(const fs::path& target, std::span<const std::uint8_t> bytes) {
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (target.empty()) return usageError("an output file name is empty");
  // Never rename over a device node, a FIFO or a folder (core/output_plan.h).
  BAKE_RETURN_IF_ERROR(checkReplaceable(target));
  std::string pattern = temporaryPatternFor(target);
  const int fd = createRegisteredTemporary(pattern);
  if (fd < 0) {
    return ioError("cannot create a file in " + dir.string() + ": " + systemMessage(errno),
                   {target.string(), ""});
  }
  const fs::path temporary = pattern;
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      removeTemporary(temporary);
      return ioError("write failed: " + systemMessage(err), {target.string(), ""});
    }
    written += std::size_t(n);
  }
  // Files are created 0600 by mkstemp; give them the usual permissions (subject to umask).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    const int err = errno;
    removeTemporary(temporary);
    return ioError("write failed: " + systemMessage(err), {target.string(), ""});
  }
  return temporary;
}

Status renameInto(const fs::path& temporary, const fs::path& target) {
  if (::rename(temporary.c_str(), target.c_str()) != 0) {
    const int err = errno;
    removeTemporary(temporary);
    return ioError("cannot replace the file: " + systemMessage(err), {target.string(), ""});
  }
  unregisterTemporary(temporary);
  return {};
}

std::span<const std::uint8_t> asBytes(const std::string& text) {
  return {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()};
}

}  // namespace

Status writeFileAtomic(const fs::path& target, std::span<const std::uint8_t> bytes) {
  BAKE_ASSIGN_OR_RETURN(const fs::path temporary, writeTemporary(target, bytes));
  return renameInto(temporary, target);
}

Status checkWritable(const fs::path& target) {
  BAKE_ASSIGN_OR_RETURN(const fs::path temporary, writeTemporary(target, {}));
  removeTemporary(temporary);
  return {};
}

Status writeFileAtomic(const fs::path& target, const std::string& text) {
  return writeFileAtomic(target, asBytes(text));
}

OutputSet::~OutputSet() { discard(); }

Status OutputSet::stage(const fs::path& target, std::span<const std::uint8_t> bytes) {
  BAKE_ASSIGN_OR_RETURN(fs::path temporary, writeTemporary(target, bytes));
  targets_.push_back(target);
  temporaries_.push_back(std::move(temporary));
  return {};
}

Status OutputSet::stage(const fs::path& target, const std::string& text) {
  return stage(target, asBytes(text));
}

Status OutputSet::commit() {
  for (std::size_t i = 0; i < targets_.size(); ++i) {
    Status status = renameInto(temporaries_[i], targets_[i]);
    if (!status.isOk()) {
      temporaries_.erase(temporaries_.begin(), temporaries_.begin() + std::ptrdiff_t(i + 1));
      discard();
      return status;
    }
  }
  temporaries_.clear();
  return {};
}

void OutputSet::discard() {
  for (const fs::path& temporary : temporaries_) removeTemporary(temporary);
  temporaries_.clear();
}

}  // namespace bake
