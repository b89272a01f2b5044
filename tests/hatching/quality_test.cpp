// TAM quality figures (hatching/bake/quality.h) on synthetic images with known answers: uniform images,
// half-black images, pure cosines below and above 4 cycles per tile, windows of known darkness, and
// hand-built maps with a known nesting violation, a non-monotone pair of tones and a missing stroke.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "hatching/bake/quality.h"

namespace bake::hatching {
namespace {

stroke::Raster uniform(int n, float brightness) {
  stroke::Raster image(n, n, 1, true);
  for (float& v : image.values) v = brightness;
  return image;
}

// brightness = 0.5 + 0.4 cos(2 pi k x / n)
stroke::Raster cosine(int n, int cycles) {
  stroke::Raster image(n, n, 1, true);
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) image.at(x, y) = float(0.5 + 0.4 * std::cos(2 * std::numbers::pi * cycles * x / n));
  }
  return image;
}

// A hand-built map: `tones` images per mip over the full chain of side n, all paper.
Tam blankTam(int tones, int n, int strokeLevels) {
  Tam tam;
  tam.tones = tones;
  tam.resolution = n;
  tam.strokeLevels = strokeLevels;
  tam.mipLevels = int(std::log2(n)) + 1;
  for (int t = 0; t < tones; ++t) {
    tam.targets.push_back(0.1 * (t + 1));
    tam.images.emplace_back();
    for (int m = 0; m < tam.mipLevels; ++m) tam.images.back().push_back(uniform(n >> m, 1.0f));
  }
  return tam;
}

TEST(TamQuality, UniformImageHasNoVariationAndNoLowFrequencyPower) {
  for (int n : {4, 64, 256}) {
    const stroke::Raster image = uniform(n, 0.3f);
    EXPECT_NEAR(meanDarkness(image), 0.7, 1e-6);
    EXPECT_EQ(inkVariation(image), 0.0);
    EXPECT_EQ(lowFrequencyPower(image), 0.0);
  }
  EXPECT_EQ(inkVariation(uniform(64, 1.0f)), 0.0);  // blank paper: no ink, no variation
}

TEST(TamQuality, HalfBlackImage) {
  stroke::Raster image = uniform(128, 1.0f);
  for (int y = 0; y < 128; ++y) {
    for (int x = 0; x < 64; ++x) image.at(x, y) = 0.0f;
  }
  EXPECT_NEAR(meanDarkness(image), 0.5, 1e-12);
  // Windows: 8 black (darkness 1), 8 white (0): mean 0.5, standard deviation 0.5.
  EXPECT_NEAR(inkVariation(image), 1.0, 1e-12);
  // A square wave: the odd harmonics carry 1/k^2 of the power, so harmonics 1 and 3 hold
  // (1 + 1/9) / (pi^2 / 8) = 90 % of it (a little more once sampled).
  const double low = lowFrequencyPower(image);
  EXPECT_GT(low, 0.89);
  EXPECT_LT(low, 0.93);
}

TEST(TamQuality, CosinesBelowAndAboveFourCyclesPerTile) {
  EXPECT_NEAR(lowFrequencyPower(cosine(64, 1)), 1.0, 1e-9);
  EXPECT_NEAR(lowFrequencyPower(cosine(64, 3)), 1.0, 1e-9);
  EXPECT_NEAR(lowFrequencyPower(cosine(64, 4)), 0.0, 1e-9);  // radius 4 is not below 4
  EXPECT_NEAR(lowFrequencyPower(cosine(64, 16)), 0.0, 1e-9);
  // Half the power at 2 cycles, half at 8: a share of one half.
  stroke::Raster mixed = uniform(64, 0.5f);
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      mixed.at(x, y) = float(0.5 + 0.2 * std::cos(2 * std::numbers::pi * 2 * x / 64) + 0.2 * std::sin(2 * std::numbers::pi * 8 * y / 64));
    }
  }
  EXPECT_NEAR(lowFrequencyPower(mixed), 0.5, 1e-6);
}

TEST(TamQuality, InkVariationOfKnownWindows) {
  // A fine checkerboard: every window holds the same ink.
  stroke::Raster checker = uniform(64, 1.0f);
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) checker.at(x, y) = (x + y) % 2 ? 0.0f : 1.0f;
  }
  EXPECT_NEAR(inkVariation(checker), 0.0, 1e-12);
  // One window of 16 inked at darkness 0.8: mean 0.05, deviation sqrt(15) 0.05.
  stroke::Raster one = uniform(64, 1.0f);
  for (int y = 0; y < 16; ++y) {
    for (int x = 16; x < 32; ++x) one.at(x, y) = 0.2f;
  }
  EXPECT_NEAR(inkVariation(one), std::sqrt(15.0), 1e-5);
}

TEST(TamQuality, CountsToneNestingViolationsAndMonotony) {
  Tam tam = blankTam(2, 16, 2);
  for (int m = 0; m < tam.mipLevels; ++m) {
    for (float& v : tam.images[0][std::size_t(m)].values) v = 0.9f;
    for (float& v : tam.images[1][std::size_t(m)].values) v = 0.8f;
  }
  Quality q = measureQuality(tam);
  EXPECT_EQ(q.nestingViolationsTone, 0);
  EXPECT_TRUE(q.monotoneTones);
  EXPECT_NEAR(q.images[0].darkness, 0.1, 1e-6);
  EXPECT_NEAR(q.maxToneError, 0.0, 1e-6);  // targets 0.1 and 0.2
  EXPECT_NEAR(q.meanLevelDifference, 0.0, 1e-6);

  tam.images[1][0].at(3, 5) = 0.95f;  // brighter than the lighter tone there
  tam.images[1][2].at(0, 1) = 0.95f;  // also in a box-filtered mip
  q = measureQuality(tam);
  EXPECT_EQ(q.nestingViolationsTone, 2);
  EXPECT_TRUE(q.monotoneTones);

  for (float& v : tam.images[1][1].values) v = 0.95f;  // tone 1 lighter than tone 0 at mip 1
  q = measureQuality(tam);
  EXPECT_FALSE(q.monotoneTones);
  EXPECT_EQ(q.nestingViolationsTone, 2 + 64);
  EXPECT_NEAR(q.images[3].darkness, 0.05, 1e-6);   // tone 1 mip 1
  EXPECT_NEAR(q.images[3].toneError, 0.15, 1e-6);  // target 0.2
  EXPECT_NEAR(q.maxToneErrorOverTolerance, 0.15 / (0.8 / 8), 1e-5);
  // Tone 0: no difference; tone 1: (255 x 0.2 + 0.05) / 256 at mip 0 against 0.05 at mip 1.
  EXPECT_NEAR(q.meanLevelDifference, (0.0 + (255 * 0.2 + 0.05) / 256 - 0.05) / 2, 1e-6);
}

TEST(TamQuality, FindsAStrokeMissingFromAFinerLevel) {
  Tam tam = blankTam(1, 32, 2);
  PlacedStroke placed;
  placed.level = 0;  // placed at 16 texels, so also due at 32
  stroke::ControlPoint a, b;
  a.x = 0.2, a.y = 0.5, a.radius = 1.0;
  b = a;
  b.x = 0.7;
  placed.stroke.points = {a, b};
  tam.strokes.push_back(placed);
  stroke::draw(stroke::scaledPositions(placed.stroke, 16), tam.images[0][1]);
  EXPECT_EQ(measureQuality(tam).nestingViolationsResolution, 1);  // missing at 32
  stroke::draw(stroke::scaledPositions(placed.stroke, 32), tam.images[0][0]);
  EXPECT_EQ(measureQuality(tam).nestingViolationsResolution, 0);
}

TEST(TamQuality, UniformityTargetsCoverLargeImagesWithManyStrokes) {
  Tam tam = blankTam(4, 256, 3);  // sides 256, 128, 64
  // 100 strokes of tone 0 at level 0 (in every image), 40 of tone 2 at level 1 (tones 2-3, 256 and 128).
  PlacedStroke placed;
  placed.stroke.points.resize(2);
  for (int i = 0; i < 100; ++i) tam.strokes.push_back(placed);
  placed.tone = 2;
  placed.level = 1;
  for (int i = 0; i < 40; ++i) tam.strokes.push_back(placed);
  const Quality q = measureQuality(tam);
  ASSERT_EQ(q.images.size(), 12u);
  for (const ImageQuality& iq : q.images) {
    const long long expected = 100 + (iq.tone >= 2 && iq.side >= 128 ? 40 : 0);
    EXPECT_EQ(iq.strokes, expected) << iq.tone << " " << iq.side;
    EXPECT_EQ(iq.uniformityChecked, iq.side >= 128 && expected >= 128);
  }
  EXPECT_NE(uniformityScope().find("128"), std::string::npos);
  const nlohmann::json json = q.toJson();
  for (const char* key : {"maxToneError", "nestingViolationsTone", "nestingViolationsResolution", "monotoneTones",
                          "meanLevelDifference", "maxInkVariation", "maxLowFrequencyPower", "images"}) {
    EXPECT_TRUE(json.contains(key)) << key;
  }
  EXPECT_EQ(json["images"].size(), 12u);
}

}  // namespace
}  // namespace bake::hatching
