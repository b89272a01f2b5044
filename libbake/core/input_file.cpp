#include "bake/core/input_file.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>

#include "bake/core/atomic_file.h"
#include "bake/core/limits.h"
#include "core/hash.h"

namespace bake {
namespace fs = std::filesystem;

namespace {

struct ReadInputs {
  std::mutex mutex;
  std::map<std::string, ReadInput> read;  // absolute, normal path -> size and content hash
  // The bytes of every pipe read: a pipe cannot be read twice, and a tool may read an input twice
  // (once to list the files of the run, once to bake).
  std::map<std::string, std::shared_ptr<const std::vector<std::uint8_t>>> pipes;
  bool outsideUris = false;
};

ReadInputs& readInputs() {
  static ReadInputs state;
  return state;
}

std::string keyOf(const fs::path& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  return (ec ? path : absolute).lexically_normal().string();
}

const char* kindName(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

Status refusedKind(mode_t mode, const fs::path& path) {
  if (S_ISDIR(mode)) return ioError("is a directory, not a file", {path.string(), ""});
  return ioError(std::string("is ") + kindName(mode) + ", not a regular file; inputs are files or pipes",
                 {path.string(), ""});
}

bool readableKind(mode_t mode) { return S_ISREG(mode) || S_ISFIFO(mode); }

class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

// Waits until a pipe has data or its writer is gone; false after kPipeIdleSeconds of silence.
bool waitForPipe(int fd) {
  pollfd watched{fd, POLLIN, 0};
  for (;;) {
    const int ready = ::poll(&watched, 1, kPipeIdleSeconds * 1000);
    if (ready > 0) return true;
    if (ready == 0) return false;
    if (errno != EINTR) return true;  // let read() report the error
  }
}

// Reads to the end of the file, never more than the input-bytes budget (plus one byte, to know it
// was exceeded).
Result<std::vector<std::uint8_t>> readToEnd(int fd, bool pipe, std::uint64_t expected, const fs::path& path) {
  const std::uint64_t limit = budgets()[Budget::InputBytes];
  const std::uint64_t cap = limit + 1;
  // A FIFO opened without blocking reads as empty until a writer comes: wait for one (or its data).
  if (pipe && !waitForPipe(fd)) {
    return ioError("no writer sent data within " + std::to_string(kPipeIdleSeconds) + " s", {path.string(), ""});
  }
  std::vector<std::uint8_t> bytes(std::size_t(std::min<std::uint64_t>(std::max<std::uint64_t>(expected + 1, 65536), cap)));
  std::size_t filled = 0;
  for (;;) {
    if (filled == bytes.size()) {
      if (bytes.size() >= cap) {
        return checkBudget(Budget::InputBytes, cap, "bytes (at least)", {path.string(), ""});
      }
      bytes.resize(std::size_t(std::min<std::uint64_t>(std::uint64_t(bytes.size()) * 2, cap)));
    }
    const std::size_t room = bytes.size() - filled;
    const ssize_t n = ::read(fd, bytes.data() + filled, room);
    if (n > 0) {
      filled += std::size_t(n);
      continue;
    }
    if (n == 0) break;
    if (errno == EINTR) continue;
    if (pipe && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      if (!waitForPipe(fd)) {
        return ioError("no data arrived for " + std::to_string(kPipeIdleSeconds) + " s", {path.string(), ""});
      }
      continue;
    }
    return ioError(std::string("read failed: ") + std::strerror(errno), {path.string(), ""});
  }
  bytes.resize(filled);
  bytes.shrink_to_fit();
  return bytes;
}

}  // namespace

Result<std::vector<std::uint8_t>> readFileBytes(const fs::path& path) {
  if (path.empty()) return usageError("an input file name is empty");
  {
    ReadInputs& state = readInputs();
    std::lock_guard<std::mutex> lock(state.mutex);
    if (const auto pipe = state.pipes.find(keyOf(path)); pipe != state.pipes.end()) return *pipe->second;
  }
  // O_NONBLOCK: opening a FIFO must not wait for a writer; cleared again for regular files.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
  if (fd < 0) {
    const int err = errno;
    if (err == ENOENT) return ioError("cannot open: no such file", {path.string(), ""});
    return ioError(std::string("cannot open: ") + std::strerror(err), {path.string(), ""});
  }
  Descriptor file(fd);
  struct stat info {};
  if (::fstat(fd, &info) != 0) return ioError(std::string("cannot open: ") + std::strerror(errno), {path.string(), ""});
  if (!readableKind(info.st_mode)) return refusedKind(info.st_mode, path);
  const bool pipe = S_ISFIFO(info.st_mode);
  std::uint64_t expected = 0;
  if (!pipe) {
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    expected = std::uint64_t(info.st_size);
    // Checked before reading: a file beyond the budget would only exhaust memory.
    BAKE_RETURN_IF_ERROR(checkBudget(Budget::InputBytes, expected, "bytes", {path.string(), ""}));
  }
  BAKE_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes, readToEnd(fd, pipe, expected, path));
  {
    ReadInputs& state = readInputs();
    std::lock_guard<std::mutex> lock(state.mutex);
    state.read[keyOf(path)] = {bytes.size(), hashBytes(bytes)};
    if (pipe) state.pipes[keyOf(path)] = std::make_shared<const std::vector<std::uint8_t>>(bytes);
  }
  return bytes;
}

std::optional<ReadInput> readInputRecord(const fs::path& path) {
  ReadInputs& state = readInputs();
  std::lock_guard<std::mutex> lock(state.mutex);
  const auto found = state.read.find(keyOf(path));
  if (found == state.read.end()) return std::nullopt;
  return found->second;
}

std::optional<std::string> hashOfReadInput(const fs::path& path) {
  std::optional<ReadInput> record = readInputRecord(path);
  if (!record) return std::nullopt;
  return record->hash;
}

Status checkInputKind(const fs::path& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return {};  // the reader names a missing file itself
  if (!readableKind(info.st_mode)) return refusedKind(info.st_mode, path);
  return {};
}

std::string_view withoutByteOrderMark(std::string_view text) {
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  if (text.substr(0, kBom.size()) == kBom) text.remove_prefix(kBom.size());
  return text;
}

bool outsideUrisAllowed() {
  ReadInputs& state = readInputs();
  std::lock_guard<std::mutex> lock(state.mutex);
  return state.outsideUris;
}

void setOutsideUrisAllowed(bool allowed) {
  ReadInputs& state = readInputs();
  std::lock_guard<std::mutex> lock(state.mutex);
  state.outsideUris = allowed;
}

}  // namespace bake
