// Golden pictures of the runtime tests (tests/golden/runtime/<technique>-<case>.v<format>.png): an
// image must match its golden within a tolerance that allows for other Mesa versions rasterising
// edges a little differently; with BAKE_UPDATE_GOLDEN=1 the image is written as the new golden instead
// (review the diff before committing).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "bake/core/diagnostics.h"
#include "bake/io/image.h"
#include "io/image_compare.h"
#include "play/validate.h"
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

// `bakeplay validate --golden` on one package: it passes (its verdict lines in the failure message),
// and its first reference view, written under `views`, matches the golden `name` with the runtime
// tests' tolerance (in update mode the view becomes the golden).
inline void expectValidatesAgainstGolden(const std::filesystem::path& package, const std::string& name,
                                         const std::filesystem::path& views) {
  play::ValidateSettings settings;
  settings.packages = {package.string()};
  settings.size = 128;
  settings.viewsDirectory = views.string();
  settings.common.quiet = true;
  if (!updatingGoldens()) settings.goldens = {goldenPath(name).string()};
  Diagnostics diagnostics("bakeplay", true);
  std::FILE* out = std::tmpfile();
  const Status status = play::runValidate(settings, diagnostics, out);
  std::rewind(out);
  std::string verdicts;
  char line[4096];
  while (std::fgets(line, sizeof line, out)) verdicts += line;
  std::fclose(out);
  EXPECT_TRUE(status.isOk()) << status.describe() << "\n" << verdicts;
  std::vector<std::filesystem::path> written;
  for (const auto& entry : std::filesystem::directory_iterator(views)) written.push_back(entry.path());
  std::sort(written.begin(), written.end());
  ASSERT_FALSE(written.empty());
  Result<Image> first = readImage(written.front());
  ASSERT_TRUE(first.isOk()) << first.status().describe();
  EXPECT_TRUE(matchesGoldenImage(*first, name)) << written.front();
}

}  // namespace bake::test
