// A small parallel-for whose results never depend on the thread count: work is cut into blocks by
// the problem size alone (never by the number of threads), each block writes only its own outputs,
// and reductions combine block results in block order. Outputs are therefore byte-identical for
// --threads 1 and --threads N.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace bake {

// 0 means "all hardware threads".
unsigned resolveThreadCount(unsigned requested);

// Calls body(begin, end) for consecutive blocks of [0, count) of `blockSize` items each.
void parallelForBlocks(std::size_t count, std::size_t blockSize, unsigned threads,
                       const std::function<void(std::size_t begin, std::size_t end)>& body);

// Calls body(i) for every i in [0, count).
void parallelFor(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& body,
                 std::size_t blockSize = 256);

// Deterministic reduction: blockValue(begin, end) per fixed block, then combine in block order.
template <class T, class BlockFn, class CombineFn>
T parallelReduce(std::size_t count, std::size_t blockSize, unsigned threads, T identity,
                 BlockFn blockValue, CombineFn combine) {
  if (blockSize == 0) blockSize = 1;
  const std::size_t blocks = (count + blockSize - 1) / blockSize;
  std::vector<T> partial(blocks, identity);
  parallelForBlocks(blocks, 1, threads, [&](std::size_t b, std::size_t) {
    const std::size_t begin = b * blockSize;
    const std::size_t end = begin + blockSize < count ? begin + blockSize : count;
    partial[b] = blockValue(begin, end);
  });
  T total = identity;
  for (const T& value : partial) total = combine(total, value);
  return total;
}

}  // namespace bake
