// The groove grid (libbake/grooves/bake/grid.h; seed 000 §4.1, §4.2): automatic cell size, conservative
// and tight cell lists against an independent region test, CSR invariants, determinism across thread
// counts, wrap-around, box queries, and the special-case records.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grooves/bake/grid.h"
#include "grooves/groove_support.h"
#include "grooves/input/scene.h"

namespace bake::grooves {
namespace {

using nlohmann::json;

json sceneWith(const json& grooves, const std::string& wrap = "none", double width = 0.01) {
  json scene = json::parse(R"({
    "version": 1, "domain": {"size": [1, 1]},
    "profiles": {"v": {"points": [[-0.01, 0], [0, -0.005], [0.01, 0]]}},
    "materials": {"m": {}}, "base": "m"
  })");
  scene["wrap"] = wrap;
  scene["profiles"]["v"]["points"] = json::array({{-width, 0}, {0, -width / 2}, {width, 0}});
  // A single groove written as {line(...)} arrives as that object, not as a list of one.
  scene["grooves"] = grooves.is_array() ? grooves : json::array({grooves});
  return scene;
}

json groove(const json& path) { return {{"profile", "v"}, {"path", path}}; }
json line(double u0, double v0, double u1, double v1) { return groove({{"line", {{u0, v0}, {u1, v1}}}}); }

GrooveScene parseOk(const json& scene) {
  Result<GrooveScene> r = parseGrooveScene(scene.dump(), "scene.json");
  EXPECT_TRUE(r.isOk()) << r.status().describe();
  return r.isOk() ? r.value() : GrooveScene{};
}

double dot2(Vec2 a, Vec2 b) { return a.u * b.u + a.v * b.v; }
Vec2 minus(Vec2 a, Vec2 b) { return {a.u - b.u, a.v - b.v}; }

// The spec's region test, written out independently (formats/groove-scene.md, "Region").
bool inRegion(const GrooveScene& scene, std::size_t index, Vec2 x) {
  const Primitive& p = scene.primitives[index];
  const PrimitiveJoints joints = jointsOf(scene, index);
  if (dot2(minus(x, joints.start.point), joints.start.normal) < 0) return false;
  if (dot2(minus(x, joints.end.point), joints.end.normal) < 0) return false;
  double b = 0;
  if (p.kind == Primitive::Kind::Segment) {
    const Vec2 t = p.tangentAt(0), d = minus(x, p.a);
    b = t.u * d.v - t.v * d.u;
  } else {
    const double r = std::hypot(x.u - p.centre.u, x.v - p.centre.v);
    b = p.sweep > 0 ? p.radius - r : r - p.radius;
  }
  return std::abs(b) <= scene.grooves[p.groove].wmax;
}

std::vector<std::uint32_t> cellRefs(const GrooveGrid& grid, std::uint32_t cell) {
  return {grid.primitiveRefs.begin() + grid.cellStart[cell], grid.primitiveRefs.begin() + grid.cellStart[cell + 1]};
}

std::uint32_t cellAt(const GrooveGrid& grid, Vec2 x) {
  auto wrapIndex = [](double t, std::uint32_t n) {
    long long i = static_cast<long long>(std::floor(t));
    return static_cast<std::uint32_t>(((i % (long long)n) + n) % n);
  };
  return wrapIndex((x.v - grid.origin.v) / grid.cellSize.v, grid.cells[1]) * grid.cells[0] +
         wrapIndex((x.u - grid.origin.u) / grid.cellSize.u, grid.cells[0]);
}

// Every point of every region lies in a cell listing its primitive (sampled densely).
void expectConservative(const GrooveScene& scene, const GrooveGrid& grid, int samples, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  int inside = 0;
  for (int k = 0; k < samples; ++k) {
    const Vec2 x{unit(random) * scene.domain[0], unit(random) * scene.domain[1]};
    const std::vector<std::uint32_t> refs = cellRefs(grid, cellAt(grid, x));
    for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
      // In a repeating scene a region also covers x through its copies one period away.
      bool covered = false;
      const int periods = scene.wrapRepeat ? 1 : 0;
      for (int du = -periods; du <= periods; ++du)
        for (int dv = -periods; dv <= periods; ++dv)
          covered = covered || inRegion(scene, i, {x.u + du * scene.domain[0], x.v + dv * scene.domain[1]});
      if (!covered) continue;
      ++inside;
      EXPECT_TRUE(std::binary_search(refs.begin(), refs.end(), std::uint32_t(i)))
          << "primitive " << i << " missing at (" << x.u << ", " << x.v << ")";
    }
  }
  EXPECT_GT(inside, samples / 100);  // the samples did hit regions
}

void expectCsrValid(const GrooveGrid& grid, std::size_t primitives) {
  ASSERT_EQ(grid.cellStart.size(), grid.cellCount() + 1);
  ASSERT_EQ(grid.recordStart.size(), grid.cellCount() + 1);
  EXPECT_EQ(grid.cellStart.front(), 0u);
  EXPECT_EQ(grid.cellStart.back(), grid.primitiveRefs.size());
  EXPECT_EQ(grid.recordStart.back(), grid.recordRefs.size());
  for (std::uint64_t c = 0; c < grid.cellCount(); ++c) {
    ASSERT_LE(grid.cellStart[c], grid.cellStart[c + 1]);
    for (std::uint32_t k = grid.cellStart[c]; k + 1 < grid.cellStart[c + 1]; ++k)
      EXPECT_LT(grid.primitiveRefs[k], grid.primitiveRefs[k + 1]);
    for (std::uint32_t k = grid.recordStart[c]; k + 1 < grid.recordStart[c + 1]; ++k)
      EXPECT_LT(grid.recordRefs[k], grid.recordRefs[k + 1]);
  }
  for (const std::uint32_t ref : grid.primitiveRefs) EXPECT_LT(ref, primitives);
  for (const std::uint32_t ref : grid.recordRefs) EXPECT_LT(ref, grid.records.size());
}

std::size_t countKind(const GrooveGrid& grid, SpecialRecord::Kind kind) {
  return std::count_if(grid.records.begin(), grid.records.end(), [&](const SpecialRecord& r) { return r.kind == kind; });
}

TEST(GrooveGrid, AutomaticCellSizeIsTheMeanGrooveWidth) {
  const GrooveScene scene = parseOk(sceneWith({line(0.1, 0.1, 0.9, 0.1)}));
  const GrooveGrid grid = buildGridOk(scene);
  EXPECT_EQ(grid.cells[0], 50u);  // 2 wmax = 0.02 over a unit domain
  EXPECT_EQ(grid.cells[1], 50u);
  EXPECT_DOUBLE_EQ(grid.cellSize.u, 1.0 / 50);
  expectCsrValid(grid, scene.primitives.size());
}

TEST(GrooveGrid, CellsAreAWholeNumberPerAxisAndGrowToFitMaxCells) {
  json s = sceneWith({line(0.1, 0.1, 0.9, 0.1)});
  s["domain"]["size"] = {1.0, 0.31};
  const GrooveScene scene = parseOk(s);
  GrooveGrid grid = buildGridOk(scene);
  EXPECT_EQ(grid.cells[0], 50u);
  EXPECT_EQ(grid.cells[1], 16u);  // round(0.31 / 0.02)
  EXPECT_DOUBLE_EQ(grid.cellSize.v * grid.cells[1], 0.31);
  GridSettings small;
  small.maxCells = 100;
  grid = buildGridOk(scene, small);
  EXPECT_LE(grid.cellCount(), 100u);
  EXPECT_GE(grid.cellCount(), 50u);  // grown in small steps, not to a single cell
  EXPECT_NEAR(grid.cellSize.u * grid.cells[0], 1.0, 1e-12);
}

TEST(GrooveGrid, ExplicitCellSizeAndItsErrors) {
  const GrooveScene scene = parseOk(sceneWith({line(0.1, 0.1, 0.9, 0.1)}));
  GridSettings settings;
  settings.cellSize = 0.1;
  EXPECT_EQ(buildGridOk(scene, settings).cells[0], 10u);
  settings.cellSize = 1e-4;  // 10^8 cells
  Result<GrooveGrid> r = buildGrooveGrid(scene, settings);
  ASSERT_FALSE(r.isOk());
  EXPECT_EQ(r.status().code(), ExitCode::InvalidInput);
  settings.cellSize = -1;
  EXPECT_FALSE(buildGrooveGrid(scene, settings).isOk());
  settings.cellSize = NAN;
  EXPECT_FALSE(buildGrooveGrid(scene, settings).isOk());
}

TEST(GrooveGrid, ConservativeForLinesArcsCornersAndCurves) {
  json grooves = json::array();
  grooves.push_back(line(0.05, 0.05, 0.95, 0.83));
  grooves.push_back(groove({{"polyline", {{0.1, 0.9}, {0.4, 0.6}, {0.45, 0.9}, {0.5, 0.62}}}}));  // sharp corners
  grooves.push_back(groove({{"polyline", {{0.6, 0.05}, {0.9, 0.1}, {0.6, 0.15}, {0.9, 0.2}}}}));  // turns of 161 degrees
  grooves.push_back(groove({{"arc", {{"centre", {0.6, 0.4}}, {"radius", 0.2}, {"start", -30}, {"end", 200}}}}));
  grooves.push_back(groove({{"cubic", {{0.1, 0.1}, {0.5, 0.5}, {0.2, 0.9}, {0.9, 0.2}}}}));
  grooves.push_back(groove({{"svg", "M 0.7 0.9 L 0.9 0.9 A 0.05 0.05 0 0 0 0.9 0.8 L 0.7 0.75"}}));
  const GrooveScene scene = parseOk(sceneWith(grooves));
  const GrooveGrid grid = buildGridOk(scene);
  expectCsrValid(grid, scene.primitives.size());
  expectConservative(scene, grid, 20000, 7);
}

TEST(GrooveGrid, ADiagonalLineListsOnlyTheCellsAlongIt) {
  const GrooveScene scene = parseOk(sceneWith({line(0.001, 0.001, 0.999, 0.999)}));
  const GrooveGrid grid = buildGridOk(scene);
  ASSERT_EQ(grid.cells[0], 50u);
  // The band is 0.02 wide: about 50 diagonal cells plus two neighbours each; its box holds 2500.
  EXPECT_LE(grid.primitiveRefs.size(), 50u * 5);
  EXPECT_GE(grid.primitiveRefs.size(), 50u);
  expectConservative(scene, grid, 20000, 11);
}

TEST(GrooveGrid, IdenticalForAnyThreadCount) {
  json grooves = json::array();
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.05, 0.95);
  for (int k = 0; k < 600; ++k) grooves.push_back(line(unit(random), unit(random), unit(random), unit(random)));
  const GrooveScene scene = parseOk(sceneWith(grooves, "none", 0.002));
  GridSettings settings;
  settings.threads = 1;
  const GrooveGrid one = buildGridOk(scene, settings);
  for (const int threads : {2, 4}) {
    settings.threads = threads;
    const GrooveGrid other = buildGridOk(scene, settings);
    EXPECT_EQ(one.cellStart, other.cellStart);
    EXPECT_EQ(one.primitiveRefs, other.primitiveRefs);
    EXPECT_EQ(one.recordStart, other.recordStart);
    EXPECT_EQ(one.recordRefs, other.recordRefs);
    ASSERT_EQ(one.records.size(), other.records.size());
    for (std::size_t r = 0; r < one.records.size(); ++r) {
      EXPECT_EQ(one.records[r].primitive[0], other.records[r].primitive[0]);
      EXPECT_EQ(one.records[r].primitive[1], other.records[r].primitive[1]);
      EXPECT_EQ(one.records[r].point.u, other.records[r].point.u);
      EXPECT_EQ(one.records[r].lower.v, other.records[r].lower.v);
    }
  }
  EXPECT_GT(one.records.size(), 1000u);
  expectCsrValid(one, scene.primitives.size());
}

TEST(GrooveGrid, PerpendicularCrossingGivesOneIntersectionRecord) {
  const GrooveScene scene = parseOk(sceneWith({line(0.2, 0.5, 0.8, 0.5), line(0.4, 0.2, 0.4, 0.8)}));
  const GrooveGrid grid = buildGridOk(scene);
  ASSERT_EQ(countKind(grid, SpecialRecord::Kind::Intersection), 1u);
  EXPECT_EQ(countKind(grid, SpecialRecord::Kind::End), 4u);
  EXPECT_EQ(countKind(grid, SpecialRecord::Kind::Corner), 0u);
  const auto it = std::find_if(grid.records.begin(), grid.records.end(),
                               [](const SpecialRecord& r) { return r.kind == SpecialRecord::Kind::Intersection; });
  EXPECT_NEAR(it->point.u, 0.4, 1e-12);
  EXPECT_NEAR(it->point.v, 0.5, 1e-12);
  // The overlap of two perpendicular bands of half-width 0.01 is the square ± 0.01 around the crossing.
  EXPECT_NEAR(it->lower.u, 0.39, 1e-6);
  EXPECT_NEAR(it->upper.u, 0.41, 1e-6);
  EXPECT_NEAR(it->lower.v, 0.49, 1e-6);
  EXPECT_NEAR(it->upper.v, 0.51, 1e-6);
  EXPECT_EQ(it->primitive[0], 0u);
  EXPECT_EQ(it->primitive[1], 1u);
  // Listed in the cells its box meets, found by a box query there.
  std::vector<std::uint32_t> found;
  grid.recordsInBox({0.399, 0.499}, {0.401, 0.501}, found);
  const auto index = std::uint32_t(it - grid.records.begin());
  EXPECT_TRUE(std::find(found.begin(), found.end(), index) != found.end());
  grid.recordsInBox({0.6, 0.6}, {0.7, 0.7}, found);
  EXPECT_TRUE(found.empty());
}

TEST(GrooveGrid, EndRecordsHoldTheCap) {
  const GrooveScene scene = parseOk(sceneWith({line(0.2, 0.5, 0.8, 0.5)}));
  const GrooveGrid grid = buildGridOk(scene);
  ASSERT_EQ(grid.records.size(), 2u);
  const SpecialRecord& start = grid.records[0];
  EXPECT_EQ(start.kind, SpecialRecord::Kind::End);
  EXPECT_NEAR(start.point.u, 0.2, 1e-15);
  EXPECT_LE(start.lower.u, 0.19);
  EXPECT_GE(start.upper.v, 0.51);
  EXPECT_NEAR(grid.records[1].point.u, 0.8, 1e-15);
}

TEST(GrooveGrid, CornersOnlyAtPolylineVerticesNotInsideCurves) {
  const GrooveScene polyline = parseOk(sceneWith({groove({{"polyline", {{0.2, 0.2}, {0.5, 0.2}, {0.5, 0.5}}}})}));
  GrooveGrid grid = buildGridOk(polyline);
  ASSERT_EQ(countKind(grid, SpecialRecord::Kind::Corner), 1u);
  const auto corner = std::find_if(grid.records.begin(), grid.records.end(),
                                   [](const SpecialRecord& r) { return r.kind == SpecialRecord::Kind::Corner; });
  EXPECT_NEAR(corner->point.u, 0.5, 1e-15);
  EXPECT_NEAR(corner->point.v, 0.2, 1e-15);
  // A right angle: the mitre reaches wmax / cos 45° = 0.01414 from the corner.
  EXPECT_NEAR(corner->upper.u - corner->point.u, 0.01 * std::sqrt(2.0), 1e-6);
  EXPECT_EQ(countKind(grid, SpecialRecord::Kind::Intersection), 0u);

  const GrooveScene curve = parseOk(sceneWith({groove({{"cubic", {{0.1, 0.1}, {0.5, 0.9}, {0.6, 0.1}, {0.9, 0.8}}}})}));
  ASSERT_GT(curve.primitives.size(), 4u);
  grid = buildGridOk(curve);
  EXPECT_EQ(countKind(grid, SpecialRecord::Kind::Corner), 0u);
  EXPECT_EQ(countKind(grid, SpecialRecord::Kind::Intersection), 0u);
  EXPECT_EQ(countKind(grid, SpecialRecord::Kind::End), 2u);
}

TEST(GrooveGrid, ParallelBandsAndConcentricArcsAreNotSpecial) {
  // Two overlapping parallel lines (0.005 apart, bands 0.02 wide) and two concentric overlapping arcs.
  json grooves = {line(0.1, 0.3, 0.9, 0.3), line(0.1, 0.305, 0.9, 0.305)};
  grooves.push_back(groove({{"arc", {{"centre", {0.5, 0.7}}, {"radius", 0.15}, {"start", 0}, {"end", 80}}}}));
  grooves.push_back(groove({{"arc", {{"centre", {0.5, 0.7}}, {"radius", 0.16}, {"start", 10}, {"end", 70}}}}));
  const GrooveGrid grid = buildGridOk(parseOk(sceneWith(grooves)));
  EXPECT_EQ(countKind(grid, SpecialRecord::Kind::Intersection), 0u);
  EXPECT_EQ(countKind(grid, SpecialRecord::Kind::End), 8u);
}

TEST(GrooveGrid, ArcCrossingALineIsAnIntersectionAtTheCrossing) {
  json grooves = json::array({line(0.1, 0.5, 0.9, 0.5)});
  grooves.push_back(groove({{"arc", {{"centre", {0.5, 0.3}}, {"radius", 0.25}, {"start", 20}, {"end", 80}}}}));
  const GrooveScene scene = parseOk(sceneWith(grooves));
  const GrooveGrid grid = buildGridOk(scene);
  ASSERT_EQ(countKind(grid, SpecialRecord::Kind::Intersection), 1u);
  const auto it = std::find_if(grid.records.begin(), grid.records.end(),
                               [](const SpecialRecord& r) { return r.kind == SpecialRecord::Kind::Intersection; });
  // The circle meets v = 0.5 at u = 0.5 + sqrt(0.25^2 - 0.2^2) = 0.65.
  EXPECT_NEAR(it->point.u, 0.65, 1e-12);
  EXPECT_NEAR(it->point.v, 0.5, 1e-12);
  EXPECT_LE(it->lower.u, 0.64);
  EXPECT_GE(it->upper.u, 0.66);
}

TEST(GrooveGrid, IntersectionBoxesHoldEveryPointOfTheOverlap) {
  // Random lines and arcs: every sampled point inside two regions of a special pair lies in a box of
  // an intersection record of that pair.
  json grooves = json::array();
  std::mt19937 random(9);
  std::uniform_real_distribution<double> unit(0.2, 0.8);
  for (int k = 0; k < 12; ++k) grooves.push_back(line(unit(random), unit(random), unit(random), unit(random)));
  for (int k = 0; k < 6; ++k)
    grooves.push_back(groove({{"arc", {{"centre", {unit(random), unit(random)}}, {"radius", 0.05 + 0.2 * unit(random)},
                                        {"start", 360 * unit(random)}, {"end", 360 * unit(random)}}}}));
  const GrooveScene scene = parseOk(sceneWith(grooves, "none", 0.02));
  const GrooveGrid grid = buildGridOk(scene);
  ASSERT_GT(gridStats(grid).intersections, 10u);
  std::uniform_real_distribution<double> anywhere(0, 1);
  int checked = 0;
  for (int k = 0; k < 40000; ++k) {
    const Vec2 x{anywhere(random), anywhere(random)};
    std::vector<std::uint32_t> in;
    for (std::uint32_t i = 0; i < scene.primitives.size(); ++i)
      if (inRegion(scene, i, x)) in.push_back(i);
    for (std::size_t a = 0; a < in.size(); ++a)
      for (std::size_t b = a + 1; b < in.size(); ++b) {
        bool paired = false, boxed = false;
        for (const SpecialRecord& r : grid.records) {
          if (r.kind != SpecialRecord::Kind::Intersection || r.primitive[0] != in[a] || r.primitive[1] != in[b]) continue;
          paired = true;
          boxed = boxed || (x.u >= r.lower.u && x.u <= r.upper.u && x.v >= r.lower.v && x.v <= r.upper.v);
        }
        if (!paired) continue;  // adjacent pieces of one groove, or parallel bands
        ++checked;
        EXPECT_TRUE(boxed) << in[a] << " x " << in[b] << " at (" << x.u << ", " << x.v << ")";
      }
  }
  EXPECT_GT(checked, 100);
}

TEST(GrooveGrid, SpiralTurnsThatOverlapAreIntersectionsButSmoothNeighboursAreNot) {
  // Pitch 0.015 < the band width 0.02: each turn overlaps the next; with pitch 0.05 none do.
  auto spiral = [](double pitch) {
    return groove({{"spiral", {{"centre", {0.5, 0.5}}, {"startRadius", 0.1}, {"pitch", pitch}, {"turns", 3}, {"startAngle", 0}}}});
  };
  const GrooveGrid overlapping = buildGridOk(parseOk(sceneWith({spiral(0.015)})));
  EXPECT_GT(gridStats(overlapping).intersections, 10u);
  const GrooveGrid apart = buildGridOk(parseOk(sceneWith({spiral(0.05)})));
  EXPECT_EQ(gridStats(apart).intersections, 0u);
  EXPECT_EQ(gridStats(apart).corners, 0u);
  // Pitch 0.025 leaves gaps of 0.005 between the bands, less than the bulge of the arcs' hull polygons
  // over their chords: the turns are still apart (a record's grooves).
  const GrooveGrid close = buildGridOk(parseOk(sceneWith({spiral(0.025)})));
  EXPECT_EQ(gridStats(close).intersections, 0u);
}

TEST(GrooveGrid, RepeatingSceneWrapsBandsAndQueries) {
  // A line crossing the right border at v = 0.5: it continues at u = 0 in the wrapped copy.
  const GrooveScene scene = parseOk(sceneWith({line(0.7, 0.5, 1.2, 0.5), line(0.1, 0.3, 0.1, 0.7)}, "repeat"));
  const GrooveGrid grid = buildGridOk(scene);
  expectCsrValid(grid, scene.primitives.size());
  EXPECT_TRUE(grid.wrapRepeat);
  std::vector<std::uint32_t> found;
  grid.primitivesInBox({0.05, 0.49}, {0.06, 0.51}, found);  // wrapped part of line 0
  EXPECT_EQ(found, std::vector<std::uint32_t>({0}));
  grid.primitivesInBox({1.08, 1.28}, {1.12, 1.32}, found);  // a box in the next period
  EXPECT_EQ(found, std::vector<std::uint32_t>({1}));
  grid.primitivesInBox({-0.93, 0.49}, {0.12, 0.51}, found);  // straddles the left border
  EXPECT_EQ(found, std::vector<std::uint32_t>({0, 1}));
  // The wrapped line crosses line 1 at (0.1, 0.5) = (1.1, 0.5) in the first line's frame.
  ASSERT_EQ(countKind(grid, SpecialRecord::Kind::Intersection), 1u);
  const auto it = std::find_if(grid.records.begin(), grid.records.end(),
                               [](const SpecialRecord& r) { return r.kind == SpecialRecord::Kind::Intersection; });
  EXPECT_NEAR(std::fmod(it->point.u, 1.0), 0.1, 1e-12);
  EXPECT_NEAR(it->point.v, 0.5, 1e-12);
  grid.recordsInBox({0.09, 0.49}, {0.11, 0.51}, found);
  EXPECT_TRUE(std::find(found.begin(), found.end(), std::uint32_t(it - grid.records.begin())) != found.end());
  expectConservative(scene, grid, 20000, 5);
}

TEST(GrooveGrid, ConservativeAcrossTheBordersOfARepeatingDomain) {
  json grooves = json::array();
  grooves.push_back(groove({{"arc", {{"centre", {0.98, 0.97}}, {"radius", 0.12}, {"start", 10}, {"end", 280}}}}));
  grooves.push_back(groove({{"polyline", {{0.8, 0.1}, {1.15, -0.05}, {1.1, 0.3}, {0.9, 0.25}}}}));
  grooves.push_back(groove({{"quadratic", {{-0.2, 0.5}, {0.1, 0.9}, {0.3, 1.2}}}}));
  grooves.push_back(line(0.3, -0.4, 0.6, 1.6));
  const GrooveScene scene = parseOk(sceneWith(grooves, "repeat"));
  const GrooveGrid grid = buildGridOk(scene);
  expectCsrValid(grid, scene.primitives.size());
  expectConservative(scene, grid, 30000, 13);
}

TEST(GrooveGrid, BoxQueriesAreAscendingAndDeduplicated) {
  const GrooveScene scene = parseOk(sceneWith({line(0.1, 0.1, 0.9, 0.9), line(0.1, 0.9, 0.9, 0.1), line(0.5, 0.05, 0.5, 0.95)}));
  const GrooveGrid grid = buildGridOk(scene);
  std::vector<std::uint32_t> found;
  grid.primitivesInBox({0.3, 0.3}, {0.7, 0.7}, found);
  EXPECT_EQ(found, std::vector<std::uint32_t>({0, 1, 2}));
  grid.primitivesInBox({0.02, 0.45}, {0.05, 0.55}, found);
  EXPECT_TRUE(found.empty());
  grid.primitivesInBox({-5, -5}, {-4, -4}, found);  // outside a non-repeating domain
  EXPECT_TRUE(found.empty());
  grid.recordsInBox({0.45, 0.45}, {0.55, 0.55}, found);
  EXPECT_EQ(found.size(), 3u);  // the three pairwise crossings at the centre
  EXPECT_TRUE(std::is_sorted(found.begin(), found.end()));
}

// Many boxes at once give the union of what each box gives, ascending and once each, both below and
// above the size past which repeats are stamped out before sorting (600 long parallel lines, each
// listed in every cell it crosses).
TEST(GrooveGrid, SeveralBoxesGiveTheUnionOnceEachAscending) {
  json lines = json::array();
  for (int i = 0; i < 600; ++i) {
    const double v = 0.05 + 0.9 * i / 599.0;
    lines.push_back(line(0.02, v, 0.98, v + 0.01 * (i % 3)));
  }
  const GrooveScene scene = parseOk(sceneWith(lines, "none", 0.0005));
  const GrooveGrid grid = buildGridOk(scene);
  const std::vector<GridBox> boxSets[2] = {{{{0.1, 0.1}, {0.12, 0.2}}, {{0.11, 0.15}, {0.3, 0.16}}},
                                           {{{0.05, 0.0}, {0.06, 1.0}}, {{0.9, 0.0}, {0.95, 1.0}}, {{0.0, 0.5}, {1.0, 0.52}}}};
  for (const std::vector<GridBox>& boxes : boxSets) {
    std::vector<std::uint32_t> expected, one, found;
    for (const GridBox& b : boxes) {
      grid.primitivesInBox(b.lower, b.upper, one);
      expected.insert(expected.end(), one.begin(), one.end());
    }
    std::sort(expected.begin(), expected.end());
    expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
    grid.primitivesInBoxes(boxes.data(), int(boxes.size()), found);
    EXPECT_EQ(found, expected);
    EXPECT_FALSE(found.empty());
  }
  // The tall boxes cross every line: all 600 (the stamped path), and again (the stamps of the
  // previous gather must not hide anything).
  std::vector<std::uint32_t> all;
  grid.primitivesInBoxes(boxSets[1].data(), 2, all);
  EXPECT_EQ(all.size(), 600u);
  grid.primitivesInBoxes(boxSets[1].data(), 2, all);
  EXPECT_EQ(all.size(), 600u);
}

// The grid keeps every primitive's joint lines (the shading reads them instead of finding them per
// pixel): the very lines jointsOf gives, at open ends, mitres, G1 joints of curves and closed paths.
TEST(GrooveGrid, KeepsEveryPrimitivesJointLines) {
  json grooves = json::array();
  grooves.push_back(groove({{"polyline", {{0.1, 0.9}, {0.4, 0.6}, {0.45, 0.9}, {0.5, 0.62}}}}));
  grooves.push_back(groove({{"arc", {{"centre", {0.6, 0.4}}, {"radius", 0.2}, {"start", 0}, {"end", 360}}}}));
  grooves.push_back(groove({{"cubic", {{0.1, 0.1}, {0.5, 0.5}, {0.2, 0.9}, {0.9, 0.2}}}}));
  const GrooveScene scene = parseOk(sceneWith(grooves));
  const GrooveGrid grid = buildGridOk(scene);
  ASSERT_EQ(grid.joints.size(), scene.primitives.size());
  auto same = [](const JointLine& a, const JointLine& b) {
    return a.point.u == b.point.u && a.point.v == b.point.v && a.normal.u == b.normal.u &&
           a.normal.v == b.normal.v && a.openEnd == b.openEnd;
  };
  int openEnds = 0;
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const PrimitiveJoints expected = jointsOf(scene, i);
    EXPECT_TRUE(same(grid.joints[i].start, expected.start)) << "primitive " << i;
    EXPECT_TRUE(same(grid.joints[i].end, expected.end)) << "primitive " << i;
    openEnds += int(expected.start.openEnd) + int(expected.end.openEnd);
  }
  EXPECT_EQ(openEnds, 4);  // the polyline's and the cubic's ends; the circle is closed
}

TEST(GrooveGrid, StatsCountReferencesAndRecords) {
  const GrooveScene scene = parseOk(sceneWith({line(0.2, 0.5, 0.8, 0.5), line(0.4, 0.2, 0.4, 0.8)}));
  const GrooveGrid grid = buildGridOk(scene);
  const GridStats stats = gridStats(grid);
  EXPECT_DOUBLE_EQ(stats.meanRefsPerCell, double(grid.primitiveRefs.size()) / double(grid.cellCount()));
  EXPECT_EQ(stats.maxRefsPerCell, 2u);  // only the crossing cells hold both
  EXPECT_EQ(stats.intersections, 1u);
  EXPECT_EQ(stats.ends, 4u);
  EXPECT_EQ(stats.corners, 0u);
  EXPECT_GT(stats.emptyCells, grid.cellCount() / 2);
}

}  // namespace
}  // namespace bake::grooves
