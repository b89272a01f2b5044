// Persistent workers for the construction's per-stroke candidate scoring (build_stages.h, StepPool).
// Items are claimed through one atomic ticket holding the step's generation and the next item, so a
// worker that wakes late for a finished step can never claim an item of the next one with the old
// body: a new step first closes the ticket (so no claim of the old step can succeed), then sets the
// body and the count, then opens the ticket at item 0, all under the mutex workers read the
// generation under. The caller claims items too and then waits (yielding) only for the items workers hold.
#include "hatching/bake/build_stages.h"

namespace bake::hatching::detail {

StepPool::StepPool(unsigned threads) {
  for (unsigned t = 1; t < threads; ++t) workers_.emplace_back([this] { work(); });
}

StepPool::~StepPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

bool StepPool::claimAndRun(std::uint32_t generation) {
  std::uint64_t ticket = ticket_.load();
  for (;;) {
    if (std::uint32_t(ticket >> 32) != generation || (ticket & 0xffffffffu) >= count_.load()) return false;
    if (ticket_.compare_exchange_weak(ticket, ticket + 1)) break;
  }
  try {
    (*body_.load())(std::size_t(ticket & 0xffffffffu));
  } catch (...) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!failure_) failure_ = std::current_exception();
  }
  ++done_;
  return true;
}

void StepPool::work() {
  std::uint32_t seen = 0;
  for (;;) {
    std::uint32_t generation = 0;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      generation = seen = generation_;
    }
    while (claimAndRun(generation)) {
    }
  }
}

void StepPool::run(std::size_t count, const std::function<void(std::size_t)>& body) {
  std::uint32_t generation = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    generation = ++generation_;
    ticket_ = (std::uint64_t(generation) << 32) | 0xffffffffu;  // closed
    body_ = &body;
    count_ = count;
    done_ = 0;
    failure_ = nullptr;
    ticket_ = std::uint64_t(generation) << 32;  // open at item 0
  }
  if (!workers_.empty()) wake_.notify_all();
  while (claimAndRun(generation)) {
  }
  while (done_.load() < count) std::this_thread::yield();
  std::lock_guard<std::mutex> lock(mutex_);
  body_ = nullptr;
  if (failure_) std::rethrow_exception(failure_);
}

}  // namespace bake::hatching::detail
