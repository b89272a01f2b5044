// Property test of the vector shape map (shape_map_vector.cpp) against the independent exact
// reference (revolution/reference/exact_reference.h): thousands of random profiles, built to hit the
// degenerate cases of an inside test (vertices, arc ends, extreme points of arcs and horizontal pieces
// exactly on texel rows, vertical pieces on texel columns, pieces on and a hair off the axis, tiny
// arcs, nearly straight and nearly full arcs, contours crossing each other), at random grids. Every
// texel's sign and distance must match the reference: no sign error where the texel is more than
// 1e-6 texel off the curve, and the stored float within 1e-3 texel.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>

#include "bake/revolution/shape_map.h"
#include "revolution/reference/exact_reference.h"

namespace bake::revolution {
namespace {

class ProfileGenerator {
 public:
  ProfileGenerator(std::uint64_t seed) : rng_(seed) {}

  ShapeGrid grid() {
    ShapeGrid g;
    g.width = integer(4, 48);
    g.height = integer(4, 48);
    g.texelSize = std::pow(10.0, uniform(-3, 1));
    // Rows from an offset that is not a multiple of the texel, sometimes far from 0.
    g.hMin = (chance(0.2) ? uniform(-1e3, 1e3) : uniform(-5, 5)) * g.texelSize;
    return g;
  }

  Profile profile(const ShapeGrid& g) {
    grid_ = g;
    Profile profile;
    const int contours = integer(1, 3);
    for (int c = 0; c < contours; ++c) {
      switch (integer(0, 4)) {
        case 0: profile.contours.push_back(starPolygon(false)); break;
        case 1: profile.contours.push_back(starPolygon(true)); break;
        case 2: profile.contours.push_back(circleOfArcs()); break;
        case 3: profile.contours.push_back(gridBox()); break;
        default: profile.contours.push_back(axisContour()); break;
      }
    }
    return profile;
  }

 private:
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  bool chance(double p) { return uniform(0, 1) < p; }

  // A row or column coordinate: often exactly a texel centre or edge, else anywhere on the grid.
  double rowH() {
    const double j = integer(0, grid_.height - 1);
    if (chance(0.5)) return grid_.centreH(int(j));
    if (chance(0.3)) return grid_.hMin + j * grid_.texelSize;
    return grid_.hMin + uniform(0, grid_.height) * grid_.texelSize;
  }
  double columnR() {
    const int i = integer(0, grid_.width - 1);
    if (chance(0.1)) return 0.0;
    if (chance(0.05)) return 1e-9 * grid_.texelSize;
    if (chance(0.4)) return grid_.centreR(i);
    if (chance(0.3)) return i * grid_.texelSize;
    return uniform(0, grid_.width) * grid_.texelSize;
  }
  double bulge() {
    switch (integer(0, 6)) {
      case 0: return 0.0;
      case 1: return 0.0;
      case 2: return (chance(0.5) ? 1 : -1) * 1e-7;
      case 3: return (chance(0.5) ? 1 : -1) * 1.0;
      case 4: return (chance(0.5) ? 1 : -1) * uniform(1.0, 8.0);
      default: return uniform(-1, 1);
    }
  }

  Contour closedContour(const std::vector<Point2>& points, bool arcs) {
    Contour contour;
    contour.closed = true;
    for (std::size_t k = 0; k < points.size(); ++k) {
      Segment s{points[k], points[(k + 1) % points.size()], arcs ? bulge() : 0.0};
      if (s.a.r == s.b.r && s.a.h == s.b.h) continue;
      s.onAxis = s.a.r == 0 && s.b.r == 0 && s.bulge == 0;
      contour.segments.push_back(s);
    }
    return contour;
  }

  // A star-shaped polygon whose vertices snap to rows and columns (snapping may make it cross itself:
  // the even-odd rule and the distance are defined all the same).
  Contour starPolygon(bool arcs) {
    const int n = integer(3, 8);
    const Point2 centre{columnR(), rowH()};
    const double size = uniform(0.5, 0.5 * std::max(grid_.width, grid_.height)) * grid_.texelSize;
    std::vector<double> angles(n);
    for (double& a : angles) a = uniform(0, 2 * std::numbers::pi);
    std::sort(angles.begin(), angles.end());
    std::vector<Point2> points;
    for (double a : angles) {
      Point2 p{std::abs(centre.r + size * uniform(0.2, 1) * std::cos(a)), centre.h + size * uniform(0.2, 1) * std::sin(a)};
      if (chance(0.5)) p.h = rowH();
      if (chance(0.3)) p.r = columnR();
      if (chance(0.05)) p = {p.r + 1e-3 * grid_.texelSize, p.h};  // tiny pieces next to a vertex
      points.push_back(p);
    }
    return closedContour(points, arcs);
  }

  // A circle of 2-4 arcs whose ends, and whose top and bottom, lie on texel rows: the torus of
  // two half circles with a horizontal chord is the case that once stored a whole row outside.
  Contour circleOfArcs() {
    const int pieces = integer(2, 4);
    const double radius = integer(1, 6) * grid_.texelSize * (chance(0.5) ? 1.0 : 0.5);
    const Point2 centre{columnR() + radius, rowH()};
    const double start = chance(0.6) ? 0.0 : (chance(0.5) ? std::numbers::pi / 2 : uniform(0, 2 * std::numbers::pi));
    const double sweep = 2 * std::numbers::pi / pieces;
    std::vector<Point2> points;
    for (int k = 0; k < pieces; ++k) {
      const double a = start + k * sweep;
      points.push_back({centre.r + radius * std::cos(a), centre.h + radius * std::sin(a)});
    }
    if (start == 0.0) {
      points[0].h = centre.h;
      if (pieces == 2) points[1].h = centre.h;
      if (pieces == 4) {
        points[1].r = points[3].r = centre.r;
        points[2].h = centre.h;
      }
    }
    // Counter-clockwise with positive bulges, or the same circle walked clockwise.
    const bool clockwise = chance(0.5);
    if (clockwise) std::reverse(points.begin(), points.end());
    const double b = std::tan(sweep / 4) * (clockwise ? -1 : 1);
    Contour contour;
    contour.closed = true;
    for (int k = 0; k < pieces; ++k) contour.segments.push_back({points[k], points[(k + 1) % pieces], b});
    return contour;
  }

  // An axis-aligned box with its sides on texel rows and columns (horizontal pieces on rows).
  Contour gridBox() {
    double r0 = columnR(), r1 = columnR();
    double h0 = rowH(), h1 = rowH();
    if (r0 == r1) r1 = r0 + grid_.texelSize;
    if (h0 == h1) h1 = h0 + grid_.texelSize;
    return closedContour({{r0, h0}, {r1, h0}, {r1, h1}, {r0, h1}}, chance(0.3));
  }

  // An open contour from the axis to the axis, closed along it.
  Contour axisContour() {
    const int n = integer(1, 5);
    std::vector<Point2> points{{0.0, rowH()}};
    for (int k = 0; k < n; ++k) points.push_back({columnR(), rowH()});
    points.push_back({0.0, rowH()});
    Contour contour = closedContour(points, true);
    for (Segment& s : contour.segments)
      if (s.a.r == 0 && s.b.r == 0) {
        s.bulge = 0;
        s.onAxis = true;
      }
    return contour;
  }

  std::mt19937_64 rng_;
  ShapeGrid grid_;
};

std::string describe(const Profile& profile, const ShapeGrid& grid) {
  std::ostringstream out;
  out.precision(17);
  out << "grid " << grid.width << "x" << grid.height << " texel " << grid.texelSize << " hMin " << grid.hMin << "\n";
  for (const Contour& c : profile.contours) {
    out << "contour:";
    for (const Segment& s : c.segments)
      out << " [(" << s.a.r << "," << s.a.h << ")->(" << s.b.r << "," << s.b.h << ") b=" << s.bulge << (s.onAxis ? " axis" : "") << "]";
    out << "\n";
  }
  return out.str();
}

bool hasSurface(const Profile& profile) {
  for (const Contour& c : profile.contours)
    for (const Segment& s : c.segments)
      if (!s.onAxis) return true;
  return false;
}

TEST(ShapeMapSignProperty, RandomProfilesMatchTheExactReference) {
  ProfileGenerator generator(20261204);
  int checked = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const ShapeGrid grid = generator.grid();
    const Profile profile = generator.profile(grid);
    if (!hasSurface(profile)) continue;
    const ShapeField field = distanceFromProfile(profile, grid);
    const double texel = grid.texelSize;
    for (int j = 0; j < grid.height; ++j)
      for (int i = 0; i < grid.width; ++i) {
        const Point2 p{grid.centreR(i), grid.centreH(j)};
        const double reference = reference::signedDistanceReference(profile, p);
        const double stored = field.at(i, j);
        if (std::abs(reference) > reference::kSignSlackTexels * texel)
          ASSERT_EQ(stored < 0, reference < 0) << "sign at texel (" << i << ", " << j << "), reference " << reference / texel
                                               << " texels, stored " << stored / texel << "\n"
                                               << describe(profile, grid);
        ASSERT_LE(std::abs(stored - reference), 1e-3 * texel)
            << "distance at texel (" << i << ", " << j << ")\n" << describe(profile, grid);
      }
    // The accelerated whole-grid check agrees with the texel-by-texel one.
    const reference::FieldCheck check = reference::checkField(profile, grid, field.distance, 1);
    ASSERT_EQ(check.signErrors, 0u) << describe(profile, grid);
    ASSERT_LE(check.maxError, 1e-3) << describe(profile, grid);
    ASSERT_EQ(check.texels, std::size_t(grid.width) * grid.height);
    ++checked;
  }
  EXPECT_GT(checked, 2500);
}

// The reference itself on closed forms: a circle (|p - c| - R, inside exactly when |p - c| < R) and
// a box, including points on the rows of vertices and on horizontal sides.
TEST(ShapeMapSignProperty, ReferenceMatchesClosedForms) {
  Profile torus;
  Contour tube;
  tube.closed = true;
  tube.segments = {{{0.38, 0.3}, {0.62, 0.3}, 1.0}, {{0.62, 0.3}, {0.38, 0.3}, 1.0}};
  torus.contours = {tube};
  for (double r = 0.0; r <= 1.0; r += 1.0 / 64)
    for (double h : {0.3, 0.3 + 1e-12, 0.3 - 1e-12, 0.42, 0.18, 0.25, 0.35}) {
      const double exact = std::hypot(r - 0.5, h - 0.3) - 0.12;
      if (std::abs(exact) < 1e-9) continue;
      EXPECT_EQ(reference::insideExact(torus, {r, h}), exact < 0) << r << ", " << h;
      EXPECT_NEAR(reference::signedDistanceReference(torus, {r, h}), exact, 1e-12) << r << ", " << h;
    }
  Profile box;
  Contour square;
  square.closed = true;
  square.segments = {{{1, 1}, {2, 1}}, {{2, 1}, {2, 2}}, {{2, 2}, {1, 2}}, {{1, 2}, {1, 1}}};
  box.contours = {square};
  EXPECT_TRUE(reference::insideExact(box, {1.5, 1.5}));
  EXPECT_FALSE(reference::insideExact(box, {0.5, 1.0}));  // on a side's row, left of it
  EXPECT_FALSE(reference::insideExact(box, {2.5, 2.0}));
  EXPECT_FALSE(reference::insideExact(box, {0.5, 1.5}));
  EXPECT_NEAR(reference::distanceToSurface(box, {0.5, 1.0}), 0.5, 1e-15);
  EXPECT_NEAR(reference::distanceToSurface(box, {1.5, 1.25}), 0.25, 1e-15);
}

// The case once reported: the torus of two half-circle arcs, its chord on a texel row, stored
// outside over a whole row of the tube.
TEST(ShapeMapSignProperty, TorusChordOnATexelRow) {
  ShapeGrid grid;
  grid.width = 64;
  grid.height = 64;
  grid.texelSize = 0.01;
  grid.hMin = 0.3 - 32.5 * grid.texelSize;
  const double h = grid.centreH(32);  // the chord lies exactly on row 32's centres
  Profile torus;
  Contour tube;
  tube.closed = true;
  tube.segments = {{{0.38, h}, {0.62, h}, 1.0}, {{0.62, h}, {0.38, h}, 1.0}};
  torus.contours = {tube};
  const ShapeField field = distanceFromProfile(torus, grid);
  const reference::FieldCheck check = reference::checkField(torus, grid, field.distance, 1);
  EXPECT_EQ(check.signErrors, 0u);
  EXPECT_LE(check.maxError, 1e-3);
  EXPECT_LT(field.at(50, 32), 0.0f);  // r = 0.505, inside the tube
}

}  // namespace
}  // namespace bake::revolution
