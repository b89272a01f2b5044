// The ray-traced reference (libbake/grooves/reference/reference.h): the exact surface of formats/groove-scene.md
// (crossings, open ends, arcs, corners, wrap) and pixel values against closed forms derived by hand
// for a straight symmetric V-groove (visible facet fractions with masking, shadowed fractions), with
// the stratified sampling error bounded: the integrand is piecewise constant across the groove, so
// only the one column of strata a discontinuity passes through can be off, by at most jump / n.
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "bake/core/vec.h"
#include "grooves/input/scene.h"
#include "grooves/reference/reference.h"

namespace bake::grooves {
namespace {

std::string sceneText(const std::string& profiles, const std::string& grooves, const std::string& extra = "") {
  return R"({"version": 1, "domain": {"size": [1, 1]}, )" + extra + R"("profiles": {)" + profiles +
         R"(}, "materials": {"grey": {"albedo": [0.6, 0.6, 0.6]}}, "base": "grey", "grooves": [)" + grooves + "]}";
}

GrooveScene parseOk(const std::string& text) {
  Result<GrooveScene> scene = parseGrooveScene(text, "scene.json");
  EXPECT_TRUE(scene.isOk()) << scene.status().describe();
  return scene.isOk() ? scene.value() : GrooveScene{};
}

// A V-groove of half-width w and depth d along v through u = 0.5.
GrooveScene vGroove(double w, double d) {
  const std::string profile = R"("v": {"points": [[)" + std::to_string(-w) + ", 0], [0, " + std::to_string(-d) +
                              "], [" + std::to_string(w) + ", 0]]}";
  return parseOk(sceneText(profile, R"({"profile": "v", "path": {"line": [[0.5, 0], [0.5, 1]]}})"));
}

// One square pixel of side P centred on (0.5, 0.5).
View pixelView(double side, double theta, double phi = 0) {
  return windowView({0.5 - side / 2, 0.5 - side / 2}, {0.5 + side / 2, 0.5 + side / 2}, 1, theta, phi);
}

Lighting lightFrom(double beta, double phi = 0) {
  Lighting l;
  l.toLight = directionFromAngles(beta, phi);
  return l;
}

// 64 x 64 strata: the sampling bound is the sum of the jumps / 64.
constexpr int kStrata = 64;

double pixelValue(const GrooveScene& scene, const View& view, const Lighting& lighting, int spp = kStrata * kStrata,
                  std::uint64_t seed = 1) {
  ReferenceSettings s;
  s.samplesPerPixel = spp;
  s.seed = seed;
  s.threads = 1;
  const Image image = renderReference(scene, view, lighting, s);
  EXPECT_EQ(image.width, view.width);
  return rgbAt(image, 0, 0)[0];
}

// Lambert radiance of a facet of the V-groove: slopes down to +u (facet A, left) or -u (facet B).
double facetRadiance(double albedo, double w, double d, bool facetA, const Vec3& toLight) {
  const double n = std::hypot(w, d);
  const Vec3 normal{(facetA ? d : -d) / n, 0, w / n};
  return albedo / kPi * std::max(0.0, normal.u * toLight.u + normal.v * toLight.v + normal.w * toLight.w);
}

TEST(GrooveReference, FlatPlaneIsAlbedoOverPiTimesCosine) {
  const GrooveScene scene = parseOk(sceneText(R"("v": {"points": [[-0.01, 0], [0, -0.01], [0.01, 0]]})", ""));
  for (double beta : {0.0, 0.4, 1.2}) {
    Lighting light = lightFrom(beta, 0.7);
    light.radiance = {2, 1, 0.5};
    ReferenceSettings s;
    s.samplesPerPixel = 4;
    const Image image = renderReference(scene, windowView({0.1, 0.1}, {0.9, 0.9}, 4, 0.5, 1.0), light, s);
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(rgbAt(image, x, y)[c], 0.6 / kPi * std::cos(beta) * light.radiance[c], 1e-6);
  }
}

TEST(GrooveReference, VGrooveFromAboveMatchesFacetAreas) {
  const double w = 0.05, d = 0.05, side = 0.2;
  const GrooveScene scene = vGroove(w, d);
  const Lighting light = lightFrom(0);
  const double flat = 0.6 / kPi, facet = facetRadiance(0.6, w, d, true, light.toLight);
  const double expected = ((side - 2 * w) * flat + 2 * w * facet) / side;
  const double bound = 2 * (flat - facet) / kStrata;  // two rims cross one stratum column each
  EXPECT_NEAR(pixelValue(scene, pixelView(side, 0), light), expected, bound + 1e-6);
}

// Oblique view across the groove (viewer towards +u), light tilted towards +u little enough that
// nothing is shadowed (tan beta < w/d). Projected along E onto the base plane, facet A covers
// w + d tan(theta) and facet B w - d tan(theta); beyond tan(theta) = w/d, B is masked and A covers 2w.
TEST(GrooveReference, VGrooveObliqueViewMatchesMaskedFacetFractions) {
  const double w = 0.05, d = 0.05, side = 0.2, beta = 20 * kPi / 180;
  const GrooveScene scene = vGroove(w, d);
  const Lighting light = lightFrom(beta);
  const double flat = 0.6 / kPi * std::cos(beta);
  const double a = facetRadiance(0.6, w, d, true, light.toLight), b = facetRadiance(0.6, w, d, false, light.toLight);
  for (double degrees : {30.0, 60.0}) {
    const double theta = degrees * kPi / 180, shift = d * std::tan(theta);
    const double coverA = std::min(2 * w, w + shift), coverB = std::max(0.0, w - shift);
    const double expected = ((side - 2 * w) * flat + coverA * a + coverB * b) / side;
    const double bound = (std::abs(flat - a) + std::abs(a - b) + std::abs(b - flat)) / kStrata;
    EXPECT_NEAR(pixelValue(scene, pixelView(side, theta), light), expected, bound + 1e-6) << degrees;
  }
}

// View from above, light from +u beyond the facet slope: facet B faces away, and the right rim
// shadows facet A beyond x* = 2w / (1 + (d/w) tan(beta)) from its left rim.
TEST(GrooveReference, VGrooveShadowFractionMatchesRimShadow) {
  const double w = 0.05, d = 0.05, side = 0.2, beta = 60 * kPi / 180;
  const GrooveScene scene = vGroove(w, d);
  const Lighting light = lightFrom(beta);
  const double flat = 0.6 / kPi * std::cos(beta), a = facetRadiance(0.6, w, d, true, light.toLight);
  const double litA = 2 * w / (1 + d / w * std::tan(beta));
  ASSERT_LT(litA, w);
  const double expected = ((side - 2 * w) * flat + litA * a) / side;
  const double bound = (flat + a + a + flat) / kStrata;  // rims, shadow line, bottom
  EXPECT_NEAR(pixelValue(scene, pixelView(side, 0), light), expected, bound + 1e-6);
}

TEST(GrooveReference, CrossingHeightIsTheDeeperCut) {
  const std::string profiles =
      R"("shallow": {"points": [[-0.05, 0], [0, -0.02], [0.05, 0]]}, "deep": {"points": [[-0.04, 0], [0, -0.06], [0.04, 0]]})";
  const std::string first = R"({"profile": "shallow", "path": {"line": [[0.1, 0.5], [0.9, 0.5]]}})";
  const std::string second = R"({"profile": "deep", "path": {"line": [[0.2, 0.2], [0.8, 0.8]]}})";
  const GrooveScene both = parseOk(sceneText(profiles, first + "," + second));
  const ReferenceSurface cross(both), one(parseOk(sceneText(profiles, first))), two(parseOk(sceneText(profiles, second)));
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      const Vec2 x{0.4 + 0.2 * i / 39, 0.4 + 0.2 * j / 39};
      EXPECT_NEAR(cross.height(x), std::min(one.height(x), two.height(x)), 1e-12);
    }
  EXPECT_NEAR(cross.height({0.5, 0.5}), -0.06, 1e-12);
  ReferenceSurface::Hit hit;
  ASSERT_TRUE(cross.intersect({0.5, 0.5, 1}, {0, 0, -1}, hit));
  EXPECT_NEAR(hit.point.w, -0.06, 1e-12);
  EXPECT_NEAR(hit.t, 1.06, 1e-12);
  // Obliquely down the shallow groove's axis, steeper than the deep groove's walls there (slope
  // 1.06 along u) and above the shallow floor until inside the deep groove: it reaches the crossing.
  ASSERT_TRUE(cross.intersect({0.8, 0.5, 0.54}, {-0.3, 0, -0.6}, hit));
  EXPECT_NEAR(hit.point.u, 0.5, 1e-12);
  EXPECT_NEAR(hit.point.w, -0.06, 1e-12);
}

TEST(GrooveReference, OpenEndIsAVerticalWallFacingTheRay) {
  const std::string profile = R"("v": {"points": [[-0.05, 0], [0, -0.04], [0.05, 0]]})";
  const ReferenceSurface surface(parseOk(sceneText(profile, R"({"profile": "v", "path": {"line": [[0.3, 0.5], [0.7, 0.5]]}})")));
  EXPECT_NEAR(surface.height({0.5, 0.5}), -0.04, 1e-12);
  EXPECT_EQ(surface.height({0.7001, 0.5}), 0);
  ReferenceSurface::Hit hit;
  ASSERT_TRUE(surface.intersect({0.5, 0.5, -0.02}, {1, 0, 0}, hit));
  EXPECT_NEAR(hit.t, 0.2, 1e-12);
  EXPECT_NEAR(hit.normal.u, -1, 1e-12);
  EXPECT_NEAR(hit.normal.w, 0, 1e-12);
  ASSERT_TRUE(surface.intersect({0.5, 0.5, -0.02}, {-1, 0, 0}, hit));
  EXPECT_NEAR(hit.point.u, 0.3, 1e-12);
  EXPECT_NEAR(hit.normal.u, 1, 1e-12);
}

// Counter-clockwise arc: left (b > 0) is towards the centre; an asymmetric profile shows the sign.
TEST(GrooveReference, ArcHeightIsTheProfileAtTheRadialOffset) {
  const std::string profile = R"("skew": {"points": [[-0.04, 0], [-0.02, -0.03], [0.04, 0]]})";
  const GrooveScene scene = parseOk(sceneText(
      profile, R"({"profile": "skew", "path": {"arc": {"centre": [0.5, 0.5], "radius": 0.3, "start": 0, "end": 180}}})"));
  const ReferenceSurface surface(scene);
  const auto profileAt = [](double b) {
    if (b <= -0.04 || b >= 0.04) return 0.0;
    return b < -0.02 ? -0.03 * (b + 0.04) / 0.02 : -0.03 * (0.04 - b) / 0.06;
  };
  for (double angle : {10.0, 60.0, 135.0})
    for (double b = -0.05; b <= 0.05; b += 0.0037) {
      const double r = 0.3 - b, a = angle * kPi / 180;
      EXPECT_NEAR(surface.height({0.5 + r * std::cos(a), 0.5 + r * std::sin(a)}), profileAt(b), 1e-12) << angle << " " << b;
    }
  // A vertical ray onto the arc's floor hits the profile's bottom.
  ReferenceSurface::Hit hit;
  const double a = 1.0;
  ASSERT_TRUE(surface.intersect({0.5 + 0.32 * std::cos(a), 0.5 + 0.32 * std::sin(a), 1}, {0, 0, -1}, hit));
  EXPECT_NEAR(hit.point.w, -0.03, 1e-12);
  // An oblique ray across the arc meets it where the height equals the ray's height.
  ASSERT_TRUE(surface.intersect({0.5, 0.9, 0.05}, {0.1, -1, -0.3}, hit));
  EXPECT_NEAR(surface.height({hit.point.u, hit.point.v}), hit.point.w, 1e-9);
}

TEST(GrooveReference, RightAngleCornerIsContinuousAcrossTheMitre) {
  const std::string profile = R"("skew": {"points": [[-0.04, 0], [-0.02, -0.03], [0.04, 0]]})";
  const ReferenceSurface surface(parseOk(
      sceneText(profile, R"({"profile": "skew", "path": {"polyline": [[0.2, 0.5], [0.5, 0.5], [0.5, 0.8]]}})")));
  // The mitre line through (0.5, 0.5) runs along (1, -1) / sqrt 2 (bisector of the normals).
  for (double s = -0.05; s <= 0.05; s += 0.0041) {
    const Vec2 onMitre{0.5 + s / std::sqrt(2.0), 0.5 - s / std::sqrt(2.0)};
    const double eps = 1e-9;
    const double before = surface.height({onMitre.u - eps, onMitre.v - eps});
    const double after = surface.height({onMitre.u + eps, onMitre.v + eps});
    EXPECT_NEAR(before, after, 1e-7) << s;
  }
  // On the first piece, b is v - 0.5 (left of +u); on the second, 0.5 - u (left of +v).
  EXPECT_NEAR(surface.height({0.35, 0.48}), -0.03, 1e-12);
  EXPECT_NEAR(surface.height({0.52, 0.65}), -0.03, 1e-12);
  // The outer corner of the mitre is inside the groove too: b = -0.02 on both pieces.
  EXPECT_NEAR(surface.height({0.52, 0.48}), -0.03, 1e-12);
}

TEST(GrooveReference, WrapRepeatIsPeriodic) {
  const std::string profile = R"("v": {"points": [[-0.05, 0], [0, -0.04], [0.05, 0]]})";
  const GrooveScene scene = parseOk(sceneText(profile, R"({"profile": "v", "path": {"line": [[0.8, 0.3], [1.3, 0.6]]}})",
                                              R"("wrap": "repeat", )"));
  const ReferenceSurface surface(scene);
  // The part beyond u = 1 comes back at u - 1: the path point at u = 1.1 is (1.1, 0.48).
  EXPECT_NEAR(surface.height({0.1, 0.48}), -0.04, 1e-12);
  for (int i = 0; i < 50; ++i) {
    const Vec2 x{0.02 * i, 0.3 + 0.006 * i};
    EXPECT_NEAR(surface.height(x), surface.height({x.u + 1, x.v}), 1e-12);
    EXPECT_NEAR(surface.height(x), surface.height({x.u - 2, x.v + 3}), 1e-12);
  }
  // A ray from a periodic copy far away hits the same floor point's height.
  ReferenceSurface::Hit hit;
  ASSERT_TRUE(surface.intersect({5.1, -2 + 0.48, 1}, {0, 0, -1}, hit));
  EXPECT_NEAR(hit.point.w, -0.04, 1e-12);
}

Image rowImage(const GrooveScene& scene, int spp, std::uint64_t seed, int threads) {
  ReferenceSettings s;
  s.samplesPerPixel = spp;
  s.seed = seed;
  s.threads = threads;
  Lighting light = lightFrom(0.6, 0.3);
  View view = windowView({0.3, 0.49}, {0.7, 0.51}, 100, 0.5, 0.2);
  view.height = 1;
  return renderReference(scene, view, light, s);
}

GrooveScene crossingScene() {
  const std::string profiles = R"("v": {"points": [[-0.01, 0], [0, -0.008], [0.01, 0]]})";
  return parseOk(sceneText(profiles, R"({"profile": "v", "path": {"line": [[0.3, 0.5], [0.7, 0.5]]}},
      {"profile": "v", "path": {"polyline": [[0.3, 0.3], [0.5, 0.5], [0.7, 0.4]]}},
      {"profile": "v", "path": {"arc": {"centre": [0.5, 0.3], "radius": 0.2, "start": 30, "end": 150}}})"));
}

TEST(GrooveReference, ImagesDoNotDependOnTheThreadCount) {
  const GrooveScene scene = crossingScene();
  const Image one = rowImage(scene, 16, 3, 1), many = rowImage(scene, 16, 3, 3);
  ASSERT_EQ(one.pixels.size(), many.pixels.size());
  EXPECT_EQ(one.pixels, many.pixels);
}

TEST(GrooveReference, SeedNoiseFallsWithTheSampleCount) {
  const GrooveScene scene = crossingScene();
  const double coarse = imageError(rowImage(scene, 16, 1, 0), rowImage(scene, 16, 2, 0)).rmse;
  const double fine = imageError(rowImage(scene, 256, 1, 0), rowImage(scene, 256, 2, 0)).rmse;
  EXPECT_GT(fine, 0);
  // At least as fast as 1 / sqrt(spp) (a factor 4 here); stratification does better.
  EXPECT_LT(fine, coarse / 4 * 1.25);
}

TEST(GrooveReference, NonSquareSampleCountsRoundToTheNearestSquare) {
  const GrooveScene scene = crossingScene();
  EXPECT_EQ(rowImage(scene, 15, 1, 1).pixels, rowImage(scene, 16, 1, 1).pixels);
}

TEST(GrooveReference, ReferenceRadianceSeesWhatTheViewLineHits) {
  const double w = 0.05, d = 0.05;
  const GrooveScene scene = vGroove(w, d);
  const ReferenceSurface surface(scene);
  const Lighting light = lightFrom(0);
  // From above, the bottom-left facet point: Lambert with the facet normal.
  const Rgb facet = referenceRadiance(surface, scene, {0.48, 0.5}, {0, 0, 1}, light);
  EXPECT_NEAR(facet[0], facetRadiance(0.6, w, d, true, light.toLight), 1e-12);
}

TEST(GrooveReference, MirrorGrooveAddsReflectedLight) {
  // A 90-degree V with mirror walls, seen from above and lit from above: one bounce off a wall
  // goes across to the other wall and back up: it leaves, so the mirror adds nothing at 1 bounce
  // from the wall (it sees the other wall, lit) and the pixel rises.
  const std::string text = R"({"version": 1, "domain": {"size": [1, 1]},
    "profiles": {"v": {"points": [[-0.05, 0], [0, -0.05], [0.05, 0]]}},
    "materials": {"m": {"albedo": [0.2, 0.2, 0.2], "mirror": [0.5, 0.5, 0.5]}}, "base": "m",
    "grooves": [{"profile": "v", "path": {"line": [[0.5, 0], [0.5, 1]]}}]})";
  const GrooveScene scene = parseOk(text);
  const ReferenceSurface surface(scene);
  Lighting light = lightFrom(0);
  const double direct = 0.2 / kPi * std::cos(kPi / 4);
  light.maxBounces = 0;
  EXPECT_NEAR(referenceRadiance(surface, scene, {0.48, 0.5}, {0, 0, 1}, light)[0], direct, 1e-12);
  // The reflected ray leaves horizontally towards +u, hits the other wall at the same height,
  // reflects up and leaves: one bounce adds mirror x direct(other wall seen horizontally).
  light.maxBounces = 1;
  const Vec3 toViewerAtWall{-1, 0, 0};
  Material m = scene.materials[0];
  const double n = std::sqrt(0.5);
  const Rgb other = directRadiance(m, {-n, 0, n}, toViewerAtWall, light);
  EXPECT_NEAR(referenceRadiance(surface, scene, {0.48, 0.5}, {0, 0, 1}, light)[0], direct + 0.5 * other[0], 1e-9);
  // Two bounces: the second reflection goes straight up and leaves: nothing more.
  light.maxBounces = 2;
  EXPECT_NEAR(referenceRadiance(surface, scene, {0.48, 0.5}, {0, 0, 1}, light)[0], direct + 0.5 * other[0], 1e-9);
}


TEST(GrooveReference, PerturbedHeightFollowsScaleAndOffset) {
  const std::string profile = R"("skew": {"points": [[-0.04, 0], [-0.02, -0.03], [0.04, 0]]})";
  const auto profileAt = [](double b) {
    if (b <= -0.04 || b >= 0.04) return 0.0;
    return b < -0.02 ? -0.03 * (b + 0.04) / 0.02 : -0.03 * (0.04 - b) / 0.06;
  };
  // Along +u from (0.1, 0.5): s = u - 0.1, b = v - 0.5.
  const ReferenceSurface scaled(parseOk(sceneText(profile, R"({"profile": "skew", "path": {"line": [[0.1, 0.5], [0.9, 0.5]]},
      "perturbation": {"kind": "scale", "amplitude": 0.4, "wavelength": 0.2, "phase": 0.5}})")));
  const ReferenceSurface offset(parseOk(sceneText(profile, R"({"profile": "skew", "path": {"line": [[0.1, 0.5], [0.9, 0.5]]},
      "perturbation": {"kind": "offset", "amplitude": 0.01, "wavelength": 0.3}})")));
  for (double u = 0.15; u < 0.85; u += 0.0123)
    for (double b = -0.06; b <= 0.06; b += 0.0071) {
      const double s = u - 0.1, f = 1 + 0.4 * std::sin(2 * kPi * s / 0.2 + 0.5), o = 0.01 * std::sin(2 * kPi * s / 0.3);
      EXPECT_NEAR(scaled.height({u, 0.5 + b}), f * profileAt(b / f), 1e-12);
      EXPECT_NEAR(offset.height({u, 0.5 + b}), profileAt(b - o), 1e-12);
    }
}

// Every kind of region at once: crossings, an arc, a corner, open ends, a ridge with vertical walls
// and perturbed grooves.
GrooveScene everyKindScene() {
  const std::string profiles = R"("v": {"points": [[-0.03, 0], [0, -0.03], [0.03, 0]]},
      "box": {"points": [[-0.02, 0], [-0.02, -0.02], [0.02, -0.02], [0.02, 0]]},
      "ridge": {"points": [[-0.03, 0], [-0.01, 0], [-0.01, 0.02], [0.01, 0.02], [0.01, 0], [0.03, 0]]})";
  const std::string grooves = R"({"profile": "v", "path": {"line": [[0.2, 0.5], [0.8, 0.5]]}},
      {"profile": "box", "path": {"polyline": [[0.3, 0.2], [0.5, 0.5], [0.7, 0.3]]}},
      {"profile": "ridge", "path": {"line": [[0.5, 0.2], [0.5, 0.8]]}},
      {"profile": "v", "path": {"arc": {"centre": [0.5, 0.5], "radius": 0.2, "start": 20, "end": 160}}},
      {"profile": "v", "path": {"line": [[0.2, 0.7], [0.8, 0.75]]}, "perturbation": {"kind": "scale", "amplitude": 0.5, "wavelength": 0.1}},
      {"profile": "box", "path": {"arc": {"centre": [0.5, 0.45], "radius": 0.3, "start": 200, "end": 340}},
       "perturbation": {"kind": "offset", "amplitude": 0.01, "wavelength": 0.15}})";
  return parseOk(sceneText(profiles, grooves));
}

// For rays in many directions over every kind of region the hit lies on the surface (or on a wall
// between its two sides), and no point sampled along the ray before it is below the surface.
TEST(GrooveReference, RayHitsAgreeWithTheHeightField) {
  const GrooveScene scene = everyKindScene();
  const ReferenceSurface surface(scene);
  std::uint64_t state = 7;
  const auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) * 0x1.0p-53;
  };
  int walls = 0;
  for (int k = 0; k < 400; ++k) {
    const double theta = 1.4 * next(), phi = 2 * kPi * next();
    const Vec3 e = directionFromAngles(theta, phi);
    const Vec2 target{0.15 + 0.7 * next(), 0.15 + 0.7 * next()};
    const Vec3 origin{target.u + 0.05 / e.w * e.u, target.v + 0.05 / e.w * e.v, 0.05};
    const Vec3 dir{-e.u, -e.v, -e.w};
    ReferenceSurface::Hit hit;
    ASSERT_TRUE(surface.intersect(origin, dir, hit));
    const Vec2 at{hit.point.u, hit.point.v};
    if (hit.normal.w == 0) {  // a wall: its height lies between the heights on its two sides
      ++walls;
      const Vec2 n{hit.normal.u * 1e-7, hit.normal.v * 1e-7};
      const double front = surface.height({at.u + n.u, at.v + n.v}), back = surface.height({at.u - n.u, at.v - n.v});
      EXPECT_LE(front, hit.point.w + 1e-9);
      EXPECT_GE(back, hit.point.w - 1e-9);
    } else {
      EXPECT_NEAR(surface.height(at), hit.point.w, 1e-9) << k;
    }
    for (int i = 1; i < 400; ++i) {
      const double t = hit.t * i / 400;
      const Vec3 p{origin.u + t * dir.u, origin.v + t * dir.v, origin.w + t * dir.w};
      EXPECT_GT(p.w - surface.height({p.u, p.v}), -1e-9) << k << " " << i;
    }
  }
  EXPECT_GT(walls, 0);
}


// The benchmark scene set: every scene loads, and a one-row reference render of it is finite.
TEST(GrooveReference, BenchmarkScenesLoadAndRender) {
  const std::filesystem::path dir = std::filesystem::path(BAKE_SOURCE_DIR) / "bench" / "groove" / "scenes";
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    ++count;
    Result<GrooveScene> scene = readGrooveScene(entry.path().string());
    ASSERT_TRUE(scene.isOk()) << scene.status().describe();
    EXPECT_FALSE(scene->grooves.empty()) << entry.path();
    EXPECT_TRUE(scene->warnings.empty()) << entry.path();
    ReferenceSettings s;
    s.samplesPerPixel = 4;
    Lighting light = lightFrom(0.7, 0.4);
    light.maxBounces = 2;
    View view = windowView({0.2, 0.5}, {0.8, 0.52}, 24, 1.0, 0.3);
    const Image image = renderReference(*scene, view, light, s);
    for (float value : image.pixels) {
      EXPECT_TRUE(std::isfinite(value)) << entry.path();
      EXPECT_GE(value, 0.0f) << entry.path();
    }
  }
  EXPECT_GE(count, 18);
}


// The material rule: the largest |h| wins (the deeper cut at a crossing), base where nothing cuts,
// and a wall takes the side with the larger |H| (the cavity's side at an open end).
TEST(GrooveReference, MaterialsFollowTheLargestCut) {
  const std::string text = R"({"version": 1, "domain": {"size": [1, 1]},
    "profiles": {"shallow": {"points": [[-0.05, 0], [0, -0.02], [0.05, 0]]}, "deep": {"points": [[-0.04, 0], [0, -0.06], [0.04, 0]]}},
    "materials": {"base": {}, "a": {"albedo": [1, 0, 0]}, "b": {"albedo": [0, 1, 0]}}, "base": "base",
    "grooves": [{"profile": "shallow", "material": "a", "path": {"line": [[0.1, 0.5], [0.9, 0.5]]}},
                {"profile": "deep", "material": "b", "path": {"line": [[0.5, 0.1], [0.5, 0.7]]}}]})";
  const GrooveScene scene = parseOk(text);
  const ReferenceSurface surface(scene);
  const auto materialBelow = [&](Vec2 x) {
    ReferenceSurface::Hit hit;
    EXPECT_TRUE(surface.intersect({x.u, x.v, 1}, {0, 0, -1}, hit));
    return scene.materials[hit.material].name;
  };
  EXPECT_EQ(materialBelow({0.5, 0.5}), "b");
  EXPECT_EQ(materialBelow({0.3, 0.51}), "a");
  EXPECT_EQ(materialBelow({0.3, 0.3}), "base");
  EXPECT_EQ(materialBelow({0.51, 0.3}), "b");
  // Where the shallow groove's facet is deeper than the deep groove's rim region, "a" wins.
  EXPECT_EQ(materialBelow({0.539, 0.5}), "a");
  // The deep groove's open end at v = 0.7, seen from inside the cavity: the wall is "b"'s.
  ReferenceSurface::Hit hit;
  ASSERT_TRUE(surface.intersect({0.5, 0.6, -0.03}, {0, 1, 0}, hit));
  EXPECT_NEAR(hit.point.v, 0.7, 1e-12);
  EXPECT_EQ(scene.materials[hit.material].name, "b");
}


// A closed circle's first and last arcs meet on one line: no sliver of flat surface between them
// (which would stand as a wall), so shadow rays cross the closing joint freely.
TEST(GrooveReference, ClosedCircleHasNoSeamAtItsClosingJoint) {
  const std::string profile = R"("v": {"points": [[-0.05, 0], [0, -0.03], [0.05, 0]]})";
  const GrooveScene scene = parseOk(sceneText(
      profile, R"({"profile": "v", "path": {"arc": {"centre": [0.5, 0.5], "radius": 0.25, "start": 0, "end": 360}}})"));
  ASSERT_TRUE(scene.grooves[0].closed);
  const ReferenceSurface surface(scene);
  const Lighting light = lightFrom(40 * kPi / 180, kPi / 2);  // shadow rays run across the joint (along +v)
  for (double u = 0.71; u < 0.79; u += 0.0071) {
    const Rgb below = referenceRadiance(surface, scene, {u, 0.5 - 1e-7}, {0, 0, 1}, light);
    const Rgb above = referenceRadiance(surface, scene, {u, 0.5 + 1e-7}, {0, 0, 1}, light);
    EXPECT_NEAR(below[0], above[0], 1e-5) << u;
    EXPECT_GT(below[0], 0) << u;
  }
}

// Hit normals are the normalised (-grad H, 1): checked against central differences of height() on
// perturbed grooves (where the depth varies along the path too) and an arc.
TEST(GrooveReference, NormalsAreTheHeightGradient) {
  const std::string profiles = R"("v": {"points": [[-0.05, 0], [0, -0.03], [0.05, 0]]},
      "skew": {"points": [[-0.04, 0], [-0.02, -0.03], [0.04, 0]]})";
  const GrooveScene scene = parseOk(sceneText(profiles,
      R"({"profile": "v", "path": {"line": [[0.1, 0.3], [0.9, 0.3]]}, "perturbation": {"kind": "scale", "amplitude": 0.4, "wavelength": 0.2}},
         {"profile": "skew", "path": {"line": [[0.1, 0.6], [0.9, 0.65]]}, "perturbation": {"kind": "offset", "amplitude": 0.02, "wavelength": 0.25}},
         {"profile": "skew", "path": {"arc": {"centre": [0.5, 0.5], "radius": 0.1, "start": 200, "end": 340}}})"));
  const ReferenceSurface surface(scene);
  int checked = 0;
  for (double u = 0.15; u < 0.85; u += 0.0173)
    for (double v = 0.22; v < 0.7; v += 0.0071) {
      const double e = 1e-7;
      const double hu = (surface.height({u + e, v}) - surface.height({u - e, v})) / (2 * e);
      const double hv = (surface.height({u, v + e}) - surface.height({u, v - e})) / (2 * e);
      ReferenceSurface::Hit hit;
      ASSERT_TRUE(surface.intersect({u, v, 1}, {0, 0, -1}, hit));
      if (hit.point.w == 0 || hit.normal.w == 0) continue;
      const double n = std::sqrt(1 + hu * hu + hv * hv);
      // Skip points within a difference step of a kink (profile vertex, crossing, joint).
      const double hu2 = (surface.height({u + 2 * e, v}) - surface.height({u - 2 * e, v})) / (4 * e);
      if (std::abs(hu2 - hu) > 1e-6) continue;
      EXPECT_NEAR(hit.normal.u, -hu / n, 1e-5) << u << " " << v;
      EXPECT_NEAR(hit.normal.v, -hv / n, 1e-5) << u << " " << v;
      EXPECT_NEAR(hit.normal.w, 1 / n, 1e-5) << u << " " << v;
      ++checked;
    }
  EXPECT_GT(checked, 200);
}


// Radiance against a brute-force renderer built on height() alone: view and shadow rays marched in
// steps of 2e-5, normals from central differences. Wall hits (no difference normal) and points within
// a step of a kink are skipped; a few points may sit on a shadow or visibility edge the brute march
// resolves only to its step.
TEST(GrooveReference, RadianceAgreesWithABruteForceMarch) {
  const GrooveScene scene = everyKindScene();
  const ReferenceSurface surface(scene);
  const Lighting light = lightFrom(55 * kPi / 180, 2.0);
  const Vec3 e = directionFromAngles(50 * kPi / 180, 0.7);
  const auto march = [&](Vec3 o, Vec3 d, Vec3& at) {
    for (double t = 0; t < 2; t += 2e-5) {
      at = {o.u + t * d.u, o.v + t * d.v, o.w + t * d.w};
      if (at.w > scene.hmax + 1e-9 && d.w >= 0) return false;
      if (at.w <= surface.height({at.u, at.v})) return true;
    }
    return false;
  };
  int compared = 0, off = 0;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      const Vec2 x{0.2 + 0.6 * (i + 0.37) / 12, 0.2 + 0.6 * (j + 0.61) / 12};
      const double top = (scene.hmax + 1e-6) / e.w;
      const Vec3 origin{x.u + top * e.u, x.v + top * e.v, top * e.w};
      ReferenceSurface::Hit hit;
      ASSERT_TRUE(surface.intersect(origin, {-e.u, -e.v, -e.w}, hit));
      if (hit.normal.w == 0) continue;
      Vec3 at;
      ASSERT_TRUE(march(origin, {-e.u, -e.v, -e.w}, at));
      EXPECT_NEAR(at.u, hit.point.u, 1e-4);
      EXPECT_NEAR(at.v, hit.point.v, 1e-4);
      const auto slope = [&](double step, Vec2 dir) {
        return (surface.height({hit.point.u + step * dir.u, hit.point.v + step * dir.v}) -
                surface.height({hit.point.u - step * dir.u, hit.point.v - step * dir.v})) / (2 * step);
      };
      const double hu = slope(1e-7, {1, 0}), hv = slope(1e-7, {0, 1});
      if (std::abs(slope(1e-5, {1, 0}) - hu) > 1e-6 || std::abs(slope(1e-5, {0, 1}) - hv) > 1e-6) continue;
      const double n = std::sqrt(1 + hu * hu + hv * hv);
      const Vec3 normal{-hu / n, -hv / n, 1 / n};
      const Vec3 start{hit.point.u + 1e-6 * normal.u, hit.point.v + 1e-6 * normal.v, hit.point.w + 1e-6 * normal.w};
      Vec3 blocker;
      const bool lit = normal.u * light.toLight.u + normal.v * light.toLight.v + normal.w * light.toLight.w > 0 &&
                       !march(start, light.toLight, blocker);
      const double brute = lit ? directRadiance(scene.materials[hit.material], normal, e, light)[0] : 0;
      const double reference = referenceRadiance(surface, scene, x, e, light)[0];
      ++compared;
      if (std::abs(brute - reference) > 1e-6) ++off;
    }
  EXPECT_GT(compared, 100);
  EXPECT_LE(off, compared / 50) << off << " of " << compared;
}

}  // namespace
}  // namespace bake::grooves
