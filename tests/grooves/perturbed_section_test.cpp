// Line sampling on perturbed grooves (seed 000 §3, §5; libbake/grooves/line_sampling*.cpp): the local
// cross-section follows the perturbation at the footprint, and its change along the path tilts the
// facets (scale) and moves (first order) and bends (second order) the walls and the shadows they cast
// (offset). Pixel values against
// closed forms derived by hand, on straight grooves along u (binormal +v, arc length s = u), and the
// ray-traced reference at the same point.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bake/core/vec.h"
#include "grooves/input/scene.h"
#include "grooves/oracle/line_sampling_section.h"
#include "grooves/reference/reference.h"

namespace bake::grooves {
namespace {

using nlohmann::json;

GrooveScene perturbedScene(const json& profile, const json& perturbation) {
  const json j = {{"version", 1},
                  {"domain", {{"size", {1, 1}}}},
                  {"profiles", {{"p", {{"points", profile}}}}},
                  {"materials", {{"m", {{"albedo", {0.6, 0.5, 0.4}}}}}},
                  {"base", "m"},
                  {"grooves", json::array({{{"profile", "p"},
                                            {"path", {{"line", {{0, 0.5}, {1, 0.5}}}}},
                                            {"perturbation", perturbation}}})}};
  Result<GrooveScene> r = parseGrooveScene(j.dump(), "scene.json");
  EXPECT_TRUE(r.isOk()) << r.status().describe();
  return r.isOk() ? r.value() : GrooveScene{};
}

// Lambert only (the material has no specular), written out independently of render.cpp.
Rgb lambert(Vec3 n, Vec3 l) {
  const double length = std::sqrt(n.u * n.u + n.v * n.v + n.w * n.w);
  const double nl = std::max(0.0, (n.u * l.u + n.v * l.v + n.w * l.w) / length);
  return {0.6 / kPi * nl, 0.5 / kPi * nl, 0.4 / kPi * nl};
}

Rgb sample(const GrooveScene& s, const Footprint& f, Vec3 e, Vec3 l) {
  std::vector<LocalGroove> grooves;
  for (std::uint32_t p = 0; p < s.primitives.size(); ++p) grooves.push_back(localGroove(s, p, f.centre));
  Lighting lighting;
  lighting.toLight = l;
  return lineSample(s, grooves, f, e, lighting);
}

void expectRgbNear(const Rgb& a, const Rgb& b, double tolerance) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], tolerance) << "channel " << c;
}

constexpr double kW = 0.01, kD = 0.01;  // half-width and depth
const Vec3 kUp{0, 0, 1};

// A V whose scale varies along the path: at s = 0.5 the scale is 1 and falls at 4 pi per unit length
// (amplitude 0.4, wavelength 0.2, phase 5 pi). The right wall (b < 0) is h = -(d / w) b - d scale(s),
// so dh/ds = -d scale' = 0.04 pi: its normal is (-0.04 pi, d / w, 1) up to length, tilted along u.
TEST(PerturbedSection, ScaleTiltsTheWallAlongThePath) {
  const GrooveScene s = perturbedScene(json::array({{-kW, 0}, {0, -kD}, {kW, 0}}),
                                       {{"kind", "scale"}, {"amplitude", 0.4}, {"wavelength", 0.2}});
  const Vec3 light{0.3, 0, std::sqrt(1 - 0.09)};
  const Vec2 at{0.5, 0.5 - 0.5 * kW};  // the middle of the right wall
  const Footprint f{at, {0.001, 0}, {0, 0.001}};
  const Rgb expected = lambert({-0.04 * kPi, kD / kW, 1}, light);
  // Over the footprint (s within 5e-4 of 0.5, where scale'' = 0) the tilt changes by under 1e-6.
  expectRgbNear(sample(s, f, kUp, light), expected, 1e-6);
  // The reference sees the same surface at the footprint's centre.
  const ReferenceSurface surface(s);
  Lighting lighting;
  lighting.toLight = light;
  expectRgbNear(referenceRadiance(surface, s, at, kUp, lighting), expected, 1e-9);
  // Not the untilted wall: the light grazes the tilted one less.
  const Rgb untilted = lambert({0, kD / kW, 1}, light);
  EXPECT_GT(std::abs(expected[0] - untilted[0]), 1e-3);
}

// A box groove whose offset wanders: at s = 0.5 the offset is 0 and grows at o' = 0.04 pi per unit
// length (amplitude 0.002, wavelength 0.1). Seen from above through a footprint that is exactly the
// floor (b in [-w, w], thin along u), lit from +v and +u: a floor point at b is lit when the ray to the
// light leaves the cavity at b + d L_b / L_w before the far wall, which stands at w + o' d L_t / L_w
// where the ray comes out (the wall has moved with the path). Lit share (2w + o' d L_t / L_w -
// d L_b / L_w) / 2w; the frozen section would give (2w - d L_b / L_w) / 2w.
TEST(PerturbedSection, OffsetMovesTheWallAndItsShadow) {
  const GrooveScene s = perturbedScene(json::array({{-kW, 0}, {-kW, -kD}, {kW, -kD}, {kW, 0}}),
                                       {{"kind", "offset"}, {"amplitude", 0.002}, {"wavelength", 0.1}});
  const Vec3 light{0.4, 0.3, std::sqrt(1 - 0.25)};
  const double rate = 0.002 * 2 * kPi / 0.1;
  const double lit = (2 * kW + rate * kD * light.u / light.w - kD * light.v / light.w) / (2 * kW);
  const Footprint f{{0.5, 0.5}, {1e-4, 0}, {0, 2 * kW}};
  const Rgb floor = lambert(kUp, light);
  // The offset's curvature is 0 at s = 0.5; its third-order term over the ray's travel (d L_t / L_w)
  // moves the shadow's edge by under 1e-8, and the walls' tilt changes the floor's share by under
  // 1e-4 * o' / 2w of their ends' ramps: 1e-6 in all.
  expectRgbNear(sample(s, f, kUp, light), {lit * floor[0], lit * floor[1], lit * floor[2]}, 1e-6);
  const double frozen = (2 * kW - kD * light.v / light.w) / (2 * kW);
  EXPECT_GT(lit - frozen, 0.02);
}

// The same box groove at a crest of its wandering offset: at s = 0.5 the offset is at its largest
// (amplitude a = 0.01, wavelength 2/9: k s = 9 pi / 2), its rate is 0 and its second derivative
// o'' = -a k^2. The far wall bends back along the path: where the shadow ray from a floor point
// leaves the cavity, d L_t / L_w further along, it stands o'' (d L_t / L_w)^2 / 2 nearer. The ray is
// straight and the wall's track concave, so it clears the wall when it clears the rim: lit share
// (2w - d L_b / L_w + o'' (d L_t / L_w)^2 / 2) / 2w. A first-order section (rate 0) would miss the
// bend; following the light's tracks from the section's own line would bend them the wrong way.
TEST(PerturbedSection, OffsetCurvatureBendsTheShadow) {
  const double amplitude = 0.01, wavelength = 2.0 / 9;
  const GrooveScene s = perturbedScene(json::array({{-kW, 0}, {-kW, -kD}, {kW, -kD}, {kW, 0}}),
                                       {{"kind", "offset"}, {"amplitude", amplitude}, {"wavelength", wavelength}});
  const Vec3 light{0.4, 0.3, std::sqrt(1 - 0.25)};
  const double k = 2 * kPi / wavelength, travel = kD * light.u / light.w;
  const double bend = -amplitude * k * k * travel * travel / 2;
  const double lit = (2 * kW - kD * light.v / light.w + bend) / (2 * kW);
  const Footprint f{{0.5, 0.5 + amplitude}, {1e-4, 0}, {0, 2 * kW}};  // exactly the floor
  const Rgb floor = lambert(kUp, light);
  // The next term of the crest (a k^4 travel^4 / 24) moves the shadow's edge by 1.2e-7: 1e-6 of the
  // pixel's value.
  expectRgbNear(sample(s, f, kUp, light), {lit * floor[0], lit * floor[1], lit * floor[2]}, 2e-6);
  // The bend is visible: 0.4 % of the floor.
  EXPECT_GT(std::abs(bend) / (2 * kW), 0.004);
  // The reference agrees on the shadow's edge: lit just before it, in shadow just past it.
  const ReferenceSurface surface(s);
  Lighting lighting;
  lighting.toLight = light;
  const double edge = 0.5 + amplitude + kW - kD * light.v / light.w + bend;  // v of the last lit floor point
  EXPECT_GT(referenceRadiance(surface, s, {0.5, edge - 1e-5}, kUp, lighting)[0], 0.5 * floor[0]);
  EXPECT_LT(referenceRadiance(surface, s, {0.5, edge + 1e-5}, kUp, lighting)[0], 0.5 * floor[0]);
}

// The share of a footprint on one side of a line turned away from T: the footprint projected on
// B - rate T. A unit square cut by the line b = rate t: half of it on each side, whatever the rate.
TEST(PerturbedSection, FootprintShareAcrossATurnedLine) {
  const Footprint square{{0, 0}, {1, 0}, {0, 1}};  // A1 along u = T, A2 along v = B
  const FootprintLine line = footprintLine(square, {0, 1}, FootprintDensity::Trapezoid);
  EXPECT_NEAR(line.cdfAcross(0, 0.7), 0.5, 1e-15);
  EXPECT_NEAR(line.cdfAcross(0.25, 0), 0.75, 1e-15);
  // Points with b - t <= 0.25 inside [-1/2, 1/2]^2: all but the triangle b - t > 0.25, whose legs
  // are 1 - 0.25 = 0.75 long: 1 - 0.75^2 / 2.
  EXPECT_NEAR(line.cdfAcross(0.25, 1), 1 - 0.75 * 0.75 / 2, 1e-15);
}

}  // namespace
}  // namespace bake::grooves
