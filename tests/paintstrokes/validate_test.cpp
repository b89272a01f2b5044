// Validation and repair of stroke sets (libbake/paintstrokes/validate.h): refusals name the stroke and the
// control point; coincident points are dropped (the later one) with a warning; normals normalised.
#include <cmath>
#include <cstdio>
#include <limits>

#include <gtest/gtest.h>

#include "paintstrokes/input/validate.h"

namespace bake::paintstrokes {
namespace {

StrokeSet twoStrokes() {
  StrokeSet set;
  set.styles.emplace_back();
  for (int s = 0; s < 2; ++s) {
    Stroke stroke;
    for (int i = 0; i < 4; ++i) {
      StrokePoint p;
      p.position = {double(i), double(s), 0};
      p.radius = 0.1;
      stroke.points.push_back(p);
    }
    set.strokes.push_back(stroke);
  }
  return set;
}

std::string refusal(StrokeSet set) {
  Diagnostics diagnostics("test", true);
  Result<ValidationCounts> r = validateStrokes(set, "in.json", diagnostics);
  return r.isOk() ? std::string("(accepted)") : r.status().describe();
}

TEST(PaintstrokesValidation, RefusesBadValuesNamingStrokeAndControlPoint) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  StrokeSet set = twoStrokes();
  set.strokes[1].points[2].radius = -0.2;
  EXPECT_EQ(refusal(set), "in.json: stroke 1, control point 2: radius is -0.2 (must be > 0)");
  set = twoStrokes();
  set.strokes[0].points[3].radius = 0;
  EXPECT_NE(refusal(set).find("stroke 0, control point 3: radius is 0"), std::string::npos);
  set = twoStrokes();
  set.strokes[1].points[0].position[1] = nan;
  EXPECT_NE(refusal(set).find("stroke 1, control point 0: position is (0, nan, 0) (must be finite)"), std::string::npos) << refusal(set);
  set = twoStrokes();
  set.strokes[0].points[1].radius = inf;
  EXPECT_NE(refusal(set).find("stroke 0, control point 1: radius is inf"), std::string::npos) << refusal(set);
  set = twoStrokes();
  set.strokes[0].points[2].colour[1] = 1.5;
  EXPECT_NE(refusal(set).find("stroke 0, control point 2: colour"), std::string::npos);
  set = twoStrokes();
  set.strokes[1].points[1].opacity = -0.1;
  EXPECT_NE(refusal(set).find("stroke 1, control point 1: opacity is -0.1"), std::string::npos);
  set = twoStrokes();
  set.strokes[1].points[1].globalNormal = {nan, 0, 0};
  EXPECT_NE(refusal(set).find("stroke 1, control point 1: normal"), std::string::npos);
  set = twoStrokes();
  set.strokes[1].points.resize(1);
  EXPECT_EQ(refusal(set), "in.json: stroke 1: 1 control point (a stroke needs at least 2)");
  set = twoStrokes();
  set.strokes[0].style = 1;
  EXPECT_NE(refusal(set).find("stroke 0: style 1 does not exist"), std::string::npos);
  set = twoStrokes();
  set.strokes[0].points[0].position[0] = 2e30;
  EXPECT_NE(refusal(set).find("stroke 0, control point 0: position coordinate"), std::string::npos);
  set.strokes.clear();
  EXPECT_NE(refusal(set).find("no strokes"), std::string::npos);
}

TEST(PaintstrokesValidation, DropsCoincidentPointsDeterministicallyAndWarns) {
  StrokeSet set = twoStrokes();
  auto& points = set.strokes[1].points;
  points.insert(points.begin() + 2, points[1]);  // exactly equal to its predecessor
  points[2].radius = 0.3;                        // the later one is dropped, whatever it carries
  points.insert(points.begin() + 4, points[3]);
  points[4].position[0] += 1e-12;                // within 1e-9 x the 3-unit extent
  char buffer[4096] = {};
  std::FILE* stream = fmemopen(buffer, sizeof(buffer), "w");
  Diagnostics diagnostics("strokebake", false, stream);
  Result<ValidationCounts> r = validateStrokes(set, "in.json", diagnostics);
  std::fclose(stream);
  ASSERT_TRUE(r.isOk()) << r.status().describe();
  EXPECT_EQ(r->droppedPoints, 2u);
  ASSERT_EQ(set.strokes[1].points.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(set.strokes[1].points[i].position[0], double(i));
    EXPECT_EQ(set.strokes[1].points[i].radius, 0.1);
  }
  const std::string text(buffer);
  EXPECT_NE(text.find("in.json: stroke 1, control point 2: at the same place as the point before it: dropped"), std::string::npos) << text;
  EXPECT_NE(text.find("stroke 1, control point 4"), std::string::npos) << text;
  EXPECT_EQ(diagnostics.warnings().at("coincident-control-points").count, 2);
}

TEST(PaintstrokesValidation, PointsApartByMoreThanTheToleranceAreKept) {
  StrokeSet set = twoStrokes();
  set.strokes[0].points[1].position = {1e-8, 0, 0};  // 3.3e-9 of the extent: kept
  Diagnostics diagnostics("test", true);
  Result<ValidationCounts> r = validateStrokes(set, "in.json", diagnostics);
  ASSERT_TRUE(r.isOk());
  EXPECT_EQ(r->droppedPoints, 0u);
}

TEST(PaintstrokesValidation, AStrokeOfOnePlaceIsRefusedAfterRepair) {
  StrokeSet set = twoStrokes();
  for (StrokePoint& p : set.strokes[0].points) p.position = {5, 5, 5};
  EXPECT_NE(refusal(set).find("stroke 0: every control point is at the same place"), std::string::npos) << refusal(set);
}

TEST(PaintstrokesValidation, NormalsAreNormalisedAndZeroStaysZero) {
  StrokeSet set = twoStrokes();
  set.strokes[0].points[0].globalNormal = {0, 3, 4};
  set.strokes[0].points[1].globalNormal = {0, 0, 0};
  set.strokes[0].points[2].globalNormal = {0, 1, 0};
  Diagnostics diagnostics("test", true);
  Result<ValidationCounts> r = validateStrokes(set, "in.json", diagnostics);
  ASSERT_TRUE(r.isOk());
  EXPECT_EQ(r->normalisedNormals, 1u);
  EXPECT_NEAR(set.strokes[0].points[0].globalNormal[1], 0.6, 1e-15);
  EXPECT_NEAR(set.strokes[0].points[0].globalNormal[2], 0.8, 1e-15);
  EXPECT_EQ(set.strokes[0].points[1].globalNormal, (Vec3d{0, 0, 0}));
}

}  // namespace
}  // namespace bake::paintstrokes

namespace bake::paintstrokes {
namespace {

StrokeStyle styleNamed(const std::string& name) {
  StrokeStyle style;
  style.name = name;
  return style;
}

TEST(PaintstrokesStyles, UnusedStylesAreDroppedAndTheStrokesRenumbered) {
  StrokeSet set = twoStrokes();
  set.styles = {styleNamed("a"), styleNamed("b"), styleNamed("c"), styleNamed("d")};
  set.strokes[0].style = 3;
  set.strokes[1].style = 1;
  EXPECT_EQ(unusedStyles(set), (std::vector<std::string>{"a", "c"}));
  EXPECT_EQ(dropUnusedStyles(set), (std::vector<std::string>{"a", "c"}));
  ASSERT_EQ(set.styles.size(), 2u);
  EXPECT_EQ(set.styles[0].name, "b");
  EXPECT_EQ(set.styles[1].name, "d");
  EXPECT_EQ(set.strokes[0].style, 1u);  // "d"
  EXPECT_EQ(set.strokes[1].style, 0u);  // "b"
  EXPECT_TRUE(dropUnusedStyles(set).empty());
}

TEST(PaintstrokesStyles, ASetWithoutStrokesKeepsItsFirstStyle) {
  StrokeSet set;
  set.styles = {styleNamed("only"), styleNamed("other")};
  EXPECT_EQ(dropUnusedStyles(set), (std::vector<std::string>{"other"}));
  ASSERT_EQ(set.styles.size(), 1u);
  EXPECT_EQ(set.styles[0].name, "only");
}

}  // namespace
}  // namespace bake::paintstrokes
