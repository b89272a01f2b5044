// Exact signed distance of vector profiles (profile_distance.cpp, shape_map_vector.cpp) against
// analytic answers: circles and arcs (|p - c| - R), boxes, the sphere from a half disc closed by the
// axis; the stored map against an independent dense-sampling reference; coverage against exact
// areas.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "bake/revolution/shape_map.h"
#include "revolution/profile_shapes.h"

namespace bake::revolution {
namespace {

using namespace bake::revolution::test;

Profile validated(std::vector<Contour> contours) {
  Profile profile = makeProfile(std::move(contours));
  std::vector<std::string> warnings;
  const Status status = validateProfile(profile, warnings);
  EXPECT_TRUE(status.isOk()) << status.describe();
  return profile;
}

TEST(SignedDistance, CircleOfArcsMatchesAnalytic) {
  for (int arcs : {2, 3, 5}) {
    const Profile profile = validated({circleContour(2.0, 0.5, 1.0, arcs)});
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> r(0.0, 4.0), h(-2.0, 3.0);
    for (int k = 0; k < 2000; ++k) {
      const Point2 p{r(rng), h(rng)};
      const double len = std::hypot(p.r - 2.0, p.h - 0.5);
      const DistanceSample s = signedDistance(profile, p);
      ASSERT_NEAR(s.distance, len - 1.0, 1e-9) << arcs << " arcs at " << p.r << ", " << p.h;
      EXPECT_NEAR(s.gradR, (p.r - 2.0) / len, 1e-9);
      EXPECT_NEAR(s.gradH, (p.h - 0.5) / len, 1e-9);
    }
  }
}

TEST(SignedDistance, RectangleMatchesBoxFormula) {
  const Profile profile = validated({rectangleContour(1.0, -1.0, 3.0, 2.0)});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> r(0.0, 5.0), h(-3.0, 4.0);
  for (int k = 0; k < 2000; ++k) {
    const Point2 p{r(rng), h(rng)};
    ASSERT_NEAR(signedDistance(profile, p).distance, boxDistance(p.r, p.h, 1.0, -1.0, 3.0, 2.0), 1e-9);
  }
}

TEST(SignedDistance, HalfDiscClosedByTheAxisIsASphere) {
  // The axis piece is not surface: inside points near the axis are as deep as the sphere says.
  const Profile profile = validated({halfDiscContour(1.5)});
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> r(-2.0, 2.0), h(-2.0, 2.0);
  for (int k = 0; k < 2000; ++k) {
    const Point2 p{r(rng), h(rng)};
    const DistanceSample s = signedDistance(profile, p);
    const double len = std::hypot(p.r, p.h);
    ASSERT_NEAR(s.distance, len - 1.5, 1e-9) << p.r << ", " << p.h;
    EXPECT_NEAR(s.gradR, p.r / len, 1e-9);  // mirrored for r < 0
    EXPECT_NEAR(s.gradH, p.h / len, 1e-9);
  }
  EXPECT_NEAR(signedDistance(profile, {0.01, 0.0}).distance, -1.49, 1e-12);
}

TEST(SignedDistance, AxisSegmentIsNotSurfaceButLidsAre) {
  // One vertical piece off the axis: closed by horizontal runs (surface) and the axis (not).
  const Profile profile = validated({makeContour({{1.0, 0.0}, {1.0, 2.0}}, {}, false)});
  EXPECT_NEAR(signedDistance(profile, {0.1, 1.0}).distance, -0.9, 1e-12);
  EXPECT_NEAR(signedDistance(profile, {0.0, 1.0}).distance, -1.0, 1e-12);
  EXPECT_NEAR(signedDistance(profile, {0.5, 2.5}).distance, 0.5, 1e-12);
  EXPECT_NEAR(signedDistance(profile, {0.5, 1.9}).distance, -0.1, 1e-12);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> r(0.0, 2.0), h(-1.0, 3.0);
  for (int k = 0; k < 1000; ++k) {
    const Point2 p{r(rng), h(rng)};
    // Mirror-symmetric box [-1, 1] x [0, 2]: its distance is the revolved cylinder's.
    ASSERT_NEAR(signedDistance(profile, p).distance, boxDistance(p.r, p.h, -1.0, 0.0, 1.0, 2.0), 1e-9);
  }
}

TEST(SignedDistance, ArcPieceMatchesDenseSampling) {
  const Profile profile = validated({vaseContour()});
  const DenseProfile dense = densify(profile, 20000);
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> r(0.0, 1.2), h(-0.3, 2.3);
  for (int k = 0; k < 300; ++k) {
    const Point2 p{r(rng), h(rng)};
    const DistanceSample s = signedDistance(profile, p);
    const double reference = denseDistance(dense, p);
    ASSERT_NEAR(std::abs(s.distance), reference, 3e-5) << p.r << ", " << p.h;
    ASSERT_EQ(s.distance < 0, denseInside(dense, p)) << p.r << ", " << p.h;
    // The gradient is a unit vector, and stepping along it changes the distance by the step.
    EXPECT_NEAR(std::hypot(s.gradR, s.gradH), 1.0, 1e-9);
    const double step = 1e-6;
    const double moved = signedDistance(profile, {p.r + step * s.gradR, p.h + step * s.gradH}).distance;
    if (std::abs(s.distance) > 1e-3 && p.r > 1e-3) {
      EXPECT_NEAR(moved - s.distance, step, 1e-8);
    }
  }
}

TEST(ShapeMapVector, StoredDistanceWithinAThousandthOfATexel) {
  const Profile profile = validated({vaseContour()});
  const ShapeGrid grid = gridForBounds(profileBounds(profile), 64, 4);
  ASSERT_EQ(grid.height, 64);
  const ShapeField field = distanceFromProfile(profile, grid);
  const DenseProfile dense = densify(profile, 16000);  // spacing well under 1e-3 texel
  double worst = 0;
  for (int j = 0; j < grid.height; ++j)
    for (int i = 0; i < grid.width; ++i) {
      const Point2 p{grid.centreR(i), grid.centreH(j)};
      const double reference = (denseInside(dense, p) ? -1 : 1) * denseDistance(dense, p);
      worst = std::max(worst, std::abs(field.at(i, j) - reference) / grid.texelSize);
    }
  EXPECT_LT(worst, 1e-3);
}

TEST(ShapeMapVector, GridCoversTheProfileWithPadding) {
  const Bounds2 bounds{2.0, -1.0, 7.0};
  const ShapeGrid grid = gridForBounds(bounds, 256, 8);
  EXPECT_EQ(std::max(grid.width, grid.height), 256);
  EXPECT_GE(grid.width * grid.texelSize, bounds.rMax + 8 * grid.texelSize - 1e-9);
  EXPECT_LE(grid.hMin, bounds.hMin - 8 * grid.texelSize + 1e-9);
  EXPECT_GE(grid.hMin + grid.height * grid.texelSize, bounds.hMax + 8 * grid.texelSize - 1e-9);
}

TEST(ShapeMapVector, CoverageIsTheExactAreaOfARectangle) {
  // Box edges off the texel lattice: each texel's coverage is the product of its overlaps.
  const Profile profile = validated({rectangleContour(1.3, 0.2, 5.7, 3.9)});
  ShapeGrid grid;
  grid.width = 8;
  grid.height = 6;
  grid.texelSize = 1.0;
  grid.hMin = 0.0;
  const ShapeField field = distanceFromProfile(profile, grid);
  for (int j = 0; j < grid.height; ++j)
    for (int i = 0; i < grid.width; ++i) {
      const double overlapR = std::max(0.0, std::min(i + 1.0, 5.7) - std::max(double(i), 1.3));
      const double overlapH = std::max(0.0, std::min(j + 1.0, 3.9) - std::max(double(j), 0.2));
      EXPECT_NEAR(field.coverage[std::size_t(j) * grid.width + i], overlapR * overlapH, 1e-5) << i << ", " << j;
    }
}

TEST(ShapeMapVector, CoverageSumsToTheAreaOfADiscAndAnAnnulus) {
  // A ring: outer circle and a hole (given with the same orientation; validation flips the hole).
  const Profile profile = validated({circleContour(20.0, 20.0, 15.0, 4), circleContour(20.0, 20.0, 6.5, 3)});
  ShapeGrid grid;
  grid.width = 40;
  grid.height = 40;
  grid.texelSize = 1.0;
  const ShapeField field = distanceFromProfile(profile, grid);
  double area = 0;
  for (float c : field.coverage) {
    ASSERT_GE(c, 0.0f);
    ASSERT_LE(c, 1.0f);
    area += c;
  }
  const double exact = std::numbers::pi * (15.0 * 15.0 - 6.5 * 6.5);
  EXPECT_NEAR(area, exact, 1e-4 * exact);
}

TEST(ShapeMapVector, SignAndGradientAgreeWithTheSphere) {
  const Profile profile = validated({halfDiscContour(1.0)});
  const ShapeGrid grid = gridForBounds(profileBounds(profile), 48, 3);
  const ShapeField field = distanceFromProfile(profile, grid);
  for (int j = 0; j < grid.height; ++j)
    for (int i = 0; i < grid.width; ++i) {
      const double r = grid.centreR(i), h = grid.centreH(j), len = std::hypot(r, h);
      const std::size_t k = std::size_t(j) * grid.width + i;
      ASSERT_NEAR(field.distance[k], len - 1.0, 1e-6);
      ASSERT_NEAR(field.gradR[k], r / len, 1e-6);
      ASSERT_NEAR(field.gradH[k], h / len, 1e-6);
    }
}

}  // namespace
}  // namespace bake::revolution
