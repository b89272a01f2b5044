// Stiff cases of the stroke pipeline (validate, then package, then read back): hairpin and zigzag
// paths where the Catmull-Rom curve overshoots its control points most, radii that swing from a
// thousandth to the full width within a stroke and go to zero-like values at a tip, and a tree as wide
// as the generators allow in a small budget. What must hold: validation accepts them unchanged, every
// stored point is within the format's stated bound, the culling sphere holds the interpolated tube
// (the runtime culls by it: a sphere too small drops visible strokes), and nothing is NaN.
#include <cmath>

#include <gtest/gtest.h>

#include "bake/io/glb.h"
#include "bake/paintstrokes/generators.h"
#include "paintstrokes/input/validate.h"
#include "paintstrokes/package/package.h"

namespace bake::paintstrokes {
namespace {

Stroke strokeThrough(const std::vector<Vec3d>& positions, const std::vector<double>& radii) {
  Stroke s;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    StrokePoint p;
    p.position = positions[i];
    p.radius = radii[i];
    s.points.push_back(p);
  }
  return s;
}

// Uniform Catmull-Rom between p1 and p2 with the runtime's reflected neighbours beyond the ends.
double splineAt(const std::vector<StrokePoint>& pts, std::size_t segment, double u, double (*get)(const StrokePoint&)) {
  const long n = long(pts.size());
  auto at = [&](long j) {
    if (j < 0) return 2 * get(pts[0]) - get(pts[1]);
    if (j >= n) return 2 * get(pts[std::size_t(n - 1)]) - get(pts[std::size_t(n - 2)]);
    return get(pts[std::size_t(j)]);
  };
  const long k = long(segment);
  const double p0 = at(k - 1), p1 = at(k), p2 = at(k + 1), p3 = at(k + 2);
  return 0.5 * (2 * p1 + (p2 - p0) * u + (2 * p0 - 5 * p1 + 4 * p2 - p3) * u * u + (3 * p1 - p0 - 3 * p2 + p3) * u * u * u);
}

PaintstrokePackage roundTrip(const StrokeSet& set) {
  Result<glb::Package> built = buildPaintstrokePackage(set, {}, {}, nullptr, nullptr);
  EXPECT_TRUE(built.isOk()) << built.status().describe();
  Result<PaintstrokePackage> read = decodePaintstrokePackage(glb::decode(glb::encode(built.value()).value()).value(), "stiff.glb");
  EXPECT_TRUE(read.isOk()) << read.status().describe();
  return read.value();
}

TEST(PaintstrokesStiff, HairpinsAndZigzagsStayInsideTheirCullingSpheres) {
  StrokeSet set;
  set.styles.emplace_back();
  // A hairpin: out and back 1e-3 apart, so the curve overshoots the turn.
  set.strokes.push_back(strokeThrough({{0, 0, 0}, {1, 0, 0}, {1, 1e-3, 0}, {0, 1e-3, 0}}, {0.01, 0.01, 0.01, 0.01}));
  // A zigzag with 170-degree turns and a radius that swings over three decades.
  std::vector<Vec3d> zig;
  std::vector<double> radii;
  for (int i = 0; i < 12; ++i) {
    zig.push_back({i * 0.05, (i % 2) * 1.0, (i % 3) * 0.2});
    radii.push_back(i % 2 ? 0.2 : 2e-4);
  }
  set.strokes.push_back(strokeThrough(zig, radii));
  // Two points only (both ends reflected) and a tip radius a millionth of the root's.
  set.strokes.push_back(strokeThrough({{5, 5, 5}, {5, 7, 5}}, {0.5, 5e-7}));
  Diagnostics quiet("test", true);
  Result<ValidationCounts> counts = validateStrokes(set, "stiff.json", quiet);
  ASSERT_TRUE(counts.isOk()) << counts.status().describe();
  EXPECT_EQ(counts->droppedPoints, 0u);

  const PaintstrokePackage p = roundTrip(set);
  for (std::size_t s = 0; s < set.strokes.size(); ++s) {
    const auto& pts = set.strokes[s].points;
    const float* sphere = p.strokes[s].sphere;
    for (int k = 0; k < 4; ++k) ASSERT_TRUE(std::isfinite(sphere[k])) << s;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const std::array<double, 4> back = p.positionRadius(s, i);
      for (int k = 0; k < 3; ++k)
        EXPECT_LE(std::abs(back[k] - pts[i].position[k]), p.strokes[s].step[k] / 2.0 * (1 + 1e-9)) << s << " " << i;
    }
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      for (int j = 0; j <= 400; ++j) {
        const double u = j / 400.0;
        const double x = splineAt(pts, i, u, [](const StrokePoint& q) { return q.position[0]; });
        const double y = splineAt(pts, i, u, [](const StrokePoint& q) { return q.position[1]; });
        const double z = splineAt(pts, i, u, [](const StrokePoint& q) { return q.position[2]; });
        const double r = splineAt(pts, i, u, [](const StrokePoint& q) { return q.radius; });
        const double d = std::sqrt((x - sphere[0]) * (x - sphere[0]) + (y - sphere[1]) * (y - sphere[1]) +
                                   (z - sphere[2]) * (z - sphere[2]));
        EXPECT_LE(d + std::abs(r), double(sphere[3])) << "stroke " << s << " segment " << i << " u " << u;
      }
    }
  }
}

TEST(PaintstrokesStiff, AWideTreeIsFiniteValidAndPacks) {
  // 16 children per branch over 4 levels: 1 + 16 + 256 + 4096 + 65536 = 69,905 branches, the
  // thinnest 0.62^4 of the trunk.
  TreeSettings settings;
  settings.depth = 4;
  settings.branching = 16;
  settings.pointsPerStroke = 3;
  StrokeSet set = growTree(settings);
  ASSERT_EQ(set.strokes.size(), 69905u);
  Diagnostics quiet("test", true);
  Result<ValidationCounts> counts = validateStrokes(set, "tree", quiet);
  ASSERT_TRUE(counts.isOk()) << counts.status().describe();
  const PaintstrokePackage p = roundTrip(set);
  ASSERT_EQ(p.strokes.size(), set.strokes.size());
  for (std::size_t s = 0; s < p.strokes.size(); ++s) {
    for (int k = 0; k < 4; ++k) ASSERT_TRUE(std::isfinite(p.strokes[s].sphere[k])) << s;
    ASSERT_GT(p.positionRadius(s, set.strokes[s].points.size() - 1)[3], 0.0) << s;
  }
}

}  // namespace
}  // namespace bake::paintstrokes
