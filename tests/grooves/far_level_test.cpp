// The far level (grooves/bake/far_level.h): band areas against closed forms (parallel lines, repeated
// periods), its classes, its package round trip, and a footprint over whole bands shaded from it
// against the seed's method with every groove shaded.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "groove_support.h"
#include "grooves/bake/far_level.h"
#include "grooves/oracle/shade.h"
#include "grooves/package/package.h"

namespace bake::grooves {
namespace {

// Twenty V-grooves along v at u = 0.025 + 0.05 k over a unit domain (half-width 0.02).
std::string parallelScene(bool repeat, const std::string& extraGrooves = "") {
  std::ostringstream s;
  s << R"({"version": 1, "domain": {"size": [1, 1]}, "wrap": ")" << (repeat ? "repeat" : "none") << R"(",
          "profiles": {"vee": {"points": [[-0.02, 0], [0, -0.02], [0.02, 0]]},
                       "step": {"points": [[-0.02, 0], [-0.02, -0.01], [0.02, 0]]}},
          "materials": {"paint": {"albedo": [0.7, 0.65, 0.6], "specular": [0.04, 0.04, 0.04], "shininess": 20}},
          "base": "paint", "grooves": [)";
  for (int k = 0; k < 20; ++k)
    s << (k ? ", " : "") << R"({"profile": "vee", "path": {"line": [[)" << 0.025 + 0.05 * k << ", 0], ["
      << 0.025 + 0.05 * k << ", 1]]}}";
  s << extraGrooves << "]}";
  return s.str();
}

GrooveScene sceneOf(const std::string& json) {
  Result<GrooveScene> scene = parseGrooveScene(json, "far.json");
  EXPECT_TRUE(scene.isOk()) << scene.status().describe();
  return scene.isOk() ? scene.value() : GrooveScene{};
}

TEST(FarLevel, BandAreaOfParallelLinesIsExactOnCellBoundaries) {
  const GrooveScene scene = sceneOf(parallelScene(false));
  const GrooveGrid grid = buildGridOk(scene);
  const FarLevel& far = grid.far;
  ASSERT_EQ(far.classes.size(), 1u);
  EXPECT_NEAR(std::abs(far.classes[0].direction.v), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(far.classes[0].halfWidth, 0.02);
  // The whole domain: 20 lines x 1 long x 0.04 wide.
  EXPECT_NEAR(far.bandArea(0, {0, 0}, {1, 1}, false), 0.8, 1e-12);
  // Beyond the domain nothing more (no wrap).
  EXPECT_NEAR(far.bandArea(0, {-3, -3}, {4, 4}, false), 0.8, 1e-12);
  // A box on far cell boundaries: the lines inside it, times its height, times the width.
  const double cu = far.cellSize.u, cv = far.cellSize.v;
  const Vec2 lower{4 * cu, 3 * cv}, upper{15 * cu, 20 * cv};
  int inside = 0;
  for (int k = 0; k < 20; ++k) inside += (0.025 + 0.05 * k > lower.u && 0.025 + 0.05 * k < upper.u) ? 1 : 0;
  EXPECT_NEAR(far.bandArea(0, lower, upper, false), inside * (upper.v - lower.v) * 0.04, 1e-12);
}

TEST(FarLevel, RepeatingPatternAddsWholePeriods) {
  const GrooveScene scene = sceneOf(parallelScene(true));
  const GrooveGrid grid = buildGridOk(scene);
  // Three periods across, two up, from a negative corner.
  EXPECT_NEAR(grid.far.bandArea(0, {-1, -1}, {2, 1}, true), 3 * 2 * 0.8, 1e-9);
  // Half a period past the domain on each side: the same density.
  EXPECT_NEAR(grid.far.bandArea(0, {-0.5, 0}, {0.5, 1}, true), 0.8, 1e-9);
}

TEST(FarLevel, ClassesByProfileAndDirectionWithOrientationWhenAsymmetric) {
  // Crossing lines of the symmetric V (one class per direction), then an asymmetric step groove run
  // both ways along u (two classes: its profile's left side differs from its right).
  const std::string extra =
      R"(, {"profile": "vee", "path": {"line": [[0, 0.5], [1, 0.5]]}},
           {"profile": "step", "path": {"line": [[0, 0.3], [1, 0.3]]}},
           {"profile": "step", "path": {"line": [[1, 0.7], [0, 0.7]]}})";
  const GrooveScene scene = sceneOf(parallelScene(false, extra));
  const GrooveGrid grid = buildGridOk(scene);
  ASSERT_EQ(grid.far.classes.size(), 4u);
  int alongU = 0, stepBothWays = 0;
  for (const FarClass& c : grid.far.classes) {
    if (std::abs(c.direction.u) > 0.999) ++alongU;
    if (scene.profiles[c.profile].name == "step") stepBothWays += c.direction.u > 0 ? 1 : 2;
  }
  EXPECT_EQ(alongU, 3);
  EXPECT_EQ(stepBothWays, 3);  // one class each way
}

TEST(FarLevel, PackageRoundTripKeepsTheLevel) {
  const GrooveScene scene = sceneOf(parallelScene(true));
  const GrooveGrid grid = buildGridOk(scene);
  Result<glb::Package> package = buildGroovePackage(scene, grid);
  ASSERT_TRUE(package.isOk()) << package.status().describe();
  Result<GroovePackage> decoded = decodeGroovePackage(*package, "far.glb");
  ASSERT_TRUE(decoded.isOk()) << decoded.status().describe();
  EXPECT_EQ(decoded->header.version, format::grooves::kVersion);
  EXPECT_EQ(decoded->header.farCells[0], grid.far.cells[0]);
  EXPECT_EQ(decoded->header.farCells[1], grid.far.cells[1]);
  ASSERT_EQ(decoded->farClasses.size(), 1u);
  EXPECT_EQ(decoded->farTable, grid.far.table);
  // A version 1 package (no far level) still reads.
  nlohmann::json& extension = package->materials[0]["extensions"][format::grooves::kExtension];
  extension["version"] = 1;
  extension.erase(format::grooves::kFar);
  Result<GroovePackage> old = decodeGroovePackage(*package, "old.glb");
  ASSERT_TRUE(old.isOk()) << old.status().describe();
  EXPECT_TRUE(old->farClasses.empty());
  // A table that does not match its grid is refused.
  extension["version"] = 2;
  extension[format::grooves::kFar] = {{"cells", {3, 3}}, {"cellSize", {0.3, 0.3}}};
  EXPECT_EQ(decodeGroovePackage(*package, "bad.glb").status().code(), ExitCode::InvalidInput);
}

TEST(FarLevel, WholeBandsShadeAsEveryGrooveShaded) {
  // A footprint over [0.2, 0.8]^2: twelve whole bands, its edges in the gaps between them and on far
  // cell boundaries, so the far level's share is exact there and it must give what the seed's method
  // gives with every groove shaded.
  const GrooveScene scene = sceneOf(parallelScene(false));
  const GrooveGrid grid = buildGridOk(scene);
  ASSERT_NEAR(std::remainder(0.2, grid.far.cellSize.u), 0.0, 1e-12);
  const Footprint footprint{{0.5, 0.5}, {0.6, 0}, {0, 0.6}};
  for (const Vec3 toViewer : {Vec3{0, 0, 1}, Vec3{0.5, 0.0, std::sqrt(0.75)}, Vec3{0.0, 0.6, 0.8}}) {
    const Lighting light = lightTowards({0.6, 0.1, 0.8});
    ShadeStats exactStats, farStats;
    const Rgb everyGroove = SeedShader(scene, grid).shade(footprint, toViewer, light, &exactStats);
    SeedSettings capped;
    capped.foundCap = 5;
    const Rgb fromFar = SeedShader(scene, grid, capped).shade(footprint, toViewer, light, &farStats);
    EXPECT_FALSE(exactStats.far);
    EXPECT_TRUE(farStats.far);
    EXPECT_GE(exactStats.primitives, 12u);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(fromFar[k], everyGroove[k], 1e-6) << "channel " << k;
  }
}

TEST(FarLevel, RepeatingPatternWiderThanItsPeriodIsItsAreaAverage) {
  // Footprints over 3 and 40 periods of the repeating set against the set without wrap under a
  // footprint exactly one period wide, its edges in the gaps between bands, shaded with every groove:
  // the same area average. Before, each groove was counted once however many periods lay under it.
  const GrooveScene repeating = sceneOf(parallelScene(true)), single = sceneOf(parallelScene(false));
  const GrooveGrid repeatingGrid = buildGridOk(repeating), singleGrid = buildGridOk(single);
  const Lighting light = lightTowards({0.6, 0.1, 0.8});
  for (const Vec3 toViewer : {Vec3{0, 0, 1}, Vec3{0.5, 0.0, std::sqrt(0.75)}}) {
    const Rgb onePeriod = SeedShader(single, singleGrid).shade({{0.5, 0.5}, {1.0, 0}, {0, 0.6}}, toViewer, light);
    for (double periods : {3.0, 40.0}) {
      ShadeStats stats;
      const Rgb wide = SeedShader(repeating, repeatingGrid).shade({{0.5, 0.3}, {periods, 0}, {0, periods}}, toViewer,
                                                                  light, &stats);
      EXPECT_TRUE(stats.far);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(wide[k], onePeriod[k], 1e-6) << periods << " periods, channel " << k;
    }
  }
}

}  // namespace
}  // namespace bake::grooves
