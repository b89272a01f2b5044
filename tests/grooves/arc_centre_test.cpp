// A circular groove whose radius equals its half-width (formats/groove-scene.md allows R = wmax): the
// inner wall reaches the centre, where the V profile becomes a cone h = -d r / R with its apex on the
// base plane. A footprint centred on the apex, seen from above under a light steep enough that the
// cone neither shades nor shadows itself, has a closed form: the cone's normal is (d/R r_hat, 1) up to
// length, r_hat averages to 0 over a footprint symmetric about the apex, so the pixel is
// albedo / pi L_w / sqrt(1 + (d/R)^2) whatever the light's azimuth.
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bake/core/vec.h"
#include "groove_support.h"
#include "grooves/oracle/shade.h"
#include "grooves/reference/reference.h"

namespace bake::grooves {
namespace {

using nlohmann::json;
constexpr double kR = 0.05, kDepth = 0.03;

GrooveScene tightCircle() {
  const json j = {{"version", 1},
                  {"domain", {{"size", {1, 1}}}},
                  {"profiles", {{"vee", {{"points", {{-kR, 0}, {0, -kDepth}, {kR, 0}}}}}}},
                  {"materials", {{"m", {{"albedo", {0.6, 0.6, 0.6}}}}}},
                  {"base", "m"},
                  {"grooves", json::array({{{"profile", "vee"},
                                            {"path", {{"arc", {{"centre", {0.5, 0.5}},
                                                               {"radius", kR},
                                                               {"start", 0},
                                                               {"end", 360}}}}}}})}};
  Result<GrooveScene> r = parseGrooveScene(j.dump(), "scene.json");
  EXPECT_TRUE(r.isOk()) << r.status().describe();
  return r.isOk() ? r.value() : GrooveScene{};
}

// Light 60 degrees above the horizon (tan 60 > d / R = 0.6), from the +u, +v quarter.
const Lighting kLight = lightTowards({0.5 * std::cos(0.6), 0.5 * std::sin(0.6), std::sqrt(0.75)});
const double kExpected = 0.6 / kPi * kLight.toLight.w / std::hypot(1.0, kDepth / kR);
// The bench's pixel (a 0.2 window over 16 pixels): a quarter of R.
const Footprint kApexPixel{{0.5, 0.5}, {0.0125, 0}, {0, 0.0125}};

// The reference, integrated over the footprint by a fine midpoint rule, has the closed form (the
// cone's shading is linear in r_hat, so the rule's error is rounding only).
TEST(ArcCentre, ReferenceMatchesTheClosedFormAtTheApex) {
  const GrooveScene scene = tightCircle();
  const ReferenceSurface surface(scene);
  const int n = 64;
  double sum = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec2 x{kApexPixel.centre.u + ((i + 0.5) / n - 0.5) * kApexPixel.axis1.u,
                   kApexPixel.centre.v + ((j + 0.5) / n - 0.5) * kApexPixel.axis2.v};
      sum += referenceRadiance(surface, scene, x, {0, 0, 1}, kLight)[0];
    }
  EXPECT_NEAR(sum / (n * n), kExpected, 1e-9);
}

// The seed's method straightens the circle at the foot point of the footprint's centre (§4), so the
// footprint becomes a density along one radial line; around the apex the circles of constant b are
// smaller than the footprint and that fails (0.024 off on 0.142 here: the section along B holds only
// the quarter arc whose region contains F). A footprint this near an arc's centre is split in 3 x 3
// sub-footprints (shade.cpp nearArcCentre), each with its own foot points; the middle one still holds
// the apex, so the pixel is not exact, but within 2.5% of the closed form.
TEST(ArcCentre, MethodNearTheClosedFormAtTheApex) {
  const GrooveScene scene = tightCircle();
  const GrooveGrid grid = buildGridOk(scene);
  const SeedShader shader(scene, grid);
  const double value = shader.shade(kApexPixel, {0, 0, 1}, kLight)[0];
  EXPECT_NEAR(value, kExpected, 0.025 * kExpected);
  SeedSettings straight;
  straight.curvedSections = false;
  const double seedValue = SeedShader(scene, grid, straight).shade(kApexPixel, {0, 0, 1}, kLight)[0];
  EXPECT_GT(std::abs(seedValue - kExpected), 4 * std::abs(value - kExpected));
  std::printf("[ grooves ] apex pixel of a ring of R = w: %.5f (split), %.5f (one section), closed form %.5f\n", value,
              seedValue, kExpected);
}

// Away from the apex, the footprints near the cone's foot span a fan of 15 degrees of the circle: each
// visible, lit span's edges move along B with the footprint's travel along T (the section turning
// about the centre) and bend with the circles (line_sampling.cpp shadeSection). The bench's view of
// this ring (45 degrees, light 40 degrees up from azimuth 120) is within 3x the reference's noise
// floor at 256 samples per pixel (4.0x with the edges left parallel to T).
TEST(ArcCentre, TightRingWithinThreeNoiseFloors) {
  const GrooveScene scene = tightCircle();
  const View view = windowView({0.4, 0.4}, {0.6, 0.6}, 16, kPi / 4, 0);
  const Lighting light = lightTowards({std::cos(kPi * 40 / 180) * std::cos(kPi * 120 / 180),
                                       std::cos(kPi * 40 / 180) * std::sin(kPi * 120 / 180), std::sin(kPi * 40 / 180)});
  ReferenceSettings settings;
  settings.samplesPerPixel = 256;
  const Image a = renderReference(scene, view, light, settings);
  settings.seed = 2;
  const double floor = imageError(a, renderReference(scene, view, light, settings)).rmse;
  const double error = imageError(renderSeed(scene, buildGridOk(scene), view, light, 0), a).rmse;
  EXPECT_LT(error, 3 * floor);
  std::printf("[ grooves ] ring of R = w at 45 degrees: RMSE %.3g = %.2f x the noise floor\n", error, error / floor);
}

}  // namespace
}  // namespace bake::grooves
