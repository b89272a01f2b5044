// When a tool re-executes itself with glibc's huge-page tunable (core/huge_pages.h).
#include "bake/core/huge_pages.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

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

TEST(HugePages, OnlyAnInputOfAMebibyteOrMoreIsWorthASecondStart) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "huge_pages_input";
  std::filesystem::create_directories(dir);
  auto fileOf = [&](const char* name, std::uintmax_t bytes) {
    const std::filesystem::path path = dir / name;
    std::ofstream(path, std::ios::binary) << std::string(bytes, 'x');
    return path.string();
  };
  EXPECT_TRUE(inputWorthHugePages(fileOf("exactly.obj", kHugePagesWorthInputBytes)));
  EXPECT_FALSE(inputWorthHugePages(fileOf("one-short.obj", kHugePagesWorthInputBytes - 1)));
  EXPECT_FALSE(inputWorthHugePages((dir / "missing.obj").string()));
  EXPECT_FALSE(inputWorthHugePages(dir.string()));  // a folder has no file size
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace bake
