// The CPU march (libbake/revolution/march*.cpp) against analytic answers. Shape maps are built here
// from closed-form distances (a sphere: |p| - 1) and encoded by the format's formulas, so the tests
// do not depend on the bake's own field code. Checked: bilinear sampling (texel centres, linear in
// between, the mirror at r = 0, clamping, filtering before decoding), the exact intersection against
// the closed forms of sphere, cylinder, cone and torus, march hits within margin + epsilon of the
// sphere, the proxy bands containing every surface point, and the error curve falling with the budget.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include "revolution/oracle/march.h"
#include "revolution/profile_shapes.h"

namespace bake::revolution {
namespace {

// --- hand-built fields and encodings -------------------------------------------------------------

ShapeField fieldFrom(const ShapeGrid& grid, double (*distance)(double r, double h)) {
  ShapeField f;
  f.grid = grid;
  const std::size_t n = std::size_t(grid.width) * grid.height;
  f.distance.resize(n), f.gradR.assign(n, 0), f.gradH.assign(n, 0), f.coverage.assign(n, 0);
  for (int j = 0; j < grid.height; ++j)
    for (int i = 0; i < grid.width; ++i)
      f.distance[std::size_t(j) * grid.width + i] = float(distance(grid.centreR(i), grid.centreH(j)));
  return f;
}

void putU16(std::vector<std::uint8_t>& bytes, double v01) {
  const auto v = std::uint16_t(std::lround(std::clamp(v01, 0.0, 1.0) * 65535));
  bytes.push_back(std::uint8_t(v & 0xff)), bytes.push_back(std::uint8_t(v >> 8));
}

// RGBA per the format (bake_formats/revolution.h); only B matters to the march.
EncodedShapeMap encode(const ShapeField& f, DistanceEncoding encoding) {
  EncodedShapeMap m;
  m.encoding = encoding;
  double largest = 0;
  for (float d : f.distance) largest = std::max(largest, double(std::abs(d)));
  m.distanceScale = encoding == DistanceEncoding::Float ? 1.0 : largest;
  for (float d : f.distance) {
    switch (encoding) {
      case DistanceEncoding::Float: {
        const float texel[4] = {0, 0, d, 0};
        const auto* p = reinterpret_cast<const std::uint8_t*>(texel);
        m.bytes.insert(m.bytes.end(), p, p + sizeof texel);
        break;
      }
      case DistanceEncoding::Unorm16:
        putU16(m.bytes, 0.5), putU16(m.bytes, 0.5), putU16(m.bytes, 0.5 + 0.5 * d / largest), putU16(m.bytes, 0);
        break;
      case DistanceEncoding::Sqrt8: {
        const double e = std::sqrt(std::abs(d) / largest);
        const double b = 0.5 + 0.5 * (d < 0 ? -e : e);
        m.bytes.insert(m.bytes.end(), {128, 128, std::uint8_t(std::lround(b * 255)), 0});
        break;
      }
    }
  }
  return m;
}

double sphereDistance(double r, double h) { return std::hypot(r, h) - 1.0; }

ShapeGrid sphereGrid(int width) {
  ShapeGrid g;
  g.width = width;
  g.height = 2 * width;
  g.texelSize = 1.25 / width;
  g.hMin = -1.25;
  return g;
}

// The margin that makes samples lower bounds of the exact distance, measured on a sub-texel lattice
// near the surface, plus the quantisation step.
double measuredMargin(const EncodedShapeMap& m, const ShapeGrid& g) {
  double over = 0;
  for (double h = -1.2; h <= 1.2; h += g.texelSize / 7)
    for (double r = 0; r <= 1.2; r += g.texelSize / 7) {
      const double exact = sphereDistance(r, h);
      if (std::abs(exact) > 0.2) continue;
      over = std::max(over, sampleDistance(m, g, r, h) - exact);
    }
  return over + m.distanceScale / 65535.0;
}

Profile sphereProfile() {
  Profile p;
  Contour c;
  c.segments.push_back({{0, -1}, {0, 1}, 1.0, false});  // half circle through (1, 0)
  c.segments.push_back({{0, 1}, {0, -1}, 0.0, true});
  c.closed = true;
  p.contours.push_back(c);
  return p;
}

Profile polygonProfile(std::vector<Point2> points) {
  Profile p;
  Contour c;
  c.closed = true;
  for (std::size_t k = 0; k < points.size(); ++k) {
    Segment s{points[k], points[(k + 1) % points.size()], 0, false};
    s.onAxis = s.a.r == 0 && s.b.r == 0;
    c.segments.push_back(s);
  }
  p.contours.push_back(c);
  return p;
}

Vec3d randomUnit(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  Vec3d v{n(rng), n(rng), n(rng)};
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / l, v[1] / l, v[2] / l};
}

// A ray from distance `far` towards a random point within `spread` of `target`.
Ray randomRay(std::mt19937_64& rng, Vec3d target, double spread, double far) {
  std::uniform_real_distribution<double> u(-spread, spread);
  const Vec3d from = randomUnit(rng);
  Vec3d aim{target[0] + u(rng), target[1] + u(rng), target[2] + u(rng)};
  Ray ray;
  for (int c = 0; c < 3; ++c) ray.origin[c] = aim[c] + far * from[c];
  Vec3d d{aim[0] - ray.origin[0], aim[1] - ray.origin[1], aim[2] - ray.origin[2]};
  const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  ray.direction = {d[0] / l, d[1] / l, d[2] / l};
  return ray;
}

Vec3d at(const Ray& ray, double t) {
  return {ray.origin[0] + t * ray.direction[0], ray.origin[1] + t * ray.direction[1],
          ray.origin[2] + t * ray.direction[2]};
}

// --- sampling --------------------------------------------------------------------------------------

TEST(MarchSample, TexelCentresLinearInBetweenMirroredAtTheAxisClampedElsewhere) {
  ShapeGrid g{6, 5, 0.5, -1.0};
  ShapeField f = fieldFrom(g, [](double r, double h) { return 3 * r - 2 * h + 0.25; });
  const EncodedShapeMap m = encode(f, DistanceEncoding::Float);
  for (int j = 0; j < g.height; ++j)
    for (int i = 0; i < g.width; ++i)
      EXPECT_DOUBLE_EQ(sampleDistance(m, g, g.centreR(i), g.centreH(j)), f.at(i, j));
  // Between centres the filter is exact for a linear field.
  EXPECT_NEAR(sampleDistance(m, g, 1.1, 0.3), 3 * 1.1 - 2 * 0.3 + 0.25, 1e-6);
  // r below the first centre: both taps read column 0 (mirror), so the sample is column 0's value.
  for (double r : {0.0, 0.05, 0.2, 0.25})
    EXPECT_NEAR(sampleDistance(m, g, r, g.centreH(2)), f.at(0, 2), 1e-6) << "r " << r;
  // Mirrored: -r reads like r.
  EXPECT_DOUBLE_EQ(sampleDistance(m, g, -0.6, 0.1), sampleDistance(m, g, 0.6, 0.1));
  // Clamped beyond the last column and below/above the rows.
  EXPECT_NEAR(sampleDistance(m, g, 10.0, g.centreH(1)), f.at(g.width - 1, 1), 1e-6);
  EXPECT_NEAR(sampleDistance(m, g, g.centreR(2), -5.0), f.at(2, 0), 1e-6);
  EXPECT_NEAR(sampleDistance(m, g, g.centreR(2), 50.0), f.at(2, g.height - 1), 1e-6);
}

TEST(MarchSample, FiltersEncodedValuesBeforeDecoding) {
  ShapeGrid g{2, 1, 1.0, 0.0};
  ShapeField f = fieldFrom(g, [](double r, double) { return r < 1 ? -0.04 : 1.0; });
  const EncodedShapeMap m = encode(f, DistanceEncoding::Sqrt8);
  // Halfway between the centres: the sqrt-encoded values are averaged, then squared.
  const double b0 = std::lround((0.5 - 0.5 * std::sqrt(0.04)) * 255) / 255.0, b1 = 1.0;
  const double e = (b0 + b1) - 1;  // 2 * average - 1
  EXPECT_NEAR(sampleDistance(m, g, 1.0, 0.5), e * std::abs(e) * m.distanceScale, 1e-12);
  // Unorm16 is linear: filtering before or after decoding agree within quantisation.
  const EncodedShapeMap u = encode(f, DistanceEncoding::Unorm16);
  EXPECT_NEAR(sampleDistance(u, g, 1.0, 0.5), 0.5 * (-0.04 + 1.0), 2 * u.distanceScale / 65535);
}

TEST(MarchSample, ReadsTheBakesEncodingsAsItsDecoderDoes) {
  const ShapeGrid g = sphereGrid(24);
  const ShapeField field = fieldFrom(g, sphereDistance);
  for (DistanceEncoding encoding : {DistanceEncoding::Float, DistanceEncoding::Unorm16, DistanceEncoding::Sqrt8}) {
    const EncodedShapeMap encoded = encodeShapeMap(field, encoding);
    const ShapeField decoded = decodeShapeMap(encoded, g);
    for (int j = 0; j < g.height; ++j)
      for (int i = 0; i < g.width; ++i)
        ASSERT_NEAR(sampleDistance(encoded, g, g.centreR(i), g.centreH(j)), decoded.at(i, j), 1e-6)
            << encodingName(encoding) << " texel " << i << "," << j;
  }
}

// --- exact intersection -----------------------------------------------------------------------------

TEST(MarchExact, SphereMatchesTheClosedForm) {
  const Profile sphere = sphereProfile();
  std::mt19937_64 rng(7);
  int hits = 0;
  for (int k = 0; k < 2000; ++k) {
    const Ray ray = randomRay(rng, {0, 0, 0}, 1.1, 4.0);
    // |o + t d|^2 = 1: t = -b - sqrt(b^2 - c + 1), b = o.d, c = |o|^2.
    const double b = ray.origin[0] * ray.direction[0] + ray.origin[1] * ray.direction[1] + ray.origin[2] * ray.direction[2];
    const double c = ray.origin[0] * ray.origin[0] + ray.origin[1] * ray.origin[1] + ray.origin[2] * ray.origin[2];
    const double disc = b * b - c + 1;
    const auto t = intersectExact(ray, sphere);
    if (disc < 1e-9) {
      EXPECT_FALSE(t.has_value() && disc < -1e-9) << "ray " << k;
      continue;
    }
    ASSERT_TRUE(t.has_value()) << "ray " << k;
    EXPECT_NEAR(*t, -b - std::sqrt(disc), 1e-9) << "ray " << k;
    ++hits;
  }
  EXPECT_GT(hits, 500);
}

TEST(MarchExact, CylinderWithCapsMatchesTheClosedForm) {
  // r = 1, h in [0, 2], closed along the axis.
  const Profile can = polygonProfile({{0, 0}, {1, 0}, {1, 2}, {0, 2}});
  std::mt19937_64 rng(11);
  int wall = 0, cap = 0;
  for (int k = 0; k < 2000; ++k) {
    const Ray ray = randomRay(rng, {0, 1, 0}, 1.2, 5.0);
    // Slab and infinite cylinder, intersected.
    double tIn = -1e300, tOut = 1e300;
    const double dy = ray.direction[1];
    if (dy != 0) {
      double a = (0 - ray.origin[1]) / dy, b = (2 - ray.origin[1]) / dy;
      tIn = std::max(tIn, std::min(a, b)), tOut = std::min(tOut, std::max(a, b));
    }
    const double A = ray.direction[0] * ray.direction[0] + ray.direction[2] * ray.direction[2];
    const double B = ray.origin[0] * ray.direction[0] + ray.origin[2] * ray.direction[2];
    const double C = ray.origin[0] * ray.origin[0] + ray.origin[2] * ray.origin[2] - 1;
    const double disc = B * B - A * C;
    const bool expected = disc > 0 && std::max(tIn, (-B - std::sqrt(disc)) / A) < std::min(tOut, (-B + std::sqrt(disc)) / A);
    const auto t = intersectExact(ray, can);
    ASSERT_EQ(t.has_value(), expected) << "ray " << k;
    if (!expected) continue;
    const double tCyl = (-B - std::sqrt(disc)) / A;
    const double want = std::max(tIn, tCyl);
    EXPECT_NEAR(*t, want, 1e-9) << "ray " << k;
    (tCyl > tIn ? wall : cap)++;
  }
  EXPECT_GT(wall, 200);
  EXPECT_GT(cap, 200);
}

TEST(MarchExact, ConeHitsLieOnTheConeAndNothingIsCrossedBefore) {
  // Solid cone: base radius 1 at h = 0, apex at h = 1.5.
  const Profile cone = polygonProfile({{0, 0}, {1, 0}, {0, 1.5}});
  auto inside = [](const Vec3d& p) { return p[1] > 0 && p[1] < 1.5 && std::hypot(p[0], p[2]) < 1 - p[1] / 1.5; };
  std::mt19937_64 rng(13);
  int hits = 0;
  for (int k = 0; k < 1000; ++k) {
    const Ray ray = randomRay(rng, {0, 0.5, 0}, 0.8, 4.0);
    const auto t = intersectExact(ray, cone);
    // Dense walk: the first inside point brackets the entry.
    double firstInside = -1;
    for (double s = 0; s < 8; s += 1e-3)
      if (inside(at(ray, s))) {
        firstInside = s;
        break;
      }
    if (firstInside < 0) {
      if (t) {  // allowed only for a graze that the walk stepped over
        const Vec3d p = at(ray, *t);
        EXPECT_NEAR(std::hypot(p[0], p[2]), std::max(0.0, 1 - p[1] / 1.5), 1e-7) << "ray " << k;
      }
      continue;
    }
    ASSERT_TRUE(t.has_value()) << "ray " << k;
    EXPECT_LE(*t, firstInside + 1e-12);
    EXPECT_GT(*t, firstInside - 1e-3 - 1e-9);
    const Vec3d p = at(ray, *t);
    const double onSide = std::abs(std::hypot(p[0], p[2]) - (1 - p[1] / 1.5));
    const double onBase = std::abs(p[1]);
    EXPECT_LT(std::min(onSide, onBase), 1e-9) << "ray " << k;
    ++hits;
  }
  EXPECT_GT(hits, 300);
}

TEST(MarchExact, TorusHitsLieOnTheTorusAndNothingIsCrossedBefore) {
  // Tube of radius 0.5 around the circle r = 2, h = 0: two half-circle arcs.
  Profile torus;
  Contour c;
  c.closed = true;
  c.segments.push_back({{2, -0.5}, {2, 0.5}, 1.0, false});
  c.segments.push_back({{2, 0.5}, {2, -0.5}, 1.0, false});
  torus.contours.push_back(c);
  auto tubeDistance = [](const Vec3d& p) { return std::hypot(std::hypot(p[0], p[2]) - 2, p[1]) - 0.5; };
  std::mt19937_64 rng(17);
  int hits = 0, throughHole = 0;
  for (int k = 0; k < 1000; ++k) {
    const Ray ray = randomRay(rng, {0, 0, 0}, 2.5, 6.0);
    const auto t = intersectExact(ray, torus);
    // Sphere-trace the closed-form torus distance for the reference entry.
    double s = 0, reference = -1;
    for (int it = 0; it < 100000 && s < 20; ++it) {
      const double d = tubeDistance(at(ray, s));
      if (d < 1e-12) {
        reference = s;
        break;
      }
      s += d;
    }
    if (reference < 0) {
      if (t) EXPECT_LT(std::abs(tubeDistance(at(ray, *t))), 1e-8) << "ray " << k;  // graze
      else ++throughHole;
      continue;
    }
    ASSERT_TRUE(t.has_value()) << "ray " << k;
    EXPECT_NEAR(*t, reference, 1e-8) << "ray " << k;
    ++hits;
  }
  EXPECT_GT(hits, 200);
  EXPECT_GT(throughHole, 50);
}

TEST(MarchExact, RaysAwayFromTheObjectMiss) {
  Ray ray{{3, 0, 0}, {1, 0, 0}};
  EXPECT_FALSE(intersectExact(ray, sphereProfile()).has_value());
  EXPECT_FALSE(intersectExact(ray, Profile{}).has_value());
}

// --- proxy bands and the march -----------------------------------------------------------------------

struct SphereMap {
  ShapeGrid grid;
  ShapeField field;
  EncodedShapeMap encoded;
  double margin = 0;
  std::vector<ProxyBand> bands;
};

SphereMap sphereMap(int width, DistanceEncoding encoding = DistanceEncoding::Unorm16) {
  SphereMap s;
  s.grid = sphereGrid(width);
  s.field = fieldFrom(s.grid, sphereDistance);
  s.encoded = encode(s.field, encoding);
  s.margin = measuredMargin(s.encoded, s.grid);
  s.bands = buildProxyBands(s.field, 16, s.margin);
  return s;
}

TEST(MarchProxy, BandsContainEverySurfacePointAndAreTight) {
  const SphereMap s = sphereMap(128);
  ASSERT_EQ(s.bands.size(), 16u);
  EXPECT_DOUBLE_EQ(s.bands.front().hMin, s.grid.hMin);
  EXPECT_NEAR(s.bands.back().hMax, s.grid.hMin + s.grid.height * s.grid.texelSize, 1e-12);
  for (std::size_t b = 1; b < s.bands.size(); ++b) EXPECT_DOUBLE_EQ(s.bands[b].hMin, s.bands[b - 1].hMax);
  for (int k = 0; k <= 20000; ++k) {
    const double angle = std::numbers::pi * (k / 20000.0 - 0.5);
    const double r = std::cos(angle), h = std::sin(angle);
    bool inside = false;
    for (const ProxyBand& band : s.bands)
      inside |= h >= band.hMin && h <= band.hMax && r + s.margin <= band.rMax;
    EXPECT_TRUE(inside) << "surface point (" << r << ", " << h << ")";
  }
  // Bands reach one row beyond their own (the margin is below a texel here).
  const double reach = s.grid.texelSize;
  for (const ProxyBand& band : s.bands) {
    // The widest surface radius in the band and its reach (the equator, or the edge nearest it).
    const double hNearest = std::clamp(0.0, band.hMin - reach, band.hMax + reach);
    const double widest = std::abs(hNearest) < 1 ? std::sqrt(1 - hNearest * hNearest) : 0;
    if (widest > 0) EXPECT_LE(band.rMax, widest + s.margin + 1.5 * s.grid.texelSize);
  }
}

TEST(MarchProxy, TallMapsCutBandsOnRowGroupsAndStillContainTheSurface) {
  const ShapeGrid g = sphereGrid(1000);  // 2000 rows: cuts every 2 rows
  const ShapeField field = fieldFrom(g, sphereDistance);
  const double margin = 0.5 * g.texelSize;
  const std::vector<ProxyBand> bands = buildProxyBands(field, 64, margin);
  ASSERT_EQ(bands.size(), 64u);
  for (std::size_t b = 1; b < bands.size(); ++b) EXPECT_DOUBLE_EQ(bands[b].hMin, bands[b - 1].hMax);
  for (int k = 0; k <= 20000; ++k) {
    const double angle = std::numbers::pi * (k / 20000.0 - 0.5);
    const double r = std::cos(angle), h = std::sin(angle);
    bool inside = false;
    for (const ProxyBand& band : bands) inside |= h >= band.hMin && h <= band.hMax && r + margin <= band.rMax;
    EXPECT_TRUE(inside) << "surface point (" << r << ", " << h << ")";
  }
}

TEST(MarchProxy, EntryAndExitBracketTheSphere) {
  const SphereMap s = sphereMap(64);
  const Profile sphere = sphereProfile();
  std::mt19937_64 rng(3);
  for (int k = 0; k < 500; ++k) {
    const Ray ray = randomRay(rng, {0, 0, 0}, 1.0, 4.0);
    const auto span = enterBands(ray, s.bands);
    const auto t = intersectExact(ray, sphere);
    if (!t) continue;
    ASSERT_TRUE(span.has_value()) << "ray " << k;
    EXPECT_LE((*span)[0], *t);
    EXPECT_GE((*span)[1], *t);
  }
  EXPECT_FALSE(enterBands(Ray{{5, 0, 0}, {0, 1, 0}}, s.bands).has_value());
}

TEST(March, HitsLieWithinMarginAndEpsilonOfTheSphere) {
  const SphereMap s = sphereMap(128);
  MarchSettings settings;
  settings.maxIterations = 256;
  settings.safetyMargin = s.margin;
  settings.hitEpsilon = 0.05 * s.grid.texelSize;
  const Profile sphere = sphereProfile();
  std::mt19937_64 rng(5);
  for (bool proxy : {true, false})
    for (double omega : {1.0, 1.6}) {
      settings.useProxy = proxy;
      settings.overRelaxation = omega;
      int hits = 0;
      for (int k = 0; k < 1000; ++k) {
        const Ray ray = randomRay(rng, {0, 0, 0}, 1.1, 4.0);
        const MarchResult m = marchRay(ray, s.encoded, s.grid, s.bands, settings);
        const auto t = intersectExact(ray, sphere);
        if (m.hit) {
          const Vec3d p = at(ray, m.t);
          const double d = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1;
          EXPECT_GE(d, -1e-9) << "ray " << k << " inside the sphere";
          // (The margin is measured on a sub-texel lattice: allow 1 % for points between its nodes.)
          EXPECT_LE(d, 1.01 * (s.margin + settings.hitEpsilon)) << "ray " << k;
          // A ray grazing within margin + epsilon of the sphere hits the march's surface only.
          if (t) EXPECT_LE(m.t, *t + 1e-9);
          ++hits;
        }
        EXPECT_LE(m.fetches, settings.maxIterations);
      }
      EXPECT_GT(hits, 400) << "proxy " << proxy << " omega " << omega;
    }
}

TEST(March, MismatchFallsWithTheBudget) {
  const SphereMap s = sphereMap(128);
  MarchSettings base;
  base.safetyMargin = s.margin;
  base.hitEpsilon = 0.05 * s.grid.texelSize;
  MarchErrorSettings sweep;
  sweep.raysPerView = 64 * 64;
  sweep.views = 4;
  sweep.iterationBudgets = {4, 8, 16, 32, 64, 128};
  sweep.threads = 2;
  const std::vector<MarchErrorPoint> curve = measureMarchError(sphereProfile(), s.encoded, s.grid, s.bands, base, sweep);
  ASSERT_EQ(curve.size(), sweep.iterationBudgets.size());
  for (std::size_t k = 0; k < curve.size(); ++k) {
    EXPECT_EQ(curve[k].iterations, sweep.iterationBudgets[k]);
    EXPECT_TRUE(std::isfinite(curve[k].silhouetteMismatch));
    if (k > 0) {
      EXPECT_LE(curve[k].silhouetteMismatch, curve[k - 1].silhouetteMismatch + 1e-3) << "budget " << curve[k].iterations;
      EXPECT_GE(curve[k].meanFetches, curve[k - 1].meanFetches);
    }
  }
  EXPECT_GT(curve.front().silhouetteMismatch, 0.05);
  EXPECT_LT(curve.back().silhouetteMismatch, 0.01);
  // Hits stop margin + epsilon before the surface; along a grazing ray that is up to
  // sqrt(2 R (margin + epsilon)) before the reference hit.
  const double stop = s.margin + base.hitEpsilon;
  EXPECT_LE(curve.back().meanHitError, 3 * stop);
  EXPECT_LE(curve.back().maxHitError, std::sqrt(2 * stop) + stop);
  for (const MarchErrorPoint& p : curve)
    std::printf("budget %3d mismatch %.5f meanHitError %.2e maxHitError %.2e fetches %.2f\n", p.iterations,
                p.silhouetteMismatch, p.meanHitError, p.maxHitError, p.meanFetches);
  // The same curve whatever the thread count.
  sweep.threads = 1;
  const std::vector<MarchErrorPoint> serial = measureMarchError(sphereProfile(), s.encoded, s.grid, s.bands, base, sweep);
  for (std::size_t k = 0; k < curve.size(); ++k) {
    EXPECT_EQ(serial[k].silhouetteMismatch, curve[k].silhouetteMismatch);
    EXPECT_EQ(serial[k].meanHitError, curve[k].meanHitError);
  }
  EXPECT_EQ(iterationsForTarget(curve, 0.01), [&] {
    for (const MarchErrorPoint& p : curve)
      if (p.silhouetteMismatch <= 0.01) return p.iterations;
    return 0;
  }());
}

TEST(March, IterationsForTargetPicksTheSmallestBudgetOrTheLargest) {
  std::vector<MarchErrorPoint> curve(3);
  curve[0] = {10, 0.2}, curve[1] = {20, 0.004}, curve[2] = {40, 0.001};
  EXPECT_EQ(iterationsForTarget(curve, 0.005), 20);
  EXPECT_EQ(iterationsForTarget(curve, 0.0001), 40);
  EXPECT_EQ(iterationsForTarget(curve, 0.5), 10);
}

TEST(March, RelaxedStepsNeverJumpOverAThinRing) {
  // A ring: tube of radius 0.1 about r = 0.6, h = 0.25; the march interval hugs it, so an
  // over-relaxed step from the hole can leave the interval across the tube.
  ShapeGrid g{192, 80, 0.75 / 192, 0.1};
  const ShapeField field = fieldFrom(g, [](double r, double h) { return std::hypot(r - 0.6, h - 0.25) - 0.1; });
  const EncodedShapeMap encoded = encode(field, DistanceEncoding::Float);
  Profile ring;
  Contour c;
  c.segments.push_back({{0.7, 0.25}, {0.5, 0.25}, 1.0, false});
  c.segments.push_back({{0.5, 0.25}, {0.7, 0.25}, 1.0, false});
  ring.contours.push_back(c);
  MarchSettings settings;
  settings.maxIterations = 256;
  settings.safetyMargin = 0.75 * g.texelSize;  // above the bilinear overestimate of this field
  const std::vector<ProxyBand> bands = buildProxyBands(field, 16, settings.safetyMargin);
  std::mt19937_64 rng(23);
  int deepHits = 0;
  for (int k = 0; k < 3000; ++k) {
    const Ray ray = randomRay(rng, {0, 0.25, 0}, 0.7, 3.0);
    const auto t = intersectExact(ray, ring);
    if (!t) continue;
    // Rays that cross the tube more than a texel deep must be hits.
    double deepest = 0;
    for (double s = *t; s < *t + 0.3; s += 1e-3) {
      const Vec3d p = at(ray, s);
      deepest = std::min(deepest, std::hypot(std::hypot(p[0], p[2]) - 0.6, p[1] - 0.25) - 0.1);
    }
    if (deepest > -g.texelSize) continue;
    ++deepHits;
    const MarchResult m = marchRay(ray, encoded, g, bands, settings);
    EXPECT_TRUE(m.hit) << "ray " << k << " fetches " << m.fetches;
    if (m.hit) EXPECT_LE(m.t, *t + 1e-9);
  }
  EXPECT_GT(deepHits, 300);
}

// --- stiff cases: axis rays, grazing rays, extreme scales, degenerate input ------------------------

Profile scaledSphere(double radius) {
  Profile p;
  Contour c;
  c.segments.push_back({{0, -radius}, {0, radius}, 1.0, false});
  p.contours.push_back(c);
  return p;
}

TEST(MarchStiff, RaysAlongAndParallelToTheAxis) {
  // Down the axis: r(t) = 0 throughout.
  const Ray down{{0, 5, 0}, {0, -1, 0}};
  ASSERT_TRUE(intersectExact(down, sphereProfile()).has_value());
  EXPECT_NEAR(*intersectExact(down, sphereProfile()), 4.0, 1e-12);
  const Profile can = polygonProfile({{0, 0}, {1, 0}, {1, 2}, {0, 2}});
  EXPECT_NEAR(*intersectExact(down, can), 3.0, 1e-12);
  // Parallel to the axis inside the can's radius hits the cap; on the wall's radius it grazes.
  EXPECT_NEAR(*intersectExact(Ray{{0.7, -3, 0}, {0, 1, 0}}, can), 3.0, 1e-12);
  EXPECT_FALSE(intersectExact(Ray{{1.5, -3, 0}, {0, 1, 0}}, can).has_value());
  const Profile cone = polygonProfile({{0, 0}, {1, 0}, {0, 1.5}});
  EXPECT_NEAR(*intersectExact(Ray{{0, 0.5, 0.5}, {0, 1, 0}}, cone), 0.25, 1e-12);  // r = 0.5 at h = 0.75
  // The march down the axis (column 0 mirrored) stops within margin + epsilon above the pole.
  const SphereMap s = sphereMap(64);
  MarchSettings settings;
  settings.maxIterations = 128;
  settings.safetyMargin = s.margin;
  const MarchResult m = marchRay(down, s.encoded, s.grid, s.bands, settings);
  ASSERT_TRUE(m.hit);
  EXPECT_LE(m.t, 4.0);
  EXPECT_GE(m.t, 4.0 - s.margin - 0.05 * s.grid.texelSize - 1e-9);
}

TEST(MarchStiff, GrazingRaysFinishWithAFiniteAnswer) {
  const Profile sphere = sphereProfile();
  for (double offset : {-1e-12, 0.0, 1e-12, 1e-9, 1e-6}) {
    const Ray ray{{-5, 0.3, std::sqrt(1 - 0.09) + offset}, {1, 0, 0}};
    const auto t = intersectExact(ray, sphere);
    if (t) {
      EXPECT_TRUE(std::isfinite(*t));
      EXPECT_NEAR(*t, 5.0, 2e-3) << "offset " << offset;  // the tangent point, to sqrt(offset)
    }
    if (offset >= 1e-9) EXPECT_FALSE(t.has_value()) << "offset " << offset;
  }
  // Grazing the torus's outer equator and the inside of its hole.
  Profile torus;
  Contour c;
  c.segments.push_back({{2, -0.5}, {2, 0.5}, 1.0, false});
  c.segments.push_back({{2, 0.5}, {2, -0.5}, 1.0, false});
  torus.contours.push_back(c);
  for (double z : {2.5, 1.5, 2.5 + 1e-10, 1.5 - 1e-10}) {
    const auto t = intersectExact(Ray{{-6, 0, z}, {1, 0, 0}}, torus);
    if (t) EXPECT_TRUE(std::isfinite(*t));
  }
}

TEST(MarchStiff, HugeAndTinyProfilesKeepRelativeAccuracy) {
  for (double radius : {1e-6, 1e-3, 1e3, 1e6}) {
    const Profile sphere = scaledSphere(radius);
    const Ray ray{{-3 * radius, 0.2 * radius, 0.1 * radius}, {1, 0, 0}};
    const double expected = 3 * radius - std::sqrt(1 - 0.05) * radius;
    const auto t = intersectExact(ray, sphere);
    ASSERT_TRUE(t.has_value()) << "radius " << radius;
    EXPECT_NEAR(*t, expected, 1e-10 * radius) << "radius " << radius;
    const Profile can = polygonProfile({{0, 0}, {radius, 0}, {radius, radius}, {0, radius}});
    const auto tc = intersectExact(Ray{{-3 * radius, 0.5 * radius, 0}, {1, 0, 0}}, can);
    ASSERT_TRUE(tc.has_value());
    EXPECT_NEAR(*tc, 2 * radius, 1e-12 * radius);
  }
}

TEST(MarchStiff, NearlyStraightArcsActLikeTheirChord) {
  Profile arc, chord;
  Contour a, b;
  a.segments.push_back({{1, 0}, {1, 2}, 1e-13, false});
  b.segments.push_back({{1, 0}, {1, 2}, 0.0, false});
  arc.contours.push_back(a), chord.contours.push_back(b);
  const Ray ray{{-4, 0.7, 0.2}, {1, 0, 0}};
  ASSERT_TRUE(intersectExact(ray, chord).has_value());
  EXPECT_NEAR(*intersectExact(ray, arc), *intersectExact(ray, chord), 1e-12);
}

TEST(MarchStiff, BrokenRaysAndEmptyInputsGiveMissesNotNaN) {
  const SphereMap s = sphereMap(32);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Ray broken{{nan, 0, 0}, {1, 0, 0}};
  EXPECT_FALSE(intersectExact(broken, sphereProfile()).has_value());
  MarchSettings settings;
  settings.safetyMargin = s.margin;
  EXPECT_FALSE(marchRay(broken, s.encoded, s.grid, s.bands, settings).hit);
  EXPECT_TRUE(std::isfinite(sampleDistance(s.encoded, s.grid, nan, nan)));
  // An empty grid: no bands, nothing to sample, every ray misses.
  const ShapeGrid empty{};
  EXPECT_TRUE(buildProxyBands(ShapeField{}, 16, 0.0).empty());
  EXPECT_FALSE(marchRay(Ray{{-5, 0, 0}, {1, 0, 0}}, EncodedShapeMap{}, empty, {}, settings).hit);
  EXPECT_TRUE(measureMarchError(Profile{}, EncodedShapeMap{}, empty, {}, settings, MarchErrorSettings{}).empty());
  // Band counts beyond the format's limit are clamped.
  EXPECT_EQ(buildProxyBands(s.field, 1000, s.margin).size(), 64u);
  EXPECT_EQ(buildProxyBands(s.field, 0, s.margin).size(), 1u);
}

// --- the bake's own field on a vase with arcs -------------------------------------------------------

// The vase of profile_shapes.h through the bake's stages at the default size (1024 texels high,
// exact field, unorm16, measured margin, 16 bands), marched from 6 views of 128 x 128 rays.
TEST(MarchVase, SilhouetteMismatchFallsAndTheProxyNeverHurts) {
  const int resolution = 1024;
  Profile vase = test::makeProfile({test::vaseContour()});
  std::vector<std::string> warnings;
  ASSERT_TRUE(validateProfile(vase, warnings).isOk());
  const ShapeGrid grid = gridForBounds(profileBounds(vase), resolution, 4);
  const ShapeField field = distanceFromProfile(vase, grid);
  const EncodedShapeMap encoded = encodeShapeMap(field, DistanceEncoding::Unorm16);
  const SafetyMargin margin = measureSafetyMargin(decodeShapeMap(encoded, grid), &vase);
  MarchSettings base;
  base.safetyMargin = margin.total();
  base.hitEpsilon = 0.05 * grid.texelSize;
  const std::vector<ProxyBand> bands = buildProxyBands(field, 16, base.safetyMargin);
  // Bands never cut the solid: every surface point, widened by the margin, is inside one.
  for (const Contour& contour : vase.contours)
    for (const Segment& piece : contour.segments)
      for (int k = 0; k <= 400; ++k) {
        const Point2 p = test::densePoint(piece, k / 400.0);
        bool inside = false;
        for (const ProxyBand& band : bands)
          inside |= p.h >= band.hMin && p.h <= band.hMax && p.r + base.safetyMargin <= band.rMax;
        EXPECT_TRUE(inside) << "surface point (" << p.r << ", " << p.h << ")";
      }
  MarchErrorSettings sweep;
  std::vector<std::vector<MarchErrorPoint>> curves;
  for (bool proxy : {true, false}) {
    base.useProxy = proxy;
    curves.push_back(measureMarchError(vase, encoded, grid, bands, base, sweep));
  }
  std::printf("vase %dx%d unorm16, margin %.3g texels, %d rays x %d views\n", grid.width, grid.height,
              base.safetyMargin / grid.texelSize, sweep.raysPerView, sweep.views);
  for (std::size_t k = 0; k < curves[0].size(); ++k) {
    const MarchErrorPoint &a = curves[0][k], &b = curves[1][k];
    std::printf("budget %3d  proxy: mismatch %.5f fetches %6.2f meanHit %.2e | box: mismatch %.5f fetches %6.2f\n",
                a.iterations, a.silhouetteMismatch, a.meanFetches, a.meanHitError, b.silhouetteMismatch, b.meanFetches);
    // Starting at the bands never costs accuracy at equal budget and saves fetches.
    EXPECT_LE(a.silhouetteMismatch, b.silhouetteMismatch + 1e-3) << "budget " << a.iterations;
    EXPECT_LE(a.meanFetches, b.meanFetches) << "budget " << a.iterations;
  }
  EXPECT_GT(curves[0].front().silhouetteMismatch, curves[0].back().silhouetteMismatch);
  // Measured 0.69 % at 35 fetches and 0.16 % once converged (the rest are rays grazing the march's
  // surface, margin + epsilon outside the true one).
  const auto at35 = std::find_if(curves[0].begin(), curves[0].end(), [](const MarchErrorPoint& p) { return p.iterations == 35; });
  ASSERT_NE(at35, curves[0].end());
  EXPECT_LE(at35->silhouetteMismatch, 0.01);
  EXPECT_LE(curves[0].back().silhouetteMismatch, 0.003);
  EXPECT_LE(curves[0].back().meanHitError, 3 * (base.safetyMargin + base.hitEpsilon));
}

}  // namespace
}  // namespace bake::revolution
