// The groove scene reader (libbake/grooves; formats/groove-scene.md): path kinds and their
// flattening, SVG path data, generators, validation errors and duplicate merging.
#include <cmath>
#include <fstream>
#include <numbers>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bake/core/vec.h"
#include "grooves/input/generators.h"
#include "grooves/input/scene.h"
#include "support/node_check.h"

namespace bake::grooves {
namespace {

using nlohmann::json;

// A V-shaped groove of half-width 0.01 and depth 0.005 (symmetric) and a skewed one with a ridge.
json baseScene() {
  return json::parse(R"({
    "version": 1, "units": "mm", "domain": {"size": [1, 1]}, "wrap": "none",
    "profiles": {
      "v": {"points": [[-0.01, 0], [0, -0.005], [0.01, 0]]},
      "skew": {"points": [[-0.01, 0], [-0.005, 0.002], [0, -0.004], [0.02, 0]]}
    },
    "materials": {"metal": {"albedo": [0.5, 0.5, 0.5], "specular": [1, 1, 1], "shininess": 40, "mirror": [0.8, 0.8, 0.8]},
                  "paint": {"albedo": [0.9, 0.1, 0.1]}},
    "base": "metal", "grooves": []
  })");
}

json withGroove(const json& path, const std::string& profile = "v") {
  json scene = baseScene();
  scene["grooves"].push_back({{"profile", profile}, {"path", path}});
  return scene;
}

Result<GrooveScene> parse(const json& scene) { return parseGrooveScene(scene.dump(), "scene.json"); }

GrooveScene parseOk(const json& scene) {
  Result<GrooveScene> r = parse(scene);
  EXPECT_TRUE(r.isOk()) << r.status().describe();
  return r.isOk() ? r.value() : GrooveScene{};
}

// Expects exit code 3 and every fragment in the described error.
void expectInvalid(const json& scene, std::initializer_list<const char*> fragments) {
  Result<GrooveScene> r = parse(scene);
  ASSERT_FALSE(r.isOk());
  EXPECT_EQ(r.status().code(), ExitCode::InvalidInput);
  EXPECT_EQ(int(r.status().code()), 3);
  const std::string text = r.status().describe();
  for (const char* f : fragments) EXPECT_NE(text.find(f), std::string::npos) << "missing \"" << f << "\" in: " << text;
}

double totalLength(const GrooveScene& s, std::size_t g) {
  double sum = 0;
  for (std::size_t i = 0; i < s.grooves[g].primitiveCount; ++i) sum += s.primitives[s.grooves[g].firstPrimitive + i].length;
  return sum;
}

double distanceToChain(const GrooveScene& s, Vec2 q) {
  double best = 1e300;
  for (const Primitive& p : s.primitives) {
    double d;
    if (p.kind == Primitive::Kind::Arc) {
      // Nearest point on the arc: the radial projection when inside the sweep, else an end.
      const double angle = std::atan2(q.v - p.centre.v, q.u - p.centre.u);
      double t = std::remainder(angle - p.startAngle, 2 * kPi) / p.sweep;
      if (t < 0 && p.sweep > 0) t += 2 * kPi / p.sweep;
      if (t < 0 && p.sweep < 0) t -= 2 * kPi / p.sweep;
      d = std::min(std::hypot(q.u - p.a.u, q.v - p.a.v), std::hypot(q.u - p.b.u, q.v - p.b.v));
      if (t >= 0 && t <= 1) d = std::abs(std::hypot(q.u - p.centre.u, q.v - p.centre.v) - p.radius);
    } else {
      const double du = p.b.u - p.a.u, dv = p.b.v - p.a.v;
      const double t = std::clamp(((q.u - p.a.u) * du + (q.v - p.a.v) * dv) / (du * du + dv * dv), 0.0, 1.0);
      d = std::hypot(q.u - p.a.u - t * du, q.v - p.a.v - t * dv);
    }
    best = std::min(best, d);
  }
  return best;
}

// Consecutive primitives of each groove meet (C0), and arc-length starts add up.
void expectChained(const GrooveScene& s) {
  for (const Groove& g : s.grooves) {
    double arc = 0;
    for (std::size_t i = 0; i < g.primitiveCount; ++i) {
      const Primitive& p = s.primitives[g.firstPrimitive + i];
      EXPECT_NEAR(p.arcStart, arc, 1e-9);
      arc += p.length;
      const Vec2 a = p.pointAt(0), b = p.pointAt(1);
      EXPECT_NEAR(a.u, p.a.u, 1e-9);
      EXPECT_NEAR(a.v, p.a.v, 1e-9);
      EXPECT_NEAR(b.u, p.b.u, 1e-9);
      EXPECT_NEAR(b.v, p.b.v, 1e-9);
      if (i > 0) {
        const Primitive& q = s.primitives[g.firstPrimitive + i - 1];
        EXPECT_NEAR(q.b.u, p.a.u, 1e-9);
        EXPECT_NEAR(q.b.v, p.a.v, 1e-9);
      }
    }
  }
}

TEST(GrooveScene, ReadsProfilesMaterialsAndBounds) {
  const GrooveScene s = parseOk(withGroove({{"line", {{0.1, 0.1}, {0.9, 0.1}}}}, "skew"));
  ASSERT_EQ(s.profiles.size(), 2u);
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.units, "mm");
  const Profile& skew = s.profiles[1].name == "skew" ? s.profiles[1] : s.profiles[0];
  EXPECT_DOUBLE_EQ(skew.wmax, 0.02);
  EXPECT_DOUBLE_EQ(skew.hmax, 0.002);
  EXPECT_DOUBLE_EQ(skew.dmax, 0.004);
  EXPECT_FALSE(skew.symmetric);
  EXPECT_DOUBLE_EQ(s.wmax, 0.02);
  EXPECT_DOUBLE_EQ(s.hmax, 0.002);
  EXPECT_DOUBLE_EQ(s.dmax, 0.004);
  EXPECT_EQ(s.materials[s.grooves[0].material].name, "metal");  // the base by default
  EXPECT_TRUE(s.materials[s.baseMaterial].hasMirror);
  EXPECT_DOUBLE_EQ(s.flatteningTolerance, 1e-5);  // 1e-3 x the smallest half-width
}

TEST(GrooveScene, LineIsOneSegmentWithOpenEnds) {
  const GrooveScene s = parseOk(withGroove({{"line", {{0.1, 0.2}, {0.4, 0.6}}}}));
  ASSERT_EQ(s.primitives.size(), 1u);
  const Primitive& p = s.primitives[0];
  EXPECT_EQ(p.kind, Primitive::Kind::Segment);
  EXPECT_DOUBLE_EQ(p.length, 0.5);
  EXPECT_TRUE(p.endAtStart);
  EXPECT_TRUE(p.endAtEnd);
  EXPECT_FALSE(s.grooves[0].closed);
}

TEST(GrooveScene, PolylineVerticesAreCornersAndClosedPolylineHasNoEnds) {
  const GrooveScene s = parseOk(withGroove({{"polyline", {{0.1, 0.1}, {0.5, 0.1}, {0.5, 0.5}, {0.1, 0.1}}}}));
  ASSERT_EQ(s.primitives.size(), 3u);
  EXPECT_TRUE(s.grooves[0].closed);
  for (const Primitive& p : s.primitives) {
    EXPECT_TRUE(p.cornerAtStart);  // the first too: the closing vertex is a corner
    EXPECT_FALSE(p.endAtStart);
    EXPECT_FALSE(p.endAtEnd);
  }
  // Collinear vertices are no corners.
  const GrooveScene t = parseOk(withGroove({{"polyline", {{0.1, 0.1}, {0.3, 0.1}, {0.5, 0.1}}}}));
  ASSERT_EQ(t.primitives.size(), 2u);
  EXPECT_FALSE(t.primitives[1].cornerAtStart);
  expectChained(s);
}

TEST(GrooveScene, ArcIsKeptExactly) {
  const GrooveScene s = parseOk(withGroove({{"arc", {{"centre", {0.5, 0.5}}, {"radius", 0.2}, {"start", 0}, {"end", 90}}}}));
  ASSERT_EQ(s.primitives.size(), 1u);
  const Primitive& p = s.primitives[0];
  EXPECT_EQ(p.kind, Primitive::Kind::Arc);
  EXPECT_NEAR(p.length, 0.2 * kPi / 2, 1e-12);
  EXPECT_NEAR(p.sweep, kPi / 2, 1e-12);
  EXPECT_NEAR(p.a.u, 0.7, 1e-12);
  EXPECT_NEAR(p.b.v, 0.7, 1e-12);
  // end < start: clockwise.
  const GrooveScene c = parseOk(withGroove({{"arc", {{"centre", {0.5, 0.5}}, {"radius", 0.2}, {"start", 90}, {"end", 0}}}}));
  EXPECT_NEAR(c.primitives[0].sweep, -kPi / 2, 1e-12);
  EXPECT_NEAR(c.primitives[0].tangentAt(0).u, 1, 1e-12);  // moving towards +u at the top
  // A full circle is closed.
  const GrooveScene f = parseOk(withGroove({{"arc", {{"centre", {0.5, 0.5}}, {"radius", 0.2}, {"start", 30}, {"end", 390}}}}));
  EXPECT_TRUE(f.grooves[0].closed);
  EXPECT_FALSE(f.primitives[0].cornerAtStart);
}

// Closed form of the Archimedean spiral's length r = b theta: (b/2)[theta sqrt(1+theta^2) + asinh(theta)].
double spiralLength(double r0, double pitch, double turns) {
  const double b = pitch / (2 * kPi);
  auto F = [&](double th) { return 0.5 * b * (th * std::sqrt(1 + th * th) + std::asinh(th)); };
  const double th0 = r0 / b;
  return F(th0 + 2 * kPi * turns) - F(th0);
}

TEST(GrooveScene, SpiralFlattensIntoG1ArcsWithinTolerance) {
  const double r0 = 0.1, pitch = 0.05, turns = 3;
  const json scene = withGroove({{"spiral", {{"centre", {0.5, 0.5}}, {"startRadius", r0}, {"pitch", pitch}, {"turns", turns}, {"startAngle", 0}}}});
  const GrooveScene s = parseOk(scene);
  ASSERT_GT(s.primitives.size(), 10u);
  expectChained(s);
  const double exact = spiralLength(r0, pitch, turns);
  // Each piece's length differs from the curve's by O(tolerance); the sum stays within a few tolerances.
  EXPECT_NEAR(totalLength(s, 0), exact, 1e-4 * exact);
  for (std::size_t i = 1; i < s.primitives.size(); ++i) {
    EXPECT_FALSE(s.primitives[i].cornerAtStart);
    const Vec2 t0 = s.primitives[i - 1].tangentAt(1), t1 = s.primitives[i].tangentAt(0);
    EXPECT_GT(t0.u * t1.u + t0.v * t1.v, std::cos(0.05)) << "joint " << i;  // nearly tangent
  }
  // The tolerance is honoured: dense samples of the true spiral are within it of the chain.
  const double b = pitch / (2 * kPi);
  for (int i = 0; i <= 4000; ++i) {
    const double th = 2 * kPi * turns * i / 4000.0, r = r0 + b * th;
    EXPECT_LE(distanceToChain(s, {0.5 + r * std::cos(th), 0.5 + r * std::sin(th)}), s.flatteningTolerance * 1.0001) << i;
  }
  // End points are the spiral's.
  EXPECT_NEAR(s.primitives.back().b.u, 0.5 + r0 + pitch * turns, 1e-12);
}

TEST(GrooveScene, BezierEndpointsAndToleranceHonoured) {
  const json cubic = {{0.1, 0.1}, {0.3, 0.8}, {0.7, -0.2}, {0.9, 0.5}};
  json scene = withGroove({{"cubic", cubic}});
  scene["grooves"].push_back({{"profile", "v"}, {"path", {{"quadratic", {{0.1, 0.9}, {0.5, 0.5}, {0.9, 0.9}}}}}});
  scene["flatteningTolerance"] = 1e-4;
  const GrooveScene s = parseOk(scene);
  ASSERT_EQ(s.grooves.size(), 2u);
  expectChained(s);
  const Groove& g = s.grooves[0];
  EXPECT_DOUBLE_EQ(s.primitives[g.firstPrimitive].a.u, 0.1);
  EXPECT_DOUBLE_EQ(s.primitives[g.firstPrimitive].a.v, 0.1);
  EXPECT_DOUBLE_EQ(s.primitives[g.firstPrimitive + g.primitiveCount - 1].b.u, 0.9);
  EXPECT_DOUBLE_EQ(s.primitives[g.firstPrimitive + g.primitiveCount - 1].b.v, 0.5);
  for (std::size_t i = 1; i < s.primitives.size(); ++i)
    if (s.primitives[i].groove == s.primitives[i - 1].groove) EXPECT_FALSE(s.primitives[i].cornerAtStart);
  for (int i = 0; i <= 2000; ++i) {
    const double t = i / 2000.0, u = 1 - t;
    const Vec2 c{u * u * u * 0.1 + 3 * u * u * t * 0.3 + 3 * u * t * t * 0.7 + t * t * t * 0.9,
                 u * u * u * 0.1 + 3 * u * u * t * 0.8 + 3 * u * t * t * -0.2 + t * t * t * 0.5};
    EXPECT_LE(distanceToChain(s, c), 1e-4 * 1.0001) << t;
    const Vec2 q{u * u * 0.1 + 2 * u * t * 0.5 + t * t * 0.9, u * u * 0.9 + 2 * u * t * 0.5 + t * t * 0.9};
    EXPECT_LE(distanceToChain(s, q), 1e-4 * 1.0001) << t;
  }
}

TEST(GrooveScene, SvgPathData) {
  // Absolute and relative commands describing the same square, closed by Z.
  const GrooveScene a = parseOk(withGroove({{"svg", "M 0.1 0.1 L 0.5 0.1 L 0.5 0.5 L 0.1 0.5 Z"}}));
  const GrooveScene r = parseOk(withGroove({{"svg", "m0.1,0.1 h0.4 v0.4 l-0.4 0 z"}}));
  ASSERT_EQ(a.primitives.size(), 4u);
  ASSERT_EQ(r.primitives.size(), 4u);
  EXPECT_TRUE(a.grooves[0].closed);
  EXPECT_TRUE(r.grooves[0].closed);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(a.primitives[i].a.u, r.primitives[i].a.u, 1e-12);
    EXPECT_NEAR(a.primitives[i].a.v, r.primitives[i].a.v, 1e-12);
    EXPECT_TRUE(a.primitives[i].cornerAtStart);
  }
  // Two subpaths are two grooves; curves and a circular arc.
  const GrooveScene m = parseOk(withGroove(
      {{"svg", "M0.1 0.1 C0.2 0.3 0.3 0.3 0.4 0.1 S0.6 -0.1 0.7 0.1 M0.1 0.6 Q0.2 0.8 0.3 0.6 T0.5 0.6 A0.1 0.1 0 0 1 0.7 0.6"}}));
  ASSERT_EQ(m.grooves.size(), 2u);
  const Groove& g1 = m.grooves[1];
  const Primitive& arc = m.primitives[g1.firstPrimitive + g1.primitiveCount - 1];
  EXPECT_EQ(arc.kind, Primitive::Kind::Arc);
  EXPECT_NEAR(arc.radius, 0.1, 1e-12);
  EXPECT_NEAR(arc.centre.u, 0.6, 1e-12);
  EXPECT_NEAR(arc.centre.v, 0.6, 1e-12);
  // The half circle is kept exact, split into two quarter arcs joined G1.
  EXPECT_NEAR(std::abs(arc.sweep), kPi / 2, 1e-12);
  EXPECT_NEAR(arc.b.u, 0.7, 1e-12);
  const Primitive& firstHalf = m.primitives[g1.firstPrimitive + g1.primitiveCount - 2];
  EXPECT_EQ(firstHalf.kind, Primitive::Kind::Arc);
  EXPECT_NEAR(firstHalf.radius, 0.1, 1e-12);
  EXPECT_NEAR(std::abs(firstHalf.sweep), kPi / 2, 1e-12);
  EXPECT_FALSE(arc.cornerAtStart);
  // S reflects the previous control point: the joint is smooth, not a corner.
  const Groove& g0 = m.grooves[0];
  bool smooth = true;
  for (std::size_t i = 1; i < g0.primitiveCount; ++i) smooth = smooth && !m.primitives[g0.firstPrimitive + i].cornerAtStart;
  EXPECT_TRUE(smooth);
  expectChained(m);
  // Joints between a curve and a line follow the curve's own end tangent: along it, no corner; across, a corner.
  const GrooveScene along = parseOk(withGroove({{"svg", "M0.1 0.1 C0.2 0.3 0.3 0.3 0.4 0.4 L0.5 0.5"}}));
  EXPECT_FALSE(along.primitives.back().cornerAtStart);
  const GrooveScene across = parseOk(withGroove({{"svg", "M0.1 0.1 C0.2 0.3 0.3 0.3 0.4 0.4 L0.5 0.4"}}));
  EXPECT_TRUE(across.primitives.back().cornerAtStart);
  expectInvalid(withGroove({{"svg", "M0.1 0.1 A0.1 0.2 0 0 1 0.3 0.1"}}), {"elliptical", "command 1", "(0.1, 0.1)", "/grooves/0/path/svg"});
  expectInvalid(withGroove({{"svg", "L0.1 0.1"}}), {"must start with M"});
  expectInvalid(withGroove({{"svg", "M0.1 0.1 X 3"}}), {"unknown command"});
}

TEST(GrooveScene, TileGenerators) {
  json scene = baseScene();
  scene["generators"] = json::array({{{"tiles", {{"origin", {0, 0}}, {"tileSize", {0.2, 0.1}}, {"count", {4, 3}}, {"bond", "stack"}, {"profile", "v"}}}}});
  const GrooveScene s = parseOk(scene);
  EXPECT_EQ(s.grooves.size(), 4u + 5u);  // ny + 1 horizontal, nx + 1 vertical
  // Running bond: two borders, even rows nx - 1 joints, odd rows nx joints shifted by half a tile.
  const auto lines = tileGroutLines({0, 0}, {0.2, 0.1}, 4, 3, true);
  ASSERT_EQ(lines.size(), 4u + 2u + 3u + 4u + 3u);
  for (std::size_t k = 6; k < lines.size(); ++k) {
    const PathPiece& p = lines[k][0];
    EXPECT_DOUBLE_EQ(p.p[0].u, p.p[1].u);                 // vertical
    EXPECT_NEAR(p.p[1].v - p.p[0].v, 0.1, 1e-12);         // one row high: ends on horizontal lines (T)
    const int row = int(std::lround(p.p[0].v / 0.1));
    const double phase = std::fmod(p.p[0].u + 1e-9, 0.2);
    EXPECT_NEAR(phase, row % 2 == 1 ? 0.1 : 0.0, 1e-6) << k;
  }
  scene["generators"][0]["tiles"]["bond"] = "running";
  const GrooveScene r = parseOk(scene);
  EXPECT_EQ(r.grooves.size(), lines.size());
  // A T-junction: the joint of row 1 ends on the horizontal line v = 0.2 at u = 0.1, inside it.
  bool found = false;
  for (const Primitive& p : r.primitives)
    if (std::abs(p.a.u - 0.1) < 1e-12 && std::abs(p.a.v - 0.1) < 1e-12 && std::abs(p.b.v - 0.2) < 1e-12) found = true;
  EXPECT_TRUE(found);
}

TEST(GrooveScene, RecordGenerator) {
  json scene = baseScene();
  scene["generators"] = json::array({{{"record", {{"centre", {0.5, 0.5}}, {"innerRadius", 0.1}, {"outerRadius", 0.4}, {"grooves", 6}, {"profile", "v"}}}}});
  const GrooveScene s = parseOk(scene);
  ASSERT_EQ(s.grooves.size(), 1u);
  const Primitive& first = s.primitives.front();
  const Primitive& last = s.primitives.back();
  EXPECT_NEAR(std::hypot(first.a.u - 0.5, first.a.v - 0.5), 0.1, 1e-12);
  EXPECT_NEAR(std::hypot(last.b.u - 0.5, last.b.v - 0.5), 0.4, 1e-12);
  EXPECT_NEAR(totalLength(s, 0), spiralLength(0.1, 0.05, 6), 1e-4 * spiralLength(0.1, 0.05, 6));
}

TEST(GrooveScene, PerturbationEnlargesBounds) {
  json scene = withGroove({{"line", {{0.1, 0.1}, {0.9, 0.1}}}});
  scene["grooves"][0]["perturbation"] = {{"kind", "scale"}, {"amplitude", 0.5}, {"wavelength", 0.1}, {"phase", 0}};
  const GrooveScene s = parseOk(scene);
  EXPECT_NEAR(s.wmax, 0.015, 1e-15);
  EXPECT_NEAR(s.dmax, 0.0075, 1e-15);
  scene["grooves"][0]["profile"] = "skew";
  EXPECT_NEAR(parseOk(scene).hmax, 0.003, 1e-15);
  scene["grooves"][0]["perturbation"] = {{"kind", "offset"}, {"amplitude", 0.02}, {"wavelength", 0.1}};
  const GrooveScene o = parseOk(scene);
  EXPECT_NEAR(o.wmax, 0.04, 1e-15);
  EXPECT_NEAR(o.hmax, 0.002, 1e-15);
  // The enlarged half-width is what an arc's radius is checked against.
  json arc = withGroove({{"arc", {{"centre", {0.5, 0.5}}, {"radius", 0.012}, {"start", 0}, {"end", 90}}}});
  parseOk(arc);
  arc["grooves"][0]["perturbation"] = {{"kind", "scale"}, {"amplitude", 0.5}, {"wavelength", 0.1}};
  expectInvalid(arc, {"groove 0", "segment 0", "(0.512, 0.5)", "radius"});
  scene["grooves"][0]["perturbation"]["kind"] = "scale";
  scene["grooves"][0]["perturbation"]["amplitude"] = 1.0;
  expectInvalid(scene, {"/grooves/0/perturbation/amplitude"});
}

TEST(GrooveScene, DuplicatesAreMergedWithAWarning) {
  json scene = withGroove({{"polyline", {{0.1, 0.1}, {0.5, 0.1}, {0.5, 0.5}}}});
  scene["grooves"].push_back(scene["grooves"][0]);
  scene["grooves"].push_back({{"profile", "v"}, {"path", {{"polyline", {{0.5, 0.5}, {0.5, 0.1}, {0.1, 0.1}}}}}});
  scene["grooves"].push_back({{"profile", "v"}, {"material", "paint"}, {"path", {{"polyline", {{0.1, 0.1}, {0.5, 0.1}, {0.5, 0.5}}}}}});
  const GrooveScene s = parseOk(scene);
  EXPECT_EQ(s.grooves.size(), 2u);  // the copy and the reversed copy merged; another material is kept
  ASSERT_EQ(s.warnings.size(), 2u);
  EXPECT_NE(s.warnings[0].find("groove 1 duplicates groove 0"), std::string::npos);
  EXPECT_NE(s.warnings[1].find("reversed"), std::string::npos);
  EXPECT_EQ(s.primitives.size(), 4u);
  EXPECT_EQ(s.primitives[3].groove, 1u);
  // Reversed is not a duplicate for an asymmetric profile.
  json skew = withGroove({{"line", {{0.1, 0.1}, {0.5, 0.1}}}}, "skew");
  skew["grooves"].push_back({{"profile", "skew"}, {"path", {{"line", {{0.5, 0.1}, {0.1, 0.1}}}}}});
  EXPECT_EQ(parseOk(skew).grooves.size(), 2u);
}

TEST(GrooveScene, InvalidScenesAreExitCode3) {
  expectInvalid(withGroove({{"line", {{0.1, 0.1}, {0.9, 0.1}}}}, "nope"), {"/grooves/0/profile", "unknown profile \"nope\""});
  json m = withGroove({{"line", {{0.1, 0.1}, {0.9, 0.1}}}});
  m["grooves"][0]["material"] = "gold";
  expectInvalid(m, {"/grooves/0/material", "unknown material"});
  expectInvalid(withGroove({{"line", {{0.1, 0.1}, {0.1, 0.1}}}}), {"groove 0", "segment 0", "(0.1, 0.1)", "zero-length"});
  json named = withGroove({{"polyline", {{0.1, 0.1}, {0.3, 0.1}, {0.3, 0.1}}}});
  named["grooves"][0]["name"] = "scratch";
  expectInvalid(named, {"groove 0 (\"scratch\")", "segment 1", "(0.3, 0.1)", "zero-length"});
  expectInvalid(withGroove({{"arc", {{"centre", {0.5, 0.5}}, {"radius", 0.005}, {"start", 0}, {"end", 90}}}}),
                {"groove 0", "segment 0", "(0.505, 0.5)", "smaller than the groove's half-width"});
  // A spiral starting at its centre is too tight there.
  expectInvalid(withGroove({{"spiral", {{"centre", {0.5, 0.5}}, {"startRadius", 0}, {"pitch", 0.05}, {"turns", 2}}}}),
                {"groove 0", "segment 0", "(0.5, 0.5)", "radius of curvature"});
  // A cubic with a sharp bend.
  expectInvalid(withGroove({{"cubic", {{0.1, 0.1}, {0.9, 0.1}, {0.1, 0.1005}, {0.9, 0.1005}}}}), {"groove 0", "segment", "radius of curvature"});
  {
    // A literal overflowing a double (JSON has no NaN or Inf) is refused by the parser.
    std::string text = withGroove({{"line", {{0.1, 0.1}, {12345.5, 0.1}}}}).dump();
    text.replace(text.find("12345.5"), 7, "1e999");
    Result<GrooveScene> r = parseGrooveScene(text, "scene.json");
    ASSERT_FALSE(r.isOk());
    EXPECT_EQ(r.status().code(), ExitCode::InvalidInput);
    EXPECT_NE(r.status().describe().find("overflow"), std::string::npos) << r.status().describe();
  }
  expectInvalid(withGroove({{"lines", {{0.1, 0.1}, {0.2, 0.1}}}}), {"unknown key \"lines\"", "did you mean \"line\""});
  json p = baseScene();
  auto profileCase = [&](const json& points, std::initializer_list<const char*> fragments) {
    json q = p;
    q["profiles"]["bad"] = {{"points", points}};
    expectInvalid(q, fragments);
  };
  profileCase({{-0.01, 0}, {0.01, -0.005}, {0.005, -0.002}, {0.02, 0}}, {"profile \"bad\"", "segment 1", "undercut"});
  profileCase({{-0.01, 0}, {0, -0.005}, {0, -0.005}, {0.01, 0}}, {"profile \"bad\"", "segment 1", "coincident"});
  profileCase({{-0.01, -0.001}, {0, -0.005}, {0.01, 0}}, {"profile \"bad\"", "segment 0", "surface"});
  profileCase({{-0.01, 0}, {0, -0.005}, {0.01, 0.001}}, {"profile \"bad\"", "segment 1", "surface"});
  profileCase({{0, 0}, {0, -0.005}, {0, 0}}, {"profile \"bad\"", "self-intersection"});
  profileCase({{0, 0}, {0, 0.0}}, {"profile \"bad\"", "3 points"});
  json z = baseScene();
  z["domain"]["size"] = {0, 1};
  expectInvalid(z, {"/domain/size"});
  json v = baseScene();
  v["version"] = 2;
  expectInvalid(v, {"/version"});
}

TEST(GrooveScene, ExampleSceneValidatesAgainstTheSchema) {
  const std::string example = std::string(BAKE_SOURCE_DIR) + "/tests/grooves/data/example-scene.json";
  Result<GrooveScene> r = readGrooveScene(example);
  ASSERT_TRUE(r.isOk()) << r.status().describe();
  EXPECT_GE(r->grooves.size(), 8u);
  const json answer = test::runNodeChecker(
      "check_schema.mjs", {std::string(BAKE_SOURCE_DIR) + "/formats/groove-scene.schema.json", example});
  ASSERT_TRUE(answer.is_object());
  EXPECT_TRUE(answer["valid"].get<bool>()) << answer.dump();
  // And the schema refuses what the reader refuses at the JSON level.
  std::filesystem::create_directories(BAKE_TEST_TMP);
  const std::string bad = std::string(BAKE_TEST_TMP) + "/groove-bad-scene.json";
  json doc = json::parse(std::ifstream(example));
  doc["grooves"][0]["pathh"] = doc["grooves"][0]["path"];
  std::ofstream(bad) << doc.dump();
  const json refused = test::runNodeChecker("check_schema.mjs", {std::string(BAKE_SOURCE_DIR) + "/formats/groove-scene.schema.json", bad});
  EXPECT_FALSE(refused["valid"].get<bool>());
  EXPECT_EQ(readGrooveScene(bad).status().code(), ExitCode::InvalidInput);
}

}  // namespace
}  // namespace bake::grooves
