// Re-execution with glibc's huge-page tunable (huge_pages.h).
#include "bake/core/huge_pages.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#if defined(__SANITIZE_ADDRESS__)
#define BAKE_SANITIZED_ALLOCATOR 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define BAKE_SANITIZED_ALLOCATOR 1
#endif
#endif

namespace bake {
namespace {

constexpr const char* kTunables = "glibc.malloc.hugetlb=1";

std::string transparentHugePageMode() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

bool allocatorIsSanitized() {
#ifdef BAKE_SANITIZED_ALLOCATOR
  return true;
#else
  return false;
#endif
}

bool shouldReexecForHugePages(const char* glibcTunables, std::string_view executableName, std::string_view toolName,
                              std::string_view transparentHugePageMode) {
  if (allocatorIsSanitized() || glibcTunables != nullptr) return false;
  if (executableName != toolName) return false;
  // The mode file reads e.g. "always [madvise] never": the bracketed word is the one in force.
  const bool available = transparentHugePageMode.find("[always]") != std::string_view::npos ||
                         transparentHugePageMode.find("[madvise]") != std::string_view::npos;
  return available;
}

void reexecWithHugePages(char** argv, std::string_view toolName) {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return;
  if (!shouldReexecForHugePages(std::getenv("GLIBC_TUNABLES"), self.filename().string(), toolName,
                                transparentHugePageMode()))
    return;
  if (::setenv("GLIBC_TUNABLES", kTunables, 1) != 0) return;
  ::execv("/proc/self/exe", argv);
  ::unsetenv("GLIBC_TUNABLES");  // the exec failed: run as we are
}

bool inputWorthHugePages(std::string_view input) {
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(std::filesystem::path(input), error);
  return !error && bytes >= kHugePagesWorthInputBytes;
}

void reexecWithHugePagesForInput(char** argv, std::string_view toolName, std::string_view input) {
  if (inputWorthHugePages(input)) reexecWithHugePages(argv, toolName);
}

}  // namespace bake
