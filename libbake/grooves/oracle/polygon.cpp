// Convex polygon clipping for the area sampling of seed 000 §6 (see polygon.h): Sutherland-Hodgman
// clipping by one half-plane at a time (or split into both sides of its line in the same pass);
// convex minus convex by peeling off, edge after edge of the hole, the part of the polygon outside
// that edge (the pieces are disjoint and convex).
#include "grooves/oracle/polygon.h"

#include <algorithm>
#include <cmath>

namespace bake::grooves {

HalfPlane leftOf(Vec2 a, Vec2 b) {
  const Vec2 n{-(b.v - a.v), b.u - a.u};
  return {n, n.u * a.u + n.v * a.v};
}

ConvexPolygon parallelogram(Vec2 centre, Vec2 axis1, Vec2 axis2) {
  ConvexPolygon p;
  const double h1u = 0.5 * axis1.u, h1v = 0.5 * axis1.v, h2u = 0.5 * axis2.u, h2v = 0.5 * axis2.v;
  p.add({centre.u - h1u - h2u, centre.v - h1v - h2v});
  p.add({centre.u + h1u - h2u, centre.v + h1v - h2v});
  p.add({centre.u + h1u + h2u, centre.v + h1v + h2v});
  p.add({centre.u - h1u + h2u, centre.v - h1v + h2v});
  makeCounterClockwise(p);
  return p;
}

double signedArea(const ConvexPolygon& p) {
  if (p.count < 3) return 0;
  // Relative to the first vertex, so far-off polygons keep their precision.
  const Vec2 o = p.vertex[0];
  double twice = 0;
  for (int i = 1; i + 1 < p.count; ++i) {
    const Vec2 a{p.vertex[i].u - o.u, p.vertex[i].v - o.v}, b{p.vertex[i + 1].u - o.u, p.vertex[i + 1].v - o.v};
    twice += a.u * b.v - a.v * b.u;
  }
  return 0.5 * twice;
}

double area(const ConvexPolygon& p) { return std::abs(signedArea(p)); }

Vec2 centroid(const ConvexPolygon& p) {
  if (p.count == 0) return {0, 0};
  const Vec2 o = p.vertex[0];
  double twice = 0, cu = 0, cv = 0;
  for (int i = 1; i + 1 < p.count; ++i) {
    const Vec2 a{p.vertex[i].u - o.u, p.vertex[i].v - o.v}, b{p.vertex[i + 1].u - o.u, p.vertex[i + 1].v - o.v};
    const double cross = a.u * b.v - a.v * b.u;
    twice += cross;
    cu += cross * (a.u + b.u);
    cv += cross * (a.v + b.v);
  }
  if (twice == 0) {  // degenerate: the vertex mean
    double su = 0, sv = 0;
    for (int i = 0; i < p.count; ++i) su += p.vertex[i].u, sv += p.vertex[i].v;
    return {su / p.count, sv / p.count};
  }
  return {o.u + cu / (3 * twice), o.v + cv / (3 * twice)};
}

void makeCounterClockwise(ConvexPolygon& p) {
  if (signedArea(p) < 0) std::reverse(p.vertex.begin(), p.vertex.begin() + p.count);
}

Box2 boundsOf(const ConvexPolygon& p) {
  Box2 b;
  for (int i = 0; i < p.count; ++i) {
    b.lower.u = std::min(b.lower.u, p.vertex[i].u);
    b.lower.v = std::min(b.lower.v, p.vertex[i].v);
    b.upper.u = std::max(b.upper.u, p.vertex[i].u);
    b.upper.v = std::max(b.upper.v, p.vertex[i].v);
  }
  return b;
}

namespace {

// Sutherland-Hodgman on one edge, with the distances of p's vertices to the line already known.
void clipWithDistances(const ConvexPolygon& p, const std::array<double, kPolygonMaxVertices>& d, ConvexPolygon& out) {
  out.count = 0;
  out.truncated = p.truncated;
  // Consecutive equal vertices (a crossing that rounds onto an end) are kept once: a zero-length edge
  // has no direction and would make a useless half-plane of a hole's edge.
  auto addDistinct = [&out](Vec2 x) {
    if (out.count > 0 && out.vertex[out.count - 1].u == x.u && out.vertex[out.count - 1].v == x.v) return;
    out.add(x);
  };
  for (int i = 0; i < p.count; ++i) {
    const int j = i + 1 == p.count ? 0 : i + 1;
    if (d[i] >= 0) addDistinct(p.vertex[i]);
    // A crossing strictly between the two ends.
    if ((d[i] > 0 && d[j] < 0) || (d[i] < 0 && d[j] > 0)) {
      const double t = d[i] / (d[i] - d[j]);
      const Vec2 a = p.vertex[i], b = p.vertex[j];
      addDistinct({a.u + t * (b.u - a.u), a.v + t * (b.v - a.v)});
    }
  }
  if (out.count > 1 && out.vertex[0].u == out.vertex[out.count - 1].u && out.vertex[0].v == out.vertex[out.count - 1].v)
    --out.count;
  if (out.count < 3) out.count = 0;
}

// Both parts of p at once: `in` where d >= 0 and `out` where d <= 0, the very vertices
// clipWithDistances gives for d and for -d (a crossing's t = d_i / (d_i - d_j) is the same number
// for both signs), in one pass over p.
void splitWithDistances(const ConvexPolygon& p, const std::array<double, kPolygonMaxVertices>& d, ConvexPolygon& in,
                        ConvexPolygon& out) {
  in.count = out.count = 0;
  in.truncated = out.truncated = p.truncated;
  auto addDistinct = [](ConvexPolygon& to, Vec2 x) {
    if (to.count > 0 && to.vertex[to.count - 1].u == x.u && to.vertex[to.count - 1].v == x.v) return;
    to.add(x);
  };
  for (int i = 0; i < p.count; ++i) {
    const int j = i + 1 == p.count ? 0 : i + 1;
    if (d[i] >= 0) addDistinct(in, p.vertex[i]);
    if (d[i] <= 0) addDistinct(out, p.vertex[i]);
    if ((d[i] > 0 && d[j] < 0) || (d[i] < 0 && d[j] > 0)) {
      const double t = d[i] / (d[i] - d[j]);
      const Vec2 a = p.vertex[i], b = p.vertex[j];
      const Vec2 x{a.u + t * (b.u - a.u), a.v + t * (b.v - a.v)};
      addDistinct(in, x);
      addDistinct(out, x);
    }
  }
  for (ConvexPolygon* part : {&in, &out}) {
    ConvexPolygon& q = *part;
    if (q.count > 1 && q.vertex[0].u == q.vertex[q.count - 1].u && q.vertex[0].v == q.vertex[q.count - 1].v)
      --q.count;
    if (q.count < 3) q.count = 0;
  }
}

// -1: p lies outside h (boundary included), 1: inside, 0: crossed (d holds the distances).
int sideOf(const ConvexPolygon& p, const HalfPlane& h, std::array<double, kPolygonMaxVertices>& d) {
  bool allInside = true, allOutside = true;
  for (int i = 0; i < p.count; ++i) {
    d[i] = h.distance(p.vertex[i]);
    allInside = allInside && d[i] >= 0;
    allOutside = allOutside && d[i] <= 0;
  }
  return allInside ? 1 : allOutside ? -1 : 0;
}

}  // namespace

int sideOf(const ConvexPolygon& p, const HalfPlane& h) {
  std::array<double, kPolygonMaxVertices> d;
  return sideOf(p, h, d);
}

ConvexPolygon clip(const ConvexPolygon& p, const HalfPlane& h) {
  ConvexPolygon out;
  out.truncated = p.truncated;
  if (p.count == 0) return out;
  std::array<double, kPolygonMaxVertices> d;
  const int side = sideOf(p, h, d);
  if (side > 0) return p;
  if (side < 0) return out;
  clipWithDistances(p, d, out);
  return out;
}

void clipInPlace(ConvexPolygon& p, const HalfPlane& h) {
  if (p.count == 0) return;
  std::array<double, kPolygonMaxVertices> d;
  const int side = sideOf(p, h, d);
  if (side > 0) return;
  if (side < 0) {
    p.count = 0;
    return;
  }
  ConvexPolygon out;
  clipWithDistances(p, d, out);
  p = out;
}

int split(const ConvexPolygon& p, const HalfPlane& h, ConvexPolygon& inside, ConvexPolygon& outside) {
  inside.truncated = outside.truncated = p.truncated;
  if (p.count == 0) {
    inside.count = outside.count = 0;
    return -1;
  }
  std::array<double, kPolygonMaxVertices> d;
  const int side = sideOf(p, h, d);
  if (side != 0) {
    (side > 0 ? inside : outside) = p;
    (side > 0 ? outside : inside).count = 0;
    return side;
  }
  splitWithDistances(p, d, inside, outside);
  return 0;
}

void splitInPlace(ConvexPolygon& p, const HalfPlane& h, ConvexPolygon& outside) {
  outside.truncated = p.truncated;
  if (p.count == 0) {
    outside.count = 0;
    return;
  }
  std::array<double, kPolygonMaxVertices> d;
  const int side = sideOf(p, h, d);
  if (side > 0) {
    outside.count = 0;
  } else if (side < 0) {
    outside = p;
    p.count = 0;
  } else {
    ConvexPolygon in;
    splitWithDistances(p, d, in, outside);
    p = in;
  }
}

// The half-planes of a convex polygon's edges, leaving out edges too short to have a reliable
// direction (rounding leaves such slivers where clip lines pass through vertices): the neighbouring
// edges bound the polygon there to within that length.
int edgeHalfPlanes(const ConvexPolygon& p, std::array<HalfPlane, kPolygonMaxVertices>& out) {
  // The polygon's size: its longest edge's larger extent (within a factor of the vertex count of the
  // box's size, all a relative threshold needs).
  std::array<double, kPolygonMaxVertices> extent;
  double size = 0;
  for (int i = 0; i < p.count; ++i) {
    const Vec2 a = p.vertex[i], c = p.vertex[i + 1 == p.count ? 0 : i + 1];
    extent[i] = std::max(std::abs(c.u - a.u), std::abs(c.v - a.v));
    size = std::max(size, extent[i]);
  }
  const double shortest = 1e-12 * size;
  int n = 0;
  for (int i = 0; i < p.count; ++i)
    if (extent[i] > shortest) out[n++] = leftOf(p.vertex[i], p.vertex[i + 1 == p.count ? 0 : i + 1]);
  return n;
}

ConvexPolygon intersect(const ConvexPolygon& p, const ConvexPolygon& clipper) {
  std::array<HalfPlane, kPolygonMaxVertices> edges;
  const int n = edgeHalfPlanes(clipper, edges);
  return intersect(p, edges, n);
}

ConvexPolygon intersect(const ConvexPolygon& p, const std::array<HalfPlane, kPolygonMaxVertices>& edges, int n) {
  ConvexPolygon out = p;
  for (int i = 0; i < n && !out.empty(); ++i) clipInPlace(out, edges[i]);
  if (out.empty()) out.count = 0;
  return out;
}

bool contains(const ConvexPolygon& p, Vec2 x) {
  if (p.empty()) return false;
  for (int i = 0; i < p.count; ++i)
    if (leftOf(p.vertex[i], p.vertex[i + 1 == p.count ? 0 : i + 1]).distance(x) < 0) return false;
  return true;
}

int subtract(const ConvexPolygon& p, const ConvexPolygon& hole, double minArea,
             std::array<ConvexPolygon, kPolygonMaxVertices>& pieces) {
  ConvexPolygon inside;
  return subtract(p, hole, minArea, pieces, inside);
}

int subtract(const ConvexPolygon& p, const ConvexPolygon& hole, double minArea,
             std::array<ConvexPolygon, kPolygonMaxVertices>& pieces, ConvexPolygon& rest) {
  std::array<HalfPlane, kPolygonMaxVertices> edges;
  const int count = edgeHalfPlanes(hole, edges);
  return subtract(p, edges, count, minArea, pieces, rest);
}

int subtract(const ConvexPolygon& p, const std::array<HalfPlane, kPolygonMaxVertices>& edges, int count,
             double minArea, std::array<ConvexPolygon, kPolygonMaxVertices>& pieces, ConvexPolygon& rest) {
  int n = 0;
  if (count == 0) {  // an empty hole removes nothing: p is one piece, nothing of it is inside
    if (!p.empty() && area(p) > minArea) pieces[n++] = p;
    rest.count = 0;
    return n;
  }
  rest = p;
  for (int i = 0; i < count && !rest.empty(); ++i) {
    // The part outside this edge is a piece; what is inside goes on to the next edge.
    splitInPlace(rest, edges[i], pieces[n]);
    if (!pieces[n].empty() && area(pieces[n]) > minArea) ++n;
  }
  if (rest.empty()) rest.count = 0;
  return n;
}

void FragmentSet::add(const ConvexPolygon& p, double weight) {
  if (p.empty() || area(p) <= minArea) return;
  if (count == kMaxFragments) {
    ++overflows;  // no room: the piece is lost (an under-estimate of its area)
    return;
  }
  fragment[count++] = {p, weight};
  truncated = truncated || p.truncated;
}

void FragmentSet::subtract(const ConvexPolygon& hole) {
  if (hole.empty()) return;
  const Box2 holeBox = boundsOf(hole);
  std::array<HalfPlane, kPolygonMaxVertices> edges;  // once for every fragment
  const int edgeCount = edgeHalfPlanes(hole, edges);
  std::array<ConvexPolygon, kPolygonMaxVertices> pieces;
  ConvexPolygon inside;
  const int original = count;
  for (int i = 0; i < original; ++i) {
    Fragment& f = fragment[i];
    if (f.polygon.empty() || !boundsOf(f.polygon).overlaps(holeBox)) continue;
    // One pass of clips gives both the pieces outside the hole and the overlap (`inside`).
    const int n = grooves::subtract(f.polygon, edges, edgeCount, minArea, pieces, inside);
    const double removed = area(inside);
    if (inside.empty() || removed <= minArea) continue;
    const double whole = area(f.polygon);
    if (removed >= whole - minArea) {
      f.polygon.count = 0;  // fully covered; compacted below
      continue;
    }
    // A fragment of weight < 1 stands for itself minus holes that could not be cut out; the new hole
    // is taken to miss those, so the fragment's weighted area drops by exactly `removed`.
    const double remaining = std::max(0.0, f.weight * whole - removed);
    if (n == 0) {
      f.polygon.count = 0;
    } else if (count + n - 1 <= kMaxFragments) {
      const double weight = f.weight == 1 ? 1 : std::min(1.0, remaining / (whole - removed));
      f.polygon = pieces[0];
      f.weight = weight;
      for (int k = 1; k < n; ++k) fragment[count++] = {pieces[k], weight};
      for (int k = 0; k < n; ++k) truncated = truncated || pieces[k].truncated;
    } else {
      ++overflows;
      f.weight = remaining / whole;
    }
  }
  int kept = 0;
  for (int i = 0; i < count; ++i)
    if (!fragment[i].polygon.empty()) fragment[kept++] = fragment[i];
  count = kept;
}

double FragmentSet::weightedArea() const {
  double sum = 0;
  for (int i = 0; i < count; ++i) sum += fragment[i].weight * area(fragment[i].polygon);
  return sum;
}

Box2 FragmentSet::bounds() const {
  Box2 b;
  for (int i = 0; i < count; ++i) {
    const Box2 f = boundsOf(fragment[i].polygon);
    b.lower.u = std::min(b.lower.u, f.lower.u);
    b.lower.v = std::min(b.lower.v, f.lower.v);
    b.upper.u = std::max(b.upper.u, f.upper.u);
    b.upper.v = std::max(b.upper.v, f.upper.v);
  }
  return b;
}

}  // namespace bake::grooves
