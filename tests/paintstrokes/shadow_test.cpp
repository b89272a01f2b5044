// Baked self-shadowing (libbake/paintstrokes/shadow.h): the surface is lit, the scale falls with depth and
// with grazing light as exp(-density t / c), light from behind gives the minimum, no normal gives 1.
#include <cmath>

#include <gtest/gtest.h>

#include "paintstrokes/bake/shadow.h"

namespace bake::paintstrokes {
namespace {

StrokePoint at(double depth, Vec3d normal = {0, 1, 0}) {
  StrokePoint p;
  p.depth = depth;
  p.globalNormal = normal;
  return p;
}

TEST(PaintstrokesShadow, MatchesTheBeerLambertPathThroughTheVolume) {
  const Vec3d up{0, 1, 0};
  const double density = 2.5, minimum = 0.15;
  EXPECT_DOUBLE_EQ(shadowScale(at(0), up, density, minimum), 1.0);  // at the surface: fully lit
  // Straight down: path = t.
  EXPECT_NEAR(shadowScale(at(0.4), up, density, minimum), minimum + (1 - minimum) * std::exp(-density * 0.4), 1e-15);
  // 60 degrees from the normal: c = 0.5, the path doubles.
  const Vec3d slanted{std::sqrt(3.0) / 2, 0.5, 0};
  EXPECT_NEAR(shadowScale(at(0.4), slanted, density, minimum), minimum + (1 - minimum) * std::exp(-density * 0.8), 1e-12);
  // Grazing light is clamped at c = 0.05.
  const Vec3d grazing{std::sqrt(1 - 0.01 * 0.01), 0.01, 0};
  EXPECT_NEAR(shadowScale(at(0.1), grazing, density, minimum), minimum + (1 - minimum) * std::exp(-density * 0.1 / 0.05), 1e-12);
  // From behind: the far side of the volume.
  EXPECT_DOUBLE_EQ(shadowScale(at(0.0), {0, -1, 0}, density, minimum), minimum);
  EXPECT_DOUBLE_EQ(shadowScale(at(0.5), {1, 0, 0}, density, minimum), minimum);
  // No global normal: unshadowed whatever the depth.
  EXPECT_DOUBLE_EQ(shadowScale(at(1, {0, 0, 0}), up, density, minimum), 1.0);
}

TEST(PaintstrokesShadow, DeeperIsDarkerAndNeverBelowTheMinimum) {
  const Vec3d d = defaultLightDirection();
  double previous = 2;
  for (int k = 0; k <= 20; ++k) {
    const double s = shadowScale(at(k / 20.0), d, 10.0, 0.2);
    EXPECT_LT(s, previous);
    EXPECT_GE(s, 0.2);
    previous = s;
  }
}

TEST(PaintstrokesShadow, DefaultDirectionIsTheRuntimeLightNormalisedAndTheTableIsPointMajor) {
  const Vec3d d = defaultLightDirection();
  EXPECT_NEAR(std::hypot(d[0], d[1], d[2]), 1.0, 1e-15);
  EXPECT_NEAR(d[1] / d[0], 2.0, 1e-15);
  StrokeSet set;
  set.strokes.resize(2);
  set.strokes[0].points = {at(0), at(0.5)};
  set.strokes[1].points = {at(1, {1, 0, 0})};
  const std::vector<Vec3d> directions = {{0, 1, 0}, {1, 0, 0}};
  const std::vector<double> table = bakeShadows(set, directions, 2.5, 0.15);
  ASSERT_EQ(table.size(), 6u);
  EXPECT_DOUBLE_EQ(table[2 * 1 + 0], shadowScale(at(0.5), directions[0], 2.5, 0.15));
  EXPECT_DOUBLE_EQ(table[2 * 2 + 0], 0.15);  // normal +x, light from +y: behind
  EXPECT_DOUBLE_EQ(table[2 * 2 + 1], shadowScale(at(1, {1, 0, 0}), directions[1], 2.5, 0.15));
}

}  // namespace
}  // namespace bake::paintstrokes
