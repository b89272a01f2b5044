// The style reader (hatching/style.h): defaults, every field, tone counts, the stroke image, and errors
// that name the file and the JSON pointer of the element at fault.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "bake/hatching/style.h"
#include "bake/io/image.h"
#include "support/golden.h"

namespace bake::hatching {
namespace {

namespace fs = std::filesystem;

Style parseOk(const std::string& text, const std::string& baseDir = "") {
  Result<Style> style = parseStyle(text, "style.json", baseDir);
  EXPECT_TRUE(style.isOk()) << style.status().describe();
  return style.isOk() ? style.value() : Style{};
}

// The error of parsing `text`: its code, the element it names, and a fragment of its message.
void expectError(const std::string& text, const std::string& element, const std::string& fragment,
                 ExitCode code = ExitCode::InvalidInput) {
  Result<Style> style = parseStyle(text, "style.json", "");
  ASSERT_FALSE(style.isOk()) << text;
  EXPECT_EQ(style.status().code(), code) << style.status().describe();
  EXPECT_EQ(style.status().where().file, "style.json");
  EXPECT_EQ(style.status().where().element, element) << style.status().describe();
  EXPECT_NE(style.status().message().find(fragment), std::string::npos) << style.status().describe();
}

TEST(Style, EmptyObjectGivesTheDefaults) {
  const Style style = parseOk("{}");
  ASSERT_EQ(style.tones.size(), 6u);
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(style.tones[k], 0.9 * (k + 1) / 6.0, 1e-12);
  EXPECT_EQ(style.resolution, 256);
  EXPECT_EQ(style.levels, 4);
  EXPECT_FALSE(style.levelsGiven);
  EXPECT_EQ(style.stroke.kind, StrokeKind::Hatching);
  EXPECT_EQ(style.candidates, 16);
  EXPECT_EQ(style.seed, 1u);
  EXPECT_FALSE(style.coloured());
  EXPECT_EQ(style.inputs(), std::vector<std::string>{"style.json"});
}

TEST(Style, ToneCountIsEvenlySpacedUpTo0_9) {
  const Style style = parseOk(R"({"tones": 3})");
  ASSERT_EQ(style.tones.size(), 3u);
  EXPECT_NEAR(style.tones[0], 0.3, 1e-12);
  EXPECT_NEAR(style.tones[1], 0.6, 1e-12);
  EXPECT_NEAR(style.tones[2], 0.9, 1e-12);
  EXPECT_EQ(parseOk(R"({"tones": 1})").tones, std::vector<double>{0.9});
}

TEST(Style, EveryFieldIsRead) {
  const Style style = parseOk(R"({
    "$schema": "../formats/tam-style.schema.json", "description": "test",
    "tones": [0.1, 0.3, 0.55, 0.8], "resolution": 128, "levels": 3, "candidates": 8, "blurSigma": 0.5,
    "seed": 18446744073709551615,
    "stroke": {"kind": "cross-hatching", "length": {"min": 0.2, "max": 0.4}, "width": {"min": 0.8, "max": 2},
               "angle": 45, "angleJitter": 10, "curvature": -0.1, "crossFrom": 1, "crossAngle": 80,
               "colour": [0.2, 0.1, 0.5], "opacity": 0.9, "centreOpacity": 0.95, "edgeOpacity": 0.5, "taper": 0.3}})");
  EXPECT_EQ(style.tones, (std::vector<double>{0.1, 0.3, 0.55, 0.8}));
  EXPECT_EQ(style.resolution, 128);
  EXPECT_EQ(style.levels, 3);
  EXPECT_TRUE(style.levelsGiven);
  EXPECT_EQ(style.candidates, 8);
  EXPECT_EQ(style.blurSigma, 0.5);
  EXPECT_EQ(style.seed, 18446744073709551615ull);
  const StrokeStyle& s = style.stroke;
  EXPECT_EQ(s.kind, StrokeKind::CrossHatching);
  EXPECT_EQ(s.length.min, 0.2);
  EXPECT_EQ(s.length.max, 0.4);
  EXPECT_EQ(s.width.min, 0.8);
  EXPECT_EQ(s.width.max, 2.0);
  EXPECT_EQ(s.angleDegrees, 45);
  EXPECT_EQ(s.angleJitterDegrees, 10);
  EXPECT_EQ(s.curvature, -0.1);
  EXPECT_EQ(s.crossFrom, 1);
  EXPECT_EQ(s.crossAngleDegrees, 80);
  EXPECT_EQ(s.colour, (std::array<double, 3>{0.2, 0.1, 0.5}));
  EXPECT_EQ(s.opacity, 0.9);
  EXPECT_EQ(s.centreOpacity, 0.95);
  EXPECT_EQ(s.edgeOpacity, 0.5);
  EXPECT_EQ(s.taper, 0.3);
  EXPECT_TRUE(style.coloured());
}

TEST(Style, CrossHatchingCrossesTheDarkerHalfByDefault) {
  EXPECT_EQ(parseOk(R"({"tones": 6, "stroke": {"kind": "cross-hatching"}})").stroke.crossFrom, 3);
  EXPECT_EQ(parseOk(R"({"tones": 6})").stroke.crossFrom, -1);
  EXPECT_EQ(parseOk(R"({"stroke": {"kind": "stippling"}})").stroke.kind, StrokeKind::Stippling);
}

TEST(Style, DefaultLevelsFollowTheResolution) {
  EXPECT_EQ(parseOk(R"({"resolution": 8})").levels, 1);
  EXPECT_EQ(parseOk(R"({"resolution": 64})").levels, 4);
  EXPECT_EQ(parseOk(R"({"resolution": 16})").levels, 2);
  EXPECT_EQ(parseOk(R"({"resolution": 4096})").levels, 4);
}

TEST(Style, ResolutionOverrideMovesDefaultLevelsAndChecksGivenOnes) {
  Style style = parseOk(R"({"resolution": 256})");
  ASSERT_TRUE(setResolution(style, 8, "--resolution").isOk());
  EXPECT_EQ(style.resolution, 8);
  EXPECT_EQ(style.levels, 1);
  style = parseOk(R"({"resolution": 256, "levels": 5})");
  const Status tooSmall = setResolution(style, 16, "--resolution");
  EXPECT_EQ(tooSmall.code(), ExitCode::Usage);
  EXPECT_NE(tooSmall.message().find("--resolution"), std::string::npos) << tooSmall.describe();
  EXPECT_NE(tooSmall.message().find("levels"), std::string::npos) << tooSmall.describe();
  EXPECT_EQ(setResolution(style, 100, "--resolution").code(), ExitCode::Usage);
  EXPECT_TRUE(setResolution(style, 512, "--resolution").isOk());
}

TEST(Style, MalformedJsonNamesTheByte) {
  expectError(R"({"tones": [0.1, 0.2,})", "byte 21", "malformed JSON");
  expectError("[1, 2]", "/", "must be a JSON object");
}

TEST(Style, TonesMustBeIncreasingInsideTheOpenUnitInterval) {
  expectError(R"({"tones": [0.2, 0.5, 0.5]})", "/tones/2", "strictly increasing");
  expectError(R"({"tones": [0.4, 0.3]})", "/tones/1", "strictly increasing");
  expectError(R"({"tones": [0, 0.5]})", "/tones/0", "within (0, 1)");
  expectError(R"({"tones": [0.5, 1]})", "/tones/1", "within (0, 1)");
  expectError(R"({"tones": [0.5, "dark"]})", "/tones/1", "must be a number");
  expectError(R"({"tones": []})", "/tones", "at least one");
  expectError(R"({"tones": 0})", "/tones", "within 1 .. 16");
  expectError(R"({"tones": 17})", "/tones", "within 1 .. 16");
  expectError(R"({"tones": 2.5})", "/tones", "tone count or a list");
  std::string many = R"({"tones": [)";
  for (int k = 1; k <= 17; ++k) many += (k > 1 ? "," : "") + std::to_string(k / 18.0);
  expectError(many + "]}", "/tones", "at most 16");
}

TEST(Style, UnknownKeysAreErrorsWithASuggestion) {
  expectError(R"({"tonez": 3})", "/tonez", "did you mean \"tones\"");
  expectError(R"({"stroke": {"widht": {"min": 1, "max": 2}}})", "/stroke/widht", "did you mean \"width\"");
  expectError(R"({"stroke": {"width": {"min": 1, "maximum": 2}}})", "/stroke/width/maximum", "unknown key");
  expectError(R"({"zzzzzzzzzz": 1})", "/zzzzzzzzzz", "unknown key \"zzzzzzzzzz\"");
}

TEST(Style, SizesAreChecked) {
  expectError(R"({"resolution": 100})", "/resolution", "power of two");
  expectError(R"({"resolution": 4})", "/resolution", "power of two within 8 .. 4096");
  expectError(R"({"resolution": 8192})", "/resolution", "power of two within 8 .. 4096");
  expectError(R"({"resolution": 64.5})", "/resolution", "must be an integer");
  expectError(R"({"resolution": 64, "levels": 7})", "/levels", "within 1 .. 6");
  expectError(R"({"levels": 0})", "/levels", "within 1 .. 64");
  expectError(R"({"candidates": 0})", "/candidates", "within 1 .. 4096");
  expectError(R"({"seed": -1})", "/seed", "non-negative integer");
  expectError(R"({"blurSigma": -1})", "/blurSigma", ">= 0");
}

TEST(Style, StrokeFieldsAreChecked) {
  expectError(R"({"stroke": {"kind": "scribble"}})", "/stroke/kind", "\"hatching\", \"cross-hatching\", \"stippling\", \"image\"");
  expectError(R"({"stroke": {"kind": 3}})", "/stroke/kind", "must be one of");
  expectError(R"({"stroke": {"width": {"min": 2, "max": 1}}})", "/stroke/width", "greater than max");
  expectError(R"({"stroke": {"width": {"min": 0, "max": 1}}})", "/stroke/width/min", "> 0");
  expectError(R"({"stroke": {"length": {"min": 0.2, "max": 1.5}}})", "/stroke/length/max", "<= 1");
  expectError(R"({"stroke": {"length": [0.2, 0.3]}})", "/stroke/length", "JSON object");
  expectError(R"({"stroke": {"opacity": 0}})", "/stroke/opacity", "> 0");
  expectError(R"({"stroke": {"taper": 0.7}})", "/stroke/taper", "<= 0.5");
  expectError(R"({"stroke": {"colour": [0, 0]}})", "/stroke/colour", "[R, G, B]");
  expectError(R"({"stroke": {"colour": [0, 2, 0]}})", "/stroke/colour/1", "within [0, 1]");
  expectError(R"({"stroke": {"angle": "up"}})", "/stroke/angle", "must be a number");
  expectError(R"({"stroke": {"crossFrom": 1}})", "/stroke/crossFrom", "only to the \"cross-hatching\"");
  expectError(R"({"tones": 4, "stroke": {"kind": "cross-hatching", "crossFrom": 4}})", "/stroke/crossFrom", "within 0 .. 3");
  expectError(R"({"stroke": {"image": "a.png"}})", "/stroke/image", "only to the \"image\" kind");
  expectError(R"({"stroke": {"kind": "image"}})", "/stroke/kind", "needs \"image\"");
  expectError(R"({"stroke": "hatching"})", "/stroke", "JSON object");
  expectError(R"({"stroke": {"centreOpacity": 0, "edgeOpacity": 0}})", "/stroke/centreOpacity", "no ink");
}

TEST(Style, MissingStrokeImageNamesStyleElementAndImage) {
  const fs::path dir = test::freshTempDir("missing_image");
  std::ofstream(dir / "style.json") << R"({"stroke": {"kind": "image", "image": "strokes/none.png"}})";
  Result<Style> style = readStyle((dir / "style.json").string());
  ASSERT_FALSE(style.isOk());
  EXPECT_EQ(style.status().code(), ExitCode::Io);
  EXPECT_EQ(style.status().where().file, (dir / "style.json").string());
  EXPECT_EQ(style.status().where().element, "/stroke/image");
  EXPECT_NE(style.status().message().find((dir / "strokes/none.png").string()), std::string::npos) << style.status().describe();
  // Listing the inputs does not read the image, so it may be missing.
  Result<Style> listed = readStyle((dir / "style.json").string(), false);
  ASSERT_TRUE(listed.isOk()) << listed.status().describe();
  EXPECT_EQ(listed->inputs(), (std::vector<std::string>{(dir / "style.json").string(), (dir / "strokes/none.png").string()}));
}

TEST(Style, StrokeImageIsReadAsAlphaRelativeToTheStyle) {
  const fs::path dir = test::freshTempDir("stroke_image");
  fs::create_directories(dir / "strokes");
  // A grey image: ink alpha is 1 - grey.
  Image grey{4, 2, 1, {1.0f, 0.0f, 0.2f, 0.6f, 1.0f, 1.0f, 0.0f, 0.0f}};
  ASSERT_TRUE(writeImage(dir / "strokes" / "grey.png", grey, PixelType::U8).isOk());
  // Grey + alpha: the alpha channel is the ink.
  Image withAlpha{2, 1, 2, {0.0f, 0.25f, 1.0f, 1.0f}};
  ASSERT_TRUE(writeImage(dir / "alpha.png", withAlpha, PixelType::U16).isOk());

  std::ofstream(dir / "grey.json") << R"({"stroke": {"kind": "image", "image": "strokes/grey.png"}})";
  Result<Style> style = readStyle((dir / "grey.json").string());
  ASSERT_TRUE(style.isOk()) << style.status().describe();
  const stroke::StrokeTexture& texture = style->stroke.texture;
  ASSERT_EQ(texture.width, 4);
  ASSERT_EQ(texture.height, 2);
  const float expected[8] = {0.0f, 1.0f, 0.8f, 0.4f, 0.0f, 0.0f, 1.0f, 1.0f};
  for (int i = 0; i < 8; ++i) EXPECT_NEAR(texture.alpha[i], expected[i], 1.0f / 255) << i;
  EXPECT_EQ(style->stroke.image, (dir / "strokes" / "grey.png").string());
  EXPECT_EQ(style->inputs().back(), (dir / "strokes" / "grey.png").string());

  std::ofstream(dir / "alpha.json") << R"({"stroke": {"kind": "image", "image": "alpha.png"}})";
  style = readStyle((dir / "alpha.json").string());
  ASSERT_TRUE(style.isOk()) << style.status().describe();
  ASSERT_EQ(style->stroke.texture.alpha.size(), 2u);
  EXPECT_NEAR(style->stroke.texture.alpha[0], 0.25f, 1e-4f);
  EXPECT_NEAR(style->stroke.texture.alpha[1], 1.0f, 1e-4f);
}

TEST(Style, MissingStyleFileIsAnIoError) {
  Result<Style> style = readStyle("no/such/style.json");
  ASSERT_FALSE(style.isOk());
  EXPECT_EQ(style.status().code(), ExitCode::Io);
  EXPECT_EQ(style.status().where().file, "no/such/style.json");
}

TEST(Style, KindNames) {
  EXPECT_STREQ(strokeKindName(StrokeKind::Hatching), "hatching");
  EXPECT_STREQ(strokeKindName(StrokeKind::CrossHatching), "cross-hatching");
  EXPECT_STREQ(strokeKindName(StrokeKind::Stippling), "stippling");
  EXPECT_STREQ(strokeKindName(StrokeKind::Image), "image");
}

}  // namespace
}  // namespace bake::hatching
