#include "core/parallel.h"

#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

namespace bake {

unsigned resolveThreadCount(unsigned requested) {
  if (requested > 0) return requested;
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware > 0 ? hardware : 1;
}

void parallelForBlocks(std::size_t count, std::size_t blockSize, unsigned threads,
                       const std::function<void(std::size_t, std::size_t)>& body) {
  if (count == 0) return;
  if (blockSize == 0) blockSize = 1;
  const std::size_t blocks = (count + blockSize - 1) / blockSize;
  const unsigned workers = unsigned(std::min<std::size_t>(resolveThreadCount(threads), blocks));
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failureMutex;

  auto work = [&] {
    for (std::size_t b = next++; b < blocks; b = next++) {
      try {
        const std::size_t begin = b * blockSize;
        body(begin, std::min(count, begin + blockSize));
      } catch (...) {
        std::lock_guard<std::mutex> lock(failureMutex);
        if (!failure) failure = std::current_exception();
        next = blocks;  // stop handing out work
      }
    }
  };

  std::vector<std::thread> pool;
  for (unsigned t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (std::thread& thread : pool) thread.join();
  if (failure) std::rethrow_exception(failure);
}

void parallelFor(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& body,
                 std::size_t blockSize) {
  parallelForBlocks(count, blockSize, threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) body(i);
  });
}

}  // namespace bake
