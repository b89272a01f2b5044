// Stiff cases of the groove grid (seed 000 §4.1-§4.2): huge and thin domains, coordinates far from
// the origin, near-reversal corners, paths outside or many times around the domain, a point where
// hundreds of grooves cross, grazing crossings, arcs whose inner radius vanishes. Each must give a
// finite, valid and conservative grid, or a clear error, never a hang or garbage.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grooves/bake/grid.h"
#include "grooves/groove_support.h"
#include "grooves/input/scene.h"

namespace bake::grooves {
namespace {

using nlohmann::json;

json stiffScene(double U, double V, double width, const std::string& wrap = "none") {
  json scene = {{"version", 1},
                {"domain", {{"size", {U, V}}}},
                {"wrap", wrap},
                {"profiles", {{"v", {{"points", {{-width, 0}, {0, -width / 2}, {width, 0}}}}}}},
                {"materials", {{"m", json::object()}}},
                {"base", "m"},
                {"grooves", json::array()}};
  return scene;
}

void addPath(json& scene, const json& path) { scene["grooves"].push_back({{"profile", "v"}, {"path", path}}); }

GrooveScene parseOk(const json& scene) {
  Result<GrooveScene> r = parseGrooveScene(scene.dump(), "stiff.json");
  EXPECT_TRUE(r.isOk()) << r.status().describe();
  return r.isOk() ? r.value() : GrooveScene{};
}

void expectFiniteRecords(const GrooveGrid& grid) {
  for (const SpecialRecord& r : grid.records) {
    EXPECT_TRUE(std::isfinite(r.point.u) && std::isfinite(r.point.v));
    EXPECT_TRUE(std::isfinite(r.lower.u) && std::isfinite(r.upper.v));
    EXPECT_LE(r.lower.u, r.upper.u);
    EXPECT_LE(r.lower.v, r.upper.v);
  }
  EXPECT_EQ(grid.cellStart.back(), grid.primitiveRefs.size());
  EXPECT_EQ(grid.recordStart.back(), grid.recordRefs.size());
}

bool lists(const GrooveGrid& grid, Vec2 x, std::uint32_t primitive) {
  std::vector<std::uint32_t> found;
  grid.primitivesInBox(x, x, found);
  return std::binary_search(found.begin(), found.end(), primitive);
}

TEST(GrooveGridStiff, HugeDomainWithTinyGroovesGrowsCellsToTheLimit) {
  json s = stiffScene(1e6, 1e6, 1e-3);
  addPath(s, {{"line", {{10, 10}, {9e5, 8e5}}}});
  GridSettings settings;
  settings.maxCells = 1u << 16;
  const GrooveGrid grid = buildGridOk(parseOk(s), settings);
  EXPECT_LE(grid.cellCount(), settings.maxCells);
  EXPECT_GE(grid.cellCount(), settings.maxCells / 2);
  EXPECT_NEAR(grid.cellSize.u * grid.cells[0], 1e6, 1e-6);
  // A point on the line, half way.
  const double u = 4.5e5, v = 10 + (u - 10) * (8e5 - 10) / (9e5 - 10);
  EXPECT_TRUE(lists(grid, {u, v}, 0));
  expectFiniteRecords(grid);
}

TEST(GrooveGridStiff, ThinDomainAndASingleCell) {
  json s = stiffScene(1000, 0.01, 0.001);
  addPath(s, {{"line", {{1, 0.005}, {999, 0.005}}}});
  GridSettings settings;
  settings.maxCells = 1000;
  GrooveGrid grid = buildGridOk(parseOk(s), settings);
  EXPECT_LE(grid.cellCount(), 1000u);
  EXPECT_EQ(grid.cells[1], 1u);
  settings.maxCells = 1;
  grid = buildGridOk(parseOk(s), settings);
  EXPECT_EQ(grid.cellCount(), 1u);
  EXPECT_EQ(grid.primitiveRefs, std::vector<std::uint32_t>({0}));
}

TEST(GrooveGridStiff, CoordinatesFarFromTheOrigin) {
  // A 1 mm pattern at 10^7 mm: cells of 0.02 hold the grooves, records are found.
  json s = stiffScene(1e7 + 1, 1e7 + 1, 0.01);
  addPath(s, {{"line", {{1e7 + 0.2, 1e7 + 0.5}, {1e7 + 0.8, 1e7 + 0.5}}}});
  addPath(s, {{"line", {{1e7 + 0.5, 1e7 + 0.2}, {1e7 + 0.5, 1e7 + 0.8}}}});
  GridSettings settings;
  settings.cellSize = 1e7 + 1;  // one cell: the test is about the records' arithmetic
  const GrooveGrid grid = buildGridOk(parseOk(s), settings);
  const auto n = std::count_if(grid.records.begin(), grid.records.end(),
                               [](const SpecialRecord& r) { return r.kind == SpecialRecord::Kind::Intersection; });
  ASSERT_EQ(n, 1);
  for (const SpecialRecord& r : grid.records)
    if (r.kind == SpecialRecord::Kind::Intersection) {
      EXPECT_NEAR(r.point.u, 1e7 + 0.5, 1e-8);
      EXPECT_NEAR(r.upper.u - r.lower.u, 0.02, 1e-6);
    }
  expectFiniteRecords(grid);
}

TEST(GrooveGridStiff, NearReversalCornerIsCappedAndFinite) {
  // The polyline turns by 179.9 degrees: the mitre reaches wmax tan(89.95 deg) ~ 11.5 beyond the corner,
  // more than the domain; the reach is capped, the grid and the corner record stay finite.
  json s = stiffScene(10, 10, 0.01);
  const double back = 0.1 * M_PI / 180;
  addPath(s, {{"polyline", {{2, 5}, {6, 5}, {6 - 4 * std::cos(back), 5 + 4 * std::sin(back)}}}});
  const GrooveScene scene = parseOk(s);
  const GrooveGrid grid = buildGridOk(scene);
  expectFiniteRecords(grid);
  const auto corner = std::find_if(grid.records.begin(), grid.records.end(),
                                   [](const SpecialRecord& r) { return r.kind == SpecialRecord::Kind::Corner; });
  ASSERT_NE(corner, grid.records.end());
  EXPECT_LE(corner->upper.u - corner->lower.u, 2 * (10 + 0.01) * (1 + 1e-6));
  EXPECT_GT(corner->upper.u - corner->lower.u, 2 * 5.0);  // it did reach far
  EXPECT_TRUE(lists(grid, {6.0, 5.0}, 0));
  EXPECT_TRUE(lists(grid, {6.0, 5.0}, 1));
}

TEST(GrooveGridStiff, PathsOutsideAndManyTimesAroundTheDomain) {
  json s = stiffScene(1, 1, 0.01);
  addPath(s, {{"line", {{5, 5}, {6, 5}}}});  // outside a non-repeating domain: listed nowhere
  GrooveGrid grid = buildGridOk(parseOk(s));
  EXPECT_TRUE(grid.primitiveRefs.empty());
  // Repeating: a line 5 periods long at v = 0.5 fills its row of cells, and nothing else.
  json r = stiffScene(1, 1, 0.01, "repeat");
  addPath(r, {{"line", {{-2, 0.5}, {3, 0.5}}}});
  grid = buildGridOk(parseOk(r));
  ASSERT_EQ(grid.cells[0], 50u);
  for (double u = 0.01; u < 1; u += 0.1) EXPECT_TRUE(lists(grid, {u, 0.5}, 0)) << u;
  EXPECT_FALSE(lists(grid, {0.5, 0.2}, 0));
  EXPECT_LE(grid.primitiveRefs.size(), 3u * 50);
  expectFiniteRecords(grid);
}

TEST(GrooveGridStiff, HundredsOfGroovesThroughOnePoint) {
  json s = stiffScene(2, 2, 0.005);
  const int lines = 120;
  for (int k = 0; k < lines; ++k) {
    const double a = M_PI * k / lines, c = 0.9 * std::cos(a), d = 0.9 * std::sin(a);
    addPath(s, {{"line", {{1 - c, 1 - d}, {1 + c, 1 + d}}}});
  }
  const GrooveGrid grid = buildGridOk(parseOk(s));
  const GridStats stats = gridStats(grid);
  EXPECT_EQ(stats.intersections, std::uint64_t(lines) * (lines - 1) / 2);  // every pair crosses at (1, 1)
  EXPECT_EQ(stats.ends, 2u * lines);
  EXPECT_EQ(stats.maxRefsPerCell, std::uint32_t(lines));
  std::vector<std::uint32_t> found;
  grid.recordsInBox({0.999, 0.999}, {1.001, 1.001}, found);
  EXPECT_EQ(found.size(), std::size_t(lines) * (lines - 1) / 2);
  expectFiniteRecords(grid);
}

TEST(GrooveGridStiff, GrazingCrossingHasALongButBoundedBox) {
  // Two lines crossing at 0.2 degrees (above the parallel threshold |sin| = 1e-3): the bands of
  // half-width 0.01 overlap over about 2 * 0.02 / sin(0.2 deg) ~ 11.5 along the lines (capped by their ends).
  json s = stiffScene(20, 20, 0.01);
  const double t = std::tan(0.2 * M_PI / 180);
  addPath(s, {{"line", {{1, 10}, {19, 10}}}});
  addPath(s, {{"line", {{1, 10 - 9 * t}, {19, 10 + 9 * t}}}});
  const GrooveGrid grid = buildGridOk(parseOk(s));
  const auto it = std::find_if(grid.records.begin(), grid.records.end(),
                               [](const SpecialRecord& r) { return r.kind == SpecialRecord::Kind::Intersection; });
  ASSERT_NE(it, grid.records.end());
  EXPECT_NEAR(it->point.u, 10, 1e-9);
  EXPECT_NEAR(it->point.v, 10, 1e-9);
  const double along = it->upper.u - it->lower.u;
  EXPECT_NEAR(along, 2 * 0.02 / std::sin(0.2 * M_PI / 180) / std::cos(0.1 * M_PI / 180), 0.05);
  EXPECT_LT(it->upper.v - it->lower.v, 0.05);
  // At 0.01 degrees they count as parallel: no record.
  json p = stiffScene(20, 20, 0.01);
  const double tp = std::tan(0.01 * M_PI / 180);
  addPath(p, {{"line", {{1, 10}, {19, 10}}}});
  addPath(p, {{"line", {{1, 10 - 9 * tp}, {19, 10 + 9 * tp}}}});
  EXPECT_EQ(gridStats(buildGridOk(parseOk(p))).intersections, 0u);
}

TEST(GrooveGridStiff, ArcWithRadiusEqualToTheHalfWidth) {
  // The inner edge of the band shrinks to the centre: the centre's cell lists the arc.
  json s = stiffScene(1, 1, 0.05);
  addPath(s, {{"arc", {{"centre", {0.5, 0.5}}, {"radius", 0.05}, {"start", 0}, {"end", 300}}}});
  const GrooveScene scene = parseOk(s);
  const GrooveGrid grid = buildGridOk(scene);
  std::vector<std::uint32_t> found;
  grid.primitivesInBox({0.5, 0.5}, {0.5, 0.5}, found);
  EXPECT_FALSE(found.empty());
  EXPECT_TRUE(lists(grid, {0.5 + 0.099, 0.5}, 0));  // the outer edge of the first piece
  expectFiniteRecords(grid);
}

}  // namespace
}  // namespace bake::grooves
