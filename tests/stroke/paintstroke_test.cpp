// Paintstroke rasterizer: spline, coverage profile, ink conservation, breadthwise opacity, taper,
// wrap-around and multiplicative compositing.
#include "bake/stroke/paintstroke.h"
#include "stroke/stroke_builders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <thread>
#include <vector>
#include <algorithm>

namespace bake::stroke {
namespace {

using test::line;
using test::point;

// Ink of a straight stroke with round caps: body + the disc of the two half caps.
double capsuleInk(double length, double radius, double opacity) {
  return opacity * (2 * radius * length + std::numbers::pi * radius * radius);
}

std::map<std::pair<int, int>, float> alphaMap(const InkFootprint& f) {
  std::map<std::pair<int, int>, float> m;
  for (const auto& p : f.pixels) m[std::make_pair(int(p.x), int(p.y))] = p.alpha;
  return m;
}

float get(const std::map<std::pair<int, int>, float>& m, int x, int y) {
  const auto it = m.find({x, y});
  return it == m.end() ? 0.0f : it->second;
}

TEST(PaintstrokeSpline, PassesThroughControlPoints) {
  Paintstroke s;
  s.points = {point(1, 2, 0.5), point(4, 7, 1.5), point(9, 3, 0.25), point(12, 12, 2)};
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const ControlPoint p = evaluate(s, double(i));
    EXPECT_NEAR(p.x, s.points[i].x, 1e-12) << i;
    EXPECT_NEAR(p.y, s.points[i].y, 1e-12) << i;
    EXPECT_NEAR(p.radius, s.points[i].radius, 1e-12) << i;
  }
  // A straight, evenly spaced stroke is traced at constant speed (uniform Catmull-Rom reproduces lines).
  Paintstroke straight;
  straight.points = {point(0, 0), point(1, 2), point(2, 4), point(3, 6)};
  const ControlPoint mid = evaluate(straight, 1.25);
  EXPECT_NEAR(mid.x, 1.25, 1e-12);
  EXPECT_NEAR(mid.y, 2.5, 1e-12);
}

TEST(PaintstrokeSpline, OpacityAndColourAreLinearInArcLength) {
  Paintstroke s;
  s.points = {point(0, 0, 1, 0.2), point(10, 0, 1, 1.0), point(20, 0, 1, 0.4), point(30, 0, 1, 0.4)};
  s.points[1].colour = {1, 0.5, 0};
  // Evenly spaced collinear points: on an inner segment the parameter is proportional to arc length.
  EXPECT_NEAR(evaluate(s, 1.5).x, 15, 1e-12);
  EXPECT_NEAR(evaluate(s, 1.5).opacity, 0.7, 1e-3);
  EXPECT_NEAR(evaluate(s, 1.25).opacity, 0.85, 1e-3);
  EXPECT_NEAR(evaluate(s, 1.5).colour[0], 0.5, 1e-3);
  EXPECT_NEAR(evaluate(s, 1.5).colour[1], 0.25, 1e-3);
  // Two points: the doubled ends make the spline slow near them, x(u) = (u + 3u^2 - 2u^3) / 2 of the
  // way; the opacity follows the position, not the parameter.
  Paintstroke two;
  two.points = {point(0, 0, 1, 0.0), point(8, 0, 1, 1.0)};
  const ControlPoint q = evaluate(two, 0.25);
  const double f = (0.25 + 3 * 0.0625 - 2 * 0.015625) / 2;
  EXPECT_NEAR(q.x, 8 * f, 1e-12);
  EXPECT_NEAR(q.opacity, f, 1e-3);
}

TEST(PaintstrokeRaster, StraightProfileIsSymmetric) {
  // A horizontal stroke centred on the row boundary y = 10: rows 9 and 10, 8 and 11 ... match.
  const InkFootprint f = rasterize(line(5, 10, 45, 10, 1.3), 64, 32, false);
  auto m = alphaMap(f);
  for (int dy = 0; dy < 4; ++dy) EXPECT_NEAR(get(m, 25, 9 - dy), get(m, 25, 10 + dy), 1e-6) << dy;
  EXPECT_NEAR(get(m, 25, 9), 1.0, 1e-6);
  EXPECT_NEAR(get(m, 25, 10), 1.0, 1e-6);
  EXPECT_NEAR(get(m, 25, 8), 0.3, 1e-6);  // exact area: 1.3 - 1 of the next row
  EXPECT_EQ(get(m, 25, 7), 0.0f);

  // A diagonal stroke through pixel centres: mirror symmetric about its centreline.
  const auto d = alphaMap(rasterize(line(10.5, 10.5, 40.5, 40.5, 1.7), 64, 64, false));
  for (int k = 1; k < 4; ++k) EXPECT_NEAR(get(d, 25 + k, 25), get(d, 25, 25 + k), 1e-6) << k;
}

TEST(PaintstrokeRaster, OpaqueWideStrokeIsSolidInside) {
  const auto m = alphaMap(rasterize(line(10, 20, 50, 33, 4), 64, 64, false));
  // Points well inside (distance < r - 1 from the centreline, away from the ends).
  for (double t = 0.2; t <= 0.8; t += 0.1) {
    const int x = int(10 + 40 * t), y = int(20 + 13 * t);
    EXPECT_FLOAT_EQ(get(m, x, y), 1.0f) << x << "," << y;
  }
}

TEST(PaintstrokeRaster, InkIsConservedAtAnyWidthAngleAndOffset) {
  const double length = 60;
  for (double radius : {0.1, 0.2, 0.35, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0}) {
    for (double angle : {0.0, 0.13, 0.5, std::numbers::pi / 4, 1.1, std::numbers::pi / 2, 2.7}) {
      for (double offset : {0.0, 0.25, 0.5, 0.73}) {
        const double x0 = 64 + offset, y0 = 64 + 0.37 * offset;
        const double x1 = x0 + length * std::cos(angle), y1 = y0 + length * std::sin(angle);
        const InkFootprint f = rasterize(line(x0, y0, x1, y1, radius, 0.8), 200, 200, false);
        const double expected = capsuleInk(length, radius, 0.8);
        EXPECT_NEAR(f.ink(), expected, 1e-4 * expected) << "r " << radius << " angle " << angle << " offset " << offset;
      }
    }
  }
}

// The area of each pixel within r of a polyline, by 16 x 16 point samples (the independent oracle).
double supersampledArea(const std::vector<std::pair<double, double>>& poly, double r, int x, int y) {
  constexpr int kSub = 16;
  int inside = 0;
  for (int j = 0; j < kSub; ++j)
    for (int i = 0; i < kSub; ++i) {
      const double px = x + (i + 0.5) / kSub, py = y + (j + 0.5) / kSub;
      double best = 1e300;
      for (std::size_t k = 0; k + 1 < poly.size(); ++k) {
        const double ax = poly[k].first, ay = poly[k].second, ex = poly[k + 1].first - ax, ey = poly[k + 1].second - ay;
        const double l2 = ex * ex + ey * ey;
        const double t = l2 > 0 ? std::clamp(((px - ax) * ex + (py - ay) * ey) / l2, 0.0, 1.0) : 0;
        best = std::min(best, std::hypot(px - ax - t * ex, py - ay - t * ey));
      }
      inside += best <= r;
    }
  return double(inside) / (kSub * kSub);
}

TEST(PaintstrokeRaster, CoverageMatchesSupersampledArea) {
  // A curved stroke (three quarters of a circle of radius 8) against the area of each pixel within r
  // of the spline, point-sampled 256 times per pixel.
  for (double r : {0.3, 1.0, 2.5}) {
    Paintstroke s;
    for (int i = 0; i <= 6; ++i) {
      const double a = 1.5 * std::numbers::pi * i / 6;
      s.points.push_back(point(16.3 + 8 * std::cos(a), 16.7 + 8 * std::sin(a), r));
    }
    std::vector<std::pair<double, double>> poly;
    for (int k = 0; k <= 200; ++k) {
      const ControlPoint q = evaluate(s, 6.0 * k / 200);
      poly.push_back({q.x, q.y});
    }
    const auto m = alphaMap(rasterize(s, 32, 32, false));
    double worst = 0, total = 0;
    int count = 0;
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x) {
        const double d = std::sqrt(std::pow(x + 0.5 - 16.3, 2) + std::pow(y + 0.5 - 16.7, 2));
        if (std::abs(d - 8) > r + 1.5) {
          EXPECT_EQ(get(m, x, y), 0.0f) << x << "," << y;  // (the caps lie within this ring too)
          continue;
        }
        const double error = std::abs(get(m, x, y) - supersampledArea(poly, r, x, y));
        worst = std::max(worst, error);
        total += error;
        ++count;
      }
    EXPECT_LT(worst, 0.065) << r;
    EXPECT_LT(total / count, 0.005) << r;
  }
}

TEST(PaintstrokeRaster, ThinStrokeSpreadsInsteadOfVanishing) {
  // Radius 0.1 between two rows: both rows get ink, each column sums to 0.2.
  const auto m = alphaMap(rasterize(line(5, 10, 45, 10, 0.1), 64, 32, false));
  for (int x = 10; x < 40; ++x) {
    EXPECT_NEAR(get(m, x, 9), 0.1, 1e-6);
    EXPECT_NEAR(get(m, x, 10), 0.1, 1e-6);
  }
}

TEST(PaintstrokeRaster, BreadthwiseOpacityLowersInk) {
  // Body: the mean opacity across is (centre + edge) / 2; the round caps' mean over the disc is
  // centre + (edge - centre) 2/3.
  auto expected = [](double length, double r, double centre, double edge) {
    return 2 * r * length * 0.5 * (centre + edge) + std::numbers::pi * r * r * (centre + (edge - centre) * 2.0 / 3.0);
  };
  for (double radius : {0.3, 1.0, 2.5}) {
    Paintstroke s = line(20.2, 30.6, 90.7, 51.1, radius);
    const double length = std::hypot(70.5, 20.5);
    const double full = rasterize(s, 128, 128, false).ink();
    s.centreOpacity = 1;
    s.edgeOpacity = 0;
    const double soft = rasterize(s, 128, 128, false).ink();
    EXPECT_NEAR(soft, expected(length, radius, 1, 0), 0.02 * expected(length, radius, 1, 0)) << radius;
    EXPECT_LT(soft, 0.55 * full);
    s.centreOpacity = 0.2;
    s.edgeOpacity = 0.6;
    EXPECT_NEAR(rasterize(s, 128, 128, false).ink(), expected(length, radius, 0.2, 0.6),
                0.02 * expected(length, radius, 0.2, 0.6)) << radius;
  }
}

TEST(PaintstrokeRaster, TaperReducesInkNearTheEnds) {
  Paintstroke s = line(10, 40, 90, 40, 1.5);
  const auto plain = alphaMap(rasterize(s, 128, 128, false));
  s.taper = 0.25;
  const InkFootprint tapered = rasterize(s, 128, 128, false);
  const auto t = alphaMap(tapered);
  // The middle is unchanged, the ends thin out.
  EXPECT_NEAR(get(t, 50, 39), get(plain, 50, 39), 1e-6);
  double endPlain = 0, endTapered = 0;
  for (const auto& [key, a] : plain) if (key.first < 20) endPlain += a;
  for (const auto& [key, a] : t) if (key.first < 20) endTapered += a;
  EXPECT_LT(endTapered, 0.6 * endPlain);
  // A smoothstep taper keeps half the ink over each tapered stretch: 80 x (1 - 0.25) x 3.
  EXPECT_NEAR(tapered.ink(), 2 * 1.5 * 80 * 0.75, 0.02 * 180);
}

TEST(PaintstrokeRaster, WrapGivesIdenticalFootprintsForShiftedCopies) {
  Paintstroke a;
  a.points = {point(50.3, 20.1, 1.2), point(70.6, 25.9, 1.0), point(90.2, 14.4, 0.8)};
  Paintstroke b = a;
  for (auto& p : b.points) p.x += 64;
  Paintstroke c = a;
  for (auto& p : c.points) p.x -= 128, p.y += 64;
  const InkFootprint fa = rasterize(a, 64, 64, true);
  const InkFootprint fb = rasterize(b, 64, 64, true);
  const InkFootprint fc = rasterize(c, 64, 64, true);
  ASSERT_EQ(fa.pixels.size(), fb.pixels.size());
  ASSERT_EQ(fa.pixels.size(), fc.pixels.size());
  for (std::size_t i = 0; i < fa.pixels.size(); ++i) {
    EXPECT_EQ(fa.pixels[i].x, fb.pixels[i].x);
    EXPECT_EQ(fa.pixels[i].y, fb.pixels[i].y);
    EXPECT_NEAR(fa.pixels[i].alpha, fb.pixels[i].alpha, 1e-6);
    EXPECT_NEAR(fa.pixels[i].alpha, fc.pixels[i].alpha, 1e-6);
  }
}

TEST(PaintstrokeRaster, WrapKeepsInkAcrossTheBorderAndListsPixelsOnceInOrder) {
  const Paintstroke inside = line(10.3, 20.2, 40.9, 31.5, 0.7);
  const Paintstroke straddling = line(48.3, 50.2, 78.9, 61.5, 0.7);  // leaves right and bottom sides
  const InkFootprint a = rasterize(inside, 64, 64, true);
  const InkFootprint b = rasterize(straddling, 64, 64, true);
  EXPECT_NEAR(a.ink(), b.ink(), 1e-3 * a.ink());
  for (std::size_t i = 1; i < b.pixels.size(); ++i) {
    const auto& p = b.pixels[i - 1];
    const auto& q = b.pixels[i];
    EXPECT_TRUE(p.y < q.y || (p.y == q.y && p.x < q.x)) << i;
  }
  for (const auto& p : b.pixels) {
    EXPECT_GE(p.x, 0);
    EXPECT_LT(p.x, 64);
    EXPECT_GE(p.y, 0);
    EXPECT_LT(p.y, 64);
  }
  // Without wrap the part outside is lost.
  EXPECT_LT(rasterize(straddling, 64, 64, false).ink(), 0.8 * a.ink());
}

TEST(PaintstrokeRaster, WrapEqualsFoldedCopiesOnALargerCanvas) {
  // Oracle: draw without wrap on a canvas 5 periods wide and high, shifted by two periods, and fold the
  // pixels onto the tile by summing (clamped to 1). Covers strokes narrower than, as wide as and wider
  // than the tile, at its corners.
  const int w = 16, h = 12;
  std::vector<Paintstroke> cases;
  cases.push_back(line(14.2, 10.7, 19.9, 13.1, 0.8));                   // crosses a corner
  cases.push_back(line(0.3, 5.5, 15.7, 5.9, 1.0, 0.5));                 // about as wide as the tile
  cases.push_back(line(-3.3, 2.2, 30.1, 9.6, 0.6, 0.3));                // two periods long
  Paintstroke curve;
  curve.points = {point(2, 2, 1.5, 0.2), point(20, 6, 0.7, 0.4), point(9, 15, 1.1, 0.3), point(-4, 9, 0.4, 0.6)};
  cases.push_back(curve);
  for (std::size_t c = 0; c < cases.size(); ++c) {
    Paintstroke shifted = cases[c];
    for (auto& p : shifted.points) p.x += 2 * w, p.y += 2 * h;
    std::vector<double> folded(std::size_t(w * h), 0.0);
    for (const auto& p : rasterize(shifted, 5 * w, 5 * h, false).pixels) folded[std::size_t((p.y % h) * w + p.x % w)] += p.alpha;
    std::vector<double> wrapped(std::size_t(w * h), 0.0);
    for (const auto& p : rasterize(cases[c], w, h, true).pixels) wrapped[std::size_t(p.y * w + p.x)] = p.alpha;
    for (int k = 0; k < w * h; ++k) EXPECT_NEAR(wrapped[std::size_t(k)], std::min(folded[std::size_t(k)], 1.0), 1e-5) << c << ": " << k;
  }
}

TEST(PaintstrokeRaster, WrapSumsOverlappingCopies) {
  // A horizontal stroke 1.5 periods long at half opacity, radius 0.25 centred in a row: the overlapped
  // part of the row gets 2 x 0.25, the rest 0.25.
  const auto m = alphaMap(rasterize(line(0.5, 8.5, 48.5, 8.5, 0.25, 0.5), 32, 16, true));
  EXPECT_NEAR(get(m, 8, 8), 0.5, 1e-5);
  EXPECT_NEAR(get(m, 24, 8), 0.25, 1e-5);
}

TEST(PaintstrokeRaster, ColourFollowsTheStroke) {
  Paintstroke s = line(4, 8, 60, 8, 2);
  s.points[0].colour = {1, 0, 0};
  s.points[1].colour = {0, 0, 1};
  const InkFootprint f = rasterize(s, 64, 16, false);
  for (const auto& p : f.pixels) {
    if (p.y != 8) continue;
    const double t = (p.x + 0.5 - 4) / 56;
    if (t < 0.05 || t > 0.95) continue;
    EXPECT_NEAR(p.colour[0], 1 - t, 0.02) << p.x;
    EXPECT_NEAR(p.colour[2], t, 0.02) << p.x;
  }
}

TEST(PaintstrokeRaster, TextureMultipliesAlpha) {
  StrokeTexture tex;
  tex.width = 2, tex.height = 2;
  tex.alpha = {1, 1, 0, 0};  // left edge (top row) inked, right edge not
  Paintstroke s = line(10, 20, 60, 20, 3);
  const double plain = rasterize(s, 64, 64, false).ink();
  s.texture = &tex;
  const auto m = alphaMap(rasterize(s, 64, 64, false));
  // Travelling +x in an image with y down, the left edge is at smaller y.
  EXPECT_GT(get(m, 35, 18), get(m, 35, 21));
  double sum = 0;
  for (const auto& kv : m) sum += kv.second;
  EXPECT_NEAR(sum, 0.5 * plain, 0.05 * plain);
}

TEST(PaintstrokeComposite, MultipliesAndNeverRaises) {
  Raster r(32, 32, 1, true);
  for (std::size_t i = 0; i < r.values.size(); ++i) r.values[i] = float(i % 7) / 6.0f;
  const Raster before = r;
  Paintstroke s;
  s.points = {point(3, 4, 2, 0.7), point(20, 30, 1, 0.4), point(40, 12, 3, 0.9)};
  s.points[1].colour = {0.5, 0.9, 0.2};
  const InkFootprint f = rasterize(s, 32, 32, true);
  composite(f, r);
  for (std::size_t i = 0; i < r.values.size(); ++i) EXPECT_LE(r.values[i], before.values[i]);
  for (const auto& p : f.pixels) {
    const float mean = (p.colour[0] + p.colour[1] + p.colour[2]) / 3;
    EXPECT_NEAR(r.at(p.x, p.y), before.at(p.x, p.y) * (1 - p.alpha * (1 - mean)), 1e-6);
  }
  // White ink changes nothing.
  Raster white(16, 16, 3, false);
  Paintstroke w = line(2, 2, 14, 14, 2);
  w.points[0].colour = w.points[1].colour = {1, 1, 1};
  draw(w, white);
  for (float v : white.values) EXPECT_EQ(v, 1.0f);
}

TEST(PaintstrokeComposite, DrawEqualsRasterizeThenComposite) {
  Raster a(48, 48, 3, true), b(48, 48, 3, true);
  Paintstroke s = line(40, 5, 60, 30, 1.2, 0.6);
  s.points[0].colour = {0.1, 0.2, 0.3};
  draw(s, a);
  composite(rasterize(s, 48, 48, true), b);
  EXPECT_EQ(a.values, b.values);
}

TEST(PaintstrokeRaster, ScaledPositionsKeepRadius) {
  Paintstroke s = line(1, 2, 3, 4, 0.7);
  const Paintstroke t = scaledPositions(s, 4);
  EXPECT_EQ(t.points[1].x, 12);
  EXPECT_EQ(t.points[1].y, 16);
  EXPECT_EQ(t.points[1].radius, 0.7);
}

TEST(PaintstrokeRaster, DeterministicAcrossCalls) {
  Paintstroke s;
  s.points = {point(3.3, 4.1, 1.1), point(20.7, 30.2, 0.4), point(40.5, 12.9, 1.9)};
  s.edgeOpacity = 0.3;
  const InkFootprint a = rasterize(s, 32, 32, true), b = rasterize(s, 32, 32, true);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    EXPECT_EQ(a.pixels[i].x, b.pixels[i].x);
    EXPECT_EQ(a.pixels[i].alpha, b.pixels[i].alpha);
  }
}

TEST(PaintstrokeRaster, ConcurrentCallsGiveTheSerialResults) {
  std::vector<Paintstroke> strokes;
  for (int i = 0; i < 16; ++i) {
    Paintstroke s;
    s.points = {point(3.1 * i, 2.7 * i, 0.3 + 0.2 * i), point(40 + 1.3 * i, 9.5 * i, 0.5), point(70.2, 64 - 1.7 * i, 1.1)};
    s.edgeOpacity = 0.05 * i;
    s.taper = 0.02 * i;
    strokes.push_back(s);
  }
  std::vector<InkFootprint> serial;
  for (const auto& s : strokes) serial.push_back(rasterize(s, 64, 64, true));
  std::vector<std::vector<InkFootprint>> parallel(4);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (int repeat = 0; repeat < 20; ++repeat)
        for (const auto& s : strokes) parallel[t].push_back(rasterize(s, 64, 64, true));
    });
  for (auto& th : threads) th.join();
  for (int t = 0; t < 4; ++t)
    for (std::size_t k = 0; k < parallel[t].size(); ++k) {
      const InkFootprint& a = serial[k % strokes.size()];
      const InkFootprint& b = parallel[t][k];
      ASSERT_EQ(a.pixels.size(), b.pixels.size());
      for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        ASSERT_EQ(a.pixels[i].x, b.pixels[i].x);
        ASSERT_EQ(a.pixels[i].y, b.pixels[i].y);
        ASSERT_EQ(a.pixels[i].alpha, b.pixels[i].alpha);
        ASSERT_EQ(a.pixels[i].colour, b.pixels[i].colour);
      }
    }
}

}  // namespace
}  // namespace bake::stroke
