// Stiff cases of area sampling (libbake/grooves/oracle/area_sampling.cpp): crossings at 1°, grazing views up
// to 85°, a light at and below the horizon, footprints a hundred groove widths across (many pieces:
// the caps), zero-area and degenerate footprints. Closed forms where they exist, else the ray-traced
// reference; always finite, non-negative values.
#include "area_support.h"

namespace bake::grooves {
namespace {

using namespace area_test;

void expectSane(const Rgb& value) {
  for (int c = 0; c < 3; ++c) {
    EXPECT_TRUE(std::isfinite(value[c]));
    EXPECT_GE(value[c], 0);
    EXPECT_LT(value[c], 1);  // albedo <= 0.9, unit irradiance
  }
}

// From above, lit from above, every facet of a V-groove sends albedo / pi w / sqrt(w^2 + d^2): the
// pixel only depends on the grooves' union area U in the footprint.
Rgb fromAboveByUnion(const GrooveScene& s, double footprintArea, double unionArea) {
  const Lighting l = lightTowards({0, 0, 1});
  const Rgb ground = directRadiance(materialNamed(s, "ground"), {0, 0, 1}, {0, 0, 1}, l);
  const Rgb facet = directRadiance(materialNamed(s, "red"), facetNormal(kD / kW, 0), {0, 0, 1}, l);
  Rgb out;
  for (int c = 0; c < 3; ++c) out[c] = ((footprintArea - unionArea) * ground[c] + unionArea * facet[c]) / footprintArea;
  return out;
}

TEST(GrooveAreaStiff, CrossingAtOneDegreeUnderAHugeFootprint) {
  // Bands of width 2w crossing at alpha = 1° overlap in a rhombus of area 4 w^2 / sin(alpha), 2.3 long:
  // a footprint of side 3 (150 groove widths) holds it whole.
  const double alpha = 1 * kPi / 180, side = 3;
  const Vec2 c{4, 4};
  const GrooveScene s = sceneWith(line("v", "red", {0.5, 4}, {7.5, 4}) + ", " +
                                      line("v", "red", {c.u - 3.5 * std::cos(alpha), c.v - 3.5 * std::sin(alpha)},
                                           {c.u + 3.5 * std::cos(alpha), c.v + 3.5 * std::sin(alpha)}),
                                  8);
  AreaSampleStats stats;
  const Rgb value = sample(s, squareFootprint(c, side), {0, 0, 1}, lightTowards({0, 0, 1}), &stats);
  const double unionArea = 2 * kW * side + 2 * kW * side / std::cos(alpha) - 4 * kW * kW / std::sin(alpha);
  const Rgb expected = fromAboveByUnion(s, side * side, unionArea);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(value[k], expected[k], 1e-9);
  EXPECT_EQ(stats.surface.overflows, 0u);
  EXPECT_EQ(stats.fragmentOverflows, 0u);
}

TEST(GrooveAreaStiff, CrossingAtOneDegreeObliqueAgreesWithReference) {
  const double alpha = 1 * kPi / 180;
  const GrooveScene s = sceneWith(line("v", "red", {0.1, 0.5}, {0.9, 0.5}) + ", " +
                                  line("box", "shiny", {0.5 - 0.4 * std::cos(alpha), 0.5 - 0.4 * std::sin(alpha)},
                                       {0.5 + 0.4 * std::cos(alpha), 0.5 + 0.4 * std::sin(alpha)}));
  const Footprint f = squareFootprint({0.52, 0.5}, 0.03);
  const double theta = 60 * kPi / 180;
  const Vec3 e{0.3 * std::sin(theta), -0.954 * std::sin(theta), std::cos(theta)};
  const Lighting l = lightTowards({0.2, 0.7, 0.6});
  const Rgb value = sample(s, f, e, l);
  expectSane(value);
  expectNearReference(value, referenceMean(s, f, e, l), 2e-4);
}

TEST(GrooveAreaStiff, SharpCornersAgreeWithReference) {
  // Hairpin corners of 20° and 5°: the two arms' regions meet on a mitre line nearly along the path.
  for (const double cornerDegrees : {20.0, 5.0}) {
    const double turn = kPi - cornerDegrees * kPi / 180;
    const GrooveScene s = sceneWith(polyline(
        "box", "red", {{0.2, 0.5}, {0.5, 0.5}, {0.5 + 0.3 * std::cos(turn), 0.5 + 0.3 * std::sin(turn)}}));
    const Footprint f = squareFootprint({0.49, 0.502}, 0.02);
    const double theta = 50 * kPi / 180;
    const Vec3 e{std::sin(theta) * 0.6, std::sin(theta) * 0.8, std::cos(theta)};
    const Lighting l = lightTowards({-0.3, 0.4, 0.7});
    SCOPED_TRACE(cornerDegrees);
    const Rgb value = sample(s, f, e, l);
    expectSane(value);
    expectNearReference(value, referenceMean(s, f, e, l), 2e-4);
  }
}

TEST(GrooveAreaStiff, GrazingViewOfAVGroove) {
  // At 85° across the groove the facet facing away is hidden and the one facing the viewer fills the
  // groove's whole width 2w on the base plane.
  const GrooveScene s = sceneWith(line("v", "red", {0.5, 0}, {0.5, 1}));
  const double theta = 85 * kPi / 180, side = 0.05;
  const Vec3 e{std::sin(theta), 0, std::cos(theta)};
  const Lighting l = lightTowards({0, 0, 1});
  const Rgb value = sample(s, squareFootprint({0.5, 0.5}, side), e, l);
  const Rgb ground = directRadiance(materialNamed(s, "ground"), {0, 0, 1}, e, l);
  const Rgb facet = directRadiance(materialNamed(s, "red"), facetNormal(-kD / kW, 0), e, l);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(value[c], ((side - 2 * kW) * ground[c] + 2 * kW * facet[c]) / side, 1e-9);
}

TEST(GrooveAreaStiff, GrazingViewsOfACrossingAgreeWithReference) {
  const GrooveScene s = sceneWith(line("v", "red", {0.5, 0.1}, {0.5, 0.9}) + ", " +
                                  line("box", "shiny", {0.1, 0.5}, {0.9, 0.5}));
  const Footprint f = squareFootprint({0.5, 0.5}, 0.04);
  const Lighting l = lightTowards({-0.3, 0.5, 0.7});
  for (const double degrees : {80.0, 85.0}) {
    const double theta = degrees * kPi / 180;
    const Vec3 e{std::sin(theta) * std::cos(0.5), std::sin(theta) * std::sin(0.5), std::cos(theta)};
    SCOPED_TRACE(degrees);
    const Rgb value = sample(s, f, e, l);
    expectSane(value);
    expectNearReference(value, referenceMean(s, f, e, l), 2e-4);
  }
}

TEST(GrooveAreaStiff, LightAtTheHorizon) {
  const Lighting horizon = lightTowards({1, 0, 0});
  const Footprint f = squareFootprint({0.5, 0.5}, 0.05);
  // A cavity lit horizontally is all in shadow and the ground is edge-on: black.
  const GrooveScene cut = sceneWith(line("v", "red", {0.5, 0}, {0.5, 1}));
  const Rgb dark = sample(cut, f, {0, 0, 1}, horizon);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(dark[c], 0, 1e-15);
  // A ridge: its facet facing the light is lit whole, N.L = d / sqrt(w^2 + d^2).
  const GrooveScene ridge = sceneWith(line("ridge", "red", {0.5, 0}, {0.5, 1}));
  const Rgb lit = sample(ridge, f, {0, 0, 1}, horizon);
  const Rgb facet = directRadiance(materialNamed(ridge, "red"), facetNormal(-kD / kW, 0), {0, 0, 1}, horizon);
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(facet[c], 0);
    EXPECT_NEAR(lit[c], kW * facet[c] / 0.05, 1e-9);
  }
}

TEST(GrooveAreaStiff, LightAtAndBelowTheHorizonOnACrossingAgreesWithReference) {
  // Along the crossing groove's cavity a horizontal light reaches the other groove's wall.
  const GrooveScene s = sceneWith(line("box", "red", {0.5, 0.1}, {0.5, 0.9}) + ", " +
                                  line("box", "shiny", {0.1, 0.5}, {0.9, 0.5}) + ", " +
                                  line("ridge", "green", {0.3, 0.45}, {0.7, 0.62}));
  const Footprint f = squareFootprint({0.5, 0.5}, 0.04);
  const double theta = 50 * kPi / 180;
  const Vec3 e{-std::sin(theta) * 0.8, std::sin(theta) * 0.6, std::cos(theta)};
  for (const double w : {0.0, -0.05}) {
    const Lighting l = lightTowards({1, 0.05, w});
    SCOPED_TRACE(w);
    const Rgb value = sample(s, f, e, l);
    expectSane(value);
    expectNearReference(value, referenceMean(s, f, e, l), 2e-4);
  }
}

TEST(GrooveAreaStiff, FootprintHundredGrooveWidthsOverAGrid) {
  // 10 x 10 V-grooves 0.2 apart under a footprint of side 2 (100 groove widths): 100 crossings. Seen
  // from above and lit from above the value is the union area's, U = 20 (2w) a - 100 (2w)^2.
  std::string grooves;
  for (int i = 0; i < 10; ++i) {
    const double x = 1.1 + 0.2 * i;
    grooves += (i ? ", " : "") + line("v", "red", {x, 0.5}, {x, 3.5}) + ", " + line("v", "red", {0.5, x}, {3.5, x});
  }
  const GrooveScene s = sceneWith(grooves, 4);
  const double side = 2;
  AreaSampleStats stats;
  const Rgb value = sample(s, squareFootprint({2, 2}, side), {0, 0, 1}, lightTowards({0, 0, 1}), &stats);
  const double unionArea = 20 * 2 * kW * side - 100 * 4 * kW * kW;
  const Rgb expected = fromAboveByUnion(s, side * side, unionArea);
  expectSane(value);
  // Too many pieces for the caps: the footprint is split into quarters, each exact.
  EXPECT_GT(stats.surface.overflows, 0u);
  EXPECT_GT(stats.splits, 0u);
  EXPECT_EQ(stats.incomplete, 0u);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(value[c], expected[c], 1e-9);
}

TEST(GrooveAreaStiff, PastTheSplitsPiecesAreDroppedAndCounted) {
  // A light 0.6° above the horizon, along the grid's diagonal: whatever may shadow the footprint lies
  // up to 100 groove depths away towards the light (the bound on the reach), across both families of
  // grooves, and the footprint spans 12 grooves each way, so even an eighth of it sees dozens of
  // crossings of a dense grid (grooves 0.02 wide, 0.025 apart).
  std::string grooves;
  for (int i = 0; i < 25; ++i) {
    const double x = 1.7 + 0.025 * i;
    grooves += (i ? ", " : "") + line("v", "red", {x, 1}, {x, 3}) + ", " + line("v", "red", {1, x}, {3, x});
  }
  const GrooveScene s = sceneWith(grooves, 4);
  AreaSampleStats stats;
  const Lighting l = lightTowards({1, 1, 0.01});
  const Rgb value = sample(s, squareFootprint({2, 2}, 0.3), {0, 0, 1}, l, &stats);
  EXPECT_GT(stats.incomplete, 0u) << stats.surface.cells << " " << stats.splits;
  // Dropped pieces only take light away: the value stays between 0 and the brightest piece's radiance.
  const Rgb ground = directRadiance(materialNamed(s, "ground"), {0, 0, 1}, {0, 0, 1}, l);
  const Rgb facet = directRadiance(materialNamed(s, "red"), facetNormal(-kD / kW, 0), {0, 0, 1}, l);
  for (int c = 0; c < 3; ++c) {
    EXPECT_TRUE(std::isfinite(value[c]));
    EXPECT_GE(value[c], 0);
    EXPECT_LE(value[c], std::max(ground[c], facet[c]));
  }
}

TEST(GrooveAreaStiff, HugeObliqueFootprintOnACrossingAgreesWithReference) {
  const GrooveScene s = sceneWith(line("v", "red", {2, 0.5}, {2, 3.5}) + ", " + line("box", "shiny", {0.5, 2}, {3.5, 2}), 4);
  const Footprint f{{2, 2}, {2, 0.3}, {-0.4, 1.8}};  // about 100 groove widths
  const double theta = 70 * kPi / 180;
  const Vec3 e{std::sin(theta) * 0.6, std::sin(theta) * 0.8, std::cos(theta)};
  const Lighting l = lightTowards({-0.6, 0.2, 0.5});
  AreaSampleStats stats;
  const Rgb value = sample(s, f, e, l, &stats);
  EXPECT_EQ(stats.surface.overflows, 0u);
  expectNearReference(value, referenceMean(s, f, e, l), 2e-5);
}

TEST(GrooveAreaStiff, ZeroAreaFootprintIsAPointSample) {
  const GrooveScene s = sceneWith(line("v", "red", {0.5, 0}, {0.5, 1}) + ", " + line("box", "red", {0.6, 0.5}, {0.9, 0.5}));
  const Material &ground = materialNamed(s, "ground"), &red = materialNamed(s, "red");
  const double theta = 30 * kPi / 180;
  const Vec3 e{std::sin(theta), 0, std::cos(theta)};
  const Lighting l = lightTowards({0, 0, 1});
  AreaSampleStats stats;
  auto at = [&](Vec2 x, const Vec3& view, const Lighting& light) {
    return sample(s, Footprint{x, {0, 0}, {0, 0}}, view, light, &stats);
  };
  // The ground; a facet seen through the groove's screen span (the one facing +u covers [-w, d tan]).
  const Rgb onGround = at({0.3, 0.3}, e, l), groundExpected = directRadiance(ground, {0, 0, 1}, e, l);
  EXPECT_TRUE(stats.pointSample);
  const Rgb onFacet = at({0.5 - 0.5 * kW, 0.3}, e, l);
  const Rgb facetExpected = directRadiance(red, facetNormal(-kD / kW, 0), e, l);
  // The open end's wall at u = 0.6, seen from +u over [0.6, 0.6 + d tan(theta)].
  const Lighting side = lightTowards({1, 0, 1});
  const Rgb onWall = at({0.6 + 0.5 * kD * std::tan(theta), 0.5}, e, side);
  const Rgb wallExpected = directRadiance(red, {1, 0, 0}, e, side);
  // In the V-groove's shadow (from above, light at 70° towards +u): dark past x_s, lit before it.
  const double phi = 70 * kPi / 180, cot = 1 / std::tan(phi);
  const double shadowStart = (cot * kW - kD) / (kD / kW + cot);
  const Lighting slanted = lightTowards({std::sin(phi), 0, std::cos(phi)});
  const Rgb inShadow = at({0.5 + 0.5 * shadowStart, 0.3}, {0, 0, 1}, slanted);
  const Rgb beforeShadow = at({0.5 + 0.5 * (shadowStart - kW), 0.3}, {0, 0, 1}, slanted);
  const Rgb litExpected = directRadiance(red, facetNormal(-kD / kW, 0), {0, 0, 1}, slanted);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(onGround[c], groundExpected[c], 1e-12);
    EXPECT_NEAR(onFacet[c], facetExpected[c], 1e-12);
    EXPECT_NEAR(onWall[c], wallExpected[c], 1e-12);
    EXPECT_GT(wallExpected[c], 0);
    EXPECT_EQ(inShadow[c], 0);
    EXPECT_NEAR(beforeShadow[c], litExpected[c], 1e-12);
  }
}

TEST(GrooveAreaStiff, TinyFootprintTendsToThePointSample) {
  // A footprint a millionth of the groove width inside one visible, lit piece of a crossing: its mean
  // is the point sample, to rounding.
  const GrooveScene s = sceneWith(line("v", "red", {0.1, 0.5}, {0.9, 0.5}) + ", " + line("box", "shiny", {0.5, 0.1}, {0.5, 0.9}));
  const double theta = 60 * kPi / 180;
  const Vec3 e{std::sin(theta) * 0.6, std::sin(theta) * 0.8, std::cos(theta)};
  const Lighting l = lightTowards({-0.2, 0.3, 0.9});
  std::vector<double> seen;
  for (const Vec2 c : {Vec2{0.503, 0.502}, Vec2{0.53, 0.505}, Vec2{0.53, 0.53}}) {
    const Rgb point = sample(s, Footprint{c, {0, 0}, {0, 0}}, e, l);
    const Rgb tiny = sample(s, Footprint{c, {2e-8, 0}, {0, 2e-8}}, e, l);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(tiny[k], point[k], 1e-9);
    seen.push_back(point[0]);
  }
  EXPECT_NE(seen[0], seen[1]);  // the box floor, a V facet, the ground
  EXPECT_NE(seen[1], seen[2]);
  EXPECT_NE(seen[0], seen[2]);
}

TEST(GrooveAreaStiff, SegmentFootprintIsTheMeanAlongTheSegment) {
  // A footprint with parallel axes A1 = (a, 0), A2 = (a/2, 0) has no area: it is the limit of thin
  // parallelograms, a density along the segment flat at 1/a over |x| <= a/4, where the V-groove lies:
  // seen from above and lit from above, (a - 2w) ground + 2w facet, over a.
  const GrooveScene s = sceneWith(line("v", "red", {0.5, 0}, {0.5, 1}));
  const double a = 0.05;
  const Lighting l = lightTowards({0, 0, 1});
  AreaSampleStats stats;
  const Rgb value = sample(s, Footprint{{0.5, 0.5}, {a, 0}, {0.5 * a, 0}}, {0, 0, 1}, l, &stats);
  EXPECT_FALSE(stats.pointSample);
  const Rgb expected = fromAboveByUnion(s, a, 2 * kW);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(value[c], expected[c], 1e-9);
}

}  // namespace
}  // namespace bake::grooves
