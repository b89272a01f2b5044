#include "support/golden.h"

#include <cstdlib>
#include <fstream>

namespace bake::test {
namespace fs = std::filesystem;

fs::path sourceDir() { return BAKE_SOURCE_DIR; }

fs::path goldenPath(const std::string& name) { return sourceDir() / "tests" / "golden" / name; }

bool updatingGoldens() {
  const char* value = std::getenv("BAKE_UPDATE_GOLDEN");
  return value && std::string(value) == "1";
}

std::vector<std::uint8_t> readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

::testing::AssertionResult matchesGolden(const std::string& name, std::span<const std::uint8_t> bytes) {
  const fs::path path = goldenPath(name);
  if (updatingGoldens()) {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                std::streamsize(bytes.size()));
    return ::testing::AssertionSuccess() << "updated " << path;
  }
  if (!fs::exists(path)) {
    return ::testing::AssertionFailure() << "missing golden " << path
                                         << " (run with BAKE_UPDATE_GOLDEN=1 to create it)";
  }
  const std::vector<std::uint8_t> expected = readAll(path);
  if (expected.size() != bytes.size()) {
    return ::testing::AssertionFailure() << "golden " << name << ": size " << bytes.size()
                                         << " != expected " << expected.size();
  }
  for (std::size_t i = 0; i < expected.size(); ++i) {
    if (expected[i] != bytes[i]) {
      return ::testing::AssertionFailure() << "golden " << name << ": first difference at byte " << i;
    }
  }
  return ::testing::AssertionSuccess();
}

::testing::AssertionResult matchesGolden(const std::string& name, const std::string& text) {
  return matchesGolden(name, std::span<const std::uint8_t>(
                                 reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

// CTest runs every test in its own process, in parallel: the folder carries the running test's full
// name so two tests asking for the same name never remove each other's files.
static std::string runningTestTag() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  if (!info) return "no-test";
  std::string tag = std::string(info->test_suite_name()) + "." + info->name();
  for (char& c : tag) {
    if (c == '/') c = '_';
  }
  return tag;
}

fs::path freshTempDir(const std::string& name) {
  const fs::path dir = fs::path(BAKE_TEST_TMP) / runningTestTag() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace bake::test
