// SVG drawings as groove input (libbake/grooves/input/svg_file.h; formats/groove-scene.md `svgFile`): shapes
// become grooves placed by the viewBox, the placement and element transforms; what cannot be followed
// exactly (ellipses, arcs under a skew, text) is refused naming the element.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bake/core/vec.h"
#include "grooves/input/scene.h"
#include "grooves/input/svg_file.h"

namespace bake::grooves {
namespace {

namespace fs = std::filesystem;

class SvgFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("bake-svg-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  // A drawing of 100 x 50 user units with the given body.
  fs::path drawing(const std::string& body) {
    return write("d.svg", "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 100 50\">\n" +
                              body + "\n</svg>\n");
  }
  std::vector<std::vector<PathPiece>> readOk(const fs::path& file, SvgPlacement placement = {}) {
    Result<std::vector<std::vector<PathPiece>>> r = readSvgFile(file, placement, "/grooves/0/path/svgFile/file");
    EXPECT_TRUE(r.isOk()) << r.status().describe();
    return r.isOk() ? r.value() : std::vector<std::vector<PathPiece>>{};
  }
  void expectInvalid(const fs::path& file, std::initializer_list<const char*> fragments) {
    Result<std::vector<std::vector<PathPiece>>> r = readSvgFile(file, {}, "/grooves/0/path/svgFile/file");
    ASSERT_FALSE(r.isOk());
    EXPECT_EQ(int(r.status().code()), 3);
    const std::string text = r.status().describe();
    for (const char* f : fragments) EXPECT_NE(text.find(f), std::string::npos) << "missing \"" << f << "\" in: " << text;
  }

  fs::path dir_;
};

void expectNear(Vec2 a, Vec2 b, double tolerance = 1e-12) {
  EXPECT_NEAR(a.u, b.u, tolerance);
  EXPECT_NEAR(a.v, b.v, tolerance);
}

TEST_F(SvgFile, ViewBoxPlacementFlipsYAndScales) {
  // A line from the top-left corner to the middle of the right side; placed at (1, 2), 0.01 per unit.
  const auto paths = readOk(drawing("<line x1='0' y1='0' x2='100' y2='25'/>"), {{1, 2}, 0.01});
  ASSERT_EQ(paths.size(), 1u);
  ASSERT_EQ(paths[0].size(), 1u);
  expectNear(paths[0][0].p[0], {1, 2.5});  // the top-left corner is 0.5 above the origin
  expectNear(paths[0][0].p[1], {2, 2.25});
}

TEST_F(SvgFile, EveryShapeKindAndGroupTransforms) {
  const auto paths = readOk(drawing(
      "<g transform='translate(10 5)'>"
      "  <polyline points='0,0 10,0 10,10'/>"
      "  <g transform='scale(2)'><polygon points='0 0 5 0 5 5'/></g>"
      "</g>"
      "<rect x='20' y='20' width='10' height='5'/>"
      "<rect x='40' y='20' width='10' height='10' rx='2'/>"
      "<circle cx='70' cy='25' r='5'/>"
      "<ellipse cx='90' cy='25' rx='3' ry='3'/>"
      "<path d='M 0 40 L 10 40 M 0 45 L 10 45'/>"
      "<defs><path d='M 0 0 L 1 1'/></defs><title>ignored</title>"));
  // polyline, polygon, rect, rounded rect, circle, circular ellipse, and the two subpaths of the path.
  ASSERT_EQ(paths.size(), 8u);
  // polyline: (10, 5) in user space -> (10, 50 - 5) in texture space.
  expectNear(paths[0][0].p[0], {10, 45});
  expectNear(paths[0][1].p[1], {20, 35});
  // polygon under translate(10 5) scale(2): (5, 5) -> (20, 15) -> v = 35; closed by Z (3 pieces).
  ASSERT_EQ(paths[1].size(), 3u);
  expectNear(paths[1][1].p[1], {20, 35});
  EXPECT_EQ(paths[2].size(), 4u);  // the square-cornered rectangle
  int arcs = 0;
  for (const PathPiece& p : paths[3]) arcs += p.kind == PathPiece::Kind::Arc;
  EXPECT_EQ(arcs, 4);  // the rounded rectangle's corners
  // The circle: arcs of radius 5 around (70, 25), the flip turns the sweep clockwise-positive around.
  double sweep = 0;
  for (const PathPiece& p : paths[4]) {
    ASSERT_EQ(p.kind, PathPiece::Kind::Arc);
    EXPECT_NEAR(p.radius, 5, 1e-12);
    expectNear(p.centre, {70, 25}, 1e-9);
    sweep += p.sweep;
  }
  EXPECT_NEAR(std::abs(sweep), 2 * kPi, 1e-9);
  EXPECT_EQ(paths[5][0].kind, PathPiece::Kind::Arc);
  expectNear(paths[6][0].p[0], {0, 10});
  expectNear(paths[7][0].p[0], {0, 5});
}

TEST_F(SvgFile, ArcsFollowSimilaritiesWithTheirEndPoints) {
  // A quarter circle under rotate + uniform scale: the end points computed from centre, radius and
  // angles must land where the transformed path's end points are.
  const auto paths = readOk(drawing("<path transform='rotate(30 50 25) scale(1.5)' d='M 20 10 A 10 10 0 0 1 30 20'/>"));
  ASSERT_EQ(paths.size(), 1u);
  ASSERT_EQ(paths[0].size(), 1u);
  const PathPiece& arc = paths[0][0];
  ASSERT_EQ(arc.kind, PathPiece::Kind::Arc);
  EXPECT_NEAR(arc.radius, 15, 1e-9);
  EXPECT_NEAR(std::abs(arc.sweep), kPi / 2, 1e-9);
  const Vec2 start{arc.centre.u + arc.radius * std::cos(arc.startAngle), arc.centre.v + arc.radius * std::sin(arc.startAngle)};
  const Vec2 end{arc.centre.u + arc.radius * std::cos(arc.startAngle + arc.sweep),
                 arc.centre.v + arc.radius * std::sin(arc.startAngle + arc.sweep)};
  // User (20, 10) -> scale 1.5 -> (30, 15) -> rotate 30 degrees about (50, 25) -> flip.
  const double c = std::cos(kPi / 6), s = std::sin(kPi / 6);
  auto place = [&](double x, double y) {
    x *= 1.5, y *= 1.5;
    const double rx = 50 + c * (x - 50) - s * (y - 25), ry = 25 + s * (x - 50) + c * (y - 25);
    return Vec2{rx, 50 - ry};
  };
  expectNear(start, place(20, 10), 1e-9);
  expectNear(end, place(30, 20), 1e-9);
}

TEST_F(SvgFile, RefusesWhatCannotBeFollowedExactly) {
  expectInvalid(drawing("<ellipse cx='10' cy='10' rx='5' ry='3'/>"), {"d.svg", "<ellipse>", "line 3", "rx != ry"});
  expectInvalid(drawing("<circle id='c1' transform='scale(2 1)' cx='10' cy='10' r='5'/>"),
                {"<circle id=\"c1\">", "not a similarity"});
  expectInvalid(drawing("<path transform='skewX(20)' d='M 0 0 A 5 5 0 0 1 10 0'/>"), {"not a similarity"});
  expectInvalid(drawing("<text x='1' y='1'>hi</text>"), {"<text> is not supported"});
  expectInvalid(drawing("<g transform='spin(3)'><line x1='0' y1='0' x2='1' y2='1'/></g>"), {"spin", "not an SVG transform"});
  expectInvalid(drawing("<path d='M 0 0 L 5 5 X'/>"), {"<path>", "unknown command"});
  expectInvalid(drawing("<polyline points='0 0 1'/>"), {"pairs of numbers"});
  expectInvalid(drawing("<desc>nothing</desc>"), {"no shapes"});
  expectInvalid(write("bad.svg", "<svg viewBox='0 0 1 1'><line></svg>"), {"bad.svg", "not well-formed XML", "line 1"});
  expectInvalid(write("nobox.svg", "<svg width='10mm' height='5mm'><line x1='0' y1='0' x2='1' y2='1'/></svg>"),
                {"needs a viewBox"});
  expectInvalid(write("html.svg", "<html/>"), {"root element is not <svg>"});
  expectInvalid(write("empty.svg", ""), {"empty"});
}

TEST_F(SvgFile, MissingFileIsAnIoError) {
  Result<std::vector<std::vector<PathPiece>>> r = readSvgFile(dir_ / "none.svg", {}, "/grooves/0");
  ASSERT_FALSE(r.isOk());
  EXPECT_EQ(int(r.status().code()), 2);
}

TEST_F(SvgFile, SceneGroovesFromADrawing) {
  write("logo.svg", "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 10 10'>"
                    "<line x1='1' y1='5' x2='9' y2='5'/><circle cx='5' cy='5' r='3'/></svg>");
  nlohmann::json scene = nlohmann::json::parse(R"({
    "version": 1, "domain": {"size": [1, 1]},
    "profiles": {"v": {"points": [[-0.01, 0], [0, -0.005], [0.01, 0]]}},
    "materials": {"metal": {}}, "base": "metal",
    "grooves": [{"name": "logo", "profile": "v", "path": {"svgFile": {"file": "logo.svg", "origin": [0.25, 0.25], "scale": 0.05}}}]
  })");
  const fs::path file = write("scene.json", scene.dump());
  Result<GrooveScene> r = readGrooveScene(file.string());
  ASSERT_TRUE(r.isOk()) << r.status().describe();
  ASSERT_EQ(r->grooves.size(), 2u);
  EXPECT_EQ(r->grooves[0].name, "logo#0");
  EXPECT_TRUE(r->grooves[1].closed);
  ASSERT_EQ(r->files.size(), 1u);
  EXPECT_EQ(fs::path(r->files[0]).filename(), "logo.svg");
  // The line runs across the middle of the placed drawing: v = 0.25 + 0.05 * 5.
  const Primitive& line = r->primitives[r->grooves[0].firstPrimitive];
  EXPECT_NEAR(line.a.v, 0.5, 1e-12);
  EXPECT_NEAR(line.a.u, 0.3, 1e-12);
  EXPECT_NEAR(line.b.u, 0.7, 1e-12);
  // From memory, a scene may not name files.
  Result<GrooveScene> memory = parseGrooveScene(scene.dump(), "scene.json");
  ASSERT_FALSE(memory.isOk());
  EXPECT_NE(memory.status().describe().find("not read from a file"), std::string::npos);
}

}  // namespace
}  // namespace bake::grooves
