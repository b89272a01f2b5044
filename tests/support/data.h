// The shared data set (../shared/data from the project root, or $BAKE_DATA_DIR): tests that read it
// skip with a message when it is absent.
#pragma once

#include <cstdlib>
#include <filesystem>

#include "support/golden.h"

namespace bake::test {

inline std::filesystem::path dataDir() {
  if (const char* fromEnvironment = std::getenv("BAKE_DATA_DIR"); fromEnvironment && *fromEnvironment)
    return fromEnvironment;
  return sourceDir() / ".." / "shared" / "data";
}

}  // namespace bake::test

#define BAKE_SKIP_WITHOUT_DATA()                                                          \
  do {                                                                                    \
    if (!std::filesystem::is_directory(::bake::test::dataDir() / "meshes")) {             \
      GTEST_SKIP() << "shared data set not found at " << ::bake::test::dataDir().string() \
                   << " (set BAKE_DATA_DIR to its folder to run the data tests)";         \
    }                                                                                     \
  } while (0)
