// Profile validation and readers (profile.cpp, profile_read.cpp, profile_read_svg.cpp): errors name
// the file and the element at fault; repairs are reported as warnings; readers give the pieces the
// files describe (SVG arcs as bulges, curves within 1e-4, y flipped).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>

#include "bake/revolution/shape_map.h"
#include "revolution/input/profile_geometry.h"
#include "revolution/profile_shapes.h"
#include "support/golden.h"

namespace bake::revolution {
namespace {

using namespace bake::revolution::test;

std::string writeFile(const std::string& name, const std::string& text) {
  const auto path = bake::test::freshTempDir("profile") / name;
  std::ofstream(path) << text;
  return path.string();
}

double totalArea(const Profile& profile) {
  // Area of the solid by its coverage on a fine grid: independent of the contour bookkeeping.
  const ShapeGrid grid = gridForBounds(profileBounds(profile), 128, 2);
  const ShapeField field = distanceFromProfile(profile, grid);
  double area = 0;
  for (float c : field.coverage) area += c;
  return area * grid.texelSize * grid.texelSize;
}

TEST(ValidateProfile, NotFiniteNamesContourAndPoint) {
  Profile profile = makeProfile({rectangleContour(1, 0, 2, 1), rectangleContour(3, 0, 4, 1)});
  profile.contours[1].segments[2].b.h = std::numeric_limits<double>::quiet_NaN();  // segment 2 ends at point 3
  std::vector<std::string> warnings;
  const Status status = validateProfile(profile, warnings);
  ASSERT_FALSE(status.isOk());
  EXPECT_EQ(status.where().file, "test.json");
  EXPECT_EQ(status.where().element, "contour 1, point 3");
}

TEST(ValidateProfile, NegativeRadiusIsAnError) {
  Profile profile = makeProfile({rectangleContour(-0.5, 0, 2, 1)});
  std::vector<std::string> warnings;
  const Status status = validateProfile(profile, warnings);
  ASSERT_FALSE(status.isOk());
  EXPECT_NE(status.message().find("negative radius"), std::string::npos);
  EXPECT_EQ(status.where().element, "contour 0, point 0");
}

TEST(ValidateProfile, SelfIntersectionNamesBothSegmentsAndThePoint) {
  // A bow tie: piece 0 (1,0)-(3,2) crosses piece 2 (3,0)-(1,2) at (2, 1).
  Profile profile = makeProfile({makeContour({{1, 0}, {3, 2}, {3, 0}, {1, 2}}, {}, true)});
  std::vector<std::string> warnings;
  const Status status = validateProfile(profile, warnings);
  ASSERT_FALSE(status.isOk());
  EXPECT_EQ(status.where().element, "contour 0 segment 0 and contour 0 segment 2");
  EXPECT_NE(status.message().find("(2, 1)"), std::string::npos) << status.message();
}

TEST(ValidateProfile, ArcCrossingALineIsFound) {
  // A closed contour whose arc swings through a later straight piece.
  Profile profile = makeProfile({makeContour({{1, 0}, {3, 0}, {3, 1}, {1, 1}}, {0.0, 0.0, 0.0, 0.0}, true),
                                 makeContour({{2, -1}, {2, 2}, {2.5, 2}}, {-1.0, 0.0}, true)});
  std::vector<std::string> warnings;
  EXPECT_FALSE(validateProfile(profile, warnings).isOk());
}

TEST(ValidateProfile, ZeroLengthSegmentsAreDroppedWithAWarning) {
  Profile profile = makeProfile({makeContour({{1, 0}, {2, 0}, {2, 0}, {2, 1}, {1, 1}}, {}, true)});
  std::vector<std::string> warnings;
  ASSERT_TRUE(validateProfile(profile, warnings).isOk());
  EXPECT_EQ(profile.contours[0].segments.size(), 4u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("contour 0, point 1: zero-length segment dropped"), std::string::npos) << warnings[0];
}

TEST(ValidateProfile, OpenContoursCloseAlongTheAxis) {
  Profile profile = makeProfile({makeContour({{1.0, 0.0}, {1.0, 2.0}}, {}, false)});
  std::vector<std::string> warnings;
  ASSERT_TRUE(validateProfile(profile, warnings).isOk());
  const Contour& contour = profile.contours[0];
  EXPECT_TRUE(contour.closed);
  ASSERT_EQ(contour.segments.size(), 4u);
  int onAxis = 0;
  for (const Segment& s : contour.segments) onAxis += s.onAxis ? 1 : 0;
  EXPECT_EQ(onAxis, 1);
  EXPECT_EQ(warnings.size(), 2u);  // both ends got a horizontal run
  EXPECT_NEAR(totalArea(profile), 2.0, 1e-6);
}

TEST(ValidateProfile, HolesAreOrientedOppositeToTheirOuterContour) {
  // Both given counter-clockwise; the hole must come out clockwise (negative area).
  Profile profile = makeProfile({rectangleContour(1, 0, 5, 4), rectangleContour(2, 1, 3, 2)});
  std::vector<std::string> warnings;
  ASSERT_TRUE(validateProfile(profile, warnings).isOk());
  EXPECT_NEAR(totalArea(profile), 16.0 - 1.0, 1e-6);
  EXPECT_GT(signedDistance(profile, {2.5, 1.5}).distance, 0);
  EXPECT_LT(signedDistance(profile, {1.5, 0.5}).distance, 0);
}

TEST(ValidateProfile, BoundsIncludeArcExtremes) {
  Profile profile = makeProfile({halfDiscContour(2.0)});
  std::vector<std::string> warnings;
  ASSERT_TRUE(validateProfile(profile, warnings).isOk());
  const Bounds2 bounds = profileBounds(profile);
  EXPECT_NEAR(bounds.rMax, 2.0, 1e-12);
  EXPECT_NEAR(bounds.hMin, -2.0, 1e-12);
  EXPECT_NEAR(bounds.hMax, 2.0, 1e-12);
}

TEST(ReadProfile, JsonContoursWithBulges) {
  const std::string path = writeFile("p.json", R"({"contours": [
      {"closed": false, "points": [[0, -1], [0, 1]], "bulges": [1]}]})");
  auto profile = readProfileJson(path);
  ASSERT_TRUE(profile.isOk()) << profile.status().describe();
  std::vector<std::string> warnings;
  ASSERT_TRUE(validateProfile(*profile, warnings).isOk());
  EXPECT_NEAR(signedDistance(*profile, {0.3, 0.4}).distance, -0.5, 1e-12);  // unit sphere
}

TEST(ReadProfile, JsonBareListAndErrorsNameThePoint) {
  auto bare = readProfileJson(writeFile("bare.json", "[[1, 0], [1, 2]]"));
  ASSERT_TRUE(bare.isOk()) << bare.status().describe();
  EXPECT_EQ(bare->contours.size(), 1u);
  auto bad = readProfileJson(writeFile("bad.json", R"({"contours": [{"points": [[1, 0], [1, 2]]},
      {"points": [[1, 0], [2], [1, 2]]}]})"));
  ASSERT_FALSE(bad.isOk());
  EXPECT_EQ(bad.status().where().element, "contour 1, point 1");
}

TEST(ReadProfile, CsvContoursSplitByBlankLines) {
  const std::string path = writeFile("p.csv",
                                     "# a ring and a rod\n"
                                     "3,0\n4,0\n4,1\n3,1\n3,0\n"
                                     "\n"
                                     "0,2\n1,2,0\n1,3\n0,3\n");
  auto profile = readProfileCsv(path);
  ASSERT_TRUE(profile.isOk()) << profile.status().describe();
  ASSERT_EQ(profile->contours.size(), 2u);
  EXPECT_TRUE(profile->contours[0].closed);
  EXPECT_EQ(profile->contours[0].segments.size(), 4u);
  EXPECT_FALSE(profile->contours[1].closed);
  auto bad = readProfileCsv(writeFile("bad.csv", "1,0\n1,x\n"));
  ASSERT_FALSE(bad.isOk());
  EXPECT_EQ(bad.status().where().element, "contour 0, point 1 (line 2)");
  auto nan = readProfileCsv(writeFile("nan.csv", "1,0\nnan,1\n"));
  EXPECT_FALSE(nan.isOk());
}

TEST(ReadProfile, SvgArcsBecomeBulgesWithYFlipped) {
  // A half circle of radius 1 about the origin, right of the axis, drawn in SVG's y-down frame
  // with a relative arc; then a second path that the id selects.
  const std::string path = writeFile("p.svg", R"(<?xml version="1.0"?>
<svg xmlns="http://www.w3.org/2000/svg" xmlns:ink="http://example.com/editor"><ink:pathology/>
  <path d="M0,-1 A1 1 0 0 1 0,1 Z" id='sphere'/>
  <path id="rod" d="m 1 0 v -2 h 0.5 V 0 z"/>
</svg>)");
  auto sphere = readProfileSvg(path);
  ASSERT_TRUE(sphere.isOk()) << sphere.status().describe();
  std::vector<std::string> warnings;
  ASSERT_TRUE(validateProfile(*sphere, warnings).isOk());
  for (double angle = 0.1; angle < 6; angle += 0.7) {
    const Point2 p{0.5 * std::abs(std::cos(angle)) + 0.2, 1.3 * std::sin(angle)};
    EXPECT_NEAR(signedDistance(*sphere, p).distance, std::hypot(p.r, p.h) - 1.0, 1e-9);
  }
  auto rod = readProfileSvg(path, "rod");
  ASSERT_TRUE(rod.isOk()) << rod.status().describe();
  ASSERT_TRUE(validateProfile(*rod, warnings).isOk());
  const Bounds2 bounds = profileBounds(*rod);
  EXPECT_NEAR(bounds.hMin, 0.0, 1e-12);  // y = 0 .. -2 is h = 0 .. 2
  EXPECT_NEAR(bounds.hMax, 2.0, 1e-12);
  EXPECT_NEAR(totalArea(*rod), 1.0, 1e-6);
}

TEST(ReadProfile, SvgCurvesAreFlattenedWithinTheTolerance) {
  // A quarter of a unit circle as the standard cubic approximation, closed through the origin.
  const double k = 0.5522847498;
  const std::string d = "M 0 0 L 1 0 C 1 " + std::to_string(-k) + " " + std::to_string(k) + " -1 0 -1 Z";
  auto profile = readProfileSvg(writeFile("q.svg", "<svg><path d=\"" + d + "\"/></svg>"));
  ASSERT_TRUE(profile.isOk()) << profile.status().describe();
  // Every vertex of the flattened curve lies on the cubic, so within its 3e-4 of the circle,
  // and every chord midpoint within 1e-4 + 3e-4 of it.
  int curvePieces = 0;
  for (const Segment& s : profile->contours[0].segments) {
    const double ra = std::hypot(s.a.r, s.a.h);
    if (s.a.r > 0 && s.a.h > 0 && ra > 0.5) {
      ++curvePieces;
      EXPECT_NEAR(ra, 1.0, 3e-4);
      const double mid = std::hypot(0.5 * (s.a.r + s.b.r), 0.5 * (s.a.h + s.b.h));
      EXPECT_NEAR(mid, 1.0, 4e-4);
    }
  }
  EXPECT_GT(curvePieces, 8);
}

TEST(ReadProfile, TheThreeVaseFilesDescribeTheSameSolid) {
  // tests/revolution/data/vase.{json,csv,svg}: the vase of profile_shapes.h in each format.
  const std::filesystem::path data = bake::test::sourceDir() / "tests" / "revolution" / "data";
  Profile reference = makeProfile({vaseContour()});
  std::vector<std::string> warnings;
  ASSERT_TRUE(validateProfile(reference, warnings).isOk());
  std::vector<Result<Profile>> read;
  read.push_back(readProfileJson((data / "vase.json").string()));
  read.push_back(readProfileCsv((data / "vase.csv").string()));
  read.push_back(readProfileSvg((data / "vase.svg").string(), "vase"));
  for (auto& profile : read) {
    ASSERT_TRUE(profile.isOk()) << profile.status().describe();
    ASSERT_TRUE(validateProfile(*profile, warnings).isOk()) << profile->source;
    for (double r = 0.02; r < 1.1; r += 0.09)
      for (double h = -0.2; h < 2.2; h += 0.11)
        ASSERT_NEAR(signedDistance(*profile, {r, h}).distance, signedDistance(reference, {r, h}).distance, 1e-9)
            << profile->source << " at " << r << ", " << h;
  }
}

TEST(ReadProfile, SvgEllipticalArcsAreRefused) {
  auto profile = readProfileSvg(writeFile("e.svg", "<svg><path d='M0 0 A 2 1 0 0 1 0 2'/></svg>"));
  ASSERT_FALSE(profile.isOk());
  EXPECT_NE(profile.status().message().find("elliptical arc"), std::string::npos) << profile.status().describe();
}

// One SVG reader for the library (io/svg_drawing.h): element transforms and the root's viewBox apply
// (a path under scale(0.01) is 100 times smaller), units come from the root's width and height, and
// what the reader cannot follow is an error naming the element, never skipped.
TEST(ReadProfile, SvgTransformsAndViewBoxApply) {
  // Each writeFile starts a fresh folder: read each file before writing the next.
  const std::string plain = "<svg><path d='M 0 0 L 100 0 L 100 -200 L 0 -200 Z'/></svg>";
  const std::string scaled = "<svg><g transform='scale(0.01)'><path d='M 0 0 L 100 0 L 100 -200 L 0 -200 Z'/></g></svg>";
  // 1000 user units across shown 10 mm wide: the profile is in mm, a hundredth of a millimetre per
  // user unit, and the viewBox's top (y = -2000) is the viewport's y = 0: y = -200 lands at 18 mm.
  const std::string viewBox =
      "<svg width='10mm' height='20mm' viewBox='0 -2000 1000 2000'><path d='M 0 0 L 100 0 L 100 -200 L 0 -200 Z'/></svg>";
  std::vector<std::string> warnings;
  const double expectedTop[] = {200, 2, -18};
  const double expectedRight[] = {100, 1, 1};
  int k = 0;
  for (const std::string& text : {plain, scaled, viewBox}) {
    const std::string file = writeFile("drawing.svg", text);
    auto profile = readProfileSvg(file);
    ASSERT_TRUE(profile.isOk()) << profile.status().describe();
    ASSERT_TRUE(validateProfile(*profile, warnings).isOk()) << file;
    const Bounds2 bounds = profileBounds(*profile);
    EXPECT_NEAR(bounds.hMax, expectedTop[k], 1e-9) << file;
    EXPECT_NEAR(bounds.rMax, expectedRight[k], 1e-9) << file;
    ++k;
  }
  // A circle under a rotation and a uniform scale stays a circle; the bulges follow the y flip.
  auto circle = readProfileSvg(writeFile("circle.svg", "<svg><circle transform='rotate(30) scale(2)' cx='1' cy='0' r='0.5'/></svg>"));
  ASSERT_TRUE(circle.isOk()) << circle.status().describe();
  ASSERT_TRUE(validateProfile(*circle, warnings).isOk());
  const double c = 3.14159265358979323846 / 6;
  const Point2 centre{2 * std::cos(c), -2 * std::sin(c)};
  EXPECT_NEAR(signedDistance(*circle, {centre.r, centre.h}).distance, -1.0, 1e-9);
  EXPECT_NEAR(signedDistance(*circle, {centre.r + 1.5, centre.h}).distance, 0.5, 1e-9);
}

TEST(ReadProfile, SvgConstructsItCannotFollowAreErrors) {
  auto expectError = [&](const std::string& name, const std::string& text, const std::string& part, const std::string& id = "") {
    auto profile = readProfileSvg(writeFile(name, text), id);
    ASSERT_FALSE(profile.isOk()) << name;
    EXPECT_NE(profile.status().describe().find(part), std::string::npos) << profile.status().describe();
  };
  expectError("text.svg", "<svg xmlns='http://www.w3.org/2000/svg'><text>vase</text><path d='M 0 0 L 1 0 L 1 1 Z'/></svg>", "<text> (line 1)");
  expectError("skew.svg", "<svg><path transform='skewX(20)' d='M 0 0 A 1 1 0 0 1 2 0 Z'/></svg>", "not a similarity");
  expectError("unit.svg", "<svg width='3em' height='3em' viewBox='0 0 1 1'><path d='M 0 0 L 1 0 L 1 1 Z'/></svg>", "3em");
  expectError("aspect.svg", "<svg width='1' height='2' viewBox='0 0 1 1' preserveAspectRatio='none'><path d='M 0 0 L 1 0 L 1 1 Z'/></svg>",
              "preserveAspectRatio");
  expectError("missing.svg", "<svg><path id='a' d='M 0 0 L 1 0 L 1 1 Z'/></svg>", "no shape with id", "b");
}


// Stiff cases: extreme scales, nearly straight and nearly full arcs, points on the surface, at an
// arc's centre and very far away must give finite, correct answers.
Profile scaledVase(double factor) {
  Profile profile = makeProfile({vaseContour()});
  for (Contour& c : profile.contours)
    for (Segment& s : c.segments) {
      s.a = {s.a.r * factor, s.a.h * factor};
      s.b = {s.b.r * factor, s.b.h * factor};
    }
  std::vector<std::string> warnings;
  EXPECT_TRUE(validateProfile(profile, warnings).isOk());
  return profile;
}

TEST(ProfileStiff, DistanceScalesWithTinyAndHugeProfiles) {
  const Profile unit = scaledVase(1.0);
  for (double factor : {1e-7, 1e7}) {
    const Profile scaled = scaledVase(factor);
    for (double r = 0.05; r < 1.2; r += 0.17)
      for (double h = -0.3; h < 2.3; h += 0.23) {
        const double expected = signedDistance(unit, {r, h}).distance * factor;
        const double got = signedDistance(scaled, {r * factor, h * factor}).distance;
        ASSERT_NEAR(got, expected, 1e-9 * factor) << factor << " at " << r << ", " << h;
      }
  }
}

TEST(ProfileStiff, NearlyStraightAndNearlyFullArcs) {
  // A bulge of 1e-12 is a line to within round-off; a 359-degree arc is nearly a full circle.
  Profile flat = makeProfile({makeContour({{1, 0}, {2, 0}, {2, 1}, {1, 1}}, {0.0, 1e-12, 0.0, 0.0}, true)});
  std::vector<std::string> warnings;
  ASSERT_TRUE(validateProfile(flat, warnings).isOk());
  EXPECT_NEAR(signedDistance(flat, {2.5, 0.5}).distance, 0.5, 1e-9);
  EXPECT_NEAR(signedDistance(flat, {1.9, 0.5}).distance, -0.1, 1e-9);
  const double sweep = 359.0 * std::numbers::pi / 180.0;
  const Point2 a{3 + std::cos(-0.5 * sweep), 2 + std::sin(-0.5 * sweep)};
  const Point2 b{3 + std::cos(0.5 * sweep), 2 + std::sin(0.5 * sweep)};
  Profile full = makeProfile({makeContour({a, b}, {std::tan(sweep / 4)}, true)});
  ASSERT_TRUE(validateProfile(full, warnings).isOk());
  // The closing chord (at r = 3 + cos(179.5 deg)) is surface too.
  const double chordR = 3 + std::cos(0.5 * sweep);
  EXPECT_NEAR(signedDistance(full, {3.0, 2.0}).distance, -(3.0 - chordR), 1e-9);  // the arc's centre
  EXPECT_NEAR(signedDistance(full, {4.5, 2.0}).distance, 0.5, 1e-9);
  EXPECT_NEAR(signedDistance(full, {3.0, 2.5}).distance, -0.5, 1e-9);
  EXPECT_NEAR(signedDistance(full, {3.0, 3.2}).distance, 0.2, 1e-9);
}

TEST(ProfileStiff, OnTheSurfaceAndFarAwayStayFinite) {
  const Profile profile = scaledVase(1.0);
  for (const Contour& c : profile.contours)
    for (const Segment& s : c.segments) {
      if (s.onAxis) continue;
      const DistanceSample onSurface = signedDistance(profile, pointAt(s, 0.37));
      EXPECT_NEAR(onSurface.distance, 0.0, 1e-12);
      EXPECT_NEAR(std::hypot(onSurface.gradR, onSurface.gradH), 1.0, 1e-9);
    }
  const DistanceSample far = signedDistance(profile, {1e12, -3e12});
  EXPECT_TRUE(std::isfinite(far.distance));
  EXPECT_NEAR(far.distance / std::hypot(1e12, 3e12), 1.0, 1e-6);
}

TEST(ProfileStiff, RoundOffBelowTheAxisSnapsAndOverlapsAreRefused) {
  Profile snapped = makeProfile({makeContour({{-1e-15, 0}, {1, 0}, {1, 1}, {-1e-15, 1}}, {}, true)});
  std::vector<std::string> warnings;
  ASSERT_TRUE(validateProfile(snapped, warnings).isOk());
  int onAxis = 0;
  for (const Segment& s : snapped.contours[0].segments) onAxis += s.onAxis ? 1 : 0;
  EXPECT_EQ(onAxis, 1);
  // Two contours sharing an edge overlap.
  Profile overlap = makeProfile({rectangleContour(1, 0, 2, 1), rectangleContour(2, 0.5, 3, 1.5)});
  const Status status = validateProfile(overlap, warnings);
  ASSERT_FALSE(status.isOk());
  EXPECT_TRUE(status.message().find("overlaps") != std::string::npos ||
              status.message().find("crosses") != std::string::npos) << status.message();
  // An arc that bulges across the axis.
  Profile across = makeProfile({makeContour({{0.2, 0}, {0.2, 1}}, {-1.0}, false)});
  EXPECT_FALSE(validateProfile(across, warnings).isOk());
}

}  // namespace
}  // namespace bake::revolution
