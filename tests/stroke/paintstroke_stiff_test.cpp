// Stiff cases for the paintstroke rasterizer: dots, zero and huge radii, strokes much longer than the
// image, huge, tiny and non-finite coordinates, hairpins. Output must be finite and correct, or empty.
#include "bake/stroke/paintstroke.h"
#include "stroke/stroke_builders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace bake::stroke {
namespace {

using test::line;
using test::point;

// Every pixel inside the image, listed once, in row-major order, alpha in (0, 1], colour finite.
void expectWellFormed(const InkFootprint& f, int width, int height) {
  for (std::size_t i = 0; i < f.pixels.size(); ++i) {
    const auto& p = f.pixels[i];
    ASSERT_GE(p.x, 0);
    ASSERT_LT(p.x, width);
    ASSERT_GE(p.y, 0);
    ASSERT_LT(p.y, height);
    ASSERT_TRUE(std::isfinite(p.alpha));
    ASSERT_GT(p.alpha, 0.0f);
    ASSERT_LE(p.alpha, 1.0f);
    for (float c : p.colour) ASSERT_TRUE(std::isfinite(c));
    if (i > 0) {
      const auto& q = f.pixels[i - 1];
      ASSERT_TRUE(q.y < p.y || (q.y == p.y && q.x < p.x)) << i;
    }
  }
}

TEST(PaintstrokeStiff, CoincidentPointsMakeADot) {
  for (double r : {0.05, 0.3, 1.0, 2.5, 6.0}) {
    const double cx = 20.37, cy = 11.81;
    const InkFootprint f = rasterize(line(cx, cy, cx, cy, r, 0.9), 40, 30, false);
    expectWellFormed(f, 40, 30);
    EXPECT_NEAR(f.ink(), 0.9 * std::numbers::pi * r * r, 1e-3 * r * r + 1e-6) << r;
    // Centred on the point (a dot inside one pixel puts all its ink there).
    double mx = 0, my = 0;
    for (const auto& p : f.pixels) mx += p.alpha * (p.x + 0.5), my += p.alpha * (p.y + 0.5);
    EXPECT_NEAR(mx / f.ink(), cx, r < 1 ? 0.5 : 0.05) << r;
    EXPECT_NEAR(my / f.ink(), cy, r < 1 ? 0.5 : 0.05) << r;
  }
  // Three coincident points too.
  Paintstroke three;
  three.points = {point(5, 5, 1), point(5, 5, 1), point(5, 5, 1)};
  EXPECT_NEAR(rasterize(three, 10, 10, true).ink(), std::numbers::pi, 1e-3);
}

TEST(PaintstrokeStiff, ShortStrokesKeepTheirCapsuleInk) {
  // Strokes shorter than their width: both round caps share pixels; the ink is the capsule's area.
  for (double length : {1e-6, 0.01, 0.3, 1.0, 2.5, 4.0}) {
    for (double r : {0.2, 1.0, 2.0}) {
      for (double angle : {0.0, 0.6, 2.2}) {
        const double x0 = 16.31, y0 = 15.87;
        const InkFootprint f = rasterize(
            line(x0, y0, x0 + length * std::cos(angle), y0 + length * std::sin(angle), r), 32, 32, false);
        const double expected = 2 * r * length + std::numbers::pi * r * r;
        EXPECT_NEAR(f.ink(), expected, 0.01 * expected) << "length " << length << " r " << r << " angle " << angle;
      }
    }
  }
}

TEST(PaintstrokeStiff, ZeroRadiusGivesNoInk) {
  EXPECT_TRUE(rasterize(line(3, 4, 30, 20, 0), 32, 32, true).pixels.empty());
  EXPECT_TRUE(rasterize(line(3, 4, 3, 4, 0), 32, 32, false).pixels.empty());
  Paintstroke zeroOpacity = line(3, 4, 30, 20, 2, 0);
  EXPECT_TRUE(rasterize(zeroOpacity, 32, 32, true).pixels.empty());
  // Negative radii are treated as zero.
  EXPECT_TRUE(rasterize(line(3, 4, 30, 20, -1), 32, 32, true).pixels.empty());
}

TEST(PaintstrokeStiff, TooFewPointsOrEmptyImageGiveNothing) {
  Paintstroke one;
  one.points = {point(3, 3, 1)};
  EXPECT_TRUE(rasterize(one, 8, 8, true).pixels.empty());
  EXPECT_TRUE(rasterize(Paintstroke{}, 8, 8, true).pixels.empty());
  EXPECT_TRUE(rasterize(line(1, 1, 5, 5, 1), 0, 8, true).pixels.empty());
  EXPECT_TRUE(rasterize(line(1, 1, 5, 5, 1), 8, -3, false).pixels.empty());
}

TEST(PaintstrokeStiff, StrokeMuchLongerThanTheImageWraps) {
  // Horizontal, 40 periods long, faint: every pixel of the row is covered by ~40 copies (summed).
  const int w = 32, h = 16;
  const double length = 40 * w;
  const InkFootprint f = rasterize(line(0.5, 8.5, 0.5 + length, 8.5, 0.25, 0.01), w, h, true);
  expectWellFormed(f, w, h);
  EXPECT_NEAR(f.ink(), 0.01 * (2 * 0.25 * length + std::numbers::pi * 0.0625), 1e-3 * f.ink());
  for (const auto& p : f.pixels) EXPECT_EQ(p.y, 8);
  // Diagonal at an irrational slope over a small tile: the tile fills up, clamped at 1.
  const InkFootprint g = rasterize(line(0.2, 0.7, 2000.2, 2000 * std::numbers::sqrt2 + 0.7, 1.5), 16, 16, true);
  expectWellFormed(g, 16, 16);
  EXPECT_EQ(g.pixels.size(), 256u);
  for (const auto& p : g.pixels) EXPECT_FLOAT_EQ(p.alpha, 1.0f);
}

TEST(PaintstrokeStiff, StrokeBeyondOneBufferKeepsItsInk) {
  // 3000 px along the diagonal: the bounding box (about 2100^2) exceeds one buffer, so it is drawn in
  // chunks; ink still sums to the stroke's area, and each pixel is listed once.
  const double d = 3000 / std::numbers::sqrt2;
  const InkFootprint f = rasterize(line(10.3, 10.9, 10.3 + d, 10.9 + d, 0.4, 0.5), 2200, 2200, false);
  expectWellFormed(f, 2200, 2200);
  const double expected = 0.5 * (2 * 0.4 * 3000 + std::numbers::pi * 0.16);
  EXPECT_NEAR(f.ink(), expected, 0.005 * expected);
}

TEST(PaintstrokeStiff, HugeCoordinatesWrapExactly) {
  // 2^30 is a whole number of 64-pixel periods: the same footprint as at the origin.
  const double far = 1073741824.0;
  const InkFootprint a = rasterize(line(10.25, 20.5, 40.75, 33.25, 1.3), 64, 64, true);
  const InkFootprint b = rasterize(line(far + 10.25, -far + 20.5, far + 40.75, -far + 33.25, 1.3), 64, 64, true);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    EXPECT_EQ(a.pixels[i].x, b.pixels[i].x);
    EXPECT_EQ(a.pixels[i].y, b.pixels[i].y);
    EXPECT_NEAR(a.pixels[i].alpha, b.pixels[i].alpha, 1e-5);
  }
  // Far outside a non-wrapping image: nothing, quickly.
  EXPECT_TRUE(rasterize(line(1e15, 1e15, 1e15 + 50, 1e15 + 20, 2), 64, 64, false).pixels.empty());
}

TEST(PaintstrokeStiff, ExtremeValuesStayFinite) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (const Paintstroke& s : {line(1e300, 1e300, -1e300, 5, 1), line(nan, 1, 5, 5, 1), line(1, 1, inf, 5, 1),
                               line(1, 1, 5, 5, inf), line(1, 1, 5, 5, nan), line(1e-300, 1e-300, 2e-300, 0, 1e-300),
                               line(1e12, 3, 1e12 + 1e-4, 3, 1)}) {
    for (bool wrap : {true, false}) {
      const InkFootprint f = rasterize(s, 32, 32, wrap);
      expectWellFormed(f, 32, 32);
      EXPECT_TRUE(std::isfinite(f.ink()));
    }
  }
  // A tiny stroke is a tiny dot: ink ~ pi r^2, a few pixels at most.
  const InkFootprint tiny = rasterize(line(7.5, 7.5, 7.5 + 1e-9, 7.5, 1e-3), 16, 16, false);
  EXPECT_NEAR(tiny.ink(), std::numbers::pi * 1e-6, 1e-8);
  EXPECT_LE(tiny.pixels.size(), 4u);
  // NaN opacities and colours do not leak into the image.
  Paintstroke s = line(2, 2, 12, 12, 1);
  s.points[0].opacity = nan;
  s.centreOpacity = nan;
  s.points[1].colour = {nan, inf, -inf};
  Raster r(16, 16, 3, true);
  draw(s, r);
  for (float v : r.values) {
    EXPECT_TRUE(std::isfinite(v));
    EXPECT_LE(v, 1.0f);
    EXPECT_GE(v, 0.0f);
  }
}

TEST(PaintstrokeStiff, HugeRadiusCoversTheTileOnce) {
  // With wrap, a radius far beyond the image covers every pixel; opacity 0.3 summed over the copies is
  // clamped to 1, without a huge buffer.
  const InkFootprint f = rasterize(line(3, 3, 9, 7, 1e9, 1.0), 24, 24, true);
  expectWellFormed(f, 24, 24);
  EXPECT_EQ(f.pixels.size(), 576u);
  // Without wrap: every pixel fully covered, exactly once.
  const InkFootprint g = rasterize(line(3, 3, 9, 7, 1e9, 0.3), 24, 24, false);
  expectWellFormed(g, 24, 24);
  EXPECT_EQ(g.pixels.size(), 576u);
  for (const auto& p : g.pixels) EXPECT_NEAR(p.alpha, 0.3, 1e-6);
}

TEST(PaintstrokeStiff, HairpinAndZigzagDoNotDoubleInk) {
  // A stroke that doubles back on itself: where it overlaps itself the ink is the max, not the sum.
  Paintstroke hairpin;
  hairpin.points = {point(5, 10.5, 1), point(40, 10.5, 1), point(5, 10.5, 1)};
  const InkFootprint f = rasterize(hairpin, 48, 24, false);
  expectWellFormed(f, 48, 24);
  for (const auto& p : f.pixels) EXPECT_LE(p.alpha, 1.0f);
  const double single = rasterize(line(5, 10.5, 40, 10.5, 1), 48, 24, false).ink();
  EXPECT_NEAR(f.ink(), single, 0.05 * single);
  // A sharp zigzag stays finite and close to its area.
  Paintstroke zig;
  for (int i = 0; i < 12; ++i) zig.points.push_back(point(4 + 3 * i, i % 2 ? 4 : 20, 0.3));
  const InkFootprint z = rasterize(zig, 48, 24, true);
  expectWellFormed(z, 48, 24);
  EXPECT_GT(z.ink(), 0);
}

}  // namespace
}  // namespace bake::stroke
