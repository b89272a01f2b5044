// Bake plans (pipe/plan.h) of the example scenes: the steps, the options that leave out what no
// material reads, and the left-out list with its reasons; the full plan of --keep-unused; the screen
// size bound that decides which TAM levels are left out.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "pipe/plan.h"
#include "pipe/scene.h"

namespace bake::pipe {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kOut = fs::path(BAKE_TEST_TMP) / "plan-out";

Scene exampleScene(const std::string& name) {
  Result<Scene> scene = readScene(fs::path(BAKE_SOURCE_DIR) / "pipelines" / name / "scene.json");
  EXPECT_TRUE(scene.isOk()) << scene.status().describe();
  return scene.isOk() ? scene.value() : Scene{};
}

Plan planOf(const Scene& scene, bool keepUnused = false) {
  Result<Plan> plan = makePlan(scene, {kOut, keepUnused});
  EXPECT_TRUE(plan.isOk()) << plan.status().describe();
  return plan.isOk() ? plan.value() : Plan{};
}

std::vector<std::string> leftOutList(const Plan& plan) {
  std::vector<std::string> list;
  for (const LeftOut& item : plan.leftOut) list.push_back(item.object + ": " + item.what);
  return list;
}

const Step& stepOf(const Plan& plan, const std::string& id) {
  const auto found = std::find_if(plan.steps.begin(), plan.steps.end(), [&](const Step& s) { return s.id == id; });
  EXPECT_NE(found, plan.steps.end()) << id;
  return *found;
}

bool hasArgument(const Step& step, const std::string& argument) {
  return std::find(step.arguments.begin(), step.arguments.end(), argument) != step.arguments.end();
}

// The value after `flag` in the step's arguments ("" when the flag is absent).
std::string argumentAfter(const Step& step, const std::string& flag) {
  const auto found = std::find(step.arguments.begin(), step.arguments.end(), flag);
  return found == step.arguments.end() || found + 1 == step.arguments.end() ? "" : *(found + 1);
}

TEST(PipePlan, PaintstrokesLeaveOutUnreadShadowsAndUnusedStyles) {
  const Plan plan = planOf(exampleScene("paintstrokes"));
  EXPECT_EQ(leftOutList(plan), (std::vector<std::string>{"reeds: self-shadowing table", "reeds: style 'dry'"}));
  const Step& reeds = stepOf(plan, "strokebake:reeds");
  EXPECT_TRUE(hasArgument(reeds, "--no-shadows"));
  EXPECT_TRUE(hasArgument(reeds, "--drop-unused-styles"));
  EXPECT_EQ(argumentAfter(reeds, "-o"), (kOut / "reeds.paintstrokes.glb").string());
  // The fur's light direction as strokebake reads it; its one style cannot be left out.
  const Step& fur = stepOf(plan, "strokebake:fur");
  EXPECT_EQ(argumentAfter(fur, "--light-dir"), "0.4,0.8,0.45");
  EXPECT_FALSE(hasArgument(fur, "--no-shadows"));
  EXPECT_FALSE(hasArgument(fur, "--drop-unused-styles"));
  // --keep-unused bakes everything.
  const Plan full = planOf(exampleScene("paintstrokes"), true);
  EXPECT_TRUE(full.leftOut.empty());
  EXPECT_FALSE(hasArgument(stepOf(full, "strokebake:reeds"), "--no-shadows"));
  EXPECT_FALSE(hasArgument(stepOf(full, "strokebake:reeds"), "--drop-unused-styles"));
}

TEST(PipePlan, PaintstrokeLightDirectionsMustBeTriples) {
  Scene scene = exampleScene("paintstrokes");
  scene.objects[0].options["lightDirections"] = json::array({json::array({0, 1})});
  const Result<Plan> plan = makePlan(scene, {kOut, false});
  ASSERT_FALSE(plan.isOk());
  EXPECT_NE(plan.status().describe().find("lightDirections"), std::string::npos) << plan.status().describe();
  EXPECT_NE(plan.status().describe().find("object \"fur\""), std::string::npos) << plan.status().describe();
}

TEST(PipePlan, GeodesicBakesOnlyTheFieldTheMaterialReads) {
  const Plan plan = planOf(exampleScene("geodesic"));
  EXPECT_EQ(leftOutList(plan), (std::vector<std::string>{"pretzel: field 'right tip'", "pretzel: field 'rims'"}));
  const Step& bake = stepOf(plan, "geobake:pretzel");
  EXPECT_EQ(argumentAfter(bake, "--fields"), "left tip");
  EXPECT_EQ(argumentAfter(bake, "-o"), (kOut / "pretzel.geodesic.glb").string());
  // The generated mesh is made first and read by the bake.
  EXPECT_EQ(plan.steps.front().id, "bakeshape:pretzel.glb");
  EXPECT_NE(std::find(bake.inputs.begin(), bake.inputs.end(), kOut / "pretzel.glb"), bake.inputs.end());
}

TEST(PipePlan, RevolutionLeavesOutTheUnreadDisplacementAndTheTextureOnlyItUsed) {
  const Plan plan = planOf(exampleScene("revolution"));
  EXPECT_EQ(leftOutList(plan), (std::vector<std::string>{"ring: displacement map", "(scene): generated knurl.png"}));
  EXPECT_FALSE(hasArgument(stepOf(plan, "revolbake:ring"), "--height-map"));
  EXPECT_FALSE(hasArgument(stepOf(plan, "revolbake:ring"), "--height-scale"));
  EXPECT_EQ(argumentAfter(stepOf(plan, "revolbake:vase"), "--height-map"), (kOut / "hammered.png").string());
  for (const Step& step : plan.steps) EXPECT_NE(step.id, "bakeshape:knurl.png");
  EXPECT_EQ(plan.steps.size(), 8u);  // glaze, bands, hammered, five bakes
  // Copies of one profile: the list options as revolbake reads them.
  EXPECT_EQ(argumentAfter(stepOf(plan, "revolbake:balusters"), "--grid"), "5,1,1");
  EXPECT_EQ(argumentAfter(stepOf(plan, "revolbake:balusters"), "--grid-spacing"), "0.55,0,0");
  EXPECT_EQ(argumentAfter(stepOf(plan, "revolbake:knobs"), "--ring"), "8");
  EXPECT_FALSE(hasArgument(stepOf(plan, "revolbake:knobs"), "--no-self-shadow"));
}

TEST(PipePlan, HatchingLeavesOutThresholdsAndTheLevelNoViewSamples) {
  const Plan plan = planOf(exampleScene("hatching"));
  EXPECT_EQ(leftOutList(plan), (std::vector<std::string>{"torus: threshold texture", "torus: TAM level 0 (256 texels)",
                                                         "pretzel: threshold texture"}));
  EXPECT_EQ(argumentAfter(stepOf(plan, "tambake:torus"), "--skip-levels"), "1");
  EXPECT_FALSE(hasArgument(stepOf(plan, "tambake:pretzel"), "--skip-levels"));
  EXPECT_FALSE(hasArgument(stepOf(plan, "tambake:torus"), "--threshold"));
  // The torus (radius 1.4, 8.755 deep on the camera's axis) at depth 7.355: 512 / (2 tan 20.05° 7.355)
  // = 95.36 pixels per unit on the axis, times the image corner's secant sqrt(1 + tan² 20.05° (1 + 2²))
  // = 1.291: 123.1 pixels per unit, so a level-0 texel (1/256 unit) is 0.48 pixel. The pretzel (radius
  // 2.7) comes nearer: 149 pixels per unit, the scene's largest; its TAM has fewer texels.
  EXPECT_NE(plan.leftOut[1].why.find("123.1 pixels per unit"), std::string::npos) << plan.leftOut[1].why;
  EXPECT_GT(plan.maxPixelsPerUnit, 140);
  EXPECT_LT(plan.maxPixelsPerUnit, 160);
}

TEST(PipePlan, GroovesLeaveOutRecordsOfTheFarRecordAndReportKindsThePatternLacks) {
  const Plan plan = planOf(exampleScene("grooves"));
  EXPECT_EQ(leftOutList(plan), (std::vector<std::string>{"tiles: corner records", "column: special-case records",
                                                         "record: special-case records"}));
  EXPECT_TRUE(hasArgument(stepOf(plan, "groovebake:record"), "--no-special-cases"));
  EXPECT_FALSE(hasArgument(stepOf(plan, "groovebake:plate"), "--no-special-cases"));
  // The column's grooves are drawn on the generated column (groovebake --apply-to), which the step
  // waits for; the plate keeps its preview plane.
  EXPECT_EQ(argumentAfter(stepOf(plan, "groovebake:column"), "--apply-to"), (kOut / "column.glb").string());
  EXPECT_FALSE(hasArgument(stepOf(plan, "groovebake:plate"), "--apply-to"));
  const auto& inputs = stepOf(plan, "groovebake:column").inputs;
  EXPECT_NE(std::find(inputs.begin(), inputs.end(), kOut / "column.glb"), inputs.end());
}

TEST(PipePlan, KeepUnusedPlansTheFullBakes) {
  const Plan geodesic = planOf(exampleScene("geodesic"), true);
  EXPECT_TRUE(geodesic.leftOut.empty());
  EXPECT_FALSE(hasArgument(stepOf(geodesic, "geobake:pretzel"), "--fields"));
  const Plan revolution = planOf(exampleScene("revolution"), true);
  EXPECT_TRUE(revolution.leftOut.empty());
  EXPECT_EQ(argumentAfter(stepOf(revolution, "revolbake:ring"), "--height-map"), (kOut / "knurl.png").string());
  const Plan hatching = planOf(exampleScene("hatching"), true);
  EXPECT_TRUE(hatching.leftOut.empty());
  EXPECT_EQ(argumentAfter(stepOf(hatching, "tambake:torus"), "--threshold"), (kOut / "torus.hatching.threshold.ktx2").string());
  EXPECT_FALSE(hasArgument(stepOf(hatching, "tambake:torus"), "--skip-levels"));
  const Plan grooves = planOf(exampleScene("grooves"), true);
  EXPECT_FALSE(hasArgument(stepOf(grooves, "groovebake:record"), "--no-special-cases"));
}

// A hatching scene with an explicit screen-size range: levels are left out while a texel of them is
// below half a pixel. 256 texels per tile, 2 tiles per unit: 512 texels per unit at level 0.
json hatchingScene(double maxPixelsPerUnit) {
  const std::string hatching = std::string(BAKE_SOURCE_DIR) + "/pipelines/hatching/";
  return {{"version", 1},
          {"generated", {{{"output", "torus.glb"}, {"shape", "torus"}}}},
          {"objects", {{{"name", "t"}, {"technique", "hatching"}, {"input", hatching + "hatching.json"},
                        {"mesh", "torus.glb"}, {"options", {{"tilesPerUnit", 2}}}, {"material", "m"}}}},
          {"materials", {{{"name", "m"}, {"technique", "hatching"}}}},
          {"pixelsPerUnit", {std::min(1.0, maxPixelsPerUnit), maxPixelsPerUnit}}};
}

TEST(PipePlan, TamLevelsLeftOutFollowTheHalfPixelRule) {
  const std::pair<double, std::string> cases[] = {
      {300, ""},    // level 0 texel = 300 / 512 = 0.59 px: kept
      {200, "1"},   // 0.39 px at level 0, 0.78 at level 1
      {60, "3"},    // 0.12, 0.23, 0.47, 0.94
      {0.001, "8"}, // every level but the 1x1 one
  };
  for (const auto& [pixels, skip] : cases) {
    Result<Scene> scene = parseScene(hatchingScene(pixels), fs::path(BAKE_TEST_TMP) / "hatching-scene.json");
    ASSERT_TRUE(scene.isOk()) << scene.status().describe();
    const Plan plan = planOf(scene.value());
    EXPECT_EQ(argumentAfter(stepOf(plan, "tambake:t"), "--skip-levels"), skip) << pixels << " pixels per unit";
  }
}

TEST(PipePlan, TwoStepsWritingOneFileAreAnError) {
  const std::string dir = std::string(BAKE_SOURCE_DIR) + "/pipelines/grooves/";
  const json document = {
      {"version", 1},
      {"generated", {{{"output", "a.grooves.glb"}, {"shape", "torus"}}}},
      {"objects", {{{"name", "a"}, {"technique", "grooves"}, {"input", dir + "tiles.json"}, {"material", "m"}}}},
      {"materials", {{{"name", "m"}, {"technique", "grooves"}}}}};
  Result<Scene> scene = parseScene(document, fs::path(BAKE_TEST_TMP) / "clash.json");
  ASSERT_TRUE(scene.isOk()) << scene.status().describe();
  Result<Plan> plan = makePlan(scene.value(), {kOut, true});
  ASSERT_FALSE(plan.isOk());
  EXPECT_NE(plan.status().message().find("a.grooves.glb"), std::string::npos) << plan.status().describe();
}

TEST(PipePlan, CommandLinesQuoteWordsAShellWouldSplit) {
  Step step;
  step.tool = "geobake";
  step.arguments = {"in put.glb", "--fields", "left tip", "it's"};
  EXPECT_EQ(commandLine(step, {}), "geobake 'in put.glb' --fields 'left tip' 'it'\\''s'");
}

}  // namespace
}  // namespace bake::pipe

namespace bake::pipe {
namespace {

TEST(PipePlan, CacheDirectoryIsGivenToEveryStep) {
  PlanSettings settings{kOut, false, kOut / "cache"};
  Result<Plan> plan = makePlan(exampleScene("revolution"), settings);
  ASSERT_TRUE(plan.isOk()) << plan.status().describe();
  for (const Step& step : plan->steps) EXPECT_EQ(argumentAfter(step, "--cache-dir"), (kOut / "cache").string()) << step.id;
}

}  // namespace
}  // namespace bake::pipe
