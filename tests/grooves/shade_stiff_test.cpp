// Stiff cases of the seed's method (libbake/grooves/oracle/shade.cpp, line_sampling*.cpp, interreflection.cpp):
// views up to 89 degrees and beyond, a light at and below the horizon, footprints far smaller and far
// larger than the groove, zero-area footprints (point samples), deep mirror grooves with many bounces
// (line and area sampled).
// Every value is finite and matches a closed form where one exists.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "bake/core/vec.h"
#include "grooves/bake/grid.h"
#include "grooves/groove_support.h"
#include "grooves/input/scene.h"
#include "grooves/oracle/line_sampling_section.h"
#include "grooves/oracle/shade.h"
#include "grooves/reference/reference.h"

namespace bake::grooves {
namespace {
constexpr double kDegree = kPi / 180;

std::string num(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

// One groove along u at v = 0.5 with the given profile points; base "ground" (diffuse), the groove in
// "paint" (diffuse + specular) or "chrome" (with a mirror).
GrooveScene oneGroove(const std::string& points, const std::string& material = "paint") {
  const std::string text = R"({"version": 1, "domain": {"size": [1, 1]}, "profiles": {"p": {"points": )" + points +
                           R"(}}, "materials": {"ground": {"albedo": [0.3, 0.5, 0.7]},
      "paint": {"albedo": [0.8, 0.3, 0.1], "specular": [0.4, 0.4, 0.4], "shininess": 16},
      "chrome": {"albedo": [0.1, 0.1, 0.1], "specular": [0.5, 0.5, 0.5], "shininess": 30, "mirror": [0.9, 0.9, 0.9]}},
      "base": "ground", "grooves": [{"profile": "p", "material": ")" + material +
                           R"(", "path": {"line": [[-0.5, 0.5], [1.5, 0.5]]}}]})";
  Result<GrooveScene> scene = parseGrooveScene(text, "scene.json");
  EXPECT_TRUE(scene.isOk()) << scene.status().describe();
  return scene.isOk() ? scene.value() : GrooveScene{};
}

std::string vee(double w, double d) {
  return "[[-" + num(w) + ", 0], [0, -" + num(d) + "], [" + num(w) + ", 0]]";
}

Rgb shadeWithGrid(const GrooveScene& s, const Footprint& f, const Vec3& e, const Lighting& l) {
  Result<GrooveGrid> grid = buildGrooveGrid(s, GridSettings{});
  EXPECT_TRUE(grid.isOk());
  return grid.isOk() ? SeedShader(s, grid.value()).shade(f, e, l) : Rgb{-1, -1, -1};
}

Rgb sampleLine(const GrooveScene& s, const Footprint& f, const Vec3& e, const Lighting& l) {
  const std::vector<LocalGroove> grooves{localGroove(s, 0, f.centre)};
  return lineSample(s, grooves, f, e, l);
}

Footprint square(Vec2 centre, double side) { return {centre, {side, 0}, {0, side}}; }

void expectRgbNear(const Rgb& a, const Rgb& b, double relative) {
  for (int c = 0; c < 3; ++c) {
    EXPECT_TRUE(std::isfinite(a[c]));
    EXPECT_NEAR(a[c], b[c], relative * std::max(1e-300, std::abs(b[c]))) << "channel " << c;
  }
}

Rgb mix(double wa, const Rgb& a, double wb, const Rgb& b) {
  return {wa * a[0] + wb * b[0], wa * a[1] + wb * b[1], wa * a[2] + wb * b[2]};
}

TEST(SeedShaderStiff, GrazingViewsUpTo89DegreesAndBeyond) {
  // Past tan(theta) = w / d the wall facing the viewer fills the groove's opening 2w on its own.
  const double w = 0.02, d = 0.02, side = 0.2;
  const GrooveScene s = oneGroove(vee(w, d));
  const Lighting l = lightTowards({0, 0.3, 1});
  const Vec3 facing{0, std::sqrt(0.5), std::sqrt(0.5)};
  for (double degrees : {80.0, 85.0, 88.0, 89.0, 89.9, 90 - 1e-9}) {
    SCOPED_TRACE(degrees);
    const Vec3 e{0, std::sin(degrees * kDegree), std::cos(degrees * kDegree)};
    const Rgb expected = mix((side - 2 * w) / side, directRadiance(materialNamed(s, "ground"), {0, 0, 1}, e, l),
                             2 * w / side, directRadiance(materialNamed(s, "paint"), facing, e, l));
    expectRgbNear(shadeWithGrid(s, square({0.5, 0.5}, side), e, l), expected, 1e-9);
  }
}

TEST(SeedShaderStiff, LightAtAndBelowTheHorizon) {
  // A ridge (box 0.04 wide, 0.03 high). Below the horizon the infinite base hides the light: black.
  const GrooveScene s = oneGroove("[[-0.02, 0], [-0.02, 0.03], [0.02, 0.03], [0.02, 0]]");
  const double theta = 60 * kDegree;
  const Vec3 e{0, std::sin(theta), std::cos(theta)};
  const Footprint f = square({0.5, 0.5}, 0.2);
  for (double below : {1e-300, 1e-9, 0.01, 0.5, 1.0}) {
    const Rgb value = shadeWithGrid(s, f, e, lightTowards({0, 1, -below}));
    for (double x : value) EXPECT_EQ(x, 0.0) << below;
  }
  // At the horizon, from +v: only the ridge's wall facing +v is lit; seen from 60 degrees it covers
  // 0.03 tan(60) of the footprint's 0.2 (the base and the top have N.L = 0).
  const Lighting horizon = lightTowards({0, 1, 0});
  const Rgb expected = mix(0.03 * std::tan(theta) / 0.2, directRadiance(materialNamed(s, "paint"), {0, 1, 0}, e, horizon), 0, {});
  expectRgbNear(shadeWithGrid(s, f, e, horizon), expected, 1e-12);
}

TEST(SeedShaderStiff, FootprintsFarSmallerAndFarLargerThanTheGroove) {
  const double w = 0.01, d = 0.005;
  const GrooveScene s = oneGroove(vee(w, d));
  const Vec3 e = directionFromAngles(0.3, 0.4);
  const Lighting l = lightTowards({-0.2, 0.1, 1});
  const Vec3 left{0, d / std::hypot(w, d), w / std::hypot(w, d)}, right{0, -left.v, left.w};
  const Rgb leftValue = directRadiance(materialNamed(s, "paint"), left, e, l);
  const Rgb rightValue = directRadiance(materialNamed(s, "paint"), right, e, l);
  const Rgb flat = directRadiance(materialNamed(s, "ground"), {0, 0, 1}, e, l);
  // A footprint 1e-7 of the width, seen nearly from above: the one facet under it.
  expectRgbNear(shadeWithGrid(s, square({0.5, 0.5 - 0.3 * w}, 1e-9), e, l), leftValue, 1e-12);
  // Footprints 1000 and 1e6 groove widths wide (line sampling of the one straight groove): the
  // groove's share is 2w / side, split by the facets' projected widths w + d e_b / e_w and w - ...
  const double shift = d * e.v / e.w;
  for (double side : {2000 * w, 2e6 * w}) {
    const Rgb groove = mix((w + shift) / side, leftValue, (w - shift) / side, rightValue);
    const Rgb expected = mix(1, groove, (side - 2 * w) / side, flat);
    expectRgbNear(sampleLine(s, square({0.5, 0.5}, side), e, l), expected, 1e-9);
  }
  // A groove a million times narrower than the footprint: the flat base up to 1e-6.
  const GrooveScene tiny = oneGroove(vee(1e-8, 1e-8));
  const Rgb value = sampleLine(tiny, square({0.5, 0.5}, 0.02), e, l);
  expectRgbNear(value, flat, 2e-6);
}

TEST(SeedShaderStiff, ZeroAreaFootprintsArePointSamples) {
  const double w = 0.01, d = 0.01;
  const GrooveScene s = oneGroove(vee(w, d));
  const Vec3 left{0, std::sqrt(0.5), std::sqrt(0.5)};
  const Lighting l = lightTowards({0.1, 0.2, 1});
  const Footprint point{{0.5, 0.5}, {0, 0}, {0, 0}};
  // From +v with d tan(theta) = 2w: the view line through the groove's centre line meets the left wall
  // (at b = -2w/3), not the flat base or the hidden right wall.
  const double theta = std::atan(2 * w / d);
  const Vec3 e{0, std::sin(theta), std::cos(theta)};
  expectRgbNear(shadeWithGrid(s, point, e, l), directRadiance(materialNamed(s, "paint"), left, e, l), 1e-12);
  // Beside the groove, the flat base; inside, from above, the facet under the point.
  const Vec3 up{0, 0, 1};
  expectRgbNear(shadeWithGrid(s, {{0.5, 0.3}, {0, 0}, {0, 0}}, up, l),
                directRadiance(materialNamed(s, "ground"), up, up, l), 1e-12);
  expectRgbNear(shadeWithGrid(s, {{0.5, 0.5 - 0.5 * w}, {0, 0}, {0, 0}}, up, l),
                directRadiance(materialNamed(s, "paint"), left, up, l), 1e-12);
  // A footprint collapsed to a segment along the groove is a point sample across it too.
  expectRgbNear(shadeWithGrid(s, {{0.5, 0.5 - 0.5 * w}, {0.01, 0}, {0, 0}}, up, l),
                directRadiance(materialNamed(s, "paint"), left, up, l), 1e-12);
}

TEST(SeedShaderStiff, DeepMirrorGrooveWithManyBouncesStaysBounded) {
  // A V 100 times deeper than wide: rays bounce down the walls many times. The beam stack is bounded;
  // each bounce adds a non-negative term, and the sum stays below the geometric bound
  // max direct x (1 + m + m^2 + ...) = max direct / (1 - m).
  const GrooveScene s = oneGroove(vee(0.001, 0.1), "chrome");
  const Vec3 e = directionFromAngles(0.2, 1.0);
  const Footprint f = square({0.5, 0.5}, 0.002);
  double previous = 0;
  for (int bounces : {0, 1, 4, 16, 200}) {
    const Rgb value = shadeWithGrid(s, f, e, lightTowards({0, 0.05, 1}, bounces));
    for (double x : value) EXPECT_TRUE(std::isfinite(x));
    EXPECT_GE(value[0], previous - 1e-15) << bounces;
    const double bound = (0.1 / kPi + 0.5 * 32 / (8 * kPi)) / (1 - 0.9);
    EXPECT_LE(value[0], bound);
    previous = value[0];
  }
}

// The same where footprints are area sampled: two deep box grooves with black mirror walls crossing,
// under an environment of radiance 1 and no direct light reflected (albedo and specular 0). Every
// bit of radiance is environment seen through mirrors of reflectance below 1, so no pixel may exceed
// 1 whatever the bounce count, and the value grows with the bounces followed (each adds non-negative
// terms); it also matches the reference's rays traced through a grid of the footprint (a grazing view
// sees the environment only after some twenty reflections). The beam stack and its step cap bound the
// work.
TEST(SeedShaderStiff, MirrorCavityAtACrossingWithManyBouncesStaysBounded) {
  Result<GrooveScene> parsed = parseGrooveScene(R"({"version": 1, "domain": {"size": [1, 1]},
    "profiles": {"well": {"points": [[-0.004, 0], [-0.004, -0.05], [0.004, -0.05], [0.004, 0]]}},
    "materials": {"ground": {"albedo": [0.3, 0.5, 0.7]}, "glass": {"albedo": [0, 0, 0], "mirror": [0.95, 0.9, 0.85]}},
    "base": "ground", "grooves": [
      {"profile": "well", "material": "glass", "path": {"line": [[0.1, 0.5], [0.9, 0.5]]}},
      {"profile": "well", "material": "glass", "path": {"line": [[0.5, 0.1], [0.5, 0.9]]}}]})",
                                                "well.json");
  ASSERT_TRUE(parsed.isOk()) << parsed.status().describe();
  const GrooveScene& s = parsed.value();
  Result<GrooveGrid> grid = buildGrooveGrid(s, GridSettings{});
  ASSERT_TRUE(grid.isOk());
  const SeedShader shader(s, grid.value());
  for (const Vec3& e : {directionFromAngles(0.3, 0.7), directionFromAngles(1.3, 2.0)}) {
    double previous = 0;
    for (int bounces : {1, 4, 16, 200}) {
      Lighting l = lightTowards({0.2, 0.1, 1}, bounces);
      l.environment = {1, 1, 1};
      ShadeStats stats;
      const Rgb value = shader.shade(square({0.5, 0.5}, 0.006), e, l, &stats);
      EXPECT_TRUE(stats.special);
      for (double x : value) {
        EXPECT_TRUE(std::isfinite(x));
        EXPECT_GE(x, 0.0);
        EXPECT_LE(x, 1.0 + 1e-9) << bounces;
      }
      EXPECT_GE(value[0], previous - 1e-12) << bounces;
      previous = value[0];
      // The reference's traced rays through a 40 x 40 grid of points of the footprint.
      const ReferenceSurface surface(s);
      Rgb traced{0, 0, 0};
      constexpr int kGrid = 40;
      for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j) {
          const Vec2 x{0.5 + 0.006 * ((i + 0.5) / kGrid - 0.5), 0.5 + 0.006 * ((j + 0.5) / kGrid - 0.5)};
          const Rgb r = referenceRadiance(surface, s, x, e, l);
          for (int c = 0; c < 3; ++c) traced[c] += r[c] / (kGrid * kGrid);
        }
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(value[c], traced[c], 0.005) << bounces << " channel " << c;
      std::printf("[ grooves ] mirror well crossing, view at %.2f rad, %d bounces: %.4f %.4f %.4f (traced %.4f %.4f %.4f)\n",
                  std::acos(e.w), bounces, value[0], value[1], value[2], traced[0], traced[1], traced[2]);
    }
  }
}

TEST(SeedShaderStiff, CoincidentAndNearlyParallelGrooves) {
  // The same line twice with different profiles (the deeper cut wins), and a groove 1e-9 rad off
  // parallel next to it: one combined section, finite, between the flat base and the groove values.
  const std::string text = R"({"version": 1, "domain": {"size": [1, 1]},
    "profiles": {"a": {"points": [[-0.01, 0], [0, -0.01], [0.01, 0]]}, "b": {"points": [[-0.01, 0], [0, -0.002], [0.01, 0]]}},
    "materials": {"ground": {"albedo": [0.5, 0.5, 0.5]}}, "base": "ground",
    "grooves": [{"profile": "a", "path": {"line": [[0, 0.5], [1, 0.5]]}},
                {"profile": "b", "path": {"line": [[0, 0.5], [1, 0.5]]}},
                {"profile": "a", "path": {"line": [[0, 0.515], [1, 0.515000001]]}}]})";
  Result<GrooveScene> parsed = parseGrooveScene(text, "scene.json");
  ASSERT_TRUE(parsed.isOk()) << parsed.status().describe();
  const GrooveScene& s = parsed.value();
  const Vec3 up{0, 0, 1};
  const Lighting l = lightTowards({0, 0, 1});
  std::vector<LocalGroove> one{localGroove(s, 0, {0.5, 0.5})};
  std::vector<LocalGroove> all;
  for (std::uint32_t p = 0; p < s.primitives.size(); ++p) all.push_back(localGroove(s, p, {0.5, 0.5}));
  const Footprint f = square({0.5, 0.5}, 0.02);
  // The shallow duplicate changes nothing under the deeper cut; the neighbour starts at v = 0.505, so
  // the footprint [0.49, 0.51] also sees half of its left wall.
  const Rgb alone = lineSample(s, one, f, up, l);
  const Rgb together = lineSample(s, all, f, up, l);
  const double facet = 0.5 / kPi * std::sqrt(0.5);
  EXPECT_NEAR(alone[0], facet, 1e-12);
  EXPECT_NEAR(together[0], facet, 1e-9);
}

TEST(SeedShaderStiff, CurvedSectionsOnTightArcsAtGrazingAnglesStayFinite) {
  // A circle of radius equal to the groove's half-width (its centre on the band's edge), seen and lit
  // at grazing angles with curved sections and mirror bounces: finite, non-negative, bounded.
  const std::string text = R"({"version": 1, "domain": {"size": [1, 1]},
    "profiles": {"v": {"points": [[-0.05, 0], [0, -0.08], [0.05, 0]]}},
    "materials": {"ground": {"albedo": [0.5, 0.5, 0.5]},
                  "chrome": {"albedo": [0.2, 0.2, 0.2], "specular": [0.5, 0.5, 0.5], "shininess": 20, "mirror": [0.9, 0.9, 0.9]}},
    "base": "ground",
    "grooves": [{"profile": "v", "material": "chrome", "path": {"arc": {"centre": [0.5, 0.5], "radius": 0.05, "start": 0, "end": 360}}}]})";
  Result<GrooveScene> parsed = parseGrooveScene(text, "scene.json");
  ASSERT_TRUE(parsed.isOk()) << parsed.status().describe();
  Result<GrooveGrid> grid = buildGrooveGrid(parsed.value(), GridSettings{});
  ASSERT_TRUE(grid.isOk());
  SeedSettings curved;
  curved.curvedSections = true;
  const SeedShader shader(parsed.value(), grid.value(), curved);
  const double bound = (0.5 / kPi + 0.5 * 22 / (8 * kPi)) / (1 - 0.9);
  for (double theta : {0.0, 60.0, 89.0, 90 - 1e-9})
    for (double light : {0.0, 80.0, 90.0, 95.0})
      for (Vec2 at : {Vec2{0.5, 0.5}, Vec2{0.53, 0.51}, Vec2{0.56, 0.47}}) {
        const Vec3 e = directionFromAngles(theta * kDegree, 0.7);
        for (const Footprint& f : {Footprint{at, {0, 0}, {0, 0}}, Footprint{at, {0.01, 0.002}, {-0.003, 0.02}}}) {
          const Rgb value = shader.shade(f, e, lightTowards(directionFromAngles(light * kDegree, 2.0), 8));
          for (double x : value) {
            EXPECT_TRUE(std::isfinite(x)) << theta << " " << light;
            EXPECT_GE(x, 0);
            EXPECT_LE(x, bound);
          }
        }
      }
}

}  // namespace
}  // namespace bake::grooves
