// A circular groove whose radius equals its half-width (formats/groove-scene.md allows R = wmax): the
// inner wall reaches the centre, where the V profile becomes a cone h = -d r / R with its apex on the
// base plane. A footprint centred on the apex, seen from above under a light steep enough that the
// cone neither shades nor shadows itself, has a closed form: the cone's normal is (d/R r_hat, 1) up to
// length, r_hat averages to 0 over a footprint symmetric about the apex, so the pixel is
// albedo / pi L_w / sqrt(1 + (d/R)^2) whatever the light's azimuth.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "groove/reference.h"
#include "groove/shade.h"
#include "groove_support.h"

namespace bake::groove {
namespace {

using nlohmann::json;
constexpr double kPi = std::numbers::pi;
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

// Disabled: the seed's method gets this pixel wrong, by 0.024 on 0.142 (found in bench-groove's arcs
// case, R/w = 1, whose remaining error sits on the pixels around the centre once the view lines are
// handled by curved sections). The method straightens the circle at the foot point of the footprint's centre (§4), so
// the footprint becomes a density along one radial line B; but around the apex the circles of
// constant b are smaller than the footprint, and the section along B holds only the quarter arc
// whose region contains F: past the centre it is flat base, where the real surface is the opposite
// side of the cone. At F exactly on the centre the foot point is not even defined (atan2(0, 0)).
// A fix needs the footprint integrated over the true b = R - |x - c| near the apex (or the opposite
// arc placed on the section, reversed): the seed's flat-facet assumption does not hold there.
TEST(ArcCentre, DISABLED_MethodMatchesTheClosedFormAtTheApex) {
  const GrooveScene scene = tightCircle();
  const GrooveGrid grid = buildGridOk(scene);
  SeedSettings settings;
  settings.curvedSections = true;
  const SeedShader shader(scene, grid, settings);
  // Rounding only: the closed form is exact.
  EXPECT_NEAR(shader.shade(kApexPixel, {0, 0, 1}, kLight)[0], kExpected, 1e-6);
}

}  // namespace
}  // namespace bake::groove
