// Stroke generators (paintstrokes/input/grow.cpp, tree.cpp, generators.cpp): strokes grown on a mesh land on its
// surface, follow its normals, scatter in proportion to area and are identical for a seed; a tree has
// the stroke count its branching gives, shrinking radii and continuous joints; generator entries with
// bad values are refused naming the entry's member.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "bake/io/glb.h"
#include "bake/io/image.h"
#include "bake/paintstrokes/generators.h"

namespace bake::paintstrokes {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path testFolder() {
  const fs::path folder =
      fs::path(BAKE_TEST_TMP) / "strokes-generators" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

fs::path writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

// A regular octahedron of radius 1 (eight equal faces, no normals: the generator computes them).
const char* kOctahedron =
    "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
    "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";

// Two disjoint triangles facing +z, in the planes z = 0 (area 1/2) and z = 1 (area 3/2).
const char* kTwoTriangles =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 3 0 1\nv 0 1 1\n"
    "f 1 2 3\nf 4 5 6\n";

double distance(const Vec3d& a, const Vec3d& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}
Vec3d minus(const Vec3d& a, const Vec3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double norm(const Vec3d& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

bool allFinite(const StrokeSet& set) {
  for (const Stroke& s : set.strokes) {
    for (const StrokePoint& p : s.points) {
      for (double x : {p.position[0], p.position[1], p.position[2], p.radius, p.colour[0], p.colour[1], p.colour[2],
                       p.opacity, p.reflectance, p.globalNormal[0], p.globalNormal[1], p.globalNormal[2], p.depth}) {
        if (!std::isfinite(x)) return false;
      }
    }
  }
  return true;
}

bool identical(const StrokeSet& a, const StrokeSet& b) {
  if (a.strokes.size() != b.strokes.size()) return false;
  for (std::size_t i = 0; i < a.strokes.size(); ++i) {
    const auto& pa = a.strokes[i].points;
    const auto& pb = b.strokes[i].points;
    if (pa.size() != pb.size() || a.strokes[i].style != b.strokes[i].style) return false;
    for (std::size_t k = 0; k < pa.size(); ++k) {
      if (pa[k].position != pb[k].position || pa[k].radius != pb[k].radius || pa[k].colour != pb[k].colour ||
          pa[k].globalNormal != pb[k].globalNormal || pa[k].depth != pb[k].depth)
        return false;
    }
  }
  return true;
}

// Distance from p to the octahedron |x| + |y| + |z| = 1 (the surface, not the solid): the face planes
// are n . p = 1 with n = (+-1, +-1, +-1) / sqrt(3); a point on the surface lies on the plane of the
// face of its octant, so that plane's distance is 0 exactly when p is on the surface.
double octahedronDistance(const Vec3d& p) {
  return std::abs(std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]) - 1) / std::sqrt(3.0);
}

GrowSettings octahedronSettings(const fs::path& folder) {
  GrowSettings s;
  s.mesh = writeText(folder / "octahedron.obj", kOctahedron).string();
  s.count = 2000;
  s.seed = 7;
  return s;
}

TEST(GrowOnMesh, MakesTheCountWithThePointsAskedFor) {
  GrowSettings s = octahedronSettings(testFolder());
  s.pointsPerStroke = 7;
  auto grown = growOnMesh(s, Budgets{});
  ASSERT_TRUE(grown.isOk()) << grown.status().describe();
  ASSERT_EQ(grown->strokes.size(), 2000u);
  for (const Stroke& stroke : grown->strokes) ASSERT_EQ(stroke.points.size(), 7u);
  EXPECT_TRUE(allFinite(*grown));
  EXPECT_GE(grown->styles.size(), 1u);
}

TEST(GrowOnMesh, SameSeedGivesIdenticalStrokesAnotherSeedOthers) {
  GrowSettings s = octahedronSettings(testFolder());
  auto a = growOnMesh(s, Budgets{});
  auto b = growOnMesh(s, Budgets{});
  ASSERT_TRUE(a.isOk() && b.isOk());
  EXPECT_TRUE(identical(*a, *b));
  s.seed = 8;
  auto c = growOnMesh(s, Budgets{});
  ASSERT_TRUE(c.isOk());
  EXPECT_FALSE(identical(*a, *c));
}

TEST(GrowOnMesh, RootsLieOnTheSurface) {
  auto grown = growOnMesh(octahedronSettings(testFolder()), Budgets{});
  ASSERT_TRUE(grown.isOk());
  double worst = 0;
  for (const Stroke& stroke : grown->strokes) worst = std::max(worst, octahedronDistance(stroke.points[0].position));
  // The mesh is stored in single precision: a root is off by a few float ulps of a unit coordinate.
  EXPECT_LT(worst, 1e-6);
}

TEST(GrowOnMesh, StraightStrokesFollowTheNormalAndTaper) {
  GrowSettings s = octahedronSettings(testFolder());
  s.bend = 0;
  s.jitter = 0;
  s.length = 0.1;
  s.radius = 0.01;
  s.tipRadius = 0.5;
  auto grown = growOnMesh(s, Budgets{});
  ASSERT_TRUE(grown.isOk());
  for (const Stroke& stroke : grown->strokes) {
    const StrokePoint& root = stroke.points.front();
    const StrokePoint& tip = stroke.points.back();
    const Vec3d d = minus(tip.position, root.position);
    ASSERT_NEAR(norm(d), 0.1, 1e-12);
    ASSERT_NEAR(norm(root.globalNormal), 1, 1e-12);
    // The interpolated normal is the stroke's global normal; the stroke runs along it.
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(d[c] / 0.1, root.globalNormal[c], 1e-9);
    // ... and leaves the surface outwards (the computed normals of a convex mesh point out).
    ASSERT_GT(octahedronDistance(tip.position), 0.0);
    ASSERT_GT(std::abs(tip.position[0]) + std::abs(tip.position[1]) + std::abs(tip.position[2]), 1.0);
    EXPECT_DOUBLE_EQ(root.radius, 0.01);
    EXPECT_DOUBLE_EQ(tip.radius, 0.005);
    EXPECT_EQ(root.depth, 1);
    EXPECT_EQ(tip.depth, 0);
    for (std::size_t k = 1; k < stroke.points.size(); ++k) ASSERT_LT(stroke.points[k].radius, stroke.points[k - 1].radius);
  }
}

TEST(GrowOnMesh, ColourRunsFromRootToTip) {
  GrowSettings s = octahedronSettings(testFolder());
  s.count = 10;
  s.rootColour = {0.1, 0.2, 0.3};
  s.tipColour = {0.9, 0.8, 0.7};
  auto grown = growOnMesh(s, Budgets{});
  ASSERT_TRUE(grown.isOk());
  for (const Stroke& stroke : grown->strokes) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_DOUBLE_EQ(stroke.points.front().colour[c], s.rootColour[c]);
      EXPECT_NEAR(stroke.points.back().colour[c], s.tipColour[c], 1e-15);
    }
  }
}

TEST(GrowOnMesh, BendDisplacesTheTipByBendTimesLength) {
  // A flat square facing +z, bent along +x: tip = root + L (n + bend x).
  const fs::path folder = testFolder();
  GrowSettings s;
  s.mesh = writeText(folder / "square.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n").string();
  s.count = 50;
  s.jitter = 0;
  s.bend = 0.6;
  s.bendDirection = {2, 0, 0};  // normalised by the generator
  s.length = 0.2;
  auto grown = growOnMesh(s, Budgets{});
  ASSERT_TRUE(grown.isOk());
  for (const Stroke& stroke : grown->strokes) {
    const Vec3d d = minus(stroke.points.back().position, stroke.points.front().position);
    EXPECT_NEAR(d[0], 0.6 * 0.2, 1e-12);
    EXPECT_NEAR(d[1], 0, 1e-12);
    EXPECT_NEAR(d[2], 0.2, 1e-12);
    EXPECT_NEAR(stroke.points.front().position[2], 0, 1e-12);
  }
}

TEST(GrowOnMesh, RootsScatterInProportionToArea) {
  GrowSettings s;
  s.mesh = writeText(testFolder() / "two.obj", kTwoTriangles).string();
  s.count = 8000;
  s.seed = 3;
  auto grown = growOnMesh(s, Budgets{});
  ASSERT_TRUE(grown.isOk());
  std::size_t small = 0;
  for (const Stroke& stroke : grown->strokes) {
    const Vec3d& p = stroke.points[0].position;
    if (p[2] < 0.5) {
      ++small;
      ASSERT_NEAR(p[2], 0, 1e-12);
      ASSERT_LE(p[0] + p[1], 1 + 1e-9);
    } else {
      ASSERT_NEAR(p[2], 1, 1e-12);
      ASSERT_LE(p[0] / 3 + p[1], 1 + 1e-9);
    }
  }
  // Areas 1 : 3, so the small triangle's count is binomial(n, 1/4): mean n/4 = 2000, standard
  // deviation sqrt(n 1/4 3/4) = 38.7. Five deviations: a correct sampler fails this once in 1.7 million seeds.
  const double n = double(s.count), mean = n / 4, sd = std::sqrt(n * 0.25 * 0.75);
  EXPECT_NEAR(double(small), mean, 5 * sd);
  // Within the big triangle, uniformity: the half nearest its right-angle corner (x/3 + y < 1/sqrt(2)
  // holds half the area) gets half its roots.
  std::size_t inner = 0, big = 0;
  for (const Stroke& stroke : grown->strokes) {
    const Vec3d& p = stroke.points[0].position;
    if (p[2] < 0.5) continue;
    ++big;
    if (p[0] / 3 + p[1] < 1 / std::sqrt(2.0)) ++inner;
  }
  EXPECT_NEAR(double(inner), big / 2.0, 5 * std::sqrt(big * 0.25));
}

TEST(GrowOnMesh, LengthAndColourFromTexturesAtTheRootsTexcoord) {
  const fs::path folder = testFolder();
  // Every corner at uv (0.5, 0.5): halfway between the two texels of a 2x1 image, so bilinear
  // filtering gives their mean exactly.
  GrowSettings s;
  s.mesh = writeText(folder / "uv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.5\nf 1/1 2/1 3/1\n").string();
  Image length{2, 1, 1, {0.25f, 0.75f}};
  ASSERT_TRUE(writeImage(folder / "length.exr", length, PixelType::Float).isOk());
  Image colour{2, 1, 3, {0.1f, 0.2f, 0.3f, 0.3f, 0.4f, 0.5f}};
  ASSERT_TRUE(writeImage(folder / "colour.exr", colour, PixelType::Float).isOk());
  s.lengthFrom = "texture:" + (folder / "length.exr").string();
  s.colourFrom = "texture:" + (folder / "colour.exr").string();
  s.count = 20;
  s.jitter = 0;
  s.bend = 0;
  s.length = 0.2;
  s.rootColour = s.tipColour = {1, 1, 1};
  auto grown = growOnMesh(s, Budgets{});
  ASSERT_TRUE(grown.isOk()) << grown.status().describe();
  for (const Stroke& stroke : grown->strokes) {
    EXPECT_NEAR(distance(stroke.points.front().position, stroke.points.back().position), 0.2 * 0.5, 1e-7);
    EXPECT_NEAR(stroke.points[0].colour[0], 0.2, 1e-6);
    EXPECT_NEAR(stroke.points[0].colour[1], 0.3, 1e-6);
    EXPECT_NEAR(stroke.points[0].colour[2], 0.4, 1e-6);
  }
}

TEST(GrowOnMesh, LengthAndColourFromGltfVertexAttributes) {
  const fs::path folder = testFolder();
  glb::Package package;
  glb::Primitive primitive;
  const std::vector<float> positions{0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::vector<float> lengths{2, 2, 2};
  const std::vector<float> colours{0.5f, 0.25f, 1, 0.5f, 0.25f, 1, 0.5f, 0.25f, 1};
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, positions));
  primitive.attributes.push_back(glb::Attribute::fromFloats("_LENGTH", 1, lengths));
  primitive.attributes.push_back(glb::Attribute::fromFloats("COLOR_0", 3, colours));
  primitive.indices = {0, 1, 2};
  package.meshes.push_back({"tri", {primitive}});
  glb::Node node;
  node.mesh = 0;
  package.nodes.push_back(node);
  ASSERT_TRUE(glb::write(folder / "tri.glb", package).isOk());
  GrowSettings s;
  s.mesh = (folder / "tri.glb").string();
  s.count = 10;
  s.jitter = 0;
  s.bend = 0;
  s.length = 0.1;
  s.lengthFrom = "vertex:_LENGTH";
  s.colourFrom = "vertex";
  s.rootColour = s.tipColour = {0.8, 0.8, 0.8};
  glb::Mesh grownOn;
  auto grown = growOnMesh(s, Budgets{}, &grownOn);
  ASSERT_TRUE(grown.isOk()) << grown.status().describe();
  for (const Stroke& stroke : grown->strokes) {
    EXPECT_NEAR(distance(stroke.points.front().position, stroke.points.back().position), 0.2, 1e-7);
    EXPECT_NEAR(stroke.points[0].colour[0], 0.4, 1e-6);
    EXPECT_NEAR(stroke.points[0].colour[1], 0.2, 1e-6);
    EXPECT_NEAR(stroke.points[0].colour[2], 0.8, 1e-6);
  }
  ASSERT_EQ(grownOn.primitives.size(), 1u);
  EXPECT_NE(grownOn.primitives[0].find("POSITION"), nullptr);
  EXPECT_NE(grownOn.primitives[0].find("NORMAL"), nullptr);
  EXPECT_EQ(grownOn.primitives[0].indices.size(), 3u);

  // A mesh without the attribute asked for is invalid input naming the mesh.
  s.lengthFrom = "vertex:_MISSING";
  auto missing = growOnMesh(s, Budgets{});
  ASSERT_FALSE(missing.isOk());
  EXPECT_EQ(missing.status().code(), ExitCode::InvalidInput);
  EXPECT_EQ(missing.status().where().file, s.mesh);
}

TEST(GrowOnMesh, RefusesBadSettingsAndMissingFiles) {
  GrowSettings s = octahedronSettings(testFolder());
  s.length = 0;
  auto zero = growOnMesh(s, Budgets{});
  ASSERT_FALSE(zero.isOk());
  EXPECT_EQ(zero.status().code(), ExitCode::InvalidInput);
  EXPECT_EQ(zero.status().where().element, "length");

  s = octahedronSettings(testFolder());
  s.mesh += ".missing.obj";
  auto missing = growOnMesh(s, Budgets{});
  ASSERT_FALSE(missing.isOk());
  EXPECT_EQ(missing.status().code(), ExitCode::Io);

  s = octahedronSettings(testFolder());
  Budgets tight;
  tight.triangles = 4;
  auto budget = growOnMesh(s, tight);
  ASSERT_FALSE(budget.isOk());
  EXPECT_EQ(budget.status().code(), ExitCode::InvalidInput);
  EXPECT_NE(budget.status().message().find("budget"), std::string::npos);

  s = octahedronSettings(testFolder());
  s.mesh = writeText(testFolder() / "flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n").string();
  auto flat = growOnMesh(s, Budgets{});
  ASSERT_FALSE(flat.isOk());
  EXPECT_EQ(flat.status().code(), ExitCode::InvalidInput);
}

TEST(GrowTree, CountsFollowTheBranching) {
  for (int depth : {0, 1, 3, 5}) {
    for (int branching : {1, 2, 3}) {
      TreeSettings s;
      s.depth = depth;
      s.branching = branching;
      std::size_t expected = 0, level = 1;
      for (int l = 0; l <= depth; ++l, level *= std::size_t(branching)) expected += level;
      EXPECT_EQ(treeStrokeCount(s), expected);
      const StrokeSet tree = growTree(s);
      EXPECT_EQ(tree.strokes.size(), expected) << "depth " << depth << " branching " << branching;
    }
  }
}

TEST(GrowTree, RadiiShrinkJointsAreContinuousValuesFinite) {
  TreeSettings s;
  s.depth = 4;
  s.branching = 3;
  s.pointsPerStroke = 6;
  const StrokeSet tree = growTree(s);
  ASSERT_TRUE(allFinite(tree));
  const std::size_t b = std::size_t(s.branching);
  for (std::size_t i = 0; i < tree.strokes.size(); ++i) {
    const auto& points = tree.strokes[i].points;
    ASSERT_EQ(points.size(), 6u);
    for (std::size_t k = 1; k < points.size(); ++k) ASSERT_LT(points[k].radius, points[k - 1].radius);
    for (const StrokePoint& p : points) {
      ASSERT_GT(p.radius, 0);
      ASSERT_GE(p.depth, 0);
      ASSERT_LE(p.depth, 1);
      ASSERT_NEAR(norm(p.globalNormal), 1, 1e-12);
    }
    if (i == 0) {
      EXPECT_EQ(points.front().position, s.origin);
      EXPECT_DOUBLE_EQ(points.front().radius, s.trunkRadius);
      continue;
    }
    // Breadth-first order: stroke i's parent is (i - 1) / b.
    const auto& parent = tree.strokes[(i - 1) / b].points;
    EXPECT_LT(distance(points.front().position, parent.back().position), 1e-12) << "stroke " << i;
    EXPECT_NEAR(points.front().radius, parent.back().radius, 1e-15) << "stroke " << i;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(points.front().colour[c], parent.back().colour[c], 1e-12);
  }
  // The trunk rises: its tip is above its foot by most of its height.
  EXPECT_GT(tree.strokes[0].points.back().position[1], 0.8 * s.height);
}

TEST(GrowTree, SameSeedGivesTheSameTree) {
  TreeSettings s;
  s.seed = 11;
  EXPECT_TRUE(identical(growTree(s), growTree(s)));
  TreeSettings other = s;
  other.seed = 12;
  EXPECT_FALSE(identical(growTree(s), growTree(other)));
}

TEST(GrowTree, RefusesBadSettings) {
  TreeSettings s;
  s.radiusRatio = 1.2;
  EXPECT_EQ(checkTreeSettings(s).where().element, "radiusRatio");
  s = TreeSettings{};
  s.depth = 20;
  s.branching = 16;
  EXPECT_EQ(checkTreeSettings(s).code(), ExitCode::InvalidInput);
  EXPECT_TRUE(checkTreeSettings(TreeSettings{}).isOk());
}

struct GeneratorRun {
  Status status;
  StrokeSet set;
  std::vector<std::string> inputs;
  std::optional<glb::Mesh> mesh;
};

GeneratorRun run(const json& entry, const fs::path& folder, const std::string& element) {
  GeneratorRun r;
  r.set.styles.resize(2);
  r.status = runGenerator(entry, folder, {"scene.json", element}, Budgets{}, r.set, r.inputs, &r.mesh);
  return r;
}

TEST(Generators, GrowAndTreeEntriesAppendStrokes) {
  const fs::path folder = testFolder();
  fs::create_directories(folder / "meshes");
  writeText(folder / "meshes" / "octahedron.obj", kOctahedron);
  GeneratorRun r = run({{"type", "grow"}, {"mesh", "meshes/octahedron.obj"}, {"count", 300}, {"style", 1}}, folder, "generators[0]");
  ASSERT_TRUE(r.status.isOk()) << r.status.describe();
  EXPECT_EQ(r.set.strokes.size(), 300u);
  EXPECT_EQ(r.set.strokes[0].style, 1u);
  ASSERT_EQ(r.inputs.size(), 1u);
  EXPECT_EQ(fs::path(r.inputs[0]), (folder / "meshes" / "octahedron.obj").lexically_normal());
  ASSERT_TRUE(r.mesh.has_value());
  EXPECT_EQ(r.mesh->primitives.size(), 1u);

  const json tree{{"type", "tree"}, {"depth", 2}, {"branching", 4}, {"origin", {1, 0, 0}}};
  ASSERT_TRUE(runGenerator(tree, folder, {"scene.json", "generators[1]"}, Budgets{}, r.set, r.inputs, &r.mesh).isOk());
  EXPECT_EQ(r.set.strokes.size(), 300u + 1 + 4 + 16);
  EXPECT_EQ(r.set.strokes[300].points[0].position, (Vec3d{1, 0, 0}));
  EXPECT_EQ(r.set.styles.size(), 2u);  // the input's styles are untouched
}

TEST(Generators, BadEntriesNameTheEntryAndMember) {
  const fs::path folder = testFolder();
  writeText(folder / "octahedron.obj", kOctahedron);
  const auto expectError = [&](const json& entry, ExitCode code, const std::string& element) {
    const GeneratorRun r = run(entry, folder, "generators[2]");
    ASSERT_FALSE(r.status.isOk()) << entry.dump();
    EXPECT_EQ(r.status.code(), code) << r.status.describe();
    EXPECT_EQ(r.status.where().element, element) << r.status.describe();
    EXPECT_TRUE(r.set.strokes.empty());
  };
  const json grow{{"type", "grow"}, {"mesh", "octahedron.obj"}, {"count", 100}};
  auto with = [&](const char* key, const json& value) {
    json e = grow;
    e[key] = value;
    return e;
  };
  expectError(with("count", -5), ExitCode::InvalidInput, "generators[2].count");
  expectError(with("count", 0), ExitCode::InvalidInput, "generators[2].count");
  expectError(with("count", 2.5), ExitCode::InvalidInput, "generators[2].count");
  expectError(with("count", "many"), ExitCode::InvalidInput, "generators[2].count");
  expectError(with("length", 0), ExitCode::InvalidInput, "generators[2].length");
  expectError(with("jitter", 1), ExitCode::InvalidInput, "generators[2].jitter");
  expectError(with("tipColour", json{1, 2, 0}), ExitCode::InvalidInput, "generators[2].tipColour");
  expectError(with("bendDirection", json{0, 0}), ExitCode::InvalidInput, "generators[2].bendDirection");
  expectError(with("lengthFrom", "vertex"), ExitCode::InvalidInput, "generators[2].lengthFrom");
  expectError(with("style", 2), ExitCode::InvalidInput, "generators[2].style");
  expectError(with("lenght", 1), ExitCode::InvalidInput, "generators[2].lenght");
  expectError(json{{"type", "grass"}}, ExitCode::InvalidInput, "generators[2].type");
  expectError(json{{"count", 3}}, ExitCode::InvalidInput, "generators[2].type");
  expectError(json{{"type", "grow"}}, ExitCode::InvalidInput, "generators[2].mesh");
  expectError(json{{"type", "tree"}, {"branching", 0}}, ExitCode::InvalidInput, "generators[2].branching");
  expectError(json{{"type", "tree"}, {"depth", 20}, {"branching", 16}}, ExitCode::InvalidInput, "generators[2].depth");
  expectError(json::array(), ExitCode::InvalidInput, "generators[2]");

  // The typo's message suggests the known member.
  const GeneratorRun typo = run(with("lenght", 1), folder, "generators[2]");
  EXPECT_NE(typo.status.message().find("did you mean \"length\""), std::string::npos) << typo.status.message();

  // A mesh that is not there is an I/O error naming it.
  const GeneratorRun missing = run(with("mesh", "nowhere.obj"), folder, "generators[2]");
  ASSERT_FALSE(missing.status.isOk());
  EXPECT_EQ(missing.status.code(), ExitCode::Io);
  EXPECT_NE(missing.status.describe().find("nowhere.obj"), std::string::npos);

  // The control-point budget is checked before growing, on the entry's count.
  Budgets tight;
  tight.controlPoints = 499;  // 100 strokes of 5 points need 500
  StrokeSet set;
  std::vector<std::string> inputs;
  const Status overBudget = runGenerator(grow, folder, {"scene.json", "generators[2]"}, tight, set, inputs, nullptr);
  EXPECT_EQ(overBudget.code(), ExitCode::InvalidInput);
  EXPECT_EQ(overBudget.where().element, "generators[2].count");
  EXPECT_NE(overBudget.message().find("control-points"), std::string::npos);

  // Entries named by JSON pointer get pointer members.
  const GeneratorRun pointer = run(with("count", -1), folder, "/generators/2");
  EXPECT_EQ(pointer.status.where().element, "/generators/2/count");
  const GeneratorRun relative = run(with("count", -1), folder, "generators/2");
  EXPECT_EQ(relative.status.where().element, "generators/2/count");
}

}  // namespace
}  // namespace bake::paintstrokes
