// Golden files for tests, with a compare|update mode: normally the bytes under test must equal
// tests/golden/<name>; with BAKE_UPDATE_GOLDEN=1 in the environment the golden is rewritten instead
// (review the diff before committing). Golden names carry the format version they pin.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace bake::test {

std::filesystem::path sourceDir();
std::filesystem::path goldenPath(const std::string& name);
bool updatingGoldens();

::testing::AssertionResult matchesGolden(const std::string& name, std::span<const std::uint8_t> bytes);
::testing::AssertionResult matchesGolden(const std::string& name, const std::string& text);

// A fresh empty directory for one test (under the build tree, inside a folder named after the
// running test).
std::filesystem::path freshTempDir(const std::string& name);

std::vector<std::uint8_t> readAll(const std::filesystem::path& path);

}  // namespace bake::test
