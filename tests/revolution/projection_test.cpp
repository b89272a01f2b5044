// Projection choice (libbake/revolution/projection.cpp) on hand-built profiles whose best map is
// known: walls and cones are textured without distortion by the cylindrical map; caps, spheres and
// plates make it degenerate or strongly distorted, so another map must win. The repeat ratio and the
// sphere centre are checked against their closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bake/revolution/projection.h"

namespace bake::revolution {
namespace {

Contour polyline(std::initializer_list<Point2> points, bool closed = false) {
  Contour c;
  c.closed = closed;
  const std::vector<Point2> p(points);
  for (std::size_t k = 0; k + 1 < p.size(); ++k) c.segments.push_back({p[k], p[k + 1], 0, false});
  if (closed) c.segments.push_back({p.back(), p.front(), 0, false});
  return c;
}

Profile profileOf(Contour contour) {
  Profile p;
  p.contours.push_back(std::move(contour));
  p.source = "test";
  return p;
}

const ProjectionScore& scoreOf(const ProjectionChoice& c, Projection p) { return c.scores[int(p)]; }

TEST(Projection, NamesAreTheFormats) {
  EXPECT_STREQ(projectionName(Projection::Cylindrical), "cylindrical");
  EXPECT_STREQ(projectionName(Projection::Spherical), "spherical");
  EXPECT_STREQ(projectionName(Projection::ArcLength), "arc-length");
}

TEST(Projection, WallPicksCylindricalWithSquareTexelRatio) {
  const ProjectionChoice c = chooseProjection(profileOf(polyline({{1, 0}, {1, 2}})));
  ASSERT_EQ(c.scores.size(), 3u);
  EXPECT_EQ(c.chosen, Projection::Cylindrical);
  const ProjectionScore& cyl = scoreOf(c, Projection::Cylindrical);
  EXPECT_NEAR(cyl.degenerateArea, 0, 1e-12);
  EXPECT_NEAR(cyl.meanAngleDistortion, 1, 1e-9);  // conformal: a cylinder unrolls to a rectangle
  EXPECT_NEAR(cyl.meanAreaDistortion, 1, 1e-9);
  // Circumference 2 pi, height 2: u must repeat pi times per v repeat for square texels.
  EXPECT_NEAR(cyl.repeatRatio, std::numbers::pi, 1e-9);
}

TEST(Projection, ConesPickCylindrical) {
  for (double topRadius : {0.0, 0.5}) {  // with its apex on the axis, and a frustum
    const ProjectionChoice c = chooseProjection(profileOf(polyline({{1, 0}, {topRadius, 1.5}})));
    EXPECT_EQ(c.chosen, Projection::Cylindrical) << "top radius " << topRadius;
    EXPECT_EQ(scoreOf(c, Projection::Cylindrical).degenerateArea, 0);
  }
}

TEST(Projection, CanWithCapsIsNotCylindrical) {
  const ProjectionChoice c = chooseProjection(profileOf(polyline({{0, 0}, {1, 0}, {1, 2}, {0, 2}})));
  EXPECT_NE(c.chosen, Projection::Cylindrical);
  // The two caps (area 2 pi) of a total 6 pi are degenerate under the cylindrical map.
  EXPECT_NEAR(scoreOf(c, Projection::Cylindrical).degenerateArea, 1.0 / 3.0, 1e-6);
  EXPECT_NEAR(scoreOf(c, Projection::ArcLength).degenerateArea, 0, 1e-12);
}

TEST(Projection, SpherePicksSphericalAboutItsCentre) {
  Contour half;
  half.segments.push_back({{0, -1}, {0, 1}, 1.0, false});  // bulge 1: a half circle through (1, 0)
  const ProjectionChoice c = chooseProjection(profileOf(half));
  EXPECT_NE(c.chosen, Projection::Cylindrical);
  EXPECT_EQ(c.chosen, Projection::Spherical);  // ties with arc length, which comes later
  EXPECT_NEAR(scoreOf(c, Projection::Spherical).sphereCentreH, 0, 1e-3);
  EXPECT_LT(scoreOf(c, Projection::Spherical).meanAngleDistortion,
            scoreOf(c, Projection::Cylindrical).meanAngleDistortion);
}

TEST(Projection, PlateIsNotCylindrical) {
  // A disc of radius 2 and a rim 0.05 high: nearly all area is flat.
  const ProjectionChoice c =
      chooseProjection(profileOf(polyline({{0, 0}, {2, 0}, {2, 0.05}, {1.9, 0.05}, {1.9, 0.02}, {0, 0.02}})));
  EXPECT_NE(c.chosen, Projection::Cylindrical);
  EXPECT_GT(scoreOf(c, Projection::Cylindrical).degenerateArea, 0.9);
}

TEST(Projection, ScoreCombinesTheThreeMeasuresAsDocumented) {
  const ProjectionChoice c = chooseProjection(profileOf(polyline({{0, 0}, {1, 0}, {1, 2}, {0, 2}})));
  for (const ProjectionScore& s : c.scores)
    EXPECT_NEAR(s.score, 10 * s.degenerateArea + std::log(s.meanAngleDistortion) + std::log(s.meanAreaDistortion), 1e-12);
}

TEST(Projection, ScoresAreFiniteForAnEmptyProfile) {
  const ProjectionChoice c = chooseProjection(Profile{});
  ASSERT_EQ(c.scores.size(), 3u);
  for (const ProjectionScore& s : c.scores) {
    EXPECT_TRUE(std::isfinite(s.score));
    EXPECT_EQ(s.degenerateArea, 1);
  }
}

}  // namespace
}  // namespace bake::revolution
