#include "core/temporaries.h"

#include <fcntl.h>
#include <limits.h>
#include <sys/stat.h>
#include <signal.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <random>
#include <cstring>
#include <mutex>

namespace bake {
namespace {

// A fixed table, because the signal handler may only read memory and call async-signal-safe
// functions (unlink, sigaction, raise): no allocation, no locks.
enum SlotState : int { kFree = 0, kFilling = 1, kLive = 2 };
struct Slot {
  std::atomic<int> state{kFree};
  char path[PATH_MAX];
};
Slot slots[kMaxRegisteredTemporaries];

constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGXFSZ};

constexpr char kNameLetters[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";

// Unpredictable name letters for temporaries (splitmix64 over a per-process random seed).
std::uint64_t nextRandom() {
  static const std::uint64_t seed = (std::uint64_t(std::random_device{}()) << 32) ^ std::random_device{}() ^
                                    (std::uint64_t(::getpid()) << 20);
  static std::atomic<std::uint64_t> counter{0};
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (counter.fetch_add(1, std::memory_order_relaxed) + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// A signal runs the handler on whichever thread the kernel picks, while the others go on: one may be
// creating a temporary at that very moment (after its name was checked, before the file exists), and
// would create it after the handler has unlinked everything. So creations announce themselves, the
// handler first closes the door (`dying`: no creation starts after it), waits for the creations in
// flight to finish (bounded: the creating thread may be the one the handler interrupted), and only
// then unlinks. Both flags are sequentially consistent: a creation sees `dying`, or the handler sees
// it in `creating`.
std::atomic<bool> dying{false};
std::atomic<int> creating{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "the signal handler may only use lock-free atomics");

extern "C" void removeTemporariesAndDie(int signal) {
  dying.store(true);
  for (int wait = 0; wait < 200 && creating.load() > 0; ++wait) {
    const timespec millisecond{0, 1000000};
    ::nanosleep(&millisecond, nullptr);
  }
  for (Slot& slot : slots) {
    if (slot.state.load(std::memory_order_acquire) == kLive) ::unlink(slot.path);
  }
  // Only now the default action, then the signal again, so the process ends as the signal says. The
  // handler stayed installed until here: a second signal (timeout(1) signals the process and then its
  // whole group) delivered to another thread meanwhile runs this handler too, instead of ending the
  // process before the files are gone.
  struct sigaction byDefault {};
  byDefault.sa_handler = SIG_DFL;
  sigemptyset(&byDefault.sa_mask);
  ::sigaction(signal, &byDefault, nullptr);
  ::raise(signal);
}

// Handlers go only where the default action is in force: a signal the caller chose to ignore
// (nohup's SIGHUP) or to handle stays as it was.
void installHandlers() {
  for (const int signal : kCleanupSignals) {
    struct sigaction current {};
    if (::sigaction(signal, nullptr, &current) != 0 || current.sa_handler != SIG_DFL) continue;
    struct sigaction action {};
    action.sa_handler = removeTemporariesAndDie;
    sigemptyset(&action.sa_mask);
    action.sa_flags = 0;
    ::sigaction(signal, &action, nullptr);
  }
}

void registerTemporary(const std::string& text) {
  if (text.size() >= PATH_MAX) return;
  for (Slot& slot : slots) {
    int expected = kFree;
    if (!slot.state.compare_exchange_strong(expected, kFilling, std::memory_order_acq_rel)) continue;
    std::memcpy(slot.path, text.c_str(), text.size() + 1);
    slot.state.store(kLive, std::memory_order_release);
    return;
  }
}

}  // namespace

int createRegisteredTemporary(std::string& pattern, int suffixLength) {
  static std::once_flag installed;
  std::call_once(installed, installHandlers);
  const std::size_t letters = pattern.size() - std::size_t(suffixLength) - 6;
  if (pattern.size() < std::size_t(suffixLength) + 6 || pattern.compare(letters, 6, "XXXXXX") != 0) {
    errno = EINVAL;
    return -1;
  }
  // The name is registered before the file exists: a signal delivered to any thread at any moment
  // then finds it (unlinking a name not yet created is harmless). A name already taken is skipped
  // before it is registered, so that the handler never removes someone else's file.
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::uint64_t bits = nextRandom();
    for (std::size_t i = 0; i < 6; ++i, bits /= 62) pattern[letters + i] = kNameLetters[bits % 62];
    struct stat existing {};
    if (::lstat(pattern.c_str(), &existing) == 0) continue;
    creating.fetch_add(1);
    if (dying.load()) {  // a signal is removing the temporaries: create nothing more, wait for the end
      creating.fetch_sub(1);
      for (;;) ::pause();
    }
    registerTemporary(pattern);
    const int fd = ::open(pattern.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    creating.fetch_sub(1);
    if (fd >= 0) return fd;
    const int err = errno;
    unregisterTemporary(pattern);
    if (err != EEXIST) {
      errno = err;
      return -1;
    }
  }
  errno = EEXIST;
  return -1;
}

void unregisterTemporary(const std::filesystem::path& path) {
  for (Slot& slot : slots) {
    int expected = kLive;
    if (slot.state.load(std::memory_order_acquire) != kLive || path.native() != slot.path) continue;
    if (slot.state.compare_exchange_strong(expected, kFilling, std::memory_order_acq_rel)) {
      slot.path[0] = '\0';
      slot.state.store(kFree, std::memory_order_release);
      return;
    }
  }
}

}  // namespace bake
