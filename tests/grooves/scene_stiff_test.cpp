// Stiff cases of the groove scene reader: long spirals at tight tolerances, inward spirals, large
// tile grids and many duplicates.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bake/core/vec.h"
#include "grooves/input/scene.h"

namespace bake::grooves {
namespace {

using nlohmann::json;

json stiffScene() {
  return json::parse(R"({
    "version": 1, "domain": {"size": [1, 1]},
    "profiles": {"v": {"points": [[-0.0005, 0], [0, -0.0003], [0.0005, 0]]}},
    "materials": {"m": {}}, "base": "m", "grooves": []
  })");
}

double spiralLength(double r0, double pitch, double turns) {
  const double b = pitch / (2 * kPi);
  auto F = [&](double th) { return 0.5 * b * (th * std::sqrt(1 + th * th) + std::asinh(th)); };
  const double th0 = r0 / b;
  return F(th0 + 2 * kPi * turns) - F(th0);
}

double distanceToArcChain(const GrooveScene& s, Vec2 q) {
  double best = 1e300;
  for (const Primitive& p : s.primitives) {
    double d = std::min(std::hypot(q.u - p.a.u, q.v - p.a.v), std::hypot(q.u - p.b.u, q.v - p.b.v));
    if (p.kind == Primitive::Kind::Arc) {
      double t = std::remainder(std::atan2(q.v - p.centre.v, q.u - p.centre.u) - p.startAngle, 2 * kPi) / p.sweep;
      if (t < 0) t += 2 * kPi / std::abs(p.sweep);
      if (t <= 1) d = std::abs(std::hypot(q.u - p.centre.u, q.v - p.centre.v) - p.radius);
    } else {
      const double du = p.b.u - p.a.u, dv = p.b.v - p.a.v;
      const double t = std::clamp(((q.u - p.a.u) * du + (q.v - p.a.v) * dv) / (du * du + dv * dv), 0.0, 1.0);
      d = std::hypot(q.u - p.a.u - t * du, q.v - p.a.v - t * dv);
    }
    best = std::min(best, d);
  }
  return best;
}

TEST(GrooveSceneStiff, RecordOfTwoHundredTurnsAtTheDefaultTolerance) {
  json scene = stiffScene();
  scene["generators"] = json::array({{{"record", {{"centre", {0.5, 0.5}}, {"innerRadius", 0.1}, {"outerRadius", 0.45}, {"grooves", 200}, {"profile", "v"}}}}});
  const Result<GrooveScene> r = parseGrooveScene(scene.dump(), "record.json");
  ASSERT_TRUE(r.isOk()) << r.status().describe();
  const GrooveScene& s = *r;
  EXPECT_DOUBLE_EQ(s.flatteningTolerance, 5e-7);
  double length = 0;
  for (const Primitive& p : s.primitives) {
    EXPECT_NEAR(p.arcStart, length, 1e-9);
    length += p.length;
  }
  const double exact = spiralLength(0.1, 0.35 / 200, 200);
  EXPECT_NEAR(length, exact, 1e-6 * exact);
  // Every primitive stays within the tolerance of the true spiral at its middle.
  const double b = 0.35 / 200 / (2 * kPi);
  for (const Primitive& p : s.primitives) {
    const Vec2 m = p.pointAt(0.5);
    const double angle = std::atan2(m.v - 0.5, m.u - 0.5), r = std::hypot(m.u - 0.5, m.v - 0.5);
    // The spiral's radius nearest to r at this angle: 0.1 + b (alpha + 2 pi k).
    const double alpha = angle < 0 ? angle + 2 * kPi : angle;
    const double k = std::round((r - 0.1 - b * alpha) / (2 * kPi * b));
    const double rs = 0.1 + b * (alpha + 2 * kPi * k);
    EXPECT_LE(std::abs(r - rs), s.flatteningTolerance * 1.0001 + 1e-12);
    EXPECT_FALSE(&p != &s.primitives.front() && p.cornerAtStart);
  }
}

TEST(GrooveSceneStiff, InwardSpiralMatchesTheClosedForm) {
  json scene = stiffScene();
  const json spiral = {{"centre", {0.5, 0.5}}, {"startRadius", 0.4}, {"pitch", -0.01}, {"turns", 20}, {"startAngle", 45}};
  scene["grooves"].push_back({{"profile", "v"}, {"path", {{"spiral", spiral}}}});
  const Result<GrooveScene> r = parseGrooveScene(scene.dump(), "inward.json");
  ASSERT_TRUE(r.isOk()) << r.status().describe();
  double length = 0;
  for (const Primitive& p : r->primitives) length += p.length;
  const double exact = spiralLength(0.2, 0.01, 20);
  EXPECT_NEAR(length, exact, 1e-6 * exact);
  const Vec2 end = r->primitives.back().b;
  EXPECT_NEAR(std::hypot(end.u - 0.5, end.v - 0.5), 0.2, 1e-12);
  for (int i = 0; i <= 20000; ++i) {
    const double th = 2 * kPi * 20 * i / 20000.0, rr = 0.4 - 0.01 * th / (2 * kPi), a = th + kPi / 4;
    ASSERT_LE(distanceToArcChain(*r, {0.5 + rr * std::cos(a), 0.5 + rr * std::sin(a)}), r->flatteningTolerance * 1.0001) << i;
  }
}

TEST(GrooveSceneStiff, LargeRunningBondAndRepeatedGenerators) {
  json scene = stiffScene();
  const json tiles = {{"tiles", {{"origin", {0, 0}}, {"tileSize", {0.01, 0.005}}, {"count", {100, 200}}, {"bond", "running"}, {"profile", "v"}}}};
  scene["generators"] = json::array({tiles, tiles});
  const Result<GrooveScene> r = parseGrooveScene(scene.dump(), "tiles.json");
  ASSERT_TRUE(r.isOk()) << r.status().describe();
  // 201 horizontal lines, 2 borders, 100 rows of 99 and 100 rows of 100 joints; the copy merged.
  EXPECT_EQ(r->grooves.size(), 201u + 2u + 100u * 99u + 100u * 100u);
  EXPECT_EQ(r->warnings.size(), r->grooves.size());
  for (const Groove& g : r->grooves) EXPECT_EQ(g.primitiveCount, 1u);
}

}  // namespace
}  // namespace bake::grooves
