// Golden pictures of the runtime tests (tests/golden/runtime/<technique>-<case>.v<format>.png): an
// image must match its golden within a tolerance that allows for other Mesa versions rasterising
// edges a little differently; with BAKE_UPDATE_GOLDEN=1 the image is written as the new golden instead
// (review the diff before committing).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "bake/io/image.h"
#include "io/image_compare.h"
#include "support/golden.h"

namespace bake::test {

inline constexpr ImageTolerance kTechniqueGoldenTolerance{0.02, 0.1, 1.0};

inline ::testing::AssertionResult matchesGoldenImage(const Image& image, const std::string& name,
                                                     const ImageTolerance& tolerance = kTechniqueGoldenTolerance) {
  const std::filesystem::path path = goldenPath(name);
  if (updatingGoldens()) {
    std::filesystem::create_directories(path.parent_path());
    const Status written = writeImage(path, image, PixelType::U8);
    if (!written.isOk()) return ::testing::AssertionFailure() << written.describe();
    return ::testing::AssertionSuccess() << "updated " << name;
  }
  auto expected = readImage(path);
  if (!expected.isOk()) return ::testing::AssertionFailure() << expected.status().describe();
  auto difference = compareImages(image, *expected, 0.1);
  if (!difference.isOk()) return ::testing::AssertionFailure() << difference.status().describe();
  if (!withinTolerance(*difference, tolerance)) return ::testing::AssertionFailure() << name << ": " << describe(*difference);
  return ::testing::AssertionSuccess();
}

}  // namespace bake::test
