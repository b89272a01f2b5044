#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/parallel.h"

namespace bake {
namespace {

TEST(Parallel, VisitsEveryIndexOnce) {
  for (unsigned threads : {1u, 2u, 7u}) {
    std::vector<int> hits(1000, 0);
    parallelFor(hits.size(), threads, [&](std::size_t i) { hits[i] += 1; }, 13);
    for (int h : hits) ASSERT_EQ(h, 1);
  }
}

TEST(Parallel, ReductionIsBitIdenticalForAnyThreadCount) {
  // A sum whose value depends on association order in floating point.
  auto term = [](std::size_t i) { return 1.0 / double(i + 1) * (i % 2 ? -1e8 : 1e-8); };
  auto run = [&](unsigned threads) {
    return parallelReduce(
        100000, 1024, threads, 0.0,
        [&](std::size_t b, std::size_t e) {
          double s = 0.0;
          for (std::size_t i = b; i < e; ++i) s += term(i);
          return s;
        },
        [](double a, double b) { return a + b; });
  };
  const double one = run(1);
  EXPECT_EQ(one, run(2));
  EXPECT_EQ(one, run(5));
  EXPECT_TRUE(std::isfinite(one));
}

TEST(Parallel, ExceptionsReachTheCaller) {
  EXPECT_THROW(parallelFor(100, 3, [](std::size_t i) { if (i == 57) throw std::runtime_error("x"); }),
               std::runtime_error);
}

}  // namespace
}  // namespace bake
