#include "core/temporaries.h"

#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
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

extern "C" void removeTemporariesAndDie(int signal) {
  for (Slot& slot : slots) {
    if (slot.state.load(std::memory_order_acquire) == kLive) ::unlink(slot.path);
  }
  // SA_RESETHAND restored the default action: re-raise so the process ends as the signal says.
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
    action.sa_flags = SA_RESETHAND;
    ::sigaction(signal, &action, nullptr);
  }
}

}  // namespace

void registerTemporary(const std::filesystem::path& path) {
  static std::once_flag installed;
  std::call_once(installed, installHandlers);
  const std::string& text = path.native();
  if (text.size() >= PATH_MAX) return;
  for (Slot& slot : slots) {
    int expected = kFree;
    if (!slot.state.compare_exchange_strong(expected, kFilling, std::memory_order_acq_rel)) continue;
    std::memcpy(slot.path, text.c_str(), text.size() + 1);
    slot.state.store(kLive, std::memory_order_release);
    return;
  }
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
