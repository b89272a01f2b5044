// The planar pieces of the local surface for area sampling (seed 000 §6.2, done by clipping instead of
// projecting cross-sections). With every primitive straightened at the footprint, each profile facet
// is a planar strip of the primitive's region (between its joint lines: mitre at corners, flat cut at
// open ends, formats/groove-scene.md "Region"). H = min(cuts) + max(ridges) is built by overlaying the
// grooves one after the other on a list of convex cells, each with one plane: a cell meeting a cut
// strip keeps the lower of the two planes, split along the line where they are equal (the seed's
// intersection removal: the part of a facet inside a deeper groove is removed); the part of a cell
// outside the groove's region is the cell minus the region (a few convex pieces), the part inside is
// sliced into the groove's strips (one split per line between two strips). Ridges are overlaid
// the same way with the higher plane, then the two layers are added. The flat ground between grooves
// is whatever is left of the base plane's cell (the seed's ground facet). Materials follow the spec:
// the primitive with the larger |h| (cut or ridge), the earlier one on a tie, else the base material.
#include <algorithm>
#include <cmath>

#include "grooves/oracle/area_surface.h"

namespace bake::grooves {
namespace {

struct Cell {
  ConvexPolygon polygon;
  HeightPlane plane;
  int owner = -1;  // the straight groove deciding the plane; -1: the base plane
};

// A strip of one groove's profile with one plane, or a run of facets that do not take part in this
// layer (ridges in the cut layer and the other way round), where every cell keeps its own plane.
struct Strip {
  double b0 = 0, b1 = 0;
  bool takesPart = false;
  HeightPlane plane;
};

bool isCut(Vec2 a, Vec2 b) { return a.v <= 0 && b.v <= 0 && (a.v < 0 || b.v < 0); }
bool isRidge(Vec2 a, Vec2 b) { return a.v >= 0 && b.v >= 0 && (a.v > 0 || b.v > 0); }

HeightPlane facetPlane(const StraightGroove& g, Vec2 a, Vec2 b) {
  const double slope = (b.v - a.v) / (b.u - a.u);
  const double footB = g.binormal.u * g.foot.u + g.binormal.v * g.foot.v;
  return {a.v - slope * (footB + a.u), slope * g.binormal.u, slope * g.binormal.v};
}

void stripsOf(const StraightGroove& g, bool cuts, std::vector<Strip>& strips) {
  strips.clear();
  for (std::size_t k = 0; k + 1 < g.profile.size(); ++k) {
    const Vec2 a = g.profile[k], b = g.profile[k + 1];
    if (b.u <= a.u) continue;  // a vertical segment has no strip (its wall is built elsewhere)
    const bool part = cuts ? isCut(a, b) : isRidge(a, b);
    if (!part && !strips.empty() && !strips.back().takesPart) {
      strips.back().b1 = b.u;  // merge runs of facets that keep the cell's plane
      continue;
    }
    strips.push_back({a.u, b.u, part, part ? facetPlane(g, a, b) : HeightPlane{}});
  }
}

bool hasLayer(const StraightGroove& g, bool cuts) {
  for (std::size_t k = 0; k + 1 < g.profile.size(); ++k)
    if (g.profile[k + 1].u > g.profile[k].u && (cuts ? isCut(g.profile[k], g.profile[k + 1])
                                                     : isRidge(g.profile[k], g.profile[k + 1])))
      return true;
  return false;
}

enum class Side { inside, outside, across };

// Where polygon p lies with respect to a convex polygon given by its edges' half-planes.
Side sideOf(const ConvexPolygon& p, const std::array<HalfPlane, kPolygonMaxVertices>& edges, int edgeCount) {
  bool inside = true;
  for (int e = 0; e < edgeCount; ++e) {
    bool allIn = true, allOut = true;
    for (int i = 0; i < p.count; ++i) {
      const double d = edges[e].distance(p.vertex[i]);
      allIn = allIn && d >= 0;
      allOut = allOut && d <= 0;
    }
    if (allOut) return Side::outside;
    inside = inside && allIn;
  }
  return inside ? Side::inside : Side::across;
}

// The half-plane where plane a <= plane b.
HalfPlane whereLower(const HeightPlane& a, const HeightPlane& b) {
  return {{b.gu - a.gu, b.gv - a.gv}, a.h0 - b.h0};
}

void pushCell(std::vector<Cell>& cells, const ConvexPolygon& p, const HeightPlane& plane, int owner, double minArea,
              SurfaceBuildStats& stats) {
  if (p.empty() || area(p) <= minArea) return;
  if (cells.size() >= kMaxSurfacePieces) {
    ++stats.overflows;
    return;
  }
  cells.push_back({p, plane, owner});
}

// A cell this groove leaves whole: it passed pushCell's area test already.
void keepCell(std::vector<Cell>& cells, const Cell& cell, SurfaceBuildStats& stats) {
  if (cells.size() >= kMaxSurfacePieces) {
    ++stats.overflows;
    return;
  }
  cells.push_back(cell);
}

// The cell `inside` (already clipped to a strip) against the strip's plane: the lower (cuts) or higher
// (ridges) plane wins, the cell's own on a tie (it comes from an earlier groove).
void resolve(const Cell& cell, const ConvexPolygon& inside, const HeightPlane& stripPlane, int owner, bool cuts,
             double minArea, std::vector<Cell>& out, SurfaceBuildStats& stats) {
  double lowest = 1e300, highest = -1e300;  // of cell plane - strip plane over the vertices
  for (int i = 0; i < inside.count; ++i) {
    const double d = cell.plane.at(inside.vertex[i]) - stripPlane.at(inside.vertex[i]);
    lowest = std::min(lowest, d);
    highest = std::max(highest, d);
  }
  const bool cellWinsEverywhere = cuts ? highest <= 0 : lowest >= 0;
  const bool stripWinsEverywhere = cuts ? lowest >= 0 : highest <= 0;
  if (cellWinsEverywhere) return pushCell(out, inside, cell.plane, cell.owner, minArea, stats);
  if (stripWinsEverywhere) return pushCell(out, inside, stripPlane, owner, minArea, stats);
  ConvexPolygon cellLower, stripLower;
  split(inside, whereLower(cell.plane, stripPlane), cellLower, stripLower);
  pushCell(out, cuts ? cellLower : stripLower, cell.plane, cell.owner, minArea, stats);
  pushCell(out, cuts ? stripLower : cellLower, stripPlane, owner, minArea, stats);
}

// The part of `cell` inside g's band (`inBand`, already clipped by its joint and side lines) cut into
// g's strips. They follow each other across the groove, so one split per line between two strips
// slices it; lines the part lies wholly on one side of (by its range across the groove, with a
// rounding margin) are not clipped by.
void sliceIntoStrips(const StraightGroove& g, const std::vector<Strip>& strips, const Cell& cell,
                     const ConvexPolygon& inBand, bool cuts, double minArea, std::vector<Cell>& out,
                     SurfaceBuildStats& stats) {
  double bLow = 1e300, bHigh = -1e300;
  for (int i = 0; i < inBand.count; ++i) {
    const double b = g.across(inBand.vertex[i]);
    bLow = std::min(bLow, b);
    bHigh = std::max(bHigh, b);
  }
  const double slack = 1e-9 * (std::abs(bLow) + std::abs(bHigh) + (bHigh - bLow));
  ConvexPolygon buffers[2] = {inBand, {}};
  ConvexPolygon* rest = &buffers[0];  // the part beyond the strips done so far
  ConvexPolygon* beyond = &buffers[1];
  ConvexPolygon piece;
  for (std::size_t k = 0; k < strips.size() && !rest->empty(); ++k) {
    const Strip& s = strips[k];
    if (s.b1 < bLow - slack) continue;  // the part lies beyond this strip
    const bool last = k + 1 == strips.size() || s.b1 > bHigh + slack;
    const ConvexPolygon* inStrip = rest;
    if (!last) {
      split(*rest, g.atMost(s.b1), piece, *beyond);
      std::swap(rest, beyond);
      inStrip = &piece;
    }
    if (!inStrip->empty()) {
      if (!s.takesPart)
        pushCell(out, *inStrip, cell.plane, cell.owner, minArea, stats);
      else
        resolve(cell, *inStrip, s.plane, int(g.order), cuts, minArea, out, stats);
    }
    if (last) break;
  }
}

// One layer (cuts or ridges): the base plane's cell overlaid with every groove in turn.
// `cells` and `next` are the caller's (per-thread buffers reused from sample to sample).
void buildLayer(const std::vector<StraightGroove>& grooves, const ConvexPolygon& region, bool cuts, double minArea,
                bool stopAtCap, std::vector<Cell>& cells, std::vector<Cell>& next, SurfaceBuildStats& stats) {
  thread_local std::vector<Strip> strips;
  cells.clear();
  cells.push_back({region, {}, -1});
  std::array<ConvexPolygon, kPolygonMaxVertices> outside;
  ConvexPolygon inBand;
  for (const StraightGroove& g : grooves) {
    if (stopAtCap && stats.overflows > 0) break;
    if (!hasLayer(g, cuts)) continue;
    // The band as the groove's own lines (joints, then the strip's two sides), those that cut the
    // region: inside the region (every cell is) they bound the band's part of it, with the exact
    // lines the strips below are clipped by, and no edge along the region's border to peel off for
    // nothing. A band that misses the region (which lies outside one of its lines) is skipped.
    const HalfPlane lines[4] = {g.joint[0], g.joint[1], g.atLeast(g.profile.front().u), g.atMost(g.profile.back().u)};
    std::array<HalfPlane, kPolygonMaxVertices> bandEdges;
    int bandEdgeCount = 0;
    bool missesRegion = false;
    for (int k = 0; k < 4 && !missesRegion; ++k) {
      const int side = sideOf(region, lines[k]);
      missesRegion = side < 0;
      if (side == 0) bandEdges[bandEdgeCount++] = lines[k];
    }
    if (missesRegion) continue;
    stripsOf(g, cuts, strips);
    next.clear();
    for (const Cell& cell : cells) {
      // A cell inside every line of the band has nothing outside it (subtract would find no piece),
      // one outside some line misses it: both without clipping.
      const Side side = sideOf(cell.polygon, bandEdges, bandEdgeCount);
      int n = 0;
      if (side == Side::across) {
        n = subtract(cell.polygon, bandEdges, bandEdgeCount, minArea, outside, inBand);  // inBand: cell and band
        if (area(inBand) <= minArea) n = -1;
      } else {
        inBand = cell.polygon;
      }
      if (side == Side::outside || n < 0) {
        keepCell(next, cell, stats);
        continue;
      }
      for (int i = 0; i < n; ++i) pushCell(next, outside[i], cell.plane, cell.owner, minArea, stats);
      sliceIntoStrips(g, strips, cell, inBand, cuts, minArea, next, stats);
    }
    cells.swap(next);
  }
}

Vec3 unitNormalOf(const HeightPlane& p) {
  const double n = std::sqrt(p.gu * p.gu + p.gv * p.gv + 1);
  return {-p.gu / n, -p.gv / n, 1 / n};
}

void emit(const ConvexPolygon& polygon, const HeightPlane& plane, std::size_t material,
          std::vector<SurfacePiece>& out, SurfaceBuildStats& stats) {
  if (out.size() >= kMaxSurfacePieces) {
    ++stats.overflows;
    return;
  }
  SurfacePiece& piece = out.emplace_back();  // built in place: a piece is large
  piece.count = polygon.count;
  for (int i = 0; i < polygon.count; ++i)
    piece.vertex[i] = {polygon.vertex[i].u, polygon.vertex[i].v, plane.at(polygon.vertex[i])};
  piece.normal = unitNormalOf(plane);
  const Vec3& v = piece.vertex[0];
  piece.planeOffset = piece.normal.u * v.u + piece.normal.v * v.v + piece.normal.w * v.w;
  piece.material = material;
  stats.truncated = stats.truncated || polygon.truncated;
  ++stats.cells;
}

std::size_t materialOf(const std::vector<StraightGroove>& grooves, int owner, std::size_t baseMaterial) {
  return owner < 0 ? baseMaterial : grooves[std::size_t(owner)].material;
}

// A cut cell and a ridge cell over the same ground: the heights add; the material is the one of the
// larger |h| (the earlier primitive on a tie).
void combine(const std::vector<StraightGroove>& grooves, std::size_t baseMaterial, const Cell& cut, const Cell& ridge,
             const ConvexPolygon& both, double minArea, std::vector<SurfacePiece>& out, SurfaceBuildStats& stats) {
  const HeightPlane sum{cut.plane.h0 + ridge.plane.h0, cut.plane.gu + ridge.plane.gu, cut.plane.gv + ridge.plane.gv};
  if (cut.owner < 0 || ridge.owner < 0) {
    const int owner = cut.owner >= 0 ? cut.owner : ridge.owner;
    return emit(both, sum, materialOf(grooves, owner, baseMaterial), out, stats);
  }
  // |cut| >= ridge where -cut - ridge >= 0, i.e. where the summed plane is <= 0.
  const HeightPlane zero{};
  const bool cutFirst = cut.owner < ridge.owner;  // ties go to the earlier primitive
  ConvexPolygon cutPart, ridgePart;  // where the cut is deeper, where the ridge is higher
  split(both, whereLower(sum, zero), cutPart, ridgePart);
  const ConvexPolygon& first = cutFirst ? cutPart : ridgePart;
  std::array<ConvexPolygon, kPolygonMaxVertices> rest;
  const int n = subtract(both, first, minArea, rest);
  if (!first.empty() && area(first) > minArea)
    emit(first, sum, materialOf(grooves, cutFirst ? cut.owner : ridge.owner, baseMaterial), out, stats);
  for (int i = 0; i < n; ++i)
    emit(rest[i], sum, materialOf(grooves, cutFirst ? ridge.owner : cut.owner, baseMaterial), out, stats);
}

}  // namespace

HalfPlane StraightGroove::atLeast(double b) const {
  return {binormal, binormal.u * foot.u + binormal.v * foot.v + b};
}

HalfPlane StraightGroove::atMost(double b) const {
  return {{-binormal.u, -binormal.v}, -(binormal.u * foot.u + binormal.v * foot.v + b)};
}

std::vector<StraightGroove> straighten(const GrooveScene& scene, const std::vector<LocalGroove>& grooves,
                                       Vec2 centre) {
  std::vector<StraightGroove> out;
  straighten(scene, grooves, centre, out);
  return out;
}

void straighten(const GrooveScene& scene, const std::vector<LocalGroove>& grooves, Vec2 centre,
                std::vector<StraightGroove>& out) {
  out.resize(grooves.size());
  for (std::size_t i = 0; i < grooves.size(); ++i) {
    const LocalGroove& l = grooves[i];
    StraightGroove& g = out[i];
    g.profile.clear();
    g.order = i;
    g.primitive = l.primitive;
    g.material = l.material;
    Vec2 rel{l.foot.u - centre.u, l.foot.v - centre.v};
    Vec2 shift{0, 0};  // the domain period moving this primitive next to the footprint
    if (scene.wrapRepeat) {
      shift = {scene.domain[0] * std::round(rel.u / scene.domain[0]), scene.domain[1] * std::round(rel.v / scene.domain[1])};
      rel = {rel.u - shift.u, rel.v - shift.v};
    }
    g.foot = rel;
    g.tangent = l.tangent;
    g.binormal = l.binormal;
    const JointLine* joints[2] = {&l.joints.start, &l.joints.end};
    for (int e = 0; e < 2; ++e) {
      const Vec2 p{joints[e]->point.u - centre.u - shift.u, joints[e]->point.v - centre.v - shift.v};
      g.jointPoint[e] = p;
      g.joint[e] = {joints[e]->normal, joints[e]->normal.u * p.u + joints[e]->normal.v * p.v};
      g.openEnd[e] = joints[e]->openEnd;
    }
    for (std::size_t k = 0; k < l.profile->points.size(); ++k) {
      const Vec2 point{l.profileB(k), l.profileH(k)};
      if (!g.profile.empty()) {
        const Vec2 prev = g.profile.back();
        if ((prev.v < 0 && point.v > 0) || (prev.v > 0 && point.v < 0)) {  // split at h = 0
          const double t = prev.v / (prev.v - point.v);
          g.profile.push_back({prev.u + t * (point.u - prev.u), 0});
        }
      }
      g.profile.push_back(point);
    }
  }
}

void buildHeightPieces(const std::vector<StraightGroove>& grooves, std::size_t baseMaterial,
                       const ConvexPolygon& region, double minArea, bool stopAtCap, std::vector<SurfacePiece>& out,
                       SurfaceBuildStats& stats) {
  thread_local std::vector<Cell> cuts, ridges, scratch;
  buildLayer(grooves, region, true, minArea, stopAtCap, cuts, scratch, stats);
  if (stopAtCap && stats.overflows > 0) return;
  bool anyRidge = false;
  for (const StraightGroove& g : grooves) anyRidge = anyRidge || hasLayer(g, false);
  if (!anyRidge) {
    for (const Cell& c : cuts) emit(c.polygon, c.plane, materialOf(grooves, c.owner, baseMaterial), out, stats);
    return;
  }
  buildLayer(grooves, region, false, minArea, stopAtCap, ridges, scratch, stats);
  if (stopAtCap && stats.overflows > 0) return;
  thread_local std::vector<Box2> ridgeBoxes;
  ridgeBoxes.clear();
  for (const Cell& r : ridges) ridgeBoxes.push_back(boundsOf(r.polygon));
  for (const Cell& c : cuts) {
    const Box2 cutBox = boundsOf(c.polygon);
    for (std::size_t k = 0; k < ridges.size(); ++k) {
      const Cell& r = ridges[k];
      if (!cutBox.overlaps(ridgeBoxes[k])) continue;
      const ConvexPolygon both = intersect(c.polygon, r.polygon);
      if (both.empty() || area(both) <= minArea) continue;
      combine(grooves, baseMaterial, c, r, both, minArea, out, stats);
    }
  }
}

}  // namespace bake::grooves
