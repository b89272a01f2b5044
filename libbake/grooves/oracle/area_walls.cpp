// The vertical walls of the local surface for area sampling (seed 000 §6.5: ends need no extra case
// once the region is defined). H jumps only along two kinds of lines: a primitive's open-end cut (the
// cavity stops at the flat cut) and a vertical segment of a profile. Along such a line H has a limit on
// each side, H+ and H-, both piecewise linear: their breaks are where the line crosses another
// groove's joint or profile-vertex lines, or where two grooves' heights cross (the min / max switches).
// Between consecutive breaks the wall is the vertical quad between the two limits; where they cross it
// changes side. A wall faces its lower side and takes the material of the side with the larger |H|
// (formats/groove-scene.md, "Materials on the surface"). Mitre lines need no wall: both primitives
// meet there (the small mismatch of two primitives straightened at different foot points is ignored).
#include <algorithm>
#include <cmath>

#include "grooves/oracle/area_surface.h"

namespace bake::grooves {
namespace {

struct GrooveHeight {
  bool inside = false;  // x lies in the region, on a facet with h != 0
  double h = 0;
};

// The height of one straight groove at x, using the facet that holds the nudged point `probe` (the
// side limit); the facet's plane is evaluated at x itself, so the limit is exact.
GrooveHeight heightOf(const StraightGroove& g, Vec2 x, Vec2 probe) {
  if (g.joint[0].distance(probe) < 0 || g.joint[1].distance(probe) < 0) return {};
  const double bProbe = g.across(probe);
  if (bProbe < g.profile.front().u || bProbe > g.profile.back().u) return {};
  for (std::size_t k = 0; k + 1 < g.profile.size(); ++k) {
    const Vec2 a = g.profile[k], b = g.profile[k + 1];
    if (b.u <= a.u || bProbe < a.u || bProbe > b.u) continue;
    const double h = a.v + (b.v - a.v) * (g.across(x) - a.u) / (b.u - a.u);
    return {h != 0, h};
  }
  return {};
}

// A candidate line where H may jump: x(t) = origin + t direction for t in [t0, t1], sides +-normal.
struct WallLine {
  Vec2 origin, direction, normal;
  double t0 = 0, t1 = 0;
  Vec2 at(double t) const { return {origin.u + t * direction.u, origin.v + t * direction.v}; }
};

// Narrows [t0, t1] to the part of the line inside the half-plane; false when nothing is left.
bool clipRange(WallLine& line, const HalfPlane& h) {
  const double d0 = h.distance(line.origin);
  const double rate = h.normal.u * line.direction.u + h.normal.v * line.direction.v;
  if (std::abs(rate) < 1e-15) return d0 >= 0;
  const double t = -d0 / rate;
  if (rate > 0) line.t0 = std::max(line.t0, t);
  else line.t1 = std::min(line.t1, t);
  return line.t1 > line.t0;
}

bool clipToRegion(WallLine& line, const ConvexPolygon& region) {
  for (int i = 0; i < region.count; ++i)
    if (!clipRange(line, leftOf(region.vertex[i], region.vertex[(i + 1) % region.count]))) return false;
  return true;
}

// The lines of every groove where H's pieces change: joint lines and profile-vertex lines.
void structuralBreaks(const std::vector<StraightGroove>& grooves, const WallLine& line, std::vector<double>& ts) {
  auto add = [&](const HalfPlane& h) {
    const double rate = h.normal.u * line.direction.u + h.normal.v * line.direction.v;
    if (std::abs(rate) < 1e-15) return;
    const double t = -h.distance(line.origin) / rate;
    if (t > line.t0 && t < line.t1) ts.push_back(t);
  };
  for (const StraightGroove& g : grooves) {
    add(g.joint[0]);
    add(g.joint[1]);
    for (const Vec2& p : g.profile) add(g.atLeast(p.u));
  }
}

// A linear function of t on an interval, from two samples.
struct Linear {
  double value0 = 0, slope = 0;  // value at t = 0
  double at(double t) const { return value0 + slope * t; }
};
Linear through(double ta, double va, double tb, double vb) {
  const double slope = (vb - va) / (tb - ta);
  return {va - slope * ta, slope};
}
void addCrossing(const Linear& a, const Linear& b, double lo, double hi, std::vector<double>& ts) {
  const double ds = a.slope - b.slope;
  if (ds == 0) return;
  const double t = (b.value0 - a.value0) / ds;
  if (t > lo && t < hi) ts.push_back(t);
}

// Within a structural interval every groove's side limit is linear in t: the min / max switches are
// the crossings of pairs of them.
void switchBreaks(const std::vector<StraightGroove>& grooves, const WallLine& line, double lo, double hi,
                  double nudge, std::vector<double>& ts) {
  const double ta = lo + (hi - lo) / 3, tb = lo + 2 * (hi - lo) / 3;
  for (int side = -1; side <= 1; side += 2) {
    const Vec2 shift{side * nudge * line.normal.u, side * nudge * line.normal.v};
    std::vector<Linear> cuts, ridges;
    for (const StraightGroove& g : grooves) {
      const Vec2 xa = line.at(ta), xb = line.at(tb);
      const GrooveHeight ha = heightOf(g, xa, {xa.u + shift.u, xa.v + shift.v});
      const GrooveHeight hb = heightOf(g, xb, {xb.u + shift.u, xb.v + shift.v});
      if (!ha.inside && !hb.inside) continue;
      const Linear f = through(ta, ha.h, tb, hb.h);
      (ha.h + hb.h < 0 ? cuts : ridges).push_back(f);
    }
    for (const auto* list : {&cuts, &ridges}) {
      for (std::size_t i = 0; i < list->size(); ++i) {
        addCrossing((*list)[i], Linear{}, lo, hi, ts);  // against the slab's own 0
        for (std::size_t j = i + 1; j < list->size(); ++j) addCrossing((*list)[i], (*list)[j], lo, hi, ts);
      }
    }
  }
}

void emitWall(const WallLine& line, double p0, double p1, Linear low, Linear high, Vec2 facing,
              std::size_t material, double heightTolerance, std::vector<SurfacePiece>& out,
              SurfaceBuildStats& stats) {
  if (out.size() >= kMaxSurfacePieces || stats.walls >= kMaxWalls) {
    ++stats.overflows;
    return;
  }
  SurfacePiece wall;
  wall.wall = true;
  const Vec2 a = line.at(p0), b = line.at(p1);
  auto add = [&](Vec2 x, double h) { wall.vertex[wall.count++] = {x.u, x.v, h}; };
  add(a, low.at(p0));
  add(b, low.at(p1));
  if (high.at(p1) - low.at(p1) > heightTolerance) add(b, high.at(p1));
  if (high.at(p0) - low.at(p0) > heightTolerance) add(a, high.at(p0));
  if (wall.count < 3) return;
  wall.normal = {facing.u, facing.v, 0};
  wall.planeOffset = facing.u * a.u + facing.v * a.v;
  wall.material = material;
  ++stats.walls;
  out.push_back(wall);
}

// The walls along one candidate line.
void wallsAlong(const std::vector<StraightGroove>& grooves, std::size_t baseMaterial, const WallLine& line,
                double lengthScale, std::vector<SurfacePiece>& out, SurfaceBuildStats& stats) {
  const double nudge = 1e-9 * lengthScale, heightTolerance = 1e-11 * lengthScale;
  std::vector<double> ts{line.t0, line.t1};
  structuralBreaks(grooves, line, ts);
  std::sort(ts.begin(), ts.end());
  const std::size_t structural = ts.size();
  for (std::size_t i = 0; i + 1 < structural; ++i)
    if (ts[i + 1] - ts[i] > nudge) switchBreaks(grooves, line, ts[i], ts[i + 1], nudge, ts);
  std::sort(ts.begin(), ts.end());
  const Vec2 plus = line.normal, minus{-line.normal.u, -line.normal.v};
  for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
    const double lo = ts[i], hi = ts[i + 1];
    if (hi - lo <= nudge) continue;
    const double ta = lo + (hi - lo) / 3, tb = lo + 2 * (hi - lo) / 3;
    const Vec2 xa = line.at(ta), xb = line.at(tb);
    const double tol = nudge;
    const Linear above = through(ta, surfaceLimit(grooves, baseMaterial, xa, plus, tol).height, tb,
                                 surfaceLimit(grooves, baseMaterial, xb, plus, tol).height);
    const Linear below = through(ta, surfaceLimit(grooves, baseMaterial, xa, minus, tol).height, tb,
                                 surfaceLimit(grooves, baseMaterial, xb, minus, tol).height);
    // Split where the two limits cross (the wall changes side) or where |H+| = |H-| (its material changes).
    std::vector<double> cuts{lo, hi};
    const Linear difference{above.value0 - below.value0, above.slope - below.slope};
    const Linear sum{above.value0 + below.value0, above.slope + below.slope};
    addCrossing(difference, Linear{}, lo, hi, cuts);
    addCrossing(sum, Linear{}, lo, hi, cuts);
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double p0 = cuts[k], p1 = cuts[k + 1], mid = 0.5 * (p0 + p1);
      if (p1 - p0 <= nudge) continue;
      if (std::max(std::abs(difference.at(p0)), std::abs(difference.at(p1))) <= heightTolerance) continue;
      const bool plusHigher = difference.at(mid) > 0;
      const Vec2 x = line.at(mid);
      const SurfacePoint onPlus = surfaceLimit(grooves, baseMaterial, x, plus, tol);
      const SurfacePoint onMinus = surfaceLimit(grooves, baseMaterial, x, minus, tol);
      const std::size_t material =
          std::abs(onPlus.height) >= std::abs(onMinus.height) ? onPlus.material : onMinus.material;
      emitWall(line, p0, p1, plusHigher ? below : above, plusHigher ? above : below, plusHigher ? minus : plus,
               material, heightTolerance, out, stats);
    }
  }
}

}  // namespace

SurfacePoint surfaceLimit(const std::vector<StraightGroove>& grooves, std::size_t baseMaterial, Vec2 x, Vec2 side,
                          double tolerance) {
  const Vec2 probe{x.u + tolerance * side.u, x.v + tolerance * side.v};
  double deepest = 0, highest = 0;
  int cutOwner = -1, ridgeOwner = -1;
  for (const StraightGroove& g : grooves) {
    const GrooveHeight h = heightOf(g, x, probe);
    if (!h.inside) continue;
    if (h.h < deepest) deepest = h.h, cutOwner = int(g.order);
    if (h.h > highest) highest = h.h, ridgeOwner = int(g.order);
  }
  SurfacePoint p{deepest + highest, baseMaterial};
  int owner = -1;
  if (cutOwner >= 0 && ridgeOwner >= 0) {
    const double cut = -deepest, ridge = highest;
    owner = cut > ridge || (cut == ridge && cutOwner < ridgeOwner) ? cutOwner : ridgeOwner;
  } else {
    owner = cutOwner >= 0 ? cutOwner : ridgeOwner;
  }
  if (owner >= 0) p.material = grooves[std::size_t(owner)].material;
  return p;
}

void buildWalls(const std::vector<StraightGroove>& grooves, std::size_t baseMaterial, const ConvexPolygon& region,
                double lengthScale, bool stopAtCap, std::vector<SurfacePiece>& out, SurfaceBuildStats& stats) {
  const Box2 regionBox = boundsOf(region);
  for (const StraightGroove& g : grooves) {
    if (stopAtCap && stats.overflows > 0) return;
    const double first = g.profile.front().u, last = g.profile.back().u;
    // Open-end cuts: the joint line across the band. The cut is perpendicular to the path, so its
    // wall lies within max(|first|, |last|) of the end point: an end that far from the region is
    // skipped without clipping.
    const double reach = std::max(std::abs(first), std::abs(last));
    for (int e = 0; e < 2; ++e) {
      if (!g.openEnd[e]) continue;
      const Vec2 end = g.jointPoint[e];
      if (end.u + reach < regionBox.lower.u || end.u - reach > regionBox.upper.u || end.v + reach < regionBox.lower.v ||
          end.v - reach > regionBox.upper.v)
        continue;
      const Vec2 n = g.joint[e].normal;
      WallLine line{g.jointPoint[e], {-n.v, n.u}, n, -1e300, 1e300};
      if (!clipRange(line, g.atLeast(first)) || !clipRange(line, g.atMost(last))) continue;
      if (!clipToRegion(line, region)) continue;
      wallsAlong(grooves, baseMaterial, line, lengthScale, out, stats);
    }
    // Vertical profile segments: the line b = const along the primitive, between its joints.
    for (std::size_t k = 0; k + 1 < g.profile.size(); ++k) {
      if (g.profile[k + 1].u != g.profile[k].u) continue;
      const double b = g.profile[k].u;
      WallLine line{{g.foot.u + b * g.binormal.u, g.foot.v + b * g.binormal.v}, g.tangent, g.binormal, -1e300, 1e300};
      if (!clipRange(line, g.joint[0]) || !clipRange(line, g.joint[1])) continue;
      if (!clipToRegion(line, region)) continue;
      wallsAlong(grooves, baseMaterial, line, lengthScale, out, stats);
    }
  }
}

}  // namespace bake::grooves
