// Displacement map (libbake/revolution/displacement.cpp) against analytic derivatives: a sinusoid in
// u has the derivative 2 pi k A cos(2 pi k u), also across the seam where the differences wrap; a
// ramp in v has a constant derivative, one-sided at the ends. The unorm16 bytes decode back to the
// derivatives within the quantisation step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>

#include "revolution/bake/displacement.h"

namespace bake::revolution {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

HeightMap sampled(int width, int height, double (*h)(double u, double v)) {
  HeightMap map{width, height, {}};
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) map.height01.push_back(float(h((i + 0.5) / width, (j + 0.5) / height)));
  return map;
}

double decodeUnorm16(const std::vector<std::uint8_t>& bytes, std::size_t component) {
  const unsigned v = bytes[2 * component] | (unsigned(bytes[2 * component + 1]) << 8);
  return v / 65535.0;
}

TEST(Displacement, SinusoidInUGivesTheCosineAcrossTheSeam) {
  const int width = 256, height = 8, k = 3;
  const double amplitude = 0.4, heightScale = 0.01;
  const HeightMap map = sampled(width, height, [](double u, double) { return 0.5 + 0.4 * std::sin(kTwoPi * 3 * u); });
  const DisplacementMap d = buildDisplacementMap(map, heightScale);
  ASSERT_EQ(d.width, width);
  ASSERT_EQ(d.height, height);
  // Central differences of sin have the factor sin(x)/x with x = 2 pi k / width.
  const double x = kTwoPi * k / width;
  const double discreteFactor = std::sin(x) / x;
  double largest = 0;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const double u = (i + 0.5) / width;
      const double exact = heightScale * amplitude * kTwoPi * k * std::cos(kTwoPi * k * u);
      const double got = d.dHdu[std::size_t(j) * width + i];
      EXPECT_NEAR(got, exact * discreteFactor, 1e-6 * std::abs(exact) + 1e-7) << "texel " << i << "," << j;
      EXPECT_NEAR(got, exact, 2e-3 * heightScale * amplitude * kTwoPi * k);
      EXPECT_NEAR(d.dHdv[std::size_t(j) * width + i], 0, 1e-9);
      largest = std::max(largest, std::abs(got));
    }
  // The seam texels (first and last column) use the wrapped neighbour.
  EXPECT_GT(d.dHdu[0], 0.9 * heightScale * amplitude * kTwoPi * k);
  EXPECT_GT(d.dHdu[width - 1], 0.9 * heightScale * amplitude * kTwoPi * k);
  EXPECT_NEAR(d.derivativeScale, largest, 1e-6 * largest);
}

TEST(Displacement, RampInVIsOneSidedAtTheEnds) {
  const int width = 4, height = 16;
  const HeightMap map = sampled(width, height, [](double, double v) { return v; });
  const DisplacementMap d = buildDisplacementMap(map, 2.0);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      EXPECT_NEAR(d.dHdv[std::size_t(j) * width + i], 2.0, 1e-5) << "row " << j;
      EXPECT_NEAR(d.dHdu[std::size_t(j) * width + i], 0.0, 1e-9);
    }
}

TEST(Displacement, BytesDecodeToTheDerivatives) {
  const int width = 64, height = 32;
  const HeightMap map = sampled(width, height, [](double u, double v) {
    return 0.5 + 0.25 * std::sin(kTwoPi * u) * std::cos(kTwoPi * v);
  });
  const DisplacementMap d = buildDisplacementMap(map, 0.5);
  ASSERT_EQ(d.bytes.size(), std::size_t(width) * height * 2 * 2);
  const double step = d.derivativeScale * 2 / 65535.0;
  for (std::size_t t = 0; t < d.dHdu.size(); ++t) {
    EXPECT_NEAR((decodeUnorm16(d.bytes, 2 * t) - 0.5) * 2 * d.derivativeScale, d.dHdu[t], step);
    EXPECT_NEAR((decodeUnorm16(d.bytes, 2 * t + 1) - 0.5) * 2 * d.derivativeScale, d.dHdv[t], step);
  }
}

TEST(Displacement, FlatAndEmptyMapsStayFinite) {
  const DisplacementMap flat = buildDisplacementMap(HeightMap{3, 1, {0.2f, 0.2f, 0.2f}}, 1.0);
  EXPECT_EQ(flat.derivativeScale, 1.0);
  for (float v : flat.dHdu) EXPECT_EQ(v, 0.0f);
  for (std::size_t c = 0; c < flat.bytes.size() / 2; ++c) EXPECT_NEAR(decodeUnorm16(flat.bytes, c), 0.5, 1e-4);
  const DisplacementMap empty = buildDisplacementMap(HeightMap{}, 1.0);
  EXPECT_EQ(empty.width, 0);
  EXPECT_TRUE(empty.bytes.empty());
}

}  // namespace
}  // namespace bake::revolution
