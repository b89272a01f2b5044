// TAM construction (hatching/bake/build.h): the quality targets on the default style, nesting across tones
// (pixelwise) and resolutions (each placed stroke in every finer level), determinism across thread
// counts, every stroke kind, wrapping tiles, the box-filtered mips, the threshold texture, style
// errors, and the stiff cases (one tone, tone 0.99, an 8-texel tile, huge strokes, K = 1).
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "hatching/bake/build.h"
#include "hatching/bake/quality.h"

namespace bake::hatching {
namespace {

// The default style of the issue: 6 evenly spaced tones up to 0.9, 4 stroke levels, 256 texels.
Style defaultStyle() {
  Style style;
  style.source = "default.json";
  for (int k = 1; k <= 6; ++k) style.tones.push_back(0.9 * k / 6.0);
  style.resolution = 256;
  style.levels = 4;
  return style;
}

Style smallStyle(StrokeKind kind) {
  Style style = defaultStyle();
  style.tones = {0.2, 0.5, 0.8};
  style.resolution = 128;
  style.levels = 3;
  style.stroke.kind = kind;
  return style;
}

Tam build(const Style& style, int threads = 0) {
  BuildOptions options;
  options.threads = threads;
  Result<Tam> tam = buildTam(style, options);
  EXPECT_TRUE(tam.isOk()) << tam.status().describe();
  return tam.isOk() ? std::move(tam).value() : Tam{};
}

// The checks that every construction must pass, whatever the style.
void expectSound(const Tam& tam, const Quality& q) {
  EXPECT_EQ(q.nestingViolationsTone, 0);
  EXPECT_EQ(q.nestingViolationsResolution, 0);
  EXPECT_TRUE(q.monotoneTones);
  ASSERT_EQ(int(tam.images.size()), tam.tones);
  for (const auto& chain : tam.images) {
    ASSERT_EQ(int(chain.size()), tam.mipLevels);
    for (int m = 0; m < tam.mipLevels; ++m) {
      ASSERT_EQ(chain[std::size_t(m)].width, std::max(1, tam.resolution >> m));
      for (float v : chain[std::size_t(m)].values) ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << v;
    }
  }
}

TEST(BuildTam, DefaultStyleMeetsTheQualityTargets) {
  const Style style = defaultStyle();
  const Tam tam = build(style);
  ASSERT_EQ(tam.strokeLevels, 4);
  ASSERT_EQ(tam.mipLevels, 9);
  const Quality q = measureQuality(tam);
  expectSound(tam, q);
  for (const ImageQuality& iq : q.images) {
    EXPECT_LE(iq.toneError, iq.toneTolerance) << "tone " << iq.tone << " mip " << iq.mip;
    EXPECT_DOUBLE_EQ(iq.toneTolerance, std::max(0.0025, 0.8 / iq.side));
  }
  EXPECT_LE(q.maxToneErrorOverTolerance, 1.0);
  EXPECT_LE(q.maxInkVariation, kInkVariationTarget) << q.toJson().dump(1);
  EXPECT_LE(q.maxLowFrequencyPower, kLowFrequencyPowerTarget) << q.toJson().dump(1);
  // The uniformity targets cover most of the 2 x 6 images of 128 and 256 texels (all but the
  // lightest tones, whose images hold fewer than kUniformityMinStrokes strokes).
  int checked = 0;
  for (const ImageQuality& iq : q.images) checked += iq.uniformityChecked ? 1 : 0;
  EXPECT_GE(checked, 3 * 3);
}

TEST(BuildTam, TonesNestPixelwiseAndStrokesNestAcrossLevels) {
  const Tam tam = build(smallStyle(StrokeKind::Hatching));
  for (int t = 1; t < tam.tones; ++t) {
    for (int m = 0; m < tam.mipLevels; ++m) {
      const auto& lighter = tam.images[std::size_t(t - 1)][std::size_t(m)].values;
      const auto& darker = tam.images[std::size_t(t)][std::size_t(m)].values;
      for (std::size_t i = 0; i < darker.size(); ++i) ASSERT_LE(darker[i], lighter[i] + 1e-6f) << "tone " << t << " mip " << m;
    }
  }
  // Every stroke is in its own level and every finer one, at its tone and every darker tone.
  ASSERT_FALSE(tam.strokes.empty());
  for (const PlacedStroke& placed : tam.strokes) {
    ASSERT_GE(placed.level, 0);
    ASSERT_LT(placed.level, tam.strokeLevels);
    for (int level = placed.level; level < tam.strokeLevels; ++level) {
      const int mip = tam.strokeLevels - 1 - level, n = tam.resolution >> mip;
      const stroke::InkFootprint footprint = stroke::rasterize(stroke::scaledPositions(placed.stroke, n), n, n, true);
      for (int t = placed.tone; t < tam.tones; ++t) {
        const stroke::Raster& image = tam.images[std::size_t(t)][std::size_t(mip)];
        for (const auto& p : footprint.pixels) ASSERT_LE(image.at(p.x, p.y), 1.0f - p.alpha + 1e-4f);
      }
    }
  }
  // Each level received strokes of its own, coarse levels first.
  for (int level = 0; level < tam.strokeLevels; ++level) {
    EXPECT_TRUE(std::any_of(tam.strokes.begin(), tam.strokes.end(), [&](const PlacedStroke& s) { return s.level == level; }));
  }
  EXPECT_TRUE(measureQuality(tam).nestingViolationsResolution == 0);
}

TEST(BuildTam, IdenticalWhateverTheThreadCount) {
  Style style = smallStyle(StrokeKind::CrossHatching);
  style.stroke.crossFrom = 1;
  const Tam one = build(style, 1), two = build(style, 2), four = build(style, 4);
  ASSERT_EQ(one.strokes.size(), two.strokes.size());
  ASSERT_EQ(one.strokes.size(), four.strokes.size());
  for (int t = 0; t < one.tones; ++t) {
    for (int m = 0; m < one.mipLevels; ++m) {
      EXPECT_EQ(one.images[std::size_t(t)][std::size_t(m)].values, two.images[std::size_t(t)][std::size_t(m)].values);
      EXPECT_EQ(one.images[std::size_t(t)][std::size_t(m)].values, four.images[std::size_t(t)][std::size_t(m)].values);
    }
  }
  // Another seed gives another map.
  style.seed = 2;
  const Tam other = build(style, 2);
  EXPECT_NE(one.images[1][0].values, other.images[1][0].values);
}

TEST(BuildTam, EveryStrokeKindBuilds) {
  for (StrokeKind kind : {StrokeKind::Hatching, StrokeKind::CrossHatching, StrokeKind::Stippling, StrokeKind::Image}) {
    SCOPED_TRACE(strokeKindName(kind));
    Style style = smallStyle(kind);
    if (kind == StrokeKind::CrossHatching) style.stroke.crossFrom = 1;
    if (kind == StrokeKind::Stippling) style.stroke.width = {2.0, 3.0};
    if (kind == StrokeKind::Image) {  // a soft-edged bar, darker in its middle
      stroke::StrokeTexture& texture = style.stroke.texture;
      texture.width = 16;
      texture.height = 4;
      for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 16; ++x) texture.alpha.push_back((y == 0 || y == 3) ? 0.4f : (x % 4 == 0 ? 0.7f : 1.0f));
      }
      style.stroke.image = "bar.png";
    }
    const Tam tam = build(style);
    const Quality q = measureQuality(tam);
    expectSound(tam, q);
    EXPECT_LE(q.maxToneErrorOverTolerance, 1.0) << q.toJson().dump(1);

    const double n = tam.resolution;
    for (const PlacedStroke& placed : tam.strokes) {
      const auto& pts = placed.stroke.points;
      const double dx = pts.back().x - pts.front().x, dy = pts.back().y - pts.front().y;
      const double length = std::hypot(dx, dy);
      if (kind == StrokeKind::Stippling) {  // a round dot of its width at every level
        EXPECT_LE(length * n, 1e-2);
        EXPECT_EQ(placed.stroke.taper, 0.0);
        const stroke::InkFootprint dot = stroke::rasterize(stroke::scaledPositions(placed.stroke, n), int(n), int(n), true);
        const double r = pts.front().radius;
        EXPECT_NEAR(dot.ink(), std::numbers::pi * r * r * style.stroke.opacity *
                                   (style.stroke.centreOpacity + style.stroke.edgeOpacity) / 2, 0.35 * r * r);
      } else {
        ASSERT_GE(length, style.stroke.length.min - 1e-9);
        ASSERT_LE(length, style.stroke.length.max + 1e-9);
      }
      if (kind == StrokeKind::Image) {
        EXPECT_EQ(pts.size(), 2u);
        EXPECT_EQ(placed.stroke.texture, tam.strokeTexture.get());
      }
    }
    if (kind == StrokeKind::CrossHatching) {  // crossing strokes (near 90 degrees) only from tone 1 on
      int crossing = 0;
      for (const PlacedStroke& placed : tam.strokes) {
        const auto& pts = placed.stroke.points;
        const double angle = std::atan2(pts.back().y - pts.front().y, pts.back().x - pts.front().x) * 180 / std::numbers::pi;
        const bool across = std::abs(std::abs(angle) - 90) < 10;
        if (placed.tone == 0) EXPECT_FALSE(across);
        crossing += across ? 1 : 0;
      }
      EXPECT_GT(crossing, int(tam.strokes.size()) / 5);
    }
  }
}

TEST(BuildTam, TilesWrap) {
  Style style = smallStyle(StrokeKind::Hatching);
  const Tam tam = build(style);
  // A stroke crossing the left/right border inks texels on both sides of the finest image.
  int crossing = 0;
  const int n = tam.resolution;
  const stroke::Raster& finest = tam.images.back()[0];
  for (const PlacedStroke& placed : tam.strokes) {
    const auto& pts = placed.stroke.points;
    // Crossing x = 0 or x = 1 away from the tapered ends (a fifth of the length from either end).
    const double a = std::min(pts.front().x, pts.back().x), b = std::max(pts.front().x, pts.back().x), margin = 0.2 * (b - a);
    if (!((a < -margin && b > margin) || (a < 1 - margin && b > 1 + margin))) continue;
    ++crossing;
    const stroke::InkFootprint footprint = stroke::rasterize(stroke::scaledPositions(placed.stroke, n), n, n, true);
    bool left = false, right = false;
    for (const auto& p : footprint.pixels) {
      if (p.alpha < 0.5f) continue;
      EXPECT_LE(finest.at(p.x, p.y), 1.0f - p.alpha + 1e-4f);
      left = left || p.x < 4;
      right = right || p.x >= n - 4;
    }
    EXPECT_TRUE(left && right);
  }
  EXPECT_GT(crossing, 0);
}

TEST(BuildTam, BoxFilteredMipsKeepTheMean) {
  const Tam tam = build(smallStyle(StrokeKind::Hatching));
  for (int t = 0; t < tam.tones; ++t) {
    for (int m = tam.strokeLevels; m < tam.mipLevels; ++m) {
      EXPECT_NEAR(meanDarkness(tam.images[std::size_t(t)][std::size_t(m)]),
                  meanDarkness(tam.images[std::size_t(t)][std::size_t(m - 1)]), 1e-5);
    }
    EXPECT_EQ(tam.images[std::size_t(t)].back().width, 1);
  }
}

TEST(BuildTam, ColouredInkKeepsAColourImage) {
  Style style = smallStyle(StrokeKind::Hatching);
  style.stroke.colour = {0.1, 0.2, 0.8};
  ASSERT_TRUE(style.coloured());
  const Tam tam = build(style);
  ASSERT_TRUE(tam.coloured);
  ASSERT_EQ(tam.colourImages.size(), tam.images.size());
  const stroke::Raster& colour = tam.colourImages[2][0];
  ASSERT_EQ(colour.channels, 3);
  // Where the ink is dense the colour tends to the ink colour: blue stays brighter than red.
  double red = 0, blue = 0;
  for (int i = 0; i < colour.width * colour.height; ++i) {
    red += colour.values[std::size_t(i) * 3];
    blue += colour.values[std::size_t(i) * 3 + 2];
  }
  EXPECT_GT(blue, red);
  // The tone is the ink as if black, as for black ink.
  EXPECT_LE(measureQuality(tam).maxToneErrorOverTolerance, 1.0);
}

// Webb et al. 2002's thresholds at each stroke level, checked from the textures alone: (a) the order
// of placement is kept (a texel first inked by a lighter tone never has a higher threshold than one
// first inked by a darker tone); (b) they reproduce the tone: inking, with the darkest tone's ink,
// every texel whose threshold is <= d gives mean darkness d (within the last stroke's share, up to the
// darkest tone's inked darkness); texels no tone inks stay at 1.
TEST(BuildTam, ThresholdTextureKeepsThePlacementOrderAndReproducesTheTone) {
  const Tam tam = build(smallStyle(StrokeKind::Hatching));
  const std::vector<stroke::Raster> thresholds = thresholdTexture(tam);
  ASSERT_EQ(int(thresholds.size()), tam.mipLevels);
  int none = 0;
  for (int m = 0; m < tam.strokeLevels; ++m) {
    const stroke::Raster& th = thresholds[std::size_t(m)];
    const stroke::Raster& darkest = tam.images[std::size_t(tam.tones - 1)][std::size_t(m)];
    ASSERT_EQ(th.width, tam.resolution >> m);
    std::vector<float> highest(std::size_t(tam.tones), 0.0f), lowest(std::size_t(tam.tones), 1.0f);
    double inkedDarkness = 0;
    for (int y = 0; y < th.height; ++y) {
      for (int x = 0; x < th.width; ++x) {
        int first = tam.tones;
        for (int t = tam.tones - 1; t >= 0; --t) {
          if (1.0f - tam.images[std::size_t(t)][std::size_t(m)].at(x, y) >= 0.5f) first = t;
        }
        if (first == tam.tones) {
          ASSERT_EQ(th.at(x, y), 1.0f) << "mip " << m << " texel " << x << "," << y;
          ++none;
          continue;
        }
        highest[std::size_t(first)] = std::max(highest[std::size_t(first)], th.at(x, y));
        lowest[std::size_t(first)] = std::min(lowest[std::size_t(first)], th.at(x, y));
        inkedDarkness += 1.0 - darkest.at(x, y);
      }
    }
    for (int t = 1; t < tam.tones; ++t)
      EXPECT_LE(highest[std::size_t(t - 1)], lowest[std::size_t(t)]) << "mip " << m << ": tone " << t << " inked before tone " << t - 1;
    const double texels = double(th.width) * th.height;
    for (double d = 0.05; d < inkedDarkness / texels; d += 0.05) {
      double mean = 0;
      for (int y = 0; y < th.height; ++y)
        for (int x = 0; x < th.width; ++x)
          if (th.at(x, y) <= float(d)) mean += 1.0 - darkest.at(x, y);
      EXPECT_NEAR(mean / texels, d, 0.02) << "mip " << m;
    }
  }
  EXPECT_GT(none, 0);  // the darkest tone 0.8 leaves some paper
}

TEST(BuildTam, StyleErrorsNameTheElement) {
  Style style = defaultStyle();
  style.tones = {0.2, 0.5, 0.4};
  Result<Tam> tam = buildTam(style);
  ASSERT_FALSE(tam.isOk());
  EXPECT_EQ(tam.status().code(), ExitCode::InvalidInput);
  EXPECT_EQ(tam.status().where().file, "default.json");
  EXPECT_EQ(tam.status().where().element, "/tones/2");

  style = defaultStyle();
  style.stroke.width = {2.0, 1.0};
  EXPECT_EQ(buildTam(style).status().where().element, "/stroke/width/max");
  style = defaultStyle();
  style.resolution = 100;
  EXPECT_EQ(buildTam(style).status().where().element, "/resolution");
  style = defaultStyle();
  style.stroke.kind = StrokeKind::Image;
  EXPECT_EQ(buildTam(style).status().where().element, "/stroke/image");
  style = defaultStyle();
  style.tones = {0.5, 1.0};
  EXPECT_EQ(buildTam(style).status().where().element, "/tones/1");
}

TEST(BuildTam, ReportsProgressUpToOne) {
  Style style = smallStyle(StrokeKind::Hatching);
  style.resolution = 64;
  std::vector<double> seen;
  BuildOptions options;
  options.threads = 2;
  options.progress = [&](double fraction) { seen.push_back(fraction); };
  ASSERT_TRUE(buildTam(style, options).isOk());
  ASSERT_EQ(seen.size(), std::size_t(3 * 3));  // per tone and stroke level
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_GT(seen.front(), 0.0);
  EXPECT_DOUBLE_EQ(seen.back(), 1.0);
}

TEST(BuildTam, CoarseLevelsThatCannotHoldAStrokeAreBoxFiltered) {
  Style style = defaultStyle();
  style.resolution = 64;
  style.levels = 4;  // 64, 32, 16, 8: all hold a 1.5 px stroke
  EXPECT_EQ(strokeLevelCount(style), 4);
  style.stroke.width = {1.0, 3.0};  // 8 < 4 x 3
  EXPECT_EQ(strokeLevelCount(style), 3);
  style.levels = 12;  // more than the chain has
  style.stroke.width = {1.0, 1.0};
  EXPECT_EQ(strokeLevelCount(style), 4);
}

// --- stiff cases ---

TEST(BuildTamStiff, OneTone) {
  Style style = defaultStyle();
  style.tones = {0.5};
  const Tam tam = build(style);
  const Quality q = measureQuality(tam);
  expectSound(tam, q);
  EXPECT_LE(q.maxToneErrorOverTolerance, 1.0);
}

TEST(BuildTamStiff, NearlyBlackTone) {
  Style style = defaultStyle();
  style.tones = {0.5, 0.99};
  const Tam tam = build(style);
  const Quality q = measureQuality(tam);
  expectSound(tam, q);
  EXPECT_LE(q.maxToneErrorOverTolerance, 1.0) << q.toJson().dump(1);
}

TEST(BuildTamStiff, TinyResolution) {
  Style style = defaultStyle();
  style.resolution = 8;
  const Tam tam = build(style);
  EXPECT_EQ(tam.strokeLevels, 1);  // 4, 2, 1 cannot hold a stroke
  EXPECT_EQ(tam.mipLevels, 4);
  const Quality q = measureQuality(tam);
  expectSound(tam, q);
  EXPECT_LE(q.maxToneErrorOverTolerance, 1.0) << q.toJson().dump(1);
}

TEST(BuildTamStiff, HugeStrokeWidth) {
  Style style = defaultStyle();
  style.resolution = 64;
  style.stroke.width = {24.0, 32.0};  // one stroke inks a third of the tile
  const Tam tam = build(style);
  EXPECT_EQ(tam.strokeLevels, 1);
  const Quality q = measureQuality(tam);
  expectSound(tam, q);
  for (const ImageQuality& iq : q.images) {
    EXPECT_TRUE(std::isfinite(iq.darkness));
    EXPECT_LE(iq.toneError, 0.25);  // a stroke is a large tone step: the nearest count of strokes
  }
}

TEST(BuildTamStiff, SingleCandidate) {
  Style style = defaultStyle();
  style.candidates = 1;
  const Tam tam = build(style);
  const Quality q = measureQuality(tam);
  expectSound(tam, q);
  EXPECT_LE(q.maxToneErrorOverTolerance, 1.0);
}

}  // namespace
}  // namespace bake::hatching
