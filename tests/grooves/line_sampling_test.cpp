// Line sampling (seed 000 §5, §7; libbake/grooves/line_sampling*.cpp, interreflection.cpp) against hand
// computations: the combined cross-section, the footprint density, masking, shadowing, Eq. 1 and one
// mirror bounce, on straight grooves along u (binormal +v).
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bake/core/vec.h"
#include "grooves/input/scene.h"
#include "grooves/oracle/line_sampling_section.h"

namespace bake::grooves {
namespace {

using nlohmann::json;

json sceneWith(const json& profile, const json& material = {{"albedo", {0.6, 0.5, 0.4}}}) {
  return {{"version", 1},
          {"domain", {{"size", {1, 1}}}},
          {"profiles", {{"p", {{"points", profile}}}}},
          {"materials", {{"m", material}}},
          {"base", "m"},
          {"grooves", json::array({{{"profile", "p"}, {"path", {{"line", {{0, 0.5}, {1, 0.5}}}}}}})}};
}

GrooveScene parseOk(const json& j) {
  Result<GrooveScene> r = parseGrooveScene(j.dump(), "scene.json");
  EXPECT_TRUE(r.isOk()) << r.status().describe();
  return r.isOk() ? r.value() : GrooveScene{};
}

// Normalised Blinn-Phong times the cosine, written out independently of render.cpp.
Rgb blinnPhong(const Material& m, Vec3 n, Vec3 e, Vec3 l) {
  const double nl = n.u * l.u + n.v * l.v + n.w * l.w;
  if (nl <= 0) return {0, 0, 0};
  Vec3 h{e.u + l.u, e.v + l.v, e.w + l.w};
  const double len = std::sqrt(h.u * h.u + h.v * h.v + h.w * h.w);
  const double nh = std::max(0.0, (n.u * h.u + n.v * h.v + n.w * h.w) / len);
  Rgb out;
  for (int c = 0; c < 3; ++c)
    out[c] = (m.albedo[c] / kPi + m.specular[c] * (m.shininess + 2) / (8 * kPi) * std::pow(nh, m.shininess)) * nl;
  return out;
}

// The section's points are `expected` (b, h), in order.
void expectPolyline(const CrossSection& section, const std::vector<std::pair<double, double>>& expected) {
  ASSERT_EQ(section.points.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(section.points[i].b, expected[i].first, 1e-15) << i;
    EXPECT_NEAR(section.points[i].h, expected[i].second, 1e-15) << i;
  }
}

Footprint across(double centreV, double widthAcross, double widthAlong = 0.001) {
  return {{0.5, centreV}, {widthAlong, 0}, {0, widthAcross}};
}

Rgb sample(const GrooveScene& s, const Footprint& f, Vec3 e, Vec3 l, int bounces = 0,
           FootprintDensity density = FootprintDensity::Trapezoid) {
  std::vector<LocalGroove> grooves;
  for (std::uint32_t p = 0; p < s.primitives.size(); ++p) grooves.push_back(localGroove(s, p, f.centre));
  Lighting lighting;
  lighting.toLight = l;
  lighting.maxBounces = bounces;
  SeedSettings settings;
  settings.density = density;
  return lineSampleWith(s, grooves, f, e, lighting, settings);
}

void expectRgbNear(const Rgb& a, const Rgb& b, double tolerance) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], tolerance) << "channel " << c;
}

Rgb mix(std::initializer_list<std::pair<double, Rgb>> parts) {
  Rgb out{0, 0, 0};
  for (const auto& [w, v] : parts)
    for (int c = 0; c < 3; ++c) out[c] += w * v[c];
  return out;
}

constexpr double kW = 0.01, kD = 0.01;  // half-width and depth of the V
const Vec3 kUp{0, 0, 1};
const Vec3 kLeftWall{0, kD / std::hypot(kW, kD), kW / std::hypot(kW, kD)};    // faces +v
const Vec3 kRightWall{0, -kD / std::hypot(kW, kD), kW / std::hypot(kW, kD)};  // faces -v

json vee(double w = kW, double d = kD) { return json::array({{-w, 0}, {0, -d}, {w, 0}}); }

TEST(LineSampleDensity, TrapezoidAndSegmentClosedForms) {
  FootprintLine t;
  t.wide = 2;
  t.narrow = 1;
  EXPECT_DOUBLE_EQ(t.cdf(-3), 0);
  EXPECT_DOUBLE_EQ(t.cdf(0), 0.5);
  EXPECT_DOUBLE_EQ(t.cdf(1), 0.75);                      // flat top: 1/2 + x / (2 p)
  EXPECT_DOUBLE_EQ(t.cdf(-2), 1.0 / 16);                 // ramp: (x + p + q)^2 / (8 p q)
  EXPECT_DOUBLE_EQ(t.cdf(3), 1);
  FootprintLine point;  // zero width: a step at 0
  EXPECT_EQ(point.cdf(-1e-300), 0);
  EXPECT_EQ(point.cdf(1e-300), 1);
  EXPECT_EQ(point.share(-1, 1), 1);
  // A square of side s rotated 45 degrees: a triangle of half-support s / sqrt 2 (trapezoid), the seed's
  // segment of half-width s / (2 sqrt 2).
  const double s = 1;
  const Footprint rotated{{0, 0}, {s / std::sqrt(2.0), s / std::sqrt(2.0)}, {-s / std::sqrt(2.0), s / std::sqrt(2.0)}};
  const FootprintLine tri = footprintLine(rotated, {0, 1}, FootprintDensity::Trapezoid);
  const FootprintLine seg = footprintLine(rotated, {0, 1}, FootprintDensity::SeedSegment);
  EXPECT_NEAR(tri.halfSupport(), s / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(tri.cdf(0.5 * tri.halfSupport()), 1 - 0.125, 1e-12);  // triangle tail beyond half: 1/8
  EXPECT_NEAR(seg.halfSupport(), s / (2 * std::sqrt(2.0)), 1e-15);
  EXPECT_NEAR(seg.cdf(0.5 * seg.halfSupport()), 0.75, 1e-12);
}

TEST(LineSampleSection, OverlappingCutsTakeTheDeeperAndSplitAtCrossings) {
  // Two V-grooves 0.01 apart (half-width 0.01): H = min of the two Vs, a crossing at b = 0.005.
  json j = sceneWith(vee());
  j["grooves"].push_back({{"profile", "p"}, {"path", {{"line", {{0, 0.51}, {1, 0.51}}}}}});
  const GrooveScene s = parseOk(j);
  const LocalGroove a = localGroove(s, 0, {0.5, 0.5}), b = localGroove(s, 1, {0.5, 0.5});
  CrossSection section;
  section.binormal = {0, 1};
  buildCrossSection(s, {{&a, 0.0, false}, {&b, 0.01, false}}, -0.05, 0.05, section);
  const std::vector<std::pair<double, double>> expected = {
      {-0.05, 0}, {-0.01, 0}, {0, -0.01}, {0.005, -0.005}, {0.01, -0.01}, {0.02, 0}, {0.05, 0}};
  ASSERT_NO_FATAL_FAILURE(expectPolyline(section, expected));
}

TEST(LineSampleSection, DisjointBandsWithPileUpAndSupportInsideABand) {
  // Two scratches with pile-up (their profile crosses h = 0) whose bands do not overlap, the second
  // mirrored; the footprint's support starts inside the first band. Every break is kept, each
  // crossing of h = 0 gets its point, and the flat base joins the bands.
  const json scratch = json::array({{-0.01, 0}, {-0.005, -0.01}, {0.005, 0.004}, {0.01, 0}});
  json j = sceneWith(scratch);
  j["materials"]["g"] = {{"albedo", {0.1, 0.2, 0.3}}};
  j["grooves"][0]["material"] = "g";
  j["grooves"].push_back({{"profile", "p"}, {"material", "g"}, {"path", {{"line", {{0, 0.53}, {1, 0.53}}}}}});
  const GrooveScene s = parseOk(j);
  const LocalGroove a = localGroove(s, 0, {0.5, 0.5}), b = localGroove(s, 1, {0.5, 0.5});
  CrossSection section;
  section.binormal = {0, 1};
  buildCrossSection(s, {{&a, 0.0, false}, {&b, 0.03, true}}, -0.007, 0.05, section);
  // Rising from -0.01 to 0.004 over [-0.005, 0.005]: h = 0 at -0.005 + 0.01 (10 / 14); mirrored, the
  // second falls from 0.004 to -0.01 over [0.025, 0.035]: h = 0 at 0.025 + 0.01 (4 / 14).
  const std::vector<std::pair<double, double>> expected = {
      {-0.01, 0}, {-0.007, -0.006}, {-0.005, -0.01}, {-0.005 + 0.01 * 10 / 14.0, 0}, {0.005, 0.004}, {0.01, 0},
      {0.02, 0},  {0.025, 0.004},   {0.025 + 0.01 * 4 / 14.0, 0}, {0.035, -0.01},  {0.04, 0},     {0.05, 0}};
  ASSERT_NO_FATAL_FAILURE(expectPolyline(section, expected));
  // The flat base between and after the bands takes the base material, the grooves' facets theirs.
  const std::size_t g = s.grooves[0].material, base = s.baseMaterial;
  ASSERT_NE(g, base);
  const std::vector<std::size_t> materials = {g, g, g, g, g, base, g, g, g, g, base};
  ASSERT_EQ(section.material.size(), materials.size());
  for (std::size_t i = 0; i < materials.size(); ++i) EXPECT_EQ(section.material[i], materials[i]) << i;
}

TEST(LineSampleSection, RidgeAddsToCutAndWallsAreVertical) {
  // A channel (vertical walls) under a reversed groove: b mirrored, walls kept as two points.
  const json channel = json::array({{-0.01, 0}, {-0.01, -0.004}, {0.02, -0.004}, {0.02, 0}});
  const GrooveScene s = parseOk(sceneWith(channel));
  const LocalGroove g = localGroove(s, 0, {0.5, 0.5});
  CrossSection section;
  section.binormal = {0, 1};
  buildCrossSection(s, {{&g, 0.001, true}}, -0.1, 0.1, section);
  // Reversed: b' = 0.001 - b, so the channel spans [-0.019, 0.011].
  const std::vector<std::pair<double, double>> expected = {
      {-0.1, 0}, {-0.019, 0}, {-0.019, -0.004}, {0.011, -0.004}, {0.011, 0}, {0.1, 0}};
  ASSERT_NO_FATAL_FAILURE(expectPolyline(section, expected));
  double nb = 0, nh = 0;
  facetNormal(section, 1, nb, nh);  // the wall at b = -0.019 faces -b... into the cavity: +b
  EXPECT_EQ(nb, 1);
  EXPECT_EQ(nh, 0);
}

TEST(LineSample, FlatFootprintBesideTheGrooveIsTheBaseClosedForm) {
  const json mat = {{"albedo", {0.6, 0.5, 0.4}}, {"specular", {0.3, 0.3, 0.3}}, {"shininess", 20}};
  const GrooveScene s = parseOk(sceneWith(vee(), mat));
  const Vec3 e = directionFromAngles(0.4, 0.3), l = directionFromAngles(0.2, 2.0);
  expectRgbNear(sample(s, across(0.3, 0.01), e, l), blinnPhong(s.materials[0], kUp, e, l), 1e-15);
}

TEST(LineSample, SymmetricVeeFromAboveClosedForm) {
  const json mat = {{"albedo", {0.6, 0.5, 0.4}}, {"specular", {0.3, 0.2, 0.1}}, {"shininess", 8}};
  const GrooveScene s = parseOk(sceneWith(vee(), mat));
  const Material& m = s.materials[0];
  // The footprint covers the groove exactly: each wall half of it.
  expectRgbNear(sample(s, across(0.5, 2 * kW), kUp, kUp),
                mix({{0.5, blinnPhong(m, kLeftWall, kUp, kUp)}, {0.5, blinnPhong(m, kRightWall, kUp, kUp)}}), 1e-14);
  // Twice as wide: a quarter per wall, the flat base the rest.
  expectRgbNear(sample(s, across(0.5, 4 * kW), kUp, kUp),
                mix({{0.25, blinnPhong(m, kLeftWall, kUp, kUp)},
                     {0.25, blinnPhong(m, kRightWall, kUp, kUp)},
                     {0.5, blinnPhong(m, kUp, kUp, kUp)}}),
                1e-14);
}

TEST(LineSample, ObliqueViewMasksTheFarWall) {
  const GrooveScene s = parseOk(sceneWith(vee()));
  const Material& m = s.materials[0];
  // Viewer on the +v side with d tan(theta) = 2 w: the right wall is back-facing, and through the
  // groove's opening [-w, w] only the left wall is seen (its lower third hidden by the right rim).
  const double theta = std::atan(2 * kW / kD);
  const Vec3 e{0, std::sin(theta), std::cos(theta)};
  expectRgbNear(sample(s, across(0.5, 2 * kW), e, kUp), blinnPhong(m, kLeftWall, e, kUp), 1e-14);
  expectRgbNear(sample(s, across(0.5, 4 * kW), e, kUp),
                mix({{0.5, blinnPhong(m, kLeftWall, e, kUp)}, {0.5, blinnPhong(m, kUp, e, kUp)}}), 1e-14);
  // The visible part of the left wall: t <= 2 w / (w + d tan theta) = 2/3.
  const LocalGroove g = localGroove(s, 0, {0.5, 0.5});
  CrossSection section;
  section.binormal = {0, 1};
  buildCrossSection(s, {{&g, 0.0, false}}, -0.02, 0.02, section);
  std::vector<FacetSpan> spans;
  visibleSpans(section, inSection(section, e), spans);
  ASSERT_EQ(spans.size(), 4u);
  EXPECT_NEAR(spans[1].t0, 0, 1e-15);
  EXPECT_NEAR(spans[1].t1, 2.0 / 3, 1e-14);
  EXPECT_TRUE(spans[2].empty());
  // Shallower view (d tan theta = w / 2): both walls fully visible, projected widths w + d e and w - d e.
  const double shallow = std::atan(0.5 * kW / kD);
  const Vec3 e2{0, std::sin(shallow), std::cos(shallow)};
  expectRgbNear(sample(s, across(0.5, 2 * kW), e2, kUp),
                mix({{0.75, blinnPhong(m, kLeftWall, e2, kUp)}, {0.25, blinnPhong(m, kRightWall, e2, kUp)}}), 1e-14);
}

TEST(LineSample, ObliqueLightShadowsTheLowerWall) {
  const GrooveScene s = parseOk(sceneWith(vee()));
  const Material& m = s.materials[0];
  // Light on the +v side with tan = 2 (d l = 2 w): the right wall faces away; the left wall is lit for
  // b in [-w, -w + 2 w^2 / (w + d l)] = [-w, -w/3]: a third of the opening.
  const double phi = std::atan(2.0);
  const Vec3 l{0, std::sin(phi), std::cos(phi)};
  expectRgbNear(sample(s, across(0.5, 2 * kW), kUp, l), mix({{1.0 / 3, blinnPhong(m, kLeftWall, kUp, l)}}), 1e-14);
  // From the other side, mirrored.
  const Vec3 l2{0, -std::sin(phi), std::cos(phi)};
  expectRgbNear(sample(s, across(0.5, 2 * kW), kUp, l2), mix({{1.0 / 3, blinnPhong(m, kRightWall, kUp, l2)}}), 1e-14);
}

TEST(LineSample, TrapezoidAndSeedSegmentOnARotatedFootprint) {
  const GrooveScene s = parseOk(sceneWith(vee()));
  const Material& m = s.materials[0];
  // A square footprint rotated 45 degrees whose projection on B is a triangle over [-2w, 2w]: 3/4 of
  // it falls in the groove (3/8 per wall). The seed's segment is uniform over [-w, w]: all groove.
  const double a = 2 * kW;
  const Footprint f{{0.5, 0.5}, {a, a}, {-a, a}};
  const Rgb left = blinnPhong(m, kLeftWall, kUp, kUp), right = blinnPhong(m, kRightWall, kUp, kUp),
            flat = blinnPhong(m, kUp, kUp, kUp);
  expectRgbNear(sample(s, f, kUp, kUp), mix({{0.375, left}, {0.375, right}, {0.25, flat}}), 1e-14);
  expectRgbNear(sample(s, f, kUp, kUp, 0, FootprintDensity::SeedSegment), mix({{0.5, left}, {0.5, right}}), 1e-14);
}

TEST(LineSample, MirroredSceneAndViewGiveTheSameValue) {
  const json skew = json::array({{-0.01, 0}, {-0.006, 0.003}, {-0.002, -0.007}, {0.015, 0}});
  json mirrored = json::array();
  for (auto it = skew.rbegin(); it != skew.rend(); ++it) mirrored.push_back({-(*it)[0].get<double>(), (*it)[1]});
  const json mat = {{"albedo", {0.6, 0.5, 0.4}}, {"specular", {0.5, 0.5, 0.5}}, {"shininess", 30},
                    {"mirror", {0.5, 0.6, 0.7}}};
  const GrooveScene s = parseOk(sceneWith(skew, mat)), t = parseOk(sceneWith(mirrored, mat));
  for (double theta : {0.3, 0.9, 1.3}) {
    const Vec3 e = directionFromAngles(theta, 1.2), l = directionFromAngles(0.5, 2.0);
    const Vec3 em{e.u, -e.v, e.w}, lm{l.u, -l.v, l.w};
    const Footprint f{{0.5, 0.503}, {0.004, 0.001}, {0.002, 0.011}};
    const Footprint fm{{0.5, 0.497}, {0.004, -0.001}, {0.002, -0.011}};
    const Rgb a = sample(s, f, e, l, 2), b = sample(t, fm, em, lm, 2);
    expectRgbNear(a, b, 1e-13);
    EXPECT_GT(a[0], 0) << theta;
  }
}

TEST(LineSample, ParallelSetAtThousandWidthsConvergesToTheAveragedBrdf) {
  // 1000 contiguous V-grooves of period 2w = 0.001; a footprint 1000.37 periods wide (so its ends cut
  // periods), an oblique view and light on the same side with d tan < w: no masking of whole walls.
  const double w = 0.0005, d = 0.0005;
  json j = sceneWith(vee(w, d), {{"albedo", {0.6, 0.5, 0.4}}, {"specular", {0.4, 0.4, 0.4}}, {"shininess", 12}});
  j["grooves"] = json::array();
  for (int k = 0; k < 1000; ++k) {
    const double v = w + 2 * w * k;
    j["grooves"].push_back({{"profile", "p"}, {"path", {{"line", {{0, v}, {1, v}}}}}});
  }
  const GrooveScene s = parseOk(j);
  const Material& m = s.materials[0];
  const double theta = std::atan(0.5), phi = std::atan(0.25);  // d tan = w/2 and w/4
  const Vec3 e{0, std::sin(theta), std::cos(theta)}, l{0, std::sin(phi), std::cos(phi)};
  const Vec3 nl{0, d / std::hypot(w, d), w / std::hypot(w, d)}, nr{0, -nl.v, nl.w};
  // Per period: the left wall projects to w + d tan(theta) of the 2w, the right wall to w - d tan(theta);
  // the light shadows the right wall's lower part: of its t in [0, 1] (bottom to top) the light's
  // projection runs from d tan(phi) to w, the left wall's bottom at d tan(phi) hides nothing (all of it
  // lit), so both walls are fully lit.
  const double te = std::tan(theta);
  const Rgb expected = mix({{(w + d * te) / (2 * w), blinnPhong(m, nl, e, l)}, {(w - d * te) / (2 * w), blinnPhong(m, nr, e, l)}});
  const Rgb value = sample(s, {{0.5, 0.5}, {0.0001, 0}, {0, 1000.37 * 2 * w * 0.999}}, e, l);
  expectRgbNear(value, expected, 2e-3 * expected[0]);
}

TEST(LineSample, MirrorVeeOneBounceByHand) {
  // A steep V (w = 0.01, d = 0.02) seen and lit from above: the left wall mirrors the view to
  // R = (0, 0.8, -0.6), which reaches the right wall's lower part (b in [0, 0.4545 w]), lit; and the
  // mirror image for the right wall. Pixel = sum over walls of 1/2 (f(N, E) + mirror f(N_other, -R)).
  const json mat = {{"albedo", {0.3, 0.4, 0.5}}, {"specular", {0.5, 0.5, 0.5}}, {"shininess", 10},
                    {"mirror", {0.8, 0.6, 0.4}}};
  const GrooveScene s = parseOk(sceneWith(vee(0.01, 0.02), mat));
  const Material& m = s.materials[0];
  const Vec3 nl{0, 2 / std::sqrt(5.0), 1 / std::sqrt(5.0)}, nr{0, -nl.v, nl.w};
  const Vec3 backFromRight{0, -0.8, 0.6}, backFromLeft{0, 0.8, 0.6};  // -R of each wall's bounce
  const Rgb direct = mix({{0.5, blinnPhong(m, nl, kUp, kUp)}, {0.5, blinnPhong(m, nr, kUp, kUp)}});
  Rgb expected = direct;
  const Rgb seenByLeft = blinnPhong(m, nr, backFromRight, kUp), seenByRight = blinnPhong(m, nl, backFromLeft, kUp);
  for (int c = 0; c < 3; ++c) expected[c] += 0.5 * m.mirror[c] * (seenByLeft[c] + seenByRight[c]);
  const Rgb value = sample(s, across(0.5, 0.02), kUp, kUp, 1);
  expectRgbNear(value, expected, 1e-13);
  expectRgbNear(sample(s, across(0.5, 0.02), kUp, kUp, 0), direct, 1e-14);
  // More bounces only add light.
  const Rgb two = sample(s, across(0.5, 0.02), kUp, kUp, 2);
  for (int c = 0; c < 3; ++c) EXPECT_GT(two[c], value[c]);
}

TEST(LineSample, SharesSumToOneForAnyView) {
  const json scratch = json::array({{-0.03, 0}, {-0.02, 0.003}, {-0.01, 0}, {0, -0.008}, {0.01, 0}, {0.02, 0.003}, {0.03, 0}});
  json j = sceneWith(scratch);
  j["grooves"].push_back({{"profile", "p"}, {"path", {{"line", {{1, 0.52}, {0, 0.52}}}}}});
  const GrooveScene s = parseOk(j);
  std::vector<LocalGroove> grooves{localGroove(s, 0, {0.5, 0.51}), localGroove(s, 1, {0.5, 0.51})};
  for (double theta : {0.0, 0.5, 1.0, 1.4, 1.55}) {
    for (double phi : {0.0, 1.0, 2.0, 3.5}) {
      const Vec3 e = directionFromAngles(theta, phi);
      const Footprint f{{0.5, 0.51}, {0.003, 0.002}, {-0.001, 0.02}};
      const FootprintLine line = footprintLine(f, {0, 1}, FootprintDensity::Trapezoid);
      CrossSection section;
      section.binormal = {0, 1};
      buildCrossSection(s, {{&grooves[0], 0.0, false}, {&grooves[1], 0.02, true}}, -line.halfSupport(),
                        line.halfSupport(), section);
      Lighting lighting;
      const SectionShading shading = shadeSection(s, section, line, e, lighting);
      EXPECT_NEAR(shading.visibleShare, 1, 1e-12) << theta << " " << phi;
    }
  }
}

TEST(LineSample, NonParallelCutsWithoutOverlapAgreeWithAreaSampling) {
  // A V along u and a V at 20 degrees whose bands do not meet under the footprint. Cuts cannot occlude
  // each other across flat ground, so shading each on its own section and adding their differences
  // from the flat base is exact here: it must match area sampling (exact polygons) at oblique angles.
  const double angle = 20 * kPi / 180;
  json j = sceneWith(vee(), {{"albedo", {0.6, 0.5, 0.4}}, {"specular", {0.4, 0.4, 0.4}}, {"shininess", 12}});
  const double cu = 0.5 - 0.4 * std::cos(angle), cv = 0.535 - 0.4 * std::sin(angle);
  j["grooves"].push_back(
      {{"profile", "p"}, {"path", {{"line", {{cu, cv}, {0.5 + 0.4 * std::cos(angle), 0.535 + 0.4 * std::sin(angle)}}}}}});
  const GrooveScene s = parseOk(j);
  const Footprint f{{0.5, 0.5}, {0.06, 0}, {0, 0.06}};
  std::vector<LocalGroove> grooves{localGroove(s, 0, f.centre), localGroove(s, 1, f.centre)};
  for (const auto& [e, l] : {std::pair{directionFromAngles(0.6, 1.9), directionFromAngles(0.5, -1.0)},
                             std::pair{directionFromAngles(1.1, -0.4), directionFromAngles(0.9, 2.6)}}) {
    Lighting lighting;
    lighting.toLight = l;
    const Rgb line = lineSample(s, grooves, f, e, lighting), area = areaSample(s, grooves, f, e, lighting);
    const Rgb flat = directRadiance(s.materials[0], {0, 0, 1}, e, lighting);
    EXPECT_GT(std::abs(line[0] - flat[0]), 1e-3);  // both grooves matter
    expectRgbNear(line, area, 1e-9);
  }
}

}  // namespace
}  // namespace bake::grooves
