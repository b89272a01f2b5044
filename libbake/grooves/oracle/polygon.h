// Convex polygons of fixed capacity for the area sampling of seed 000 §6 (footprint clipping,
// intersection removal and occlusion are all clips and subtractions of convex polygons): clipping by a
// half-plane (Sutherland-Hodgman on one edge; both sides of the line at once by split()),
// convex-convex intersection, and convex-minus-convex as a few convex pieces (the part outside each
// edge of the subtracted polygon in turn). Fixed capacities
// and no allocation, so the same code ports to a fragment shader; overflows degrade gracefully and are
// counted (below).
#pragma once

#include <array>
#include <cstdint>

#include "grooves/input/scene.h"

namespace bake::grooves {

// Clipping a convex n-gon by a half-plane gives at most n + 1 vertices; a piece of the surface is cut
// by its strip, joint lines, band lines and a few plane comparisons, far below this.
constexpr int kPolygonMaxVertices = 24;

// The half-plane normal . x >= offset.
struct HalfPlane {
  Vec2 normal;
  double offset = 0;
  double distance(Vec2 x) const { return normal.u * x.u + normal.v * x.v - offset; }
};
// The half-plane left of the directed line a -> b (inside of a counter-clockwise polygon's edge).
HalfPlane leftOf(Vec2 a, Vec2 b);

struct ConvexPolygon {
  // Only the first `count` vertices are set: the rest is neither initialised nor copied (polygons are
  // made and copied in the inner loops of the sampler, mostly with far fewer vertices than the cap).
  union {
    std::array<Vec2, kPolygonMaxVertices> vertex;
  };
  int count = 0;
  bool truncated = false;  // a vertex was dropped for lack of room (the polygon shrank slightly)

  ConvexPolygon() {}
  ConvexPolygon(const ConvexPolygon& o) : count(o.count), truncated(o.truncated) {
    for (int i = 0; i < o.count; ++i) vertex[i] = o.vertex[i];
  }
  ConvexPolygon& operator=(const ConvexPolygon& o) {
    count = o.count;
    truncated = o.truncated;
    for (int i = 0; i < o.count; ++i) vertex[i] = o.vertex[i];
    return *this;
  }

  bool empty() const { return count < 3; }
  void add(Vec2 x) {  // drops x (and sets `truncated`) when full
    if (count == kPolygonMaxVertices) {
      truncated = true;
      return;
    }
    vertex[count++] = x;
  }
};

ConvexPolygon parallelogram(Vec2 centre, Vec2 axis1, Vec2 axis2);  // centre +- axis1/2 +- axis2/2, CCW
double signedArea(const ConvexPolygon& p);
double area(const ConvexPolygon& p);
Vec2 centroid(const ConvexPolygon& p);  // area centroid; the vertex mean when degenerate
void makeCounterClockwise(ConvexPolygon& p);

struct Box2 {
  Vec2 lower{1e300, 1e300}, upper{-1e300, -1e300};
  bool overlaps(const Box2& o) const {
    return lower.u <= o.upper.u && o.lower.u <= upper.u && lower.v <= o.upper.v && o.lower.v <= upper.v;
  }
};
Box2 boundsOf(const ConvexPolygon& p);

ConvexPolygon clip(const ConvexPolygon& p, const HalfPlane& h);
void clipInPlace(ConvexPolygon& p, const HalfPlane& h);  // p = clip(p, h), without copying when unchanged
// 1: p lies inside h (boundary included), -1: outside it (boundary included), 0: h's line crosses it.
int sideOf(const ConvexPolygon& p, const HalfPlane& h);
// Both sides of h's line in one pass: `inside` = clip(p, h) and `outside` = clip(p, -h), vertex for
// vertex. Returns 1 when p lies inside h (boundary included), -1 when outside, 0 when the line crosses
// it.
int split(const ConvexPolygon& p, const HalfPlane& h, ConvexPolygon& inside, ConvexPolygon& outside);
// p = clip(p, h) and outside = clip(p, -h) (of the former p).
void splitInPlace(ConvexPolygon& p, const HalfPlane& h, ConvexPolygon& outside);
// The half-planes of a counter-clockwise polygon's edges that intersect() and subtract() use: edges
// shorter than 1e-12 of the polygon's size (its longest edge) are left out (their direction is
// rounding noise).
int edgeHalfPlanes(const ConvexPolygon& p, std::array<HalfPlane, kPolygonMaxVertices>& out);
// `clipper` counter-clockwise.
ConvexPolygon intersect(const ConvexPolygon& p, const ConvexPolygon& clipper);
// The same with the clipper's edgeHalfPlanes() already known (a clipper used many times).
ConvexPolygon intersect(const ConvexPolygon& p, const std::array<HalfPlane, kPolygonMaxVertices>& edges, int n);
bool contains(const ConvexPolygon& p, Vec2 x);  // p counter-clockwise; boundary included

// p minus hole (hole counter-clockwise) as at most hole.count disjoint convex pieces, written to
// `pieces`; returns their number (an empty hole leaves p whole: one piece). Pieces of area <= minArea are left out. Here and in intersect(),
// edges shorter than 1e-12 of the polygon's size are ignored (their direction is rounding noise).
int subtract(const ConvexPolygon& p, const ConvexPolygon& hole, double minArea,
             std::array<ConvexPolygon, kPolygonMaxVertices>& pieces);
// The same, also giving what is left of p inside the hole: the very polygon intersect(p, hole) returns
// (the same clips in the same order), so a caller needing both clips once.
int subtract(const ConvexPolygon& p, const ConvexPolygon& hole, double minArea,
             std::array<ConvexPolygon, kPolygonMaxVertices>& pieces, ConvexPolygon& rest);
// The same with the hole's edgeHalfPlanes() already known.
int subtract(const ConvexPolygon& p, const std::array<HalfPlane, kPolygonMaxVertices>& edges, int count,
             double minArea, std::array<ConvexPolygon, kPolygonMaxVertices>& pieces, ConvexPolygon& rest);

// A set of disjoint convex fragments with weights (the visible, lit part of a piece). The capacity is
// fixed; when a subtraction would need more room, the fragment is kept whole and its weight lowered
// so that its weighted area drops by the area of the hole inside it (exact in area as long as the
// holes that were not cut out do not overlap later holes), and `overflows` counts it.
constexpr int kMaxFragments = 48;
struct Fragment {
  ConvexPolygon polygon;
  double weight = 1;
};
struct FragmentSet {
  std::array<Fragment, kMaxFragments> fragment;
  int count = 0;
  double minArea = 0;        // fragments at or below this area are dropped
  std::uint32_t overflows = 0;
  bool truncated = false;    // some polygon lost a vertex for lack of room

  void add(const ConvexPolygon& p, double weight = 1);
  void subtract(const ConvexPolygon& hole);  // hole counter-clockwise
  double weightedArea() const;
  Box2 bounds() const;
};

}  // namespace bake::grooves
