// The seed's method through the grid (libbake/grooves/oracle/shade.cpp, seed 000 §4): the enlarged box finds
// ridges seen or casting shadows from beyond the footprint, special cases go to area sampling, wrapping
// scenes use the nearest copy, renderSeed is deterministic, and small views of a V-groove (with and
// without mirror bounces) agree with the ray-traced reference within 3x its noise floor.
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

std::string num(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

// Profiles: "v" (w 0.02, d 0.02), "ridge" (a box 0.04 wide, 0.03 high); materials: "ground" (base),
// "paint", "chrome" (a mirror).
GrooveScene sceneOf(const std::string& grooves, bool wrap = false) {
  const std::string text = std::string(R"({"version": 1, "domain": {"size": [1, 1]}, "wrap": ")") +
                           (wrap ? "repeat" : "none") + R"(",
    "profiles": {"v": {"points": [[-0.02, 0], [0, -0.02], [0.02, 0]]},
                 "deep": {"points": [[-0.01, 0], [0, -0.02], [0.01, 0]]},
                 "ridge": {"points": [[-0.02, 0], [-0.02, 0.03], [0.02, 0.03], [0.02, 0]]},
                 "scratch": {"points": [[-0.03, 0], [-0.02, 0.01], [-0.01, 0], [0, -0.015], [0.015, 0], [0.025, 0.006], [0.03, 0]]}},
    "materials": {"ground": {"albedo": [0.3, 0.5, 0.7]}, "paint": {"albedo": [0.8, 0.3, 0.1], "specular": [0.4, 0.4, 0.4], "shininess": 16},
                  "chrome": {"albedo": [0.1, 0.1, 0.1], "specular": [0.5, 0.5, 0.5], "shininess": 30, "mirror": [0.9, 0.8, 0.7]}},
    "base": "ground", "grooves": [)" + grooves + "]}";
  Result<GrooveScene> scene = parseGrooveScene(text, "scene.json");
  EXPECT_TRUE(scene.isOk()) << scene.status().describe();
  return scene.isOk() ? scene.value() : GrooveScene{};
}

std::string line(const std::string& profile, const std::string& material, Vec2 a, Vec2 b) {
  return R"({"profile": ")" + profile + R"(", "material": ")" + material + R"(", "path": {"line": [[)" + num(a.u) +
         ", " + num(a.v) + "], [" + num(b.u) + ", " + num(b.v) + "]]}}";
}

Footprint square(Vec2 centre, double side) { return {centre, {side, 0}, {0, side}}; }

void expectRgbNear(const Rgb& a, const Rgb& b, double tolerance) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], tolerance) << "channel " << c;
}

// The radiance memo of a pixel gives directRadiance's values bit for bit, for pairs it remembers,
// pairs it has forgotten (more than its few entries) and the same normal under two materials.
TEST(SeedShader, RadianceMemoGivesDirectRadianceExactly) {
  std::vector<Material> materials(2);
  for (int c = 0; c < 3; ++c) {
    materials[0].albedo[c] = 0.5 - 0.1 * c;
    materials[1].albedo[c] = 0.2 + 0.1 * c;
    materials[1].specular[c] = 0.6;
  }
  materials[1].shininess = 37;
  Lighting lighting;
  lighting.toLight = {0.3, -0.2, 0.932737905};
  const Vec3 toViewer{-0.4, 0.1, 0.910439453};
  RadianceMemo memo(materials, toViewer, lighting);
  const Vec3 normals[] = {{0, 0, 1}, {0.6, 0, 0.8}, {-0.6, 0, 0.8}, {0, 0.6, 0.8}, {0, -0.6, 0.8}, {0.28, 0.96, 0}};
  for (int round = 0; round < 3; ++round)
    for (std::size_t m = 0; m < materials.size(); ++m)
      for (const Vec3& n : normals) {
        const Rgb expected = directRadiance(materials[m], n, toViewer, lighting);
        const Rgb got = memo(m, n);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(got[c], expected[c]) << round << " " << m << " " << c;
      }
}

// The memo's entries outlive it (per thread): a later memo under the same view, light and materials
// reuses them; one under another view or light, or over materials changed in place (same vector,
// other values: a scene loaded into the same object), must not; nor must a memo whose store a memo
// under another view took over in between (a mirror bounce's).
TEST(SeedShader, RadianceMemoNeverServesAnotherViewLightOrMaterial) {
  std::vector<Material> materials(1);
  for (int c = 0; c < 3; ++c) materials[0].albedo[c] = 0.4, materials[0].specular[c] = 0.5;
  materials[0].shininess = 12;
  Lighting lighting;
  lighting.toLight = {0.3, -0.2, 0.932737905};
  const Vec3 view1{-0.4, 0.1, 0.910439453}, view2{0.2, 0.2, 0.959166305};
  const Vec3 normal{0.6, 0, 0.8};
  auto expectExact = [&](RadianceMemo& memo, const Vec3& view, const Lighting& light, const char* what) {
    const Rgb expected = directRadiance(materials[0], normal, view, light);
    const Rgb got = memo(0, normal);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(got[c], expected[c]) << what << " " << c;
  };
  {
    RadianceMemo first(materials, view1, lighting);
    expectExact(first, view1, lighting, "first");
  }
  RadianceMemo again(materials, view1, lighting);
  expectExact(again, view1, lighting, "same view again");
  RadianceMemo otherView(materials, view2, lighting);
  expectExact(otherView, view2, lighting, "another view");
  expectExact(again, view1, lighting, "the older memo after another took the store");
  Lighting dimmer = lighting;
  dimmer.radiance = {0.5, 0.5, 0.5};
  RadianceMemo otherLight(materials, view1, dimmer);
  expectExact(otherLight, view1, dimmer, "another light radiance");
  materials[0].shininess = 40;
  materials[0].albedo[1] = 0.9;
  RadianceMemo changed(materials, view1, lighting);
  expectExact(changed, view1, lighting, "materials changed in place");
}

TEST(SeedShader, NoGrooveNearIsTheFlatBase) {
  const GrooveScene s = sceneOf(line("v", "paint", {0.1, 0.5}, {0.9, 0.5}));
  const GrooveGrid grid = buildGridOk(s);
  const SeedShader shader(s, grid);
  const Vec3 e = directionFromAngles(0.6, 1.0);
  const Lighting l = lightTowards({0.2, 0.3, 1});
  ShadeStats stats;
  const Rgb value = shader.shade(square({0.5, 0.2}, 0.01), e, l, &stats);
  EXPECT_EQ(stats.primitives, 0u);
  EXPECT_FALSE(stats.special);
  const double expected = 0.3 / kPi * l.toLight.w;
  EXPECT_NEAR(value[0], expected, 1e-15);
}

TEST(SeedShader, TheEnlargedBoxFindsARidgeSeenFromBeyondTheFootprint) {
  // A ridge 0.03 high over v in [0.48, 0.52]; seen from 80 degrees towards +v, the base points up to
  // 0.03 tan(80) = 0.17 before its wall at v = 0.52 are hidden by it. The footprint [0.395, 0.405] is
  // far outside the band (enlarged by wmax: up to 0.425), and it sees only that wall, at heights
  // (0.52 - v) / tan(80) in [0.020, 0.022] < 0.03.
  const GrooveScene s = sceneOf(line("ridge", "paint", {0.1, 0.5}, {0.9, 0.5}));
  const GrooveGrid grid = buildGridOk(s);
  const SeedShader shader(s, grid);
  const double theta = 80 * kPi / 180;
  const Vec3 e{0, std::sin(theta), std::cos(theta)};
  const Lighting l = lightTowards({0, 0.3, 1});
  const Footprint f = square({0.5, 0.40}, 0.01);
  ShadeStats stats;
  const Rgb value = shader.shade(f, e, l, &stats);
  EXPECT_GE(stats.primitives, 1u);
  EXPECT_FALSE(stats.special);
  expectRgbNear(value, directRadiance(materialNamed(s, "paint"), {0, 1, 0}, e, l), 1e-12);
  // Seen from above the same footprint is flat ground.
  expectRgbNear(shader.shade(f, {0, 0, 1}, l), directRadiance(materialNamed(s, "ground"), {0, 0, 1}, {0, 0, 1}, l), 1e-15);
}

TEST(SeedShader, TheEnlargedBoxFindsARidgeCastingAShadow) {
  // The light 80 degrees from the normal towards -v: the ridge (v in [0.48, 0.52], 0.03 high) shadows
  // the base on its +v side up to 0.03 tan(80) = 0.17 beyond v = 0.52. Seen from above, the footprint
  // [0.645, 0.655] is in the shadow (its shadow rays pass v = 0.52 at heights <= 0.024), the one at
  // [0.745, 0.755] is not (>= 0.0397).
  const GrooveScene s = sceneOf(line("ridge", "paint", {0.1, 0.5}, {0.9, 0.5}));
  const GrooveGrid grid = buildGridOk(s);
  const SeedShader shader(s, grid);
  const double phi = 80 * kPi / 180;
  const Lighting l = lightTowards({0, -std::sin(phi), std::cos(phi)});
  ShadeStats stats;
  EXPECT_EQ(shader.shade(square({0.5, 0.65}, 0.01), {0, 0, 1}, l, &stats)[0], 0);
  EXPECT_GE(stats.primitives, 1u);
  EXPECT_NEAR(shader.shade(square({0.5, 0.75}, 0.01), {0, 0, 1}, l)[0], 0.3 / kPi * std::cos(phi), 1e-15);
}

TEST(SeedShader, SpecialCasesGoToAreaSampling) {
  const GrooveScene s = sceneOf(line("v", "paint", {0.1, 0.5}, {0.9, 0.5}) + ", " +
                                line("v", "paint", {0.5, 0.1}, {0.5, 0.9}));
  const GrooveGrid grid = buildGridOk(s);
  const SeedShader shader(s, grid);
  const Vec3 e = directionFromAngles(0.5, 0.7);
  const Lighting l = lightTowards({0.3, -0.2, 1});
  const Footprint f = square({0.51, 0.505}, 0.02);
  ShadeStats stats;
  const Rgb value = shader.shade(f, e, l, &stats);
  EXPECT_TRUE(stats.special);
  std::vector<LocalGroove> grooves;
  for (std::uint32_t p = 0; p < s.primitives.size(); ++p) grooves.push_back(localGroove(s, p, f.centre));
  expectRgbNear(value, areaSample(s, grooves, f, e, l), 1e-12);
  // Far from the crossing: line sampling, and the same value as the lone groove.
  const Footprint g = square({0.2, 0.505}, 0.02);
  const Rgb lone = shader.shade(g, e, l, &stats);
  EXPECT_FALSE(stats.special);
  std::vector<LocalGroove> one{localGroove(s, 0, g.centre)};
  expectRgbNear(lone, lineSample(s, one, g, e, l), 1e-15);
}

TEST(SeedShader, WrappingSceneUsesTheNearestCopy) {
  // A groove along v at u = 0.995 in a repeating unit square: footprints at u = 0.005 and u = 1.005
  // are the same place.
  const GrooveScene s = sceneOf(line("v", "paint", {0.995, -0.2}, {0.995, 1.2}), true);
  const GrooveGrid grid = buildGridOk(s);
  const SeedShader shader(s, grid);
  const Vec3 e = directionFromAngles(0.7, 0.2);
  const Lighting l = lightTowards({-0.4, 0.1, 1});
  const Rgb a = shader.shade(square({0.005, 0.5}, 0.03), e, l);
  const Rgb b = shader.shade(square({1.005, 0.5}, 0.03), e, l);
  expectRgbNear(a, b, 1e-15);
  const Rgb flat = directRadiance(materialNamed(s, "ground"), {0, 0, 1}, e, l);
  EXPECT_GT(std::abs(a[0] - flat[0]), 1e-3);
}

// A footprint many cells wide reads only the cells on its box's boundary (§4.1); long parallel
// grooves all cross it, so the value is the one of line sampling over every groove.
TEST(SeedShader, WideFootprintsReadTheBoxBoundaryAndFindEveryLongGroove) {
  std::string grooves;
  for (int k = 0; k < 25; ++k) {  // u from 0.25 to 0.73: all under the footprint
    if (k) grooves += ", ";
    const double u = 0.25 + 0.02 * k;
    grooves += line("deep", "paint", {u, 0.02}, {u, 0.98});
  }
  const GrooveScene s = sceneOf(grooves);
  const GrooveGrid grid = buildGridOk(s);
  const Footprint wide = square({0.5, 0.5}, 0.6);
  ASSERT_GT(wide.axis1.u / grid.cellSize.u, 8.0);
  const Vec3 e = directionFromAngles(0.5, 0.3);
  const Lighting l = lightTowards({0.3, -0.2, 1});
  ShadeStats stats;
  const Rgb value = SeedShader(s, grid).shade(wide, e, l, &stats);
  EXPECT_EQ(stats.primitives, s.primitives.size());
  EXPECT_FALSE(stats.special);
  std::vector<LocalGroove> all;
  for (std::uint32_t p = 0; p < s.primitives.size(); ++p) all.push_back(localGroove(s, p, wide.centre));
  expectRgbNear(value, lineSampleWith(s, all, wide, e, l, SeedSettings{}), 1e-12);
}

TEST(SeedShader, RenderIsTheSameForAnyThreadCount) {
  const GrooveScene s = sceneOf(line("v", "paint", {0.1, 0.45}, {0.9, 0.55}) + ", " +
                                line("ridge", "chrome", {0.2, 0.3}, {0.8, 0.3}));
  const GrooveGrid grid = buildGridOk(s);
  const View view = windowView({0.2, 0.2}, {0.8, 0.8}, 24, 0.8, 2.0);
  const Lighting l = lightTowards({0.3, 0.4, 1}, 2);
  const Image one = renderSeed(s, grid, view, l, 1), two = renderSeed(s, grid, view, l, 3);
  ASSERT_EQ(one.pixels.size(), std::size_t(24 * 24 * 3));
  EXPECT_EQ(one.pixels, two.pixels);
}

// The seed's method against the reference over a small view, within 3x the reference's noise floor
// (the RMSE between two reference seeds).
double expectMatchesReference(const GrooveScene& s, const View& view, const Lighting& l,
                              const SeedSettings& method = {}) {
  const GrooveGrid grid = buildGridOk(s);
  const Image seed = renderSeed(s, grid, view, l, 0, method);
  ReferenceSettings settings;
  settings.samplesPerPixel = 64;
  const Image a = renderReference(s, view, l, settings);
  settings.seed = 2;
  const Image b = renderReference(s, view, l, settings);
  const double noise = imageError(a, b).rmse;
  const ImageError error = imageError(seed, a);
  EXPECT_LT(error.rmse, 3 * noise + 1e-9) << "noise floor " << noise;
  return error.rmse;
}

TEST(SeedShader, VGrooveAgreesWithTheReference) {
  const GrooveScene s = sceneOf(line("v", "paint", {0.1, 0.52}, {0.9, 0.48}));
  for (const auto& [theta, phi, light] : {std::tuple{0.0, 0.0, Vec3{0, 0, 1}}, std::tuple{0.9, 1.7, Vec3{0.2, 0.6, 0.7}},
                                          std::tuple{1.2, -1.5, Vec3{-0.1, -0.9, 0.5}}}) {
    SCOPED_TRACE(theta);
    expectMatchesReference(s, windowView({0.4, 0.44}, {0.6, 0.56}, 16, theta, phi), lightTowards(light));
  }
}

TEST(SeedShader, MirrorVGrooveWithBouncesAgreesWithTheReference) {
  const GrooveScene s = sceneOf(line("deep", "chrome", {0.1, 0.5}, {0.9, 0.5}));
  for (int bounces : {1, 3}) {
    SCOPED_TRACE(bounces);
    expectMatchesReference(s, windowView({0.47, 0.47}, {0.53, 0.53}, 12, 0.5, 1.4),
                           lightTowards({0.1, 0.3, 1}, bounces));
  }
}

// Inter-reflections where footprints are area sampled (seed §7 in §6's special cases): two mirror
// grooves crossing, a mirror groove's open end and a polyline's corner, each seen around the special
// case, with one and three bounces and with and without an environment, against the reference's
// traced rays. The reflections must show: without them (maxBounces 0) the image is off the reference
// by far more, which the second check makes sure of (in the oblique crossing the mirror's rays all
// leave the surface, so there only the environment shows).
TEST(SeedShader, MirrorSpecialCasesWithBouncesAgreeWithTheReference) {
  struct Case {
    const char* name;
    std::string grooves;
    double theta, phi;
    Vec3 light;
    bool reflectsGrooves = true;  // false: the mirror's rays all leave the surface (only the environment shows)
  };
  const Case cases[] = {
      {"crossing", line("deep", "chrome", {0.1, 0.5}, {0.9, 0.5}) + ", " + line("deep", "chrome", {0.5, 0.1}, {0.5, 0.9}),
       0.5, 1.1, {0.1, 0.3, 1}},
      {"crossing, oblique", line("v", "chrome", {0.1, 0.45}, {0.9, 0.55}) + ", " + line("deep", "paint", {0.5, 0.1}, {0.5, 0.9}),
       1.0, -2.2, {-0.4, 0.2, 0.6}, false},
      {"open end", line("deep", "chrome", {0.1, 0.5}, {0.5, 0.5}), 0.7, 0.3, {0.3, -0.2, 0.8}},
      {"corner", R"({"profile": "deep", "material": "chrome", "path": {"polyline": [[0.1, 0.5], [0.5, 0.5], [0.5, 0.9]]}})",
       0.6, 2.5, {0.2, 0.1, 1}},
  };
  for (const Case& c : cases) {
    const GrooveScene s = sceneOf(c.grooves);
    const View view = windowView({0.485, 0.485}, {0.515, 0.515}, 12, c.theta, c.phi);
    const GrooveGrid grid = buildGridOk(s);
    const SeedShader shader(s, grid);
    ShadeStats stats;
    shader.shade(square({0.5, 0.5}, 0.002), directionFromAngles(c.theta, c.phi), lightTowards(c.light, 1), &stats);
    ASSERT_TRUE(stats.special) << c.name << ": not area sampled";
    for (int bounces : {1, 3})
      for (bool environment : {false, true}) {
        SCOPED_TRACE(std::string(c.name) + ", " + std::to_string(bounces) + (environment ? " bounces, environment" : " bounces"));
        Lighting l = lightTowards(c.light, bounces);
        if (environment) l.environment = {0.3, 0.5, 0.7};
        const double rmse = expectMatchesReference(s, view, l);
        Lighting none = l;
        none.maxBounces = 0;
        ReferenceSettings settings;
        settings.samplesPerPixel = 64;
        const double missing = imageError(renderSeed(s, grid, view, none, 0), renderReference(s, view, l, settings)).rmse;
        if (c.reflectsGrooves || environment) EXPECT_GT(missing, 5 * rmse) << "the reflections hardly show";
        std::printf("[ grooves ] mirror %s, %d bounces%s: RMSE against the reference %.4g (without bounces %.4g)\n",
                    c.name, bounces, environment ? ", environment" : "", rmse, missing);
      }
  }
}

// Light from outside the grooves (seed §7: a reflected beam's rays that leave the surface see the rest
// of the scene, weighted by the uncovered part, 1 - Σ r_i): a mirror V-groove under a constant
// environment, against the reference, whose reflected rays that leave see that environment too. The
// environment must show (the mean rises), or the check would hold with both ignoring it.
TEST(SeedShader, MirrorBouncesSeeTheEnvironmentAsTheReferenceDoes) {
  // 45-degree walls seen nearly from above: a wall sends the view across to the other wall, which
  // sends it up and out, so from the second bounce on part of every beam leaves the surface.
  const GrooveScene s = sceneOf(line("v", "chrome", {0.1, 0.5}, {0.9, 0.5}));
  const View view = windowView({0.47, 0.47}, {0.53, 0.53}, 12, 0.3, 1.4);
  for (int bounces : {2, 3}) {
    SCOPED_TRACE(bounces);
    Lighting dark = lightTowards({0.1, 0.3, 1}, bounces), lit = dark;
    lit.environment = {0.3, 0.5, 0.7};
    const double rmse = expectMatchesReference(s, view, lit);
    const GrooveGrid grid = buildGridOk(s);
    const Image without = renderSeed(s, grid, view, dark, 0), with = renderSeed(s, grid, view, lit, 0);
    double gained = 0;
    for (std::size_t i = 0; i < with.pixels.size(); ++i) gained += double(with.pixels[i]) - double(without.pixels[i]);
    EXPECT_GT(gained / double(with.pixels.size()), 0.01) << "the environment does not show";
    std::printf("[ grooves ] environment, %d bounces: mean gain %.4f, RMSE against the reference %.4g\n", bounces,
                gained / double(with.pixels.size()), rmse);

  }
}

// Closed form: the flat floor of a mirror box groove seen along the groove. Every reflected ray goes up
// between the walls and leaves, so the floor (black itself: no albedo, no specular) shows exactly
// environment x mirror, whatever the light.
TEST(SeedShader, MirrorFloorShowsEnvironmentTimesMirror) {
  Result<GrooveScene> parsed = parseGrooveScene(R"({"version": 1, "domain": {"size": [1, 1]},
    "profiles": {"box": {"points": [[-0.05, 0], [-0.05, -0.02], [0.05, -0.02], [0.05, 0]]}},
    "materials": {"ground": {"albedo": [0.3, 0.3, 0.3]}, "glass": {"albedo": [0, 0, 0], "mirror": [0.5, 0.6, 0.7]}},
    "base": "ground", "grooves": [{"profile": "box", "material": "glass", "path": {"line": [[0.1, 0.5], [0.9, 0.5]]}}]})",
                                                "box.json");
  ASSERT_TRUE(parsed.isOk()) << parsed.status().describe();
  const GrooveScene& s = parsed.value();
  const GrooveGrid grid = buildGridOk(s);
  const SeedShader shader(s, grid);
  Lighting l = lightTowards({0.4, 0.2, 1}, 1);
  l.environment = {0.3, 0.5, 0.7};
  const double n = std::hypot(0.2, 1.0);
  const Rgb value = shader.shade(square({0.5, 0.5}, 0.01), {0.2 / n, 0, 1 / n}, l);
  expectRgbNear(value, {0.3 * 0.5, 0.5 * 0.6, 0.7 * 0.7}, 1e-9);
  l.environment = {0, 0, 0};
  expectRgbNear(shader.shade(square({0.5, 0.5}, 0.01), {0.2 / n, 0, 1 / n}, l), {0, 0, 0}, 1e-12);
}

// A mirror base under an environment, over a crossing of two V-grooves (a special case, sampled by
// area) and the line-sampled grooves around it: the base reflects the environment everywhere, in
// plain footprints, in the sections' flat parts and in the area-sampled pieces alike, as in the
// reference (a ray reflected off the base goes up and nothing is above it).
TEST(SeedShader, MirrorBaseReflectsTheEnvironmentInEveryPath) {
  Result<GrooveScene> parsed = parseGrooveScene(R"({"version": 1, "domain": {"size": [1, 1]},
    "profiles": {"v": {"points": [[-0.02, 0], [0, -0.02], [0.02, 0]]}},
    "materials": {"polished": {"albedo": [0.3, 0.3, 0.3], "mirror": [0.6, 0.5, 0.4]},
                  "paint": {"albedo": [0.8, 0.3, 0.1], "specular": [0.4, 0.4, 0.4], "shininess": 16}},
    "base": "polished", "grooves": [
      {"profile": "v", "material": "paint", "path": {"line": [[0.1, 0.5], [0.9, 0.5]]}},
      {"profile": "v", "material": "paint", "path": {"line": [[0.5, 0.1], [0.5, 0.9]]}}]})",
                                                "crossing.json");
  ASSERT_TRUE(parsed.isOk()) << parsed.status().describe();
  Lighting l = lightTowards({0.2, 0.3, 1}, 1);
  l.environment = {0.4, 0.5, 0.6};
  const View view = windowView({0.44, 0.44}, {0.56, 0.56}, 12, 0.6, 0.7);
  const double rmse = expectMatchesReference(parsed.value(), view, l);
  std::printf("[ grooves ] mirror base under an environment, crossing: RMSE against the reference %.4g\n", rmse);
  // The crossing is sampled by area in the middle of the view.
  const GrooveGrid grid = buildGridOk(parsed.value());
  const SeedShader shader(parsed.value(), grid);
  ShadeStats stats;
  shader.shade(view.pixel(6, 6), view.toViewer, l, &stats);
  EXPECT_TRUE(stats.special) << "the view's centre should be the crossing's special case";
}

TEST(SeedShader, ScratchWithPileUpRidgesAgreesWithTheReference) {
  // Ridges beside the cut mask and shadow the flat ground and the cut at oblique angles.
  const GrooveScene s = sceneOf(line("scratch", "paint", {0.1, 0.47}, {0.9, 0.53}));
  for (const auto& [theta, phi, light] : {std::tuple{1.0, 1.3, Vec3{0.1, -0.8, 0.4}}, std::tuple{1.3, -1.6, Vec3{0.3, 0.9, 0.3}}}) {
    SCOPED_TRACE(theta);
    expectMatchesReference(s, windowView({0.42, 0.44}, {0.58, 0.56}, 16, theta, phi), lightTowards(light));
  }
}

TEST(SeedShader, ParallelSetUnderWideFootprintsAgreesWithTheReference) {
  // Eight V-grooves 0.05 apart seen through pixels about three periods wide, at grazing angles across
  // them: one combined section per pixel with masking and shadowing between neighbours.
  std::string grooves;
  for (int k = 0; k < 8; ++k)
    grooves += (k ? ", " : "") + line("v", "paint", {0.1, 0.325 + 0.05 * k}, {0.9, 0.325 + 0.05 * k});
  const GrooveScene s = sceneOf(grooves);
  for (const auto& [theta, phi, light] : {std::tuple{1.2, 1.5, Vec3{0, 0.8, 0.5}}, std::tuple{0.8, -1.2, Vec3{0.2, -0.7, 0.4}}}) {
    SCOPED_TRACE(theta);
    expectMatchesReference(s, windowView({0.3, 0.35}, {0.6, 0.65}, 2, theta, phi), lightTowards(light));
  }
}

TEST(SeedShader, ConcentricArcsAndAPerturbedGrooveAgreeWithTheReference) {
  // Two concentric arcs (radii 0.3 and 0.35, one combined section per pixel: their tangents are
  // parallel at every footprint) and a groove whose scale varies along it (frozen per pixel, §4).
  const std::string arcs =
      R"({"profile": "v", "material": "paint", "path": {"arc": {"centre": [0.2, 0.2], "radius": 0.3, "start": 10, "end": 80}}},
         {"profile": "v", "material": "paint", "path": {"arc": {"centre": [0.2, 0.2], "radius": 0.35, "start": 10, "end": 80}}})";
  const GrooveScene concentric = sceneOf(arcs);
  SeedSettings curved;
  curved.curvedSections = true;
  expectMatchesReference(concentric, windowView({0.37, 0.37}, {0.5, 0.5}, 12, 1.0, 2.4),
                         lightTowards({0.5, 0.2, 0.6}), curved);
  const std::string perturbed =
      R"({"profile": "scratch", "material": "paint", "perturbation": {"kind": "scale", "amplitude": 0.3, "wavelength": 0.5},
          "path": {"line": [[0.1, 0.5], [0.9, 0.5]]}})";
  expectMatchesReference(sceneOf(perturbed), windowView({0.4, 0.44}, {0.56, 0.56}, 12, 0.9, 1.2),
                         lightTowards({-0.2, -0.6, 0.6}));
}

// Curved sections are the default on arcs whose curvature shows over the travel of a view or shadow
// line (line_sampling.cpp curvatureShows): a ring of three half-widths seen at 45 degrees is closer to
// the reference with them than straightened, and an arc of a hundred half-widths is shaded exactly as
// straightened (no subdivided facets where they would change nothing).
TEST(SeedShader, CurvedSectionsWhereTheArcsCurvatureShows) {
  const View view = windowView({0.4, 0.4}, {0.6, 0.6}, 12, 0.785, 0.3);
  const Lighting light = lightTowards({0.5, -0.3, 0.7});
  const GrooveScene ring =
      sceneOf(R"({"profile": "v", "material": "paint", "path": {"arc": {"centre": [0.5, 0.5], "radius": 0.06, "start": 0, "end": 360}}})");
  const double curvedError = expectMatchesReference(ring, view, light);
  SeedSettings straight;
  straight.curvedSections = false;
  ReferenceSettings settings;
  settings.samplesPerPixel = 64;
  const double straightError =
      imageError(renderSeed(ring, buildGridOk(ring), view, light, 0, straight), renderReference(ring, view, light, settings)).rmse;
  EXPECT_LT(curvedError, 0.5 * straightError);

  const GrooveScene wide =
      sceneOf(R"({"profile": "v", "material": "paint", "path": {"arc": {"centre": [0.5, -1.5], "radius": 2.0, "start": 80, "end": 100}}})");
  const GrooveGrid grid = buildGridOk(wide);
  const Image byDefault = renderSeed(wide, grid, view, light, 0), straightened = renderSeed(wide, grid, view, light, 0, straight);
  EXPECT_EQ(byDefault.pixels, straightened.pixels);
  std::printf("[ grooves ] ring of 3 half-widths at 45 degrees: RMSE %.3g curved, %.3g straight\n", curvedError, straightError);
}

}  // namespace
}  // namespace bake::grooves
