// Distance from images (shape_map_edt.cpp): the Felzenszwalb-Huttenlocher EDT against brute force on
// random images, the signed binary field's half-texel convention, and the anti-aliased EDT on discs
// and a vase rendered with exact area coverage against their analytic / exact distances.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <tuple>
#include <utility>
#include <cstdint>

#include "bake/revolution/shape_map.h"
#include "revolution/profile_shapes.h"

namespace bake::revolution {
namespace {

using namespace bake::revolution::test;

constexpr float kInf = std::numeric_limits<float>::infinity();

std::vector<float> bruteForceSquared(const std::vector<float>& f, int w, int h) {
  std::vector<float> out(f.size(), kInf);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          if (f[std::size_t(y) * w + x] == 0)
            out[std::size_t(j) * w + i] = std::min(out[std::size_t(j) * w + i], float((x - i) * (x - i) + (y - j) * (y - j)));
  return out;
}

// Brute force over a list of feature texels (64-bit, so large images stay exact).
std::uint64_t nearestSquared(const std::vector<std::pair<int, int>>& features, int i, int j) {
  std::uint64_t best = std::numeric_limits<std::uint64_t>::max();
  for (const auto& [x, y] : features) {
    const std::int64_t dx = x - i, dy = y - j;
    best = std::min(best, std::uint64_t(dx * dx + dy * dy));
  }
  return best;
}

// Every texel of an image with random features, both polarities, squared and rooted, against brute
// force. The sizes cross the transform's bands of rows (tall images) and its row blocks.
TEST(SquaredEdt, MatchesBruteForceOnRandomImages) {
  std::mt19937 rng(42);
  for (const auto& [width, height, density] : {std::tuple{17, 23, 0.1}, {40, 9, 0.02}, {1, 30, 0.1}, {33, 1, 0.2},
                                              {31, 31, 0.001}, {25, 25, 0.6}, {7, 1100, 0.002}, {300, 900, 0.0002},
                                              {3000, 50, 0.0005}}) {
    const int w = width, h = height;  // plain variables: the lambda below captures them
    std::bernoulli_distribution feature(density);
    std::vector<std::uint8_t> image(std::size_t(w) * h);
    for (std::uint8_t& v : image) v = feature(rng) ? 255 : 0;
    for (const FeatureTexels which : {FeatureTexels::nonZero, FeatureTexels::zero}) {
      // The feature texels that border another kind of texel (or all, when there are only features):
      // the nearest feature to a texel that is not one always does, which keeps the dense polarity cheap.
      auto isFeature = [&](int i, int j) {
        return i >= 0 && j >= 0 && i < w && j < h && (image[std::size_t(j) * w + i] != 0) == (which == FeatureTexels::nonZero);
      };
      std::vector<std::pair<int, int>> features;
      bool any = false;
      for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
          if (!isFeature(i, j)) continue;
          any = true;
          const bool border = (i > 0 && !isFeature(i - 1, j)) || (i + 1 < w && !isFeature(i + 1, j)) ||
                              (j > 0 && !isFeature(i, j - 1)) || (j + 1 < h && !isFeature(i, j + 1));
          if (border) features.push_back({i, j});
        }
      std::vector<std::uint32_t> squared(image.size());
      std::vector<float> distance(image.size());
      squaredEdtBinary(image.data(), which, w, h, squared.data());
      distanceEdtBinary(image.data(), which, w, h, distance.data());
      for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
          const std::size_t k = std::size_t(j) * w + i;
          const std::uint64_t expected = isFeature(i, j) ? 0 : nearestSquared(features, i, j);
          ASSERT_EQ(squared[k], any ? expected : kNoFeature) << w << "x" << h << " texel " << i << "," << j;
          ASSERT_EQ(distance[k], any ? float(std::sqrt(double(expected))) : kInf) << w << "x" << h << " texel " << k;
        }
    }
  }
}

TEST(SquaredEdt, NoFeatureIsReported) {
  const std::vector<std::uint8_t> image(12, 0);
  std::vector<std::uint32_t> squared(12);
  std::vector<float> distance(12);
  squaredEdtBinary(image.data(), FeatureTexels::nonZero, 4, 3, squared.data());
  distanceEdtBinary(image.data(), FeatureTexels::nonZero, 4, 3, distance.data());
  for (std::uint32_t v : squared) EXPECT_EQ(v, kNoFeature);
  for (float v : distance) EXPECT_EQ(v, kInf);
  squaredEdtBinary(image.data(), FeatureTexels::zero, 4, 3, squared.data());
  for (std::uint32_t v : squared) EXPECT_EQ(v, 0u);
}

// Distances beyond 4096 texels, whose squares a float no longer holds: two single features in the
// far corners of a long image, checked in closed form along the row and at the far end of the column.
TEST(SquaredEdt, ExactBeyondFloatPrecision) {
  const int w = 20000, h = 3;
  std::vector<std::uint8_t> image(std::size_t(w) * h, 0);
  image[0] = 1;                                  // (0, 0)
  image[std::size_t(2) * w + (w - 1)] = 1;       // (w - 1, 2)
  std::vector<std::uint32_t> squared(image.size());
  squaredEdtBinary(image.data(), FeatureTexels::nonZero, w, h, squared.data());
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; i += 997) {
      const std::uint64_t a = std::uint64_t(i) * i + std::uint64_t(j) * j;
      const std::uint64_t b = std::uint64_t(w - 1 - i) * (w - 1 - i) + std::uint64_t(2 - j) * (2 - j);
      ASSERT_EQ(squared[std::size_t(j) * w + i], std::min(a, b)) << i << "," << j;
    }
  // Texel (10000, 0): 9999^2 + 2^2 to the far feature, an odd number above 2^24 that no float holds.
  EXPECT_EQ(squared[std::size_t(w / 2)], 99980005u);
}

TEST(DistanceFromBinary, SurfaceHalfATexelBetweenThePhases) {
  std::mt19937 rng(9);
  std::bernoulli_distribution solid(0.4);
  CoverageImage image;
  image.width = 29;
  image.height = 21;
  image.texelSize = 0.25;
  image.hMin = -1;
  for (int k = 0; k < image.width * image.height; ++k) image.coverage.push_back(solid(rng) ? 1.0f : 0.0f);
  ASSERT_TRUE(isBinary(image));
  const ShapeField field = distanceFromBinary(image);
  std::vector<float> toInside(image.coverage.size()), toOutside(image.coverage.size());
  for (std::size_t k = 0; k < image.coverage.size(); ++k) {
    toInside[k] = image.coverage[k] == 1 ? 0.0f : kInf;
    toOutside[k] = image.coverage[k] == 1 ? kInf : 0.0f;
  }
  const auto in = bruteForceSquared(toInside, image.width, image.height);
  const auto out = bruteForceSquared(toOutside, image.width, image.height);
  for (std::size_t k = 0; k < image.coverage.size(); ++k) {
    const bool inside = image.coverage[k] == 1;
    const double expected = inside ? -(std::sqrt(out[k]) - 0.5) * 0.25 : (std::sqrt(in[k]) - 0.5) * 0.25;
    ASSERT_NEAR(field.distance[k], expected, 1e-6);
    EXPECT_NEAR(std::hypot(field.gradR[k], field.gradH[k]), 1.0, 1e-5);
  }
}

// Coverage of a validated profile by exact area (tested in distance_test) on a unit-texel grid.
CoverageImage render(const Profile& profile, int w, int h, double hMin) {
  ShapeGrid grid;
  grid.width = w;
  grid.height = h;
  grid.texelSize = 1.0;
  grid.hMin = hMin;
  const ShapeField exact = distanceFromProfile(profile, grid);
  CoverageImage image;
  image.width = w;
  image.height = h;
  image.texelSize = 1.0;
  image.hMin = hMin;
  image.coverage = exact.coverage;
  return image;
}

struct ErrorStats {
  double mean = 0, worst = 0;
  int count = 0;
};

ErrorStats nearSurfaceError(const ShapeField& field, const Profile& profile, double band) {
  ErrorStats stats;
  for (int j = 0; j < field.grid.height; ++j)
    for (int i = 0; i < field.grid.width; ++i) {
      const double exact = signedDistance(profile, {field.grid.centreR(i), field.grid.centreH(j)}).distance;
      if (std::abs(exact) > band) continue;
      const double error = std::abs(field.at(i, j) - exact);
      stats.mean += error;
      stats.worst = std::max(stats.worst, error);
      ++stats.count;
    }
  stats.mean /= std::max(1, stats.count);
  return stats;
}

Profile validated(std::vector<Contour> contours) {
  Profile profile = makeProfile(std::move(contours));
  std::vector<std::string> warnings;
  EXPECT_TRUE(validateProfile(profile, warnings).isOk());
  return profile;
}

TEST(DistanceFromCoverage, AntiAliasedDiscWithinThreeHundredthsOfATexel) {
  for (double radius : {6.3, 17.8, 31.4}) {
    const Profile profile = validated({circleContour(radius + 3.37, radius + 2.71, radius, 4)});
    const CoverageImage image = render(profile, int(2 * radius + 8), int(2 * radius + 8), 0.0);
    ASSERT_FALSE(isBinary(image));
    const ShapeField field = distanceFromCoverage(image);
    const ErrorStats stats = nearSurfaceError(field, profile, 2.0);
    RecordProperty("disc_" + std::to_string(int(radius)) + "_mean_error_texels", std::to_string(stats.mean));
    EXPECT_LE(stats.mean, 0.03) << "radius " << radius << " worst " << stats.worst;
    EXPECT_LT(stats.worst, 0.5) << "radius " << radius;
  }
}

TEST(DistanceFromCoverage, AntiAliasedSphereAndVaseNearTheAxis) {
  // Shapes that touch the axis: column 0 has the axis on its left edge.
  const Profile sphere = validated({halfDiscContour(20.3)});
  const ShapeField sphereField = distanceFromCoverage(render(sphere, 28, 50, -25.0));
  const ErrorStats s = nearSurfaceError(sphereField, sphere, 2.0);
  EXPECT_LE(s.mean, 0.03) << "worst " << s.worst;
  RecordProperty("sphere_mean_error_texels", std::to_string(s.mean));

  Profile vase = makeProfile({vaseContour()});
  for (Contour& c : vase.contours)
    for (Segment& seg : c.segments) {
      seg.a = {seg.a.r * 40, seg.a.h * 40};
      seg.b = {seg.b.r * 40, seg.b.h * 40};
    }
  std::vector<std::string> warnings;
  ASSERT_TRUE(validateProfile(vase, warnings).isOk());
  const ShapeField vaseField = distanceFromCoverage(render(vase, 44, 90, -5.0));
  const ErrorStats v = nearSurfaceError(vaseField, vase, 2.0);
  EXPECT_LE(v.mean, 0.03) << "worst " << v.worst;
  RecordProperty("vase_mean_error_texels", std::to_string(v.mean));
}

TEST(DistanceFromCoverage, FarTexelsKeepTheirSign) {
  const Profile profile = validated({circleContour(20, 20, 10, 4)});
  const ShapeField field = distanceFromCoverage(render(profile, 40, 40, 0.0));
  for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 40; ++i) {
      const double exact = std::hypot(i + 0.5 - 20, j + 0.5 - 20) - 10;
      if (std::abs(exact) > 1) {
        EXPECT_EQ(field.at(i, j) < 0, exact < 0);
      }
      EXPECT_NEAR(field.at(i, j), exact, 0.5);
    }
}

TEST(DistanceFromImageStiff, EmptyFullTinyAndNotFiniteImages) {
  // No surface at all: finite, large, signed by the phase.
  CoverageImage empty;
  empty.width = 5;
  empty.height = 4;
  empty.coverage.assign(20, 0.0f);
  for (const ShapeField& f : {distanceFromBinary(empty), distanceFromCoverage(empty)})
    for (float d : f.distance) {
      ASSERT_TRUE(std::isfinite(d));
      ASSERT_GT(d, 0);
    }
  CoverageImage full = empty;
  full.coverage.assign(20, 1.0f);
  for (const ShapeField& f : {distanceFromBinary(full), distanceFromCoverage(full)})
    for (float d : f.distance) {
      ASSERT_TRUE(std::isfinite(d));
      ASSERT_LT(d, 0);
    }
  // One texel wide and tall images, NaN and out-of-range coverage, a short coverage vector.
  CoverageImage odd;
  odd.width = 1;
  odd.height = 3;
  odd.coverage = {std::numeric_limits<float>::quiet_NaN(), 1.7f};
  for (const ShapeField& f : {distanceFromBinary(odd), distanceFromCoverage(odd)}) {
    ASSERT_EQ(f.distance.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
      ASSERT_TRUE(std::isfinite(f.distance[k]));
      ASSERT_TRUE(std::isfinite(f.gradR[k]) && std::isfinite(f.gradH[k]));
    }
    EXPECT_LT(f.distance[1], 0);  // 1.7 is full
    EXPECT_GT(f.distance[2], 0);  // missing is empty
  }
}

}  // namespace
}  // namespace bake::revolution
