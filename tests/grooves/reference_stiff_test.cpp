// Stiff cases of the ray-traced reference (libbake/grooves/reference/reference.h): grazing views up to 89
// degrees, lights at and below the horizon, grooves tiny and huge against the footprint, a crossing
// at 1 degree, a corner folded back almost onto itself, footprints of 1000 groove widths and a tiny
// groove far out in a huge domain. Every result is finite and, where a closed
// form exists, equal to it within the stratified sampling bound (sum of the jumps / strata per side).
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
constexpr double kDegree = kPi / 180;
constexpr int kStrata = 32;

std::string number(double x) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

GrooveScene parseOk(const std::string& profiles, const std::string& grooves) {
  const std::string text = R"({"version": 1, "domain": {"size": [1, 1]}, "profiles": {)" + profiles +
                           R"(}, "materials": {"grey": {"albedo": [0.6, 0.6, 0.6]}}, "base": "grey", "grooves": [)" +
                           grooves + "]}";
  Result<GrooveScene> scene = parseGrooveScene(text, "stiff.json");
  EXPECT_TRUE(scene.isOk()) << scene.status().describe();
  return scene.isOk() ? scene.value() : GrooveScene{};
}

std::string vProfile(double w, double d) {
  return R"("v": {"points": [[)" + number(-w) + ", 0], [0, " + number(-d) + "], [" + number(w) + ", 0]]}";
}

GrooveScene vGroove(double w, double d) {
  return parseOk(vProfile(w, d), R"({"profile": "v", "path": {"line": [[0.5, 0], [0.5, 1]]}})");
}

double renderPixel(const GrooveScene& scene, double side, double theta, const Lighting& light, Vec2 centre = {0.5, 0.5}) {
  const View view = windowView({centre.u - side / 2, centre.v - side / 2}, {centre.u + side / 2, centre.v + side / 2}, 1,
                               theta, 0);
  ReferenceSettings s;
  s.samplesPerPixel = kStrata * kStrata;
  s.threads = 1;
  const Image image = renderReference(scene, view, light, s);
  EXPECT_TRUE(std::isfinite(rgbAt(image, 0, 0)[0]));
  return rgbAt(image, 0, 0)[0];
}

double lambert(double albedo, Vec3 normal, Vec3 toLight) {
  return albedo / kPi * std::max(0.0, normal.u * toLight.u + normal.v * toLight.v + normal.w * toLight.w);
}

Lighting lightAt(double beta) {
  Lighting l;
  l.toLight = directionFromAngles(beta, 0);
  return l;
}

// Beyond tan(theta) = w/d the far facet A alone fills the groove's opening of 2w.
TEST(GrooveReferenceStiff, GrazingViewsUpTo89Degrees) {
  const double w = 0.05, d = 0.05, side = 0.2;
  const GrooveScene scene = vGroove(w, d);
  const Lighting light = lightAt(20 * kDegree);
  const double flat = lambert(0.6, {0, 0, 1}, light.toLight);
  const double a = lambert(0.6, {std::sqrt(0.5), 0, std::sqrt(0.5)}, light.toLight);
  for (double degrees : {80.0, 85.0, 88.0, 89.0}) {
    const double expected = ((side - 2 * w) * flat + 2 * w * a) / side;
    EXPECT_NEAR(renderPixel(scene, side, degrees * kDegree, light), expected, 2 * std::abs(flat - a) / kStrata + 1e-6)
        << degrees;
  }
}

TEST(GrooveReferenceStiff, LightBelowTheHorizonLeavesEverythingDark) {
  const std::string profiles = vProfile(0.05, 0.03) +
                               R"(, "ridge": {"points": [[-0.02, 0], [-0.02, 0.03], [0.02, 0.03], [0.02, 0]]})";
  const GrooveScene scene = parseOk(profiles, R"({"profile": "v", "path": {"line": [[0.2, 0.5], [0.8, 0.5]]}},
      {"profile": "ridge", "path": {"line": [[0.5, 0.2], [0.5, 0.8]]}})");
  ReferenceSettings s;
  s.samplesPerPixel = 16;
  const View view = windowView({0.3, 0.3}, {0.7, 0.7}, 24, 70 * kDegree, 3.0);
  // Below the horizon every shadow ray meets the (infinite) base plane: black, exactly.
  for (double beta : {91.0, 100.0, 179.0}) {
    const Image image = renderReference(scene, view, lightAt(beta * kDegree), s);
    for (float value : image.pixels) EXPECT_EQ(value, 0.0f) << beta;
  }
  // At the horizon only the ridge's wall facing the light is lit (the floor has N.L = 0).
  const Image horizon = renderReference(scene, view, lightAt(90 * kDegree), s);
  double sum = 0;
  for (float value : horizon.pixels) {
    EXPECT_TRUE(std::isfinite(value));
    EXPECT_GE(value, 0.0f);
    EXPECT_LE(value, 0.6 / kPi + 1e-6);
    sum += value;
  }
  EXPECT_GT(sum, 0);
}

TEST(GrooveReferenceStiff, TinyGroovesInAWideFootprint) {
  for (double w : {1e-4, 1e-6}) {
    const double side = 0.4;
    const GrooveScene scene = vGroove(w, w);
    const Lighting light = lightAt(0);
    const double flat = 0.6 / kPi, facet = flat * std::sqrt(0.5);
    const double expected = ((side - 2 * w) * flat + 2 * w * facet) / side;
    EXPECT_NEAR(renderPixel(scene, side, 0, light), expected, 2 * (flat - facet) / kStrata + 1e-6) << w;
    EXPECT_NEAR(ReferenceSurface(scene).height({0.5, 0.3}), -w, 1e-15);
  }
}

// A footprint far smaller than the groove, on one facet: exactly that facet's radiance, at any view.
TEST(GrooveReferenceStiff, HugeGrooveAgainstATinyFootprint) {
  const double w = 0.2, d = 0.1;
  const GrooveScene scene = vGroove(w, d);
  const Lighting light = lightAt(30 * kDegree);
  const double n = std::hypot(w, d);
  const double facet = lambert(0.6, {d / n, 0, w / n}, light.toLight);
  for (double side : {1e-3, 1e-7})
    for (double theta : {0.0, 40 * kDegree}) {
      // The view line through (0.4, 0.5) meets facet A at (0.4 + z tan theta): still on it.
      EXPECT_NEAR(renderPixel(scene, side, theta, light, {0.4, 0.5}), facet, 1e-6) << side << " " << theta;
    }
}

TEST(GrooveReferenceStiff, OneDegreeCrossing) {
  const double angle = 1 * kDegree;
  const std::string profiles = vProfile(0.02, 0.02) + R"(, "w": {"points": [[-0.03, 0], [0, -0.01], [0.03, 0]]})";
  const std::string first = R"({"profile": "v", "path": {"line": [[0.1, 0.5], [0.9, 0.5]]}})";
  const std::string second = R"({"profile": "w", "path": {"line": [[)" + number(0.5 - 0.4 * std::cos(angle)) + ", " +
                             number(0.5 - 0.4 * std::sin(angle)) + "], [" + number(0.5 + 0.4 * std::cos(angle)) + ", " +
                             number(0.5 + 0.4 * std::sin(angle)) + "]]}}";
  const ReferenceSurface both(parseOk(profiles, first + "," + second)), one(parseOk(profiles, first)),
      two(parseOk(profiles, second));
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 9; ++j) {
      const Vec2 x{0.1 + 0.8 * i / 199, 0.47 + 0.06 * j / 8};
      EXPECT_NEAR(both.height(x), std::min(one.height(x), two.height(x)), 1e-12);
    }
  // Grazing along the crossing: the first hit lies on the surface and nothing before it is below.
  ReferenceSurface::Hit hit;
  const Vec3 origin{0.1, 0.5, 0.01}, dir{1, 0.0005, -0.0004};
  ASSERT_TRUE(both.intersect(origin, dir, hit));
  EXPECT_NEAR(both.height({hit.point.u, hit.point.v}), hit.point.w, 1e-9);
  for (int i = 1; i < 1000; ++i) {
    const double t = hit.t * i / 1000;
    EXPECT_GT(origin.w + t * dir.w - both.height({origin.u + t * dir.u, origin.v + t * dir.v}), -1e-12);
  }
  const GrooveScene scene = parseOk(profiles, first + "," + second);
  ReferenceSettings s;
  s.samplesPerPixel = 16;
  const Image image = renderReference(scene, windowView({0.2, 0.49}, {0.8, 0.51}, 60, 60 * kDegree, 0.3),
                                         lightAt(50 * kDegree), s);
  for (float value : image.pixels) {
    EXPECT_TRUE(std::isfinite(value));
    EXPECT_GE(value, 0.0f);
  }
}

// Two pieces meeting at 2 degrees: the mitre runs almost along them; heights stay finite and the
// fold's inside is the deeper of the two pieces' cuts.
TEST(GrooveReferenceStiff, CornerFoldedBackAlmostOntoItself) {
  const double angle = 2 * kDegree;
  const std::string polyline = R"({"profile": "v", "path": {"polyline": [[0.2, 0.5], [0.7, 0.5], [)" +
                               number(0.7 - 0.5 * std::cos(angle)) + ", " + number(0.5 + 0.5 * std::sin(angle)) + "]]}}";
  const GrooveScene scene = parseOk(vProfile(0.01, 0.01), polyline);
  const ReferenceSurface surface(scene);
  for (int i = 0; i <= 100; ++i) {
    const double h = surface.height({0.2 + 0.6 * i / 100, 0.5});
    EXPECT_TRUE(std::isfinite(h));
    EXPECT_GE(h, -0.01 - 1e-15);
    EXPECT_LE(h, 0.0);
  }
  EXPECT_NEAR(surface.height({0.3, 0.5}), -0.01, 1e-12);
  ReferenceSettings s;
  s.samplesPerPixel = 16;
  const Image image = renderReference(scene, windowView({0.5, 0.48}, {0.75, 0.53}, 50, 45 * kDegree, 1.0),
                                         lightAt(30 * kDegree), s);
  for (float value : image.pixels) EXPECT_TRUE(std::isfinite(value));
}


// Footprints up to 1000 x the groove width over the repeating parallel set of the benchmark: the
// pixel tends to the period's average, (flat part + facets x cos 45 degrees) / period. The samples
// spread over many periods, so the bound here is statistical: 6 standard deviations of the mean.
TEST(GrooveReferenceStiff, FootprintsUpTo1000GrooveWidthsOverRepeatingGrooves) {
  Result<GrooveScene> scene = readGrooveScene(
      (std::filesystem::path(BAKE_SOURCE_DIR) / "bench" / "groove" / "scenes" / "parallel-dense.json").string());
  ASSERT_TRUE(scene.isOk()) << scene.status().describe();
  // The material has a specular lobe: the model's own directRadiance gives each facet's value.
  const Material& paint = scene->materials[scene->baseMaterial];
  const double flat = directRadiance(paint, {0, 0, 1}, {0, 0, 1}, lightAt(0))[0];
  const double facet = directRadiance(paint, {std::sqrt(0.5), 0, std::sqrt(0.5)}, {0, 0, 1}, lightAt(0))[0];
  const double period = 0.05, width = 0.04;
  const double expected = ((period - width) * flat + width * facet) / period;
  const double spread = 0.5 * (flat - facet);  // at most half the jump
  for (double side : {0.4, 4.0, 40.0}) {
    EXPECT_NEAR(renderPixel(*scene, side, 0, lightAt(0), {0.3, 0.3}), expected, 6 * spread / kStrata + 1e-6) << side;
    EXPECT_NEAR(renderPixel(*scene, side, 0, lightAt(0), {-71.3, 13.1}), expected, 6 * spread / kStrata + 1e-6) << side;
  }
}


// Far from the origin in a huge domain (coordinates 5e2, features 1e-3): the V-groove's closed form
// with masking still holds, so offsets and tolerances scale with the features, not the domain.
TEST(GrooveReferenceStiff, TinyGrooveFarOutInAHugeDomain) {
  const std::string text = R"({"version": 1, "domain": {"size": [1000, 1000]},
    "profiles": {"v": {"points": [[-0.001, 0], [0, -0.001], [0.001, 0]]}},
    "materials": {"grey": {"albedo": [0.6, 0.6, 0.6]}}, "base": "grey",
    "grooves": [{"profile": "v", "path": {"line": [[500, 0], [500, 1000]]}}]})";
  Result<GrooveScene> scene = parseGrooveScene(text, "huge.json");
  ASSERT_TRUE(scene.isOk()) << scene.status().describe();
  const double w = 0.001, side = 0.004, beta = 20 * kDegree;
  const Lighting light = lightAt(beta);
  const double flat = lambert(0.6, {0, 0, 1}, light.toLight);
  const double a = lambert(0.6, {std::sqrt(0.5), 0, std::sqrt(0.5)}, light.toLight);
  const double b = lambert(0.6, {-std::sqrt(0.5), 0, std::sqrt(0.5)}, light.toLight);
  for (double degrees : {0.0, 60.0}) {
    const double shift = w * std::tan(degrees * kDegree);  // depth = w
    const double coverA = std::min(2 * w, w + shift), coverB = std::max(0.0, w - shift);
    const double expected = ((side - 2 * w) * flat + coverA * a + coverB * b) / side;
    const double bound = (std::abs(flat - a) + std::abs(a - b) + std::abs(b - flat)) / kStrata;
    EXPECT_NEAR(renderPixel(*scene, side, degrees * kDegree, light, {500, 600}), expected, bound + 1e-6) << degrees;
  }
}

}  // namespace
}  // namespace bake::grooves
