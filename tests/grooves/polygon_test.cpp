// Convex polygon clipping for area sampling (libbake/grooves/oracle/polygon.h): areas of known cases,
// subtraction into disjoint pieces, degenerate inputs, and the fragment set's overflow fallback.
#include <cmath>

#include <gtest/gtest.h>

#include "grooves/oracle/polygon.h"

namespace bake::grooves {
namespace {

ConvexPolygon rectangle(double u0, double v0, double u1, double v1) {
  ConvexPolygon p;
  p.add({u0, v0});
  p.add({u1, v0});
  p.add({u1, v1});
  p.add({u0, v1});
  return p;
}

// Area of a ∩ b by brute force on a fine grid of cell centres, an independent check of intersect().
double sampledOverlap(const ConvexPolygon& a, const ConvexPolygon& b, double u0, double v0, double size, int n) {
  int inside = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec2 x{u0 + (i + 0.5) * size / n, v0 + (j + 0.5) * size / n};
      inside += contains(a, x) && contains(b, x);
    }
  return inside * (size / n) * (size / n);
}

TEST(GroovePolygon, AreaAndCentroidOfKnownShapes) {
  const ConvexPolygon r = rectangle(1, 2, 4, 4);
  EXPECT_DOUBLE_EQ(signedArea(r), 6);
  EXPECT_NEAR(centroid(r).u, 2.5, 1e-15);
  EXPECT_NEAR(centroid(r).v, 3, 1e-15);
  ConvexPolygon t;
  t.add({0, 0});
  t.add({0, 3});
  t.add({3, 0});  // clockwise
  EXPECT_DOUBLE_EQ(signedArea(t), -4.5);
  makeCounterClockwise(t);
  EXPECT_DOUBLE_EQ(signedArea(t), 4.5);
  EXPECT_NEAR(centroid(t).u, 1, 1e-15);
  EXPECT_NEAR(centroid(t).v, 1, 1e-15);
  const ConvexPolygon p = parallelogram({1, 1}, {2, 0}, {1, 1});
  EXPECT_NEAR(signedArea(p), 2, 1e-15);
  const ConvexPolygon flipped = parallelogram({1, 1}, {1, 1}, {2, 0});
  EXPECT_NEAR(signedArea(flipped), 2, 1e-15);  // always counter-clockwise
}

TEST(GroovePolygon, ClipByHalfPlane) {
  const ConvexPolygon square = rectangle(0, 0, 1, 1);
  EXPECT_NEAR(area(clip(square, {{1, 0}, 0.25})), 0.75, 1e-15);
  // The diagonal u + v >= 1 keeps half.
  EXPECT_NEAR(area(clip(square, {{1, 1}, 1})), 0.5, 1e-15);
  // Everything or nothing.
  EXPECT_NEAR(area(clip(square, {{1, 0}, -5})), 1, 1e-15);
  EXPECT_TRUE(clip(square, {{1, 0}, 5}).empty());
  // A line through an edge keeps the whole square (boundary included) or drops it.
  EXPECT_NEAR(area(clip(square, {{1, 0}, 0})), 1, 1e-15);
  EXPECT_TRUE(clip(square, {{1, 0}, 1}).empty());
  // A line through two opposite vertices.
  const ConvexPolygon half = clip(square, {{-1, 1}, 0});
  EXPECT_EQ(half.count, 3);
  EXPECT_NEAR(area(half), 0.5, 1e-15);
}

TEST(GroovePolygon, IntersectionAreasMatchSampling) {
  const ConvexPolygon a = rectangle(0, 0, 2, 1);
  const ConvexPolygon b = rectangle(1, 0.5, 3, 3);
  EXPECT_NEAR(area(intersect(a, b)), 0.5, 1e-15);
  ConvexPolygon tri;
  tri.add({0.2, -0.5});
  tri.add({2.5, 0.3});
  tri.add({0.4, 1.7});
  const double exact = area(intersect(a, tri));
  EXPECT_NEAR(exact, sampledOverlap(a, tri, -1, -1, 4, 800), 2e-3);
  EXPECT_NEAR(exact, area(intersect(tri, a)), 1e-14);
  EXPECT_TRUE(intersect(a, rectangle(5, 5, 6, 6)).empty());
}

TEST(GroovePolygon, SubtractionGivesDisjointConvexPieces) {
  const ConvexPolygon square = rectangle(0, 0, 1, 1);
  const ConvexPolygon hole = rectangle(0.25, 0.25, 0.75, 0.75);
  std::array<ConvexPolygon, kPolygonMaxVertices> pieces;
  const int n = subtract(square, hole, 0, pieces);
  ASSERT_EQ(n, 4);
  double total = 0;
  for (int i = 0; i < n; ++i) {
    total += area(pieces[i]);
    EXPECT_GT(signedArea(pieces[i]), 0);
    EXPECT_LT(area(intersect(pieces[i], hole)), 1e-15);
    for (int j = i + 1; j < n; ++j) EXPECT_LT(area(intersect(pieces[i], pieces[j])), 1e-15);
  }
  EXPECT_NEAR(total, 0.75, 1e-15);
  // A hole covering everything leaves nothing; a disjoint hole leaves the polygon whole.
  EXPECT_EQ(subtract(square, rectangle(-1, -1, 2, 2), 0, pieces), 0);
  ASSERT_EQ(subtract(square, rectangle(3, 3, 4, 4), 0, pieces), 1);
  EXPECT_NEAR(area(pieces[0]), 1, 1e-15);
  // A hole over one corner: the L-shaped rest in two pieces.
  const int m = subtract(square, rectangle(0.5, 0.5, 2, 2), 0, pieces);
  double rest = 0;
  for (int i = 0; i < m; ++i) rest += area(pieces[i]);
  EXPECT_NEAR(rest, 0.75, 1e-15);
}

TEST(GroovePolygon, DegenerateInputs) {
  ConvexPolygon segment;
  segment.add({0, 0});
  segment.add({1, 1});
  EXPECT_TRUE(segment.empty());
  EXPECT_EQ(area(segment), 0);
  EXPECT_TRUE(intersect(segment, rectangle(0, 0, 1, 1)).empty());
  // A collinear "triangle" has zero area and its centroid is the vertex mean.
  ConvexPolygon flat = segment;
  flat.add({2, 2});
  EXPECT_EQ(area(flat), 0);
  EXPECT_NEAR(centroid(flat).u, 1, 1e-15);
  // Subtracting a zero-area hole removes nothing.
  FragmentSet set;
  set.add(rectangle(0, 0, 1, 1));
  set.subtract(flat);
  EXPECT_NEAR(set.weightedArea(), 1, 1e-15);
  // p minus an empty hole is p, whole: one piece and nothing inside (the surface build subtracts
  // the part of a cell where one layer wins, which can be empty).
  std::array<ConvexPolygon, kPolygonMaxVertices> pieces;
  ConvexPolygon inside;
  const int n = subtract(rectangle(0, 0, 1, 1), ConvexPolygon{}, 0, pieces, inside);
  ASSERT_EQ(n, 1);
  EXPECT_NEAR(area(pieces[0]), 1, 1e-15);
  EXPECT_TRUE(inside.empty());
  // A point outside, on the edge, inside.
  const ConvexPolygon square = rectangle(0, 0, 1, 1);
  EXPECT_FALSE(contains(square, {1.5, 0.5}));
  EXPECT_TRUE(contains(square, {1, 0.5}));
  EXPECT_TRUE(contains(square, {0.5, 0.5}));
  // A full polygon drops the extra vertex and says so.
  ConvexPolygon full;
  for (int i = 0; i <= kPolygonMaxVertices; ++i) full.add({double(i), 0});
  EXPECT_EQ(full.count, kPolygonMaxVertices);
  EXPECT_TRUE(full.truncated);
}

TEST(GroovePolygon, RepeatedVerticesDoNotBreakSubtraction) {
  // A hole whose vertex list repeats a point (a clip line through a vertex can leave one): its
  // zero-length edge must not turn into a half-plane.
  ConvexPolygon hole;
  hole.add({0, 0});
  hole.add({1, 0});
  hole.add({1, 0});
  hole.add({0, 1});
  ConvexPolygon nearly = hole;
  nearly.vertex[2] = {1, 1e-17};  // a few ulps away: no reliable direction either
  const ConvexPolygon square = rectangle(-1, -1, 2, 2);
  std::array<ConvexPolygon, kPolygonMaxVertices> pieces;
  for (const ConvexPolygon& h : {hole, nearly}) {
    const int n = subtract(square, h, 0, pieces);
    double rest = 0;
    for (int i = 0; i < n; ++i) rest += area(pieces[i]);
    EXPECT_NEAR(rest, 9 - 0.5, 1e-12);
    EXPECT_NEAR(area(intersect(square, h)), 0.5, 1e-12);
  }
  // Clipping through a vertex does not repeat it.
  ConvexPolygon triangle;
  triangle.add({0, 0});
  triangle.add({2, 0});
  triangle.add({0, 2});
  const ConvexPolygon cut = clip(triangle, {{1, 0}, 0});
  EXPECT_EQ(cut.count, 3);
}

TEST(GroovePolygon, FragmentSetSubtractsOverlappingHoles) {
  FragmentSet set;
  set.add(rectangle(0, 0, 4, 4));
  set.subtract(rectangle(1, 1, 3, 3));
  set.subtract(rectangle(2, 2, 5, 5));  // overlaps the first hole: inclusion-exclusion
  EXPECT_NEAR(set.weightedArea(), 16 - 4 - 4 + 1, 1e-13);
  EXPECT_EQ(set.overflows, 0u);
  for (int i = 0; i < set.count; ++i)
    for (int j = i + 1; j < set.count; ++j)
      EXPECT_LT(area(intersect(set.fragment[i].polygon, set.fragment[j].polygon)), 1e-13);
}

TEST(GroovePolygon, FragmentOverflowDegradesGracefully) {
  // Many small holes in a grid split the square into more fragments than the set holds.
  FragmentSet set;
  set.add(rectangle(0, 0, 1, 1));
  const int n = 12;
  const double hole = 0.25 / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = (i + 0.5) / n, v = (j + 0.5) / n;
      set.subtract(rectangle(u - hole, v - hole, u + hole, v + hole));
    }
  EXPECT_GT(set.overflows, 0u);
  EXPECT_LE(set.count, kMaxFragments);
  // Disjoint holes: the weight fallback is exact in area.
  const double expected = 1 - n * n * (2 * hole) * (2 * hole);
  EXPECT_NEAR(set.weightedArea(), expected, 1e-12);
}

// The in-place clip and the subtraction's inner part are the very polygons clip() and intersect()
// give (the sampler relies on it to clip once where it used to clip twice), and copies carry exactly
// the vertices that are set.
TEST(GroovePolygon, InPlaceClipAndSubtractionRestMatchClipAndIntersect) {
  ConvexPolygon p;
  for (int k = 0; k < 7; ++k) p.add({std::cos(0.9 * k), 0.8 * std::sin(0.9 * k)});
  makeCounterClockwise(p);
  ConvexPolygon hole;
  hole.add({-0.3, -0.4});
  hole.add({0.6, -0.2});
  hole.add({0.5, 0.7});
  hole.add({-0.2, 0.3});
  for (const HalfPlane& h : {HalfPlane{{1, 0.2}, 0.1}, HalfPlane{{0, 1}, 2}, HalfPlane{{0, 1}, -2}}) {
    const ConvexPolygon expected = clip(p, h);
    ConvexPolygon got = p;
    clipInPlace(got, h);
    ASSERT_EQ(got.count, expected.count);
    for (int i = 0; i < got.count; ++i) {
      EXPECT_EQ(got.vertex[i].u, expected.vertex[i].u);
      EXPECT_EQ(got.vertex[i].v, expected.vertex[i].v);
    }
  }
  std::array<ConvexPolygon, kPolygonMaxVertices> pieces, again;
  ConvexPolygon rest;
  const int n = subtract(p, hole, 0, pieces, rest);
  EXPECT_EQ(subtract(p, hole, 0, again), n);
  const ConvexPolygon inside = intersect(p, hole);
  ASSERT_EQ(rest.count, inside.count);
  for (int i = 0; i < rest.count; ++i) {
    EXPECT_EQ(rest.vertex[i].u, inside.vertex[i].u);
    EXPECT_EQ(rest.vertex[i].v, inside.vertex[i].v);
  }
  double sum = area(rest);
  for (int i = 0; i < n; ++i) sum += area(pieces[i]);
  EXPECT_NEAR(sum, area(p), 1e-14);
  const ConvexPolygon copy = rest;
  ConvexPolygon assigned;
  assigned = copy;
  EXPECT_EQ(assigned.count, rest.count);
  EXPECT_EQ(area(assigned), area(rest));
}

// split() gives both sides of a line in one pass: vertex for vertex the polygons clip() gives for the
// half-plane and for its opposite (the surface build slices cells with it instead of clipping twice).
TEST(GroovePolygon, SplitGivesBothClipsVertexForVertex) {
  ConvexPolygon p;
  for (int k = 0; k < 7; ++k) p.add({std::cos(0.9 * k), 0.8 * std::sin(0.9 * k)});
  makeCounterClockwise(p);
  auto expectSame = [](const ConvexPolygon& a, const ConvexPolygon& b) {
    ASSERT_EQ(a.count, b.count);
    for (int i = 0; i < a.count; ++i) {
      EXPECT_EQ(a.vertex[i].u, b.vertex[i].u);
      EXPECT_EQ(a.vertex[i].v, b.vertex[i].v);
    }
  };
  // Across, across through a vertex ((1, 0) lies on v = 0), wholly inside, wholly outside.
  const HalfPlane cases[] = {{{1, 0.2}, 0.1}, {{0, 1}, 0}, {{0, 1}, -2}, {{0, 1}, 2}};
  const int sides[] = {0, 0, 1, -1};
  for (int c = 0; c < 4; ++c) {
    const HalfPlane h = cases[c];
    const HalfPlane opposite{{-h.normal.u, -h.normal.v}, -h.offset};
    ConvexPolygon inside, outside;
    EXPECT_EQ(split(p, h, inside, outside), sides[c]) << "case " << c;
    expectSame(inside, clip(p, h));
    expectSame(outside, clip(p, opposite));
    ConvexPolygon kept = p, away;
    splitInPlace(kept, h, away);
    expectSame(kept, inside);
    expectSame(away, outside);
    if (sides[c] == 0) EXPECT_NEAR(area(inside) + area(outside), area(p), 1e-14) << "case " << c;
  }
}

}  // namespace
}  // namespace bake::grooves
