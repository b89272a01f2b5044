// Area sampling for the special cases of seed 000 §6 (intersections, intersected ends, isolated ends,
// corners), exact for straightened primitives. The local surface is built as planar convex pieces
// (area_surface.cpp, area_walls.cpp: the seed's facets after intersection removal, §6.2, and the walls
// of ends, §6.5). Then, for every piece facing the viewer:
// - footprint clipping and masking (§6.1, §6.3): the piece is projected along the view onto the base
//   plane (x' = x - (h / E_w) E_uv, "screen" coordinates); its visible part is its projection clipped
//   to the footprint parallelogram, minus the projections of the pieces in front of it. Pieces of a
//   height field do not interpenetrate, so "in front" is decided once, at one point of the overlap.
//   Pieces facing away are hidden by the pieces in front of them and are skipped.
// - shadowing (§6.3): every piece nearer the light is projected along L onto the piece's plane and
//   from there along the view onto the base plane (both affine maps of the piece's plane), and
//   subtracted from the visible part.
// - reflection (§6.4, Eq. 1): r_i = (area of the visible, lit part on the base plane) / footprint area,
//   and the pixel is sum r_i directRadiance(material_i, N_i, E, L).
// - inter-reflections (§7): while bounces are followed, the visible part of a mirror piece (lit or
//   not) is a beam, sampled like a footprint of its own along the mirrored view (area_reflections.cpp):
//   what it shows is added x the mirror's reflectance, its own mirrors' parts become beams in turn,
//   and its rays that leave the surface see the environment (§7's light from outside, 1 - Σ r_i).
// Both tests first compare the other piece with the piece's plane: wholly behind it, it can neither
// hide nor shadow the piece; wholly in front, the one-point test's verdict is known and the clip
// against the piece is skipped.
// A zero-area footprint is a point sample: the radiance of the point seen along the view line.
// The working region covers the footprint, what its view lines cross and what can shadow that, as a
// box (workingRegion below); for a light near the horizon, shadows are looked for up to kMaxLightSlope
// times the grooves' height range away (as far as the shader's query box reaches), beyond that they
// are missed.
// Caps: kMaxSurfacePieces (512) pieces and kMaxWalls (128) walls per footprint, kMaxFragments (48)
// convex fragments per visible piece, kPolygonMaxVertices (24) vertices per polygon. Overflows are
// counted (AreaSampleStats) and degrade gracefully: too many pieces split the footprint in quarters
// (exact, up to three times: 64 sub-footprints), past that the pieces that do not fit are left out
// (their light is lost); too many fragments keep a fragment whole with a weight that removes the
// hole's area (polygon.h); a polygon out of vertices drops one (it shrinks slightly). Buffers are
// per-thread and reused, so a footprint (not point) sample allocates nothing once they have grown.
#include <algorithm>
#include <array>
#include <cmath>

#include "bake_formats/grooves.h"
#include "grooves/oracle/area_surface.h"
#include "grooves/oracle/area_sampling_stages.h"

namespace bake::grooves {
namespace area_stages {

Vec2 toScreen(const Frame& f, const Vec3& p) {
  if (!f.baseScreen) return {dot(p, f.screenAxis1), dot(p, f.screenAxis2)};
  const double k = p.w / f.toViewer.w;
  return {p.u - k * f.toViewer.u, p.v - k * f.toViewer.v};
}

// The screen point x in 3D.
Vec3 fromScreen(const Frame& f, Vec2 x) {
  if (f.baseScreen) return {x.u, x.v, 0};
  const Vec3 &a = f.screenAxis1, &b = f.screenAxis2;
  return {x.u * a.u + x.v * b.u, x.u * a.v + x.v * b.v, x.u * a.w + x.v * b.w};
}

Vec2 toLightPlane(const Frame& f, const Vec3& p) { return {dot(p, f.lightAxis1), dot(p, f.lightAxis2)}; }

void perpendicularAxes(const Vec3& d, Vec3& a, Vec3& b) {
  const Vec3 helper = std::abs(d.w) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  a = {helper.v * d.w - helper.w * d.v, helper.w * d.u - helper.u * d.w, helper.u * d.v - helper.v * d.u};
  const double n = std::sqrt(dot(a, a));
  a = {a.u / n, a.v / n, a.w / n};
  b = {d.v * a.w - d.w * a.v, d.w * a.u - d.u * a.w, d.u * a.v - d.v * a.u};
}

// `withLightView`: the point sample tests containment in the light's view; area samples need only its
// box.
Projected project(const Frame& f, const SurfacePiece& piece, bool withLightView) {
  Projected p;
  p.piece = &piece;
  p.facingViewer = dot(piece.normal, f.toViewer);
  p.facingLight = dot(piece.normal, f.toLight);
  for (int i = 0; i < piece.count; ++i) {
    p.screen.add(toScreen(f, piece.vertex[i]));
    const Vec2 l = toLightPlane(f, piece.vertex[i]);
    p.lightBox.lower = {std::min(p.lightBox.lower.u, l.u), std::min(p.lightBox.lower.v, l.v)};
    p.lightBox.upper = {std::max(p.lightBox.upper.u, l.u), std::max(p.lightBox.upper.v, l.v)};
    if (withLightView) p.lightView.add(l);
  }
  // A facet's screen image keeps its counter-clockwise order when it faces the viewer (the map
  // x -> x - h(x) E_uv / E_w has determinant N.E / (N_w E_w) > 0, and the sampler skips the pieces
  // facing it less than that); walls and back faces are sorted.
  if (piece.wall || !(p.facingViewer > 1e-12) || !f.baseScreen) makeCounterClockwise(p.screen);
  if (withLightView) makeCounterClockwise(p.lightView);
  p.screenBox = boundsOf(p.screen);
  return p;
}

// Distance along the view line through screen point x (from the screen, towards the viewer) to the
// piece's plane.
double viewDepth(const Frame& f, const Projected& p, Vec2 x) {
  return (p.piece->planeOffset - dot(p.piece->normal, fromScreen(f, x))) / p.facingViewer;
}

// The point of piece p seen at screen point x.
Vec3 seenPoint(const Frame& f, const Projected& p, Vec2 x) {
  const double t = viewDepth(f, p, x);
  const Vec3 s = fromScreen(f, x);
  return {s.u + t * f.toViewer.u, s.v + t * f.toViewer.v, s.w + t * f.toViewer.w};
}

// Signed distance from q along L to the plane of p (positive: the plane is towards the light).
double lightDistance(const Projected& p, const Vec3& q) {
  return (p.piece->planeOffset - dot(p.piece->normal, q)) / p.facingLight;
}

bool occludesLight(const Frame& f, const Projected& p) {
  return f.lightAllOccluders ? std::abs(p.facingLight) > 1e-12 : p.facingLight > 1e-12;
}

// True when no vertex of `other` lies strictly on the side of me's plane that me's normal points to.
// Then, for a piece me facing the viewer (the light), other hides (shadows) none of it: the view line
// (light ray) from a point of me leaves on that side. The full test would reach the same verdict at
// the cost of a clip and a subtraction; this keeps the pair count of the two loops below small (the
// ground behind the facets, a facet behind the ground).
bool behindPlaneOf(const Projected& me, const Projected& other) {
  const SurfacePiece& a = *me.piece;
  const SurfacePiece& b = *other.piece;
  for (int k = 0; k < b.count; ++k)
    if (dot(a.normal, b.vertex[k]) - a.planeOffset > 0) return false;
  return true;
}

// True when every vertex of `other` lies more than `margin` on the side of me's plane that me's normal
// points to. Then, for me facing the viewer (the light), wherever the two overlap on the screen (in
// the shadow), other is in front by more than the margin, which is the verdict the one-point test
// would give: the subtraction can go ahead without clipping the two against each other.
bool inFrontOfPlaneOf(const Projected& me, const Projected& other, double margin) {
  const SurfacePiece& a = *me.piece;
  const SurfacePiece& b = *other.piece;
  for (int k = 0; k < b.count; ++k)
    if (!(dot(a.normal, b.vertex[k]) - a.planeOffset > margin)) return false;
  return true;
}

// Where piece me lies against other's plane (the two tests above the other way round): on the side
// other's normal points to (or on the plane) with every vertex, more than `margin` on the far side
// with every vertex, or across. For other facing the viewer (the light), a line from a point of me
// towards the viewer (the light) then never crosses other's plane, so other hides (shadows) none of
// me; or always does, with other in front by more than the margin wherever they overlap, the one-point
// test's verdict. Both spare the clip that finds a point of the overlap.
enum class Against { front, behind, across };
Against sideOfPlaneOf(const Projected& me, const Projected& other, double margin) {
  const SurfacePiece& plane = *other.piece;
  const SurfacePiece& b = *me.piece;
  bool front = true, behind = true;
  for (int k = 0; k < b.count && (front || behind); ++k) {
    const double d = dot(plane.normal, b.vertex[k]) - plane.planeOffset;
    front = front && !(d < 0);
    behind = behind && d < -margin;
  }
  return front ? Against::front : (behind ? Against::behind : Against::across);
}

// The visible part of piece i inside the footprint: its projection minus the pieces in front. The
// footprint is clipped by the piece (rather than the other way round): it is the smaller of the two,
// mostly inside every edge of the piece, and such an edge costs no clip.
void visiblePart(const Frame& f, const std::vector<Projected>& all, std::size_t i, const ConvexPolygon& footprint,
                 const ScreenEdges& meEdges, FragmentSet& visible) {
  const Projected& me = all[i];
  visible.add(intersect(footprint, meEdges.edge, meEdges.count));
  Box2 bounds = visible.bounds();  // kept up to date: it only changes with a subtraction
  for (std::size_t j = 0; j < all.size() && visible.count > 0; ++j) {
    const Projected& other = all[j];
    if (j == i || other.facingViewer <= 1e-12 || !other.screenBox.overlaps(bounds) || behindPlaneOf(me, other))
      continue;
    const Against side = inFrontOfPlaneOf(me, other, f.depthTolerance) ? Against::behind
                                                                        : sideOfPlaneOf(me, other, f.depthTolerance);
    if (side == Against::front) continue;
    if (side == Against::behind) {
      visible.subtract(other.screen);  // drops nothing where they do not overlap
      bounds = visible.bounds();
      continue;
    }
    const ConvexPolygon overlap = intersect(other.screen, meEdges.edge, meEdges.count);
    if (overlap.empty() || area(overlap) <= f.minArea) continue;
    const Vec2 c = centroid(overlap);
    if (viewDepth(f, other, c) > viewDepth(f, me, c) + f.depthTolerance) {
      visible.subtract(other.screen);
      bounds = visible.bounds();
    }
  }
}

// Piece j's shadow on piece i's plane, seen on the screen.
ConvexPolygon shadowOnScreen(const Frame& f, const Projected& receiver, const Projected& caster) {
  ConvexPolygon s;
  for (int k = 0; k < caster.piece->count; ++k) {
    const Vec3& q = caster.piece->vertex[k];
    const double lambda = lightDistance(receiver, q);
    s.add(toScreen(f, {q.u + lambda * f.toLight.u, q.v + lambda * f.toLight.v, q.w + lambda * f.toLight.w}));
  }
  makeCounterClockwise(s);
  return s;
}

// The lit part of `part` (visible fragments of piece me), shadowed by the pieces `casters` but `self`
// (the piece me was cut from, or me).
void litPart(const Frame& f, const Projected& me, const std::vector<Projected>& casters, const SurfacePiece* self,
             const ScreenEdges& meEdges, FragmentSet& part) {
  Box2 bounds = part.bounds();  // kept up to date: it only changes with a subtraction
  for (std::size_t j = 0; j < casters.size() && part.count > 0; ++j) {
    const Projected& other = casters[j];
    if (other.piece == self || !occludesLight(f, other) || !other.lightBox.overlaps(me.lightBox))
      continue;
    if (me.facingLight > 0 && behindPlaneOf(me, other)) continue;
    // Against the caster's plane, when the caster faces the light.
    const Against side = other.facingLight > 1e-12 ? sideOfPlaneOf(me, other, f.depthTolerance) : Against::across;
    if (side == Against::front) continue;
    const ConvexPolygon shadow = shadowOnScreen(f, me, other);
    if (!shadow.empty() && !boundsOf(shadow).overlaps(bounds)) continue;
    if (side == Against::behind || (me.facingLight > 0 && inFrontOfPlaneOf(me, other, f.depthTolerance))) {
      part.subtract(shadow);  // drops nothing where they do not overlap
      bounds = part.bounds();
      continue;
    }
    const ConvexPolygon overlap = intersect(shadow, meEdges.edge, meEdges.count);
    if (overlap.empty() || area(overlap) <= f.minArea) continue;
    const Vec3 p = seenPoint(f, me, centroid(overlap));
    if (lightDistance(other, p) > f.depthTolerance) {
      part.subtract(shadow);
      bounds = part.bounds();
    }
  }
}

bool isBlack(const Rgb& c) { return c[0] == 0 && c[1] == 0 && c[2] == 0; }

// The radiance of the surface point seen along the view line through the footprint centre.
Rgb pointSample(const GrooveScene& scene, const Frame& f, const std::vector<Projected>& all, const Lighting& lighting) {
  const Vec2 centre{0, 0};
  const Projected* front = nullptr;
  double best = -1e300;
  for (const Projected& p : all) {
    if (p.facingViewer <= 1e-12 || !contains(p.screen, centre)) continue;
    const double t = viewDepth(f, p, centre);
    if (t > best) best = t, front = &p;
  }
  if (!front) return {0, 0, 0};
  const Vec3 x = seenPoint(f, *front, centre);
  const Rgb direct = directRadiance(scene.materials[front->piece->material], front->piece->normal, f.toViewer, lighting);
  if (isBlack(direct)) return direct;
  const Vec2 xl = toLightPlane(f, x);
  for (const Projected& p : all) {
    if (&p == front || !occludesLight(f, p) || !contains(p.lightView, xl)) continue;
    if (lightDistance(p, x) > f.depthTolerance) return {0, 0, 0};
  }
  return direct;
}

// The extent of the local geometry: half-width, height above and depth below the base plane.
struct Extent {
  double width = 0, height = 0, depth = 0;
};
Extent extentOf(const std::vector<StraightGroove>& grooves) {
  Extent e;
  for (const StraightGroove& g : grooves)
    for (const Vec2& p : g.profile) {
      e.width = std::max(e.width, std::abs(p.u));
      e.height = std::max(e.height, p.v);
      e.depth = std::max(e.depth, -p.v);
    }
  return e;
}

// How far from a point its view line and its light ray travel over the grooves' height range; a light
// near or below the horizon is followed up to a bounded distance.
constexpr double kMaxLightSlope = format::grooves::kMaxReach;  // as far as the query box (shade.cpp)
double reach(const Vec3& d, double heightRange) {
  const double horizontal = std::sqrt(d.u * d.u + d.v * d.v);  // d is a unit direction: no overflow
  if (horizontal == 0) return 0;
  const double slope = d.w > horizontal / kMaxLightSlope ? horizontal / d.w : kMaxLightSlope;
  return heightRange * slope;
}

// The horizontal shift per unit of height along d (d / d_w, bounded like reach()).
Vec2 shiftPerHeight(const Vec3& d) {
  const double horizontal = std::sqrt(d.u * d.u + d.v * d.v);  // d is a unit direction: no overflow
  if (horizontal == 0) return {0, 0};
  const double k = reach(d, 1) / horizontal;
  return {k * d.u, k * d.v};
}

// The box `start`, grown by e, swept by h a for h in aRange, then by k b for k in bRange: the
// rectangle around it, cut to the slabs along a and along b that hold the swept set (a long sweep
// askew to the axes covers a small part of its rectangle).
ConvexPolygon sweptBox(const Box2& start, double e, Vec2 a, const double (&aRange)[2], Vec2 b,
                       const double (&bRange)[2]) {
  std::array<Vec2, 16> corners;
  int n = 0;
  Box2 box;
  for (const double cu : {start.lower.u - e, start.upper.u + e})
    for (const double cv : {start.lower.v - e, start.upper.v + e})
      for (const double h : aRange)
        for (const double k : bRange) {
          const Vec2 x{cu + h * a.u + k * b.u, cv + h * a.v + k * b.v};
          corners[std::size_t(n++)] = x;
          box.lower = {std::min(box.lower.u, x.u), std::min(box.lower.v, x.v)};
          box.upper = {std::max(box.upper.u, x.u), std::max(box.upper.v, x.v)};
        }
  ConvexPolygon region;
  region.add(box.lower);
  region.add({box.upper.u, box.lower.v});
  region.add(box.upper);
  region.add({box.lower.u, box.upper.v});
  for (const Vec2 along : {a, b}) {
    if (along.u == 0 && along.v == 0) continue;
    const Vec2 across{-along.v, along.u};
    double lowest = 1e300, highest = -1e300;
    for (const Vec2& x : corners) {
      const double d = across.u * x.u + across.v * x.v;
      lowest = std::min(lowest, d);
      highest = std::max(highest, d);
    }
    clipInPlace(region, HalfPlane{across, lowest});
    clipInPlace(region, HalfPlane{{-across.u, -across.v}, -highest});
  }
  return region;
}

// The working region: the points of the surface that can be seen in the footprint, hide them or
// shadow them, boxed. A point of height h seen at the footprint point x' lies at x' + h E' (E' =
// E_uv / E_w), h in [-depth, height]; what hides it lies further along the same view line, higher, so
// within the same set; what shadows it lies along L' (= L_uv / L_w) from it, at most height + depth
// further up. So the region is the footprint swept by [-depth, height] E' and then by
// [0, height + depth] L' (the light's reach bounded like reach()). Pieces are clipped to it whole
// or in part; a part of a piece still decides its occlusion of another at one point of their overlap
// correctly: pieces of a height field have disjoint convex domains, which keep one order along every
// view line (and light ray) crossing both. Its 4 edges keep the base plane's cells cheap to clip
// against.
ConvexPolygon workingRegion(const Job& job, const Box2& footprintBox) {
  const double e = 1e-6 * job.lengthScale;
  const double viewSweep[2] = {-job.depth - e, job.height + e};
  const double lightSweep[2] = {0, job.height + job.depth + e};
  return sweptBox(footprintBox, e, shiftPerHeight(job.frame.toViewer), viewSweep, shiftPerHeight(job.frame.toLight),
                  lightSweep);
}

// The pieces of the surface over the working region of the footprint box; false when a cap was
// reached.
bool buildPiecesOver(const Job& job, const ConvexPolygon& region, double minArea, bool stopAtCap,
                     std::vector<SurfacePiece>& pieces, AreaSampleStats& stats) {
  SurfaceBuildStats local;
  buildHeightPieces(job.grooves, job.scene.baseMaterial, region, minArea, stopAtCap, pieces, local);
  buildWalls(job.grooves, job.scene.baseMaterial, region, job.lengthScale, stopAtCap, pieces, local);
  stats.surface.cells += local.cells;
  stats.surface.walls += local.walls;
  stats.surface.truncated = stats.surface.truncated || local.truncated;
  if (local.overflows == 0) return true;
  stats.surface.overflows += local.overflows;
  return false;
}

bool buildPieces(const Job& job, const Box2& footprintBox, double minArea, bool stopAtCap,
                 std::vector<SurfacePiece>& pieces, AreaSampleStats& stats) {
  return buildPiecesOver(job, workingRegion(job, footprintBox), minArea, stopAtCap, pieces, stats);
}

}  // namespace area_stages

namespace {

using namespace area_stages;

// Splits a footprint into 2 x 2 halves at most this many times when its pieces overflow the caps
// (at most 4^3 sub-footprints, each with fewer pieces); past that, pieces are dropped (counted).
constexpr int kMaxSplitDepth = 3;

Rgb sampleParallelogram(const Job& job, Vec2 centre, Vec2 axis1, Vec2 axis2, int depth, AreaSampleStats& stats) {
  const ConvexPolygon fp = parallelogram(centre, axis1, axis2);
  const double footprintArea = area(fp);
  Frame f = job.frame;
  f.minArea = 1e-13 * footprintArea;
  const Box2 fpBox = boundsOf(fp);
  // Per-thread scratch, reused from pixel to pixel (a split footprint refills it; its own pieces are
  // no longer needed then).
  thread_local std::vector<SurfacePiece> pieces;
  thread_local std::vector<Projected> all;
  pieces.clear();
  const bool complete = buildPieces(job, fpBox, f.minArea, depth < kMaxSplitDepth, pieces, stats);
  if (!complete && depth == kMaxSplitDepth) ++stats.incomplete;
  if (!complete && depth < kMaxSplitDepth) {
    ++stats.splits;
    const Vec2 h1{0.5 * axis1.u, 0.5 * axis1.v}, h2{0.5 * axis2.u, 0.5 * axis2.v};
    Rgb sum{0, 0, 0};
    for (const double s1 : {-0.5, 0.5})
      for (const double s2 : {-0.5, 0.5}) {
        const Vec2 c{centre.u + s1 * h1.u + s2 * h2.u, centre.v + s1 * h1.v + s2 * h2.v};
        const Rgb quarter = sampleParallelogram(job, c, h1, h2, depth + 1, stats);
        for (int k = 0; k < 3; ++k) sum[k] += 0.25 * quarter[k];
      }
    return sum;
  }
  all.clear();
  for (const SurfacePiece& p : pieces) all.push_back(project(f, p, false));

  Rgb sum{0, 0, 0};
  thread_local FragmentSet visible;
  RadianceMemo radianceOf(job.scene.materials, f.toViewer, job.lighting);
  ScreenEdges meEdges;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Projected& me = all[i];
    if (me.facingViewer <= 1e-12 || !me.screenBox.overlaps(fpBox)) continue;
    const Rgb radiance = radianceOf(me.piece->material, me.piece->normal);
    const Material& material = job.scene.materials[me.piece->material];
    const bool reflects = material.hasMirror && job.lighting.maxBounces > 0;
    if (isBlack(radiance) && !reflects) continue;  // no direct light, nothing reflected
    visible.count = 0;
    visible.minArea = f.minArea;
    visible.overflows = 0;
    meEdges.count = edgeHalfPlanes(me.screen, meEdges.edge);
    visiblePart(f, all, i, fp, meEdges, visible);
    if (visible.count == 0) continue;
    ++stats.visiblePieces;
    if (reflects && !job.traceReflections) {  // the runtime's model: the reflection leaves the surface
      const double seen = visible.weightedArea() / footprintArea;
      const Rgb reflected = environmentReflection(material, job.lighting);
      for (int c = 0; c < 3; ++c) sum[c] += seen * reflected[c];
    } else if (reflects) {  // the visible part (lit or not) mirrors what its reflected rays meet
      AreaBeam beam;
      liftFragments(f, me, visible, 1.0, beam.fragments);
      beam.normal = me.piece->normal;
      beam.material = me.piece->material;
      beam.toViewer = f.toViewer;
      beam.share = visible.weightedArea() / footprintArea;
      const Rgb reflected = traceReflections(job, std::move(beam), stats);
      for (int c = 0; c < 3; ++c) sum[c] += reflected[c];
    }
    if (isBlack(radiance)) continue;
    litPart(f, me, all, me.piece, meEdges, visible);
    stats.fragmentOverflows += visible.overflows;
    const double share = visible.weightedArea() / footprintArea;
    for (int c = 0; c < 3; ++c) sum[c] += share * radiance[c];
  }
  return sum;
}

}  // namespace

Rgb areaSampleWithStats(const GrooveScene& scene, const std::vector<LocalGroove>& grooves, const Footprint& footprint,
                        const Vec3& toViewer, const Lighting& lighting, AreaSampleStats& stats,
                        bool traceReflections) {
  stats = {};
  if (!(toViewer.w > 0)) return {0, 0, 0};
  thread_local std::vector<StraightGroove> straight;  // per-thread, reused from sample to sample
  straighten(scene, grooves, footprint.centre, straight);
  const Extent extent = extentOf(straight);

  // The footprint around the origin.
  Vec2 axis1 = footprint.axis1, axis2 = footprint.axis2;
  const double span = std::hypot(axis1.u, axis1.v) + std::hypot(axis2.u, axis2.v);
  stats.pointSample = span == 0;
  if (!stats.pointSample && area(parallelogram({0, 0}, axis1, axis2)) < 1e-12 * span * span) {
    // Parallel axes: the limit of a thin parallelogram, so the shorter axis gets a tiny perpendicular
    // part (the density along the segment stays the one of the flattened parallelogram).
    const bool firstLonger = std::hypot(axis1.u, axis1.v) >= std::hypot(axis2.u, axis2.v);
    const Vec2 along = firstLonger ? axis1 : axis2;
    const double n = std::hypot(along.u, along.v);
    Vec2& shorter = firstLonger ? axis2 : axis1;
    shorter = {shorter.u - along.v / n * 1e-6 * span, shorter.v + along.u / n * 1e-6 * span};
  }

  Job job{scene, straight, lighting, traceReflections, {}, extent.height, extent.depth,
          std::max({span, extent.width, extent.height + extent.depth, 1e-300})};
  Frame& f = job.frame;
  f.toViewer = toViewer;
  f.toLight = lighting.toLight;
  perpendicularAxes(f.toLight, f.lightAxis1, f.lightAxis2);
  f.depthTolerance = 1e-12 * job.lengthScale;
  f.lightAllOccluders = f.toLight.w < 0.05;

  if (!stats.pointSample) return sampleParallelogram(job, {0, 0}, axis1, axis2, 0, stats);
  f.minArea = 1e-19 * job.lengthScale * job.lengthScale;
  std::vector<SurfacePiece> pieces;
  Box2 point;
  point.lower = point.upper = {0, 0};
  if (!buildPieces(job, point, f.minArea, false, pieces, stats)) ++stats.incomplete;
  std::vector<Projected> all;
  all.reserve(pieces.size());
  for (const SurfacePiece& p : pieces) all.push_back(project(f, p, true));
  return pointSample(scene, f, all, lighting);
}

Rgb areaSample(const GrooveScene& scene, const std::vector<LocalGroove>& grooves, const Footprint& footprint,
               const Vec3& toViewer, const Lighting& lighting, bool traceReflections) {
  AreaSampleStats stats;
  return areaSampleWithStats(scene, grooves, footprint, toViewer, lighting, stats, traceReflections);
}

}  // namespace bake::grooves
