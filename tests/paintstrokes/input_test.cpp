// Stroke list readers (libbake/paintstrokes/input.h, formats/paintstroke-input.md): defaults, styles by
// index and name, CSV grouping by consecutive stroke ids, and messages naming the file, stroke and
// control point for malformed documents (parse errors included).
#include <gtest/gtest.h>

#include "bake/core/limits.h"
#include "paintstrokes/input/input.h"

namespace bake::paintstrokes {
namespace {

std::string messageOf(const Result<StrokeInput>& r) { return r.isOk() ? std::string("(ok)") : r.status().describe(); }

TEST(PaintstrokesInput, JsonFillsDefaultsAndResolvesStylesByName) {
  const char* text = R"({"version": 1, "units": "m",
    "styles": [{"name": "bark"}, {"name": "fuzz", "edgeOpacity": 0.1, "volumeOpacity": [0.3, 0.9], "specular": [0.2, 0.2, 0.2]}],
    "strokes": [{"points": [{"p": [0, 0, 0], "r": 0.1}, {"p": [1, 0, 0], "r": 0.05, "colour": [1, 0, 0], "opacity": 0.5,
                            "reflectance": 0.25, "normal": [0, 1, 0], "depth": 0.5}]},
                {"style": "fuzz", "points": [{"p": [0, 1, 0], "r": 0.1}, {"p": [0, 2, 0], "r": 0.1}]},
                {"style": 1, "points": [{"p": [0, 1, 0], "r": 0.1}, {"p": [0, 3, 0], "r": 0.1}]}]})";
  Result<StrokeInput> r = parseStrokeJson(text, "s.json");
  ASSERT_TRUE(r.isOk()) << messageOf(r);
  const StrokeSet& set = r->set;
  EXPECT_EQ(set.units, "m");
  ASSERT_EQ(set.styles.size(), 2u);
  EXPECT_DOUBLE_EQ(set.styles[1].volumeAlong, 0.9);
  ASSERT_EQ(set.strokes.size(), 3u);
  EXPECT_EQ(set.strokes[0].style, 0u);
  EXPECT_EQ(set.strokes[1].style, 1u);
  EXPECT_EQ(set.strokes[2].style, 1u);
  const StrokePoint& a = set.strokes[0].points[0];
  EXPECT_EQ(a.colour, (Vec3d{0.5, 0.5, 0.5}));
  EXPECT_EQ(a.opacity, 1);
  EXPECT_EQ(a.globalNormal, (Vec3d{0, 0, 0}));
  const StrokePoint& b = set.strokes[0].points[1];
  EXPECT_EQ(b.colour, (Vec3d{1, 0, 0}));
  EXPECT_DOUBLE_EQ(b.reflectance, 0.25);
  EXPECT_DOUBLE_EQ(b.depth, 0.5);
  EXPECT_EQ(b.globalNormal, (Vec3d{0, 1, 0}));
}

TEST(PaintstrokesInput, JsonErrorsNameStrokeAndControlPoint) {
  auto expect = [](const char* text, const char* fragment) {
    Result<StrokeInput> r = parseStrokeJson(text, "s.json");
    ASSERT_FALSE(r.isOk()) << fragment;
    EXPECT_EQ(r.status().code(), ExitCode::InvalidInput);
    EXPECT_NE(messageOf(r).find(fragment), std::string::npos) << messageOf(r);
  };
  const std::string head = R"({"version": 1, "strokes": [{"points": [{"p": [0,0,0], "r": 1}, {"p": [1,0,0], "r": 1}]}, {"points": [{"p": [0,0,0], "r": 1}, )";
  expect((head + R"({"p": [1,0], "r": 1}]}]})").c_str(), "s.json: stroke 1, control point 1: \"p\" must be 3 numbers");
  expect((head + R"({"p": [1,0,0]}]}]})").c_str(), "stroke 1, control point 1: \"r\" (the radius) is missing");
  expect((head + R"({"p": [1,0,0], "r": 1, "radius": 2}]}]})").c_str(), "stroke 1, control point 1: unknown key \"radius\"");
  // The parser refuses 1e999 (it overflows a double): the path still names the place.
  expect((head + R"({"p": [1,0,0], "r": 1e999}]}]})").c_str(), "s.json: stroke 1, control point 1, \"r\": not valid JSON");
  expect((head + R"({"p": [1,NaN,0], "r": 1}]}]})").c_str(), "stroke 1, control point 1, \"p\": not valid JSON");
  expect((head + R"({"p": [1,0,0], "r)").c_str(), "stroke 1, control point 1");
  // An object where the strokes array should be, cut off after a key of forty digits (too large for
  // an index): the JSON pointer names the place.
  expect(R"({"version": 1, "strokes": {"4444444444444444444444444444444444444444"points''4')",
         "s.json: /strokes/4444444444444444444444444444444444444444: not valid JSON");
  expect(R"({"version": 1, "strokes": [{"points": {"99999999999999999999999"x)",
         "s.json: stroke 0, \"points\": not valid JSON");
  expect(R"({"version": 1, "strokes": [{"style": 3, "points": []}]})", "s.json: stroke 0: style 3 does not exist");
  expect(R"({"version": 1, "strokes": [{"style": "hair", "points": []}]})", "stroke 0: style \"hair\" is not defined");
  expect(R"({"version": 2, "strokes": []})", "version: must be 1");
  expect(R"({"version": 1, "styles": [{"edgeOpacity": 3}], "strokes": []})", "style 0: opacities");
}

TEST(PaintstrokesInput, ControlPointBudgetIsCheckedBeforeStrokesAreBuilt) {
  const Budgets saved = budgets();
  Budgets small = saved;
  small.controlPoints = 3;
  setBudgets(small);
  const Result<StrokeInput> json = parseStrokeJson(
      R"({"version": 1, "strokes": [{"points": [{"p": [0,0,0], "r": 1}, {"p": [1,0,0], "r": 1}]},
                                    {"points": [{"p": [0,0,0], "r": 1}, {"p": [1,0,0], "r": 1}]}]})", "s.json");
  const Result<StrokeInput> csv = parseStrokeCsv("stroke,x,y,z,radius\n1,0,0,0,1\n1,1,0,0,1\n2,0,0,0,1\n2,1,0,0,1\n", "s.csv");
  setBudgets(saved);
  ASSERT_FALSE(json.isOk());
  EXPECT_NE(messageOf(json).find("4 control points exceed the budget"), std::string::npos) << messageOf(json);
  ASSERT_FALSE(csv.isOk());
  EXPECT_NE(messageOf(csv).find("control-points"), std::string::npos) << messageOf(csv);
}

TEST(PaintstrokesInput, CsvGroupsConsecutiveRowsByStrokeId) {
  const char* text =
      "# comment\n"
      "stroke, x, y, z, radius, r, g, b, opacity, nx, ny, nz, depth, style\n"
      "a,0,0,0,0.1,1,0,0,0.5,0,1,0,0.25,0\n"
      "a,1,0,0,0.1,1,0,0,0.5,0,1,0,0.5,0\n"
      "7,0,1,0,0.2,0,1,0,1,0,0,0,0,2\n"
      "7,0,2,0,0.2,0,1,0,1,0,0,0,0,2\n"
      "7,0,3,0,0.2,0,1,0,1,0,0,0,0,2\n";
  Result<StrokeInput> r = parseStrokeCsv(text, "s.csv");
  ASSERT_TRUE(r.isOk()) << messageOf(r);
  const StrokeSet& set = r->set;
  ASSERT_EQ(set.strokes.size(), 2u);
  EXPECT_EQ(set.strokes[0].points.size(), 2u);
  EXPECT_EQ(set.strokes[1].points.size(), 3u);
  EXPECT_EQ(set.strokes[1].style, 2u);
  EXPECT_EQ(set.styles.size(), 3u);
  EXPECT_DOUBLE_EQ(set.strokes[0].points[1].depth, 0.5);
  EXPECT_EQ(set.strokes[1].points[2].position, (Vec3d{0, 3, 0}));
  EXPECT_EQ(set.strokes[0].points[0].colour, (Vec3d{1, 0, 0}));
  EXPECT_DOUBLE_EQ(set.strokes[1].points[0].reflectance, 1.0);  // default: no column
}

TEST(PaintstrokesInput, CsvErrorsNameLineStrokeAndControlPoint) {
  auto expect = [](const std::string& text, const char* fragment) {
    Result<StrokeInput> r = parseStrokeCsv(text, "s.csv");
    ASSERT_FALSE(r.isOk()) << fragment;
    EXPECT_NE(messageOf(r).find(fragment), std::string::npos) << messageOf(r);
  };
  expect("stroke,x,y,z\n", "column \"radius\" is missing");
  expect("stroke,x,y,z,radius,width\n", "unknown column \"width\"");
  expect("stroke,x,y,z,radius\n1,0,0,0,1\n1,0,0,x,1\n", "s.csv: line 3 (stroke 0, control point 1): column \"z\": \"x\" is not a number");
  expect("stroke,x,y,z,radius\n1,0,0,0,1\n1,0,0,0\n", "line 3: 4 fields");
  expect("stroke,x,y,z,radius\n1,0,0,0,1\n2,0,0,0,1\n1,0,0,0,1\n", "line 4: stroke id \"1\" appears again");
  expect("stroke,x,y,z,radius\n", "no control points");
  // nan and inf are read here and refused by validation with their place.
  Result<StrokeInput> r = parseStrokeCsv("stroke,x,y,z,radius\n1,nan,0,0,1\n1,0,0,0,inf\n", "s.csv");
  ASSERT_TRUE(r.isOk()) << messageOf(r);
  EXPECT_TRUE(std::isnan(r->set.strokes[0].points[0].position[0]));
  EXPECT_TRUE(std::isinf(r->set.strokes[0].points[1].radius));
}

}  // namespace
}  // namespace bake::paintstrokes
