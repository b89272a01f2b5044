// Stiff cases of the whole revolbake run (label stiff): sub-texel flanges and gaps warn with the
// thinnest feature in texels, profiles touching or crossing the axis, pixel-aligned edges, a sharp
// spike, a 20:1 flat object at the smallest and largest resolutions, zero-length segments, crossings,
// negative r and NaN: a finite, consistent package or a clear error, and nothing written on failure.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bake/io/glb.h"
#include "bake/revolution/bake.h"
#include "bake_formats/revolution.h"
#include "support/golden.h"

namespace bake::revolution {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct BakeOutcome {
  Status status;
  std::string messages;  // what the tool printed (warnings and errors)
  json extension;        // BAKE_revolution of the package, when one was written
  json report;
};

// Writes `profile` (the JSON profile format) and bakes it with `settings`' options.
BakeOutcome bakeProfile(const std::string& name, const json& profile, Settings settings) {
  const fs::path dir = test::freshTempDir(name);
  settings.input = (dir / "profile.json").string();
  settings.output = (dir / "out.glb").string();
  settings.common.reportPath = (dir / "report.json").string();
  std::ofstream(settings.input) << profile.dump();
  std::FILE* stream = std::tmpfile();
  Diagnostics diagnostics("revolbake", false, stream);
  BakeOutcome outcome;
  outcome.status = run(settings, diagnostics);
  std::rewind(stream);
  for (int c = std::fgetc(stream); c != EOF; c = std::fgetc(stream)) outcome.messages += char(c);
  std::fclose(stream);
  if (fs::exists(settings.output)) {
    auto package = glb::read(settings.output);
    EXPECT_TRUE(package.isOk()) << package.status().describe();
    if (package.isOk()) outcome.extension = package->materials[0]["extensions"][format::revolution::kExtension];
  }
  if (fs::exists(settings.common.reportPath)) std::ifstream(settings.common.reportPath) >> outcome.report;
  return outcome;
}

Settings smallSettings(int resolution = 128) {
  Settings settings;
  settings.resolution = resolution;
  settings.encoding = DistanceEncoding::Float;
  return settings;
}

json closedContour(const std::vector<std::array<double, 2>>& points) {
  return {{"contours", {{{"closed", true}, {"points", points}}}}};
}

// Every number in the package description is finite, and the march budget is a real one.
void expectConsistent(const BakeOutcome& outcome) {
  ASSERT_TRUE(outcome.status.isOk()) << outcome.status.describe();
  ASSERT_TRUE(outcome.extension.is_object());
  const json& map = outcome.extension["shapeMap"];
  EXPECT_GT(map["width"].get<int>(), 0);
  EXPECT_GT(map["height"].get<int>(), 0);
  EXPECT_TRUE(std::isfinite(map["texelSize"].get<double>()) && map["texelSize"].get<double>() > 0);
  EXPECT_TRUE(std::isfinite(outcome.extension["safetyMargin"].get<double>()));
  EXPECT_GE(outcome.extension["march"]["iterations"].get<int>(), 1);
  for (const json& band : outcome.extension["proxyBands"])
    for (const json& value : band) EXPECT_TRUE(std::isfinite(value.get<double>()));
}

// The report's distance error of the stored map against the exact reference, in texels (every texel;
// a sign error anywhere counts as a huge error).
double storedErrorTexels(const BakeOutcome& outcome) {
  for (const json& entry : outcome.report["accuracy"])
    if (entry["quantity"].get<std::string>().find("stored shape map signed distance") != std::string::npos)
      return entry["metrics"]["signErrors"].get<int>() > 0 ? 1e9 : entry["metrics"]["max"].get<double>();
  ADD_FAILURE() << "no shape map accuracy in the report";
  return 1e9;
}

TEST(RevolbakeStiff, SubTexelFlangeAndGapWarnWithTheirWidthInTexels) {
  // A disc 1 wide and 0.002 thick at 128 texels across: the flange is about a quarter texel.
  const BakeOutcome flange = bakeProfile("thin_flange", closedContour({{0, 0}, {1, 0}, {1, 0.002}, {0, 0.002}}),
                                         smallSettings());
  expectConsistent(flange);
  EXPECT_NE(flange.messages.find("thinnest flange is 0.2"), std::string::npos) << flange.messages;
  // Two rings 0.002 apart: the gap between them is under a texel.
  const json twoRings = {{"contours",
                          {{{"closed", true}, {"points", {{0.3, 0}, {0.6, 0}, {0.6, 0.5}, {0.3, 0.5}}}},
                           {{"closed", true}, {"points", {{0.602, 0}, {0.9, 0}, {0.9, 0.5}, {0.602, 0.5}}}}}}};
  const BakeOutcome gap = bakeProfile("thin_gap", twoRings, smallSettings());
  expectConsistent(gap);
  EXPECT_NE(gap.messages.find("thinnest gap"), std::string::npos) << gap.messages;
  // A sound profile says nothing of the kind.
  const BakeOutcome sound = bakeProfile("sound", closedContour({{0, 0}, {1, 0}, {1, 0.5}, {0, 0.5}}), smallSettings());
  expectConsistent(sound);
  EXPECT_EQ(sound.messages.find("thinnest"), std::string::npos) << sound.messages;
}

TEST(RevolbakeStiff, ProfilesTouchingTheAxisBakeAndCrossingItIsAnError) {
  // A diamond whose lowest and highest corners touch the axis (a double cone).
  const BakeOutcome touching = bakeProfile("touching", closedContour({{0, 0}, {0.5, 0.5}, {0, 1}}), smallSettings());
  expectConsistent(touching);
  EXPECT_LT(storedErrorTexels(touching), 1e-3);
  const BakeOutcome crossing = bakeProfile("crossing", closedContour({{0.2, 0}, {0.5, 0.5}, {-0.3, 1}}), smallSettings());
  EXPECT_EQ(crossing.status.code(), ExitCode::InvalidInput);
  EXPECT_NE(crossing.status.describe().find("point 2"), std::string::npos) << crossing.status.describe();
  EXPECT_TRUE(crossing.extension.is_null()) << "nothing may be written on failure";
}

TEST(RevolbakeStiff, PixelAlignedEdgesAndASharpSpikeStayExact) {
  // With 4 texels of padding and 64 texels across 0.5, the texel is 0.5 / 56: edges at whole texels.
  const double texel = 0.5 / 56;
  const BakeOutcome aligned = bakeProfile(
      "aligned", closedContour({{0, 0}, {20 * texel, 0}, {20 * texel, 56 * texel}, {0, 56 * texel}}), smallSettings(64));
  expectConsistent(aligned);
  EXPECT_LT(storedErrorTexels(aligned), 1e-3);
  // A 2-degree spike: the sharpest corner a lathe profile could have.
  const double tip = 1.0, halfAngle = 1.0 * M_PI / 180;
  const BakeOutcome spike = bakeProfile(
      "spike", closedContour({{0.2, 0.5}, {0.2 + tip, 0.5 - tip * std::tan(halfAngle)}, {0.2 + tip, 0.5 + tip * std::tan(halfAngle)}}),
      smallSettings(256));
  expectConsistent(spike);
  EXPECT_LT(storedErrorTexels(spike), 1e-3);
}

TEST(RevolbakeStiff, FlatObjectAtTheSmallestAndLargestResolutions) {
  // 20:1 long and flat: a disc of radius 1 and thickness 0.1 (a coin), at 64 and 8192 texels across.
  const json coin = closedContour({{0, 0}, {1, 0}, {1, 0.1}, {0, 0.1}});
  for (int resolution : {64, 8192}) {
    SCOPED_TRACE(resolution);
    const BakeOutcome outcome = bakeProfile("coin_" + std::to_string(resolution), coin, smallSettings(resolution));
    expectConsistent(outcome);
    const json& map = outcome.extension["shapeMap"];
    EXPECT_EQ(std::max(map["width"].get<int>(), map["height"].get<int>()), resolution);
    // Square texels: the map's extent follows the object's 1 : 0.1 (plus the padding).
    const double texel = map["texelSize"].get<double>();
    EXPECT_NEAR(map["width"].get<int>() * texel, 1.0 + 4 * texel, 1.01 * texel);
    EXPECT_LT(storedErrorTexels(outcome), 1e-3);
  }
}

TEST(RevolbakeStiff, ZeroLengthSegmentsAreDroppedAndBrokenInputIsRefused) {
  const BakeOutcome repeated = bakeProfile("zero_length", closedContour({{0, 0}, {1, 0}, {1, 0}, {1, 0.5}, {0, 0.5}}),
                                           smallSettings());
  expectConsistent(repeated);
  EXPECT_NE(repeated.messages.find("warning"), std::string::npos) << repeated.messages;
  const BakeOutcome bowTie = bakeProfile("bow_tie", closedContour({{0.2, 0}, {1, 1}, {1, 0}, {0.2, 1}}), smallSettings());
  EXPECT_EQ(bowTie.status.code(), ExitCode::InvalidInput);
  EXPECT_TRUE(bowTie.extension.is_null());
  // NaN is not JSON: the reader refuses the file, naming it.
  const fs::path dir = test::freshTempDir("not_finite");
  Settings settings = smallSettings();
  settings.input = (dir / "profile.json").string();
  settings.output = (dir / "out.glb").string();
  std::ofstream(settings.input) << R"({"contours": [{"closed": true, "points": [[0.5, 0], [1, 0], [1, NaN]]}]})";
  Diagnostics quiet("revolbake", true);
  const Status status = run(settings, quiet);
  EXPECT_EQ(status.code(), ExitCode::InvalidInput);
  EXPECT_NE(status.describe().find("profile.json"), std::string::npos) << status.describe();
  EXPECT_FALSE(fs::exists(settings.output));
}

}  // namespace
}  // namespace bake::revolution
