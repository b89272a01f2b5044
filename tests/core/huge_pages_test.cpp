// When a tool re-executes itself with glibc's huge-page tunable (core/huge_pages.h).
#include "bake/core/huge_pages.h"

#include <gtest/gtest.h>

namespace bake {
namespace {

constexpr const char* kMadvise = "always [madvise] never\n";

TEST(HugePages, ReexecutesOnlyTheToolItselfWithoutTunablesWhereTheKernelHasThem) {
  if (allocatorIsSanitized()) GTEST_SKIP() << "a sanitizer build never re-executes (its allocator is not glibc's)";
  EXPECT_TRUE(shouldReexecForHugePages(nullptr, "groovebake", "groovebake", kMadvise));
  EXPECT_TRUE(shouldReexecForHugePages(nullptr, "groovebake", "groovebake", "[always] madvise never\n"));
}

TEST(HugePages, TheUsersTunablesValgrindAndAKernelWithoutThemStand) {
  EXPECT_FALSE(shouldReexecForHugePages("", "groovebake", "groovebake", kMadvise));  // the opt-out
  EXPECT_FALSE(shouldReexecForHugePages("glibc.malloc.arena_max=1", "groovebake", "groovebake", kMadvise));
  EXPECT_FALSE(shouldReexecForHugePages(nullptr, "memcheck-amd64-linux", "groovebake", kMadvise));
  EXPECT_FALSE(shouldReexecForHugePages(nullptr, "groovebake", "groovebake", "always madvise [never]\n"));
  EXPECT_FALSE(shouldReexecForHugePages(nullptr, "groovebake", "groovebake", ""));  // no such file
}

}  // namespace
}  // namespace bake
