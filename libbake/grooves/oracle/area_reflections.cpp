// Inter-reflections (seed 000 §7) in footprints sampled by area (§6's special cases): the beam of each
// mirror piece the eye sees, sampled along the mirrored view like a footprint of its own, and the
// beams of the mirrors it reaches. The beam and its bounds are described in area_sampling_stages.h.
#include <algorithm>
#include <cmath>

#include "grooves/oracle/area_sampling_stages.h"
#include "grooves/oracle/line_sampling_section.h"  // kMaxBeams

namespace bake::grooves::area_stages {
namespace {

constexpr int kMaxAreaBeamSteps = 4 * kMaxBeams;
constexpr double kNegligibleBeam = 1e-12;

// The part of piece p on the side of the plane (normal, offset) that the normal points to, by more than
// `tolerance` (Sutherland-Hodgman in 3D); count 0 when nothing is left.
SurfacePiece inFrontOfPlane(const SurfacePiece& p, const Vec3& normal, double offset, double tolerance) {
  SurfacePiece out = p;
  out.count = 0;
  for (int k = 0; k < p.count; ++k) {
    const Vec3& a = p.vertex[k];
    const Vec3& b = p.vertex[(k + 1) % p.count];
    const double da = dot(normal, a) - offset - tolerance, db = dot(normal, b) - offset - tolerance;
    if (da > 0) out.vertex[out.count++] = a;
    if ((da > 0) != (db > 0) && out.count < kPolygonMaxVertices) {
      const double t = da / (da - db);
      out.vertex[out.count++] = {a.u + t * (b.u - a.u), a.v + t * (b.v - a.v), a.w + t * (b.w - a.w)};
    }
    if (out.count == kPolygonMaxVertices) break;
  }
  if (out.count < 3) out.count = 0;
  return out;
}

// The region the beam's rays cross over the grooves' height range (and what shadows it), boxed: the
// fragments' box swept forward along R (up or down) until the rays leave the height range, then along
// L (as workingRegion). A ray from x0 at height w0 reaches x0 + s R_uv / |R_w| after a change of height
// s, at most height - w0 going up and w0 + depth going down (the horizontal reach bounded by kMaxReach,
// for rays near the horizon, as for the light).
ConvexPolygon beamRegion(const Job& job, const AreaBeam& beam, const Vec3& R) {
  const double e = 1e-6 * job.lengthScale, range = job.height + job.depth + e;
  const Vec3 level{R.u, R.v, std::abs(R.w)};  // the same shift per height, up or down
  Box2 start;
  double lowest = job.height, highest = -job.depth;
  for (const Polygon3& p : beam.fragments)
    for (int v = 0; v < p.count; ++v) {
      start.lower = {std::min(start.lower.u, p.vertex[v].u), std::min(start.lower.v, p.vertex[v].v)};
      start.upper = {std::max(start.upper.u, p.vertex[v].u), std::max(start.upper.v, p.vertex[v].v)};
      lowest = std::min(lowest, p.vertex[v].w);
      highest = std::max(highest, p.vertex[v].w);
    }
  const double climb = R.w > 0 ? job.height - lowest : (R.w < 0 ? highest + job.depth : range);
  const double raySweep[2] = {0, std::clamp(climb + e, 0.0, range)}, lightSweep[2] = {0, range};
  return sweptBox(start, e, shiftPerHeight(level), raySweep, shiftPerHeight(job.frame.toLight), lightSweep);
}

void addWeighted(Rgb& sum, const Rgb& weight, double share, const Rgb& radiance) {
  for (int c = 0; c < 3; ++c) sum[c] += weight[c] * share * radiance[c];
}

// Follows one beam: adds what its rays see to `sum` and pushes the beams of the mirrors they reach.
void followBeam(const Job& job, const AreaBeam& beam, Rgb& sum, std::vector<AreaBeam>& stack, AreaSampleStats& stats) {
  const Vec3 N = beam.normal;
  if (!(dot(N, beam.toViewer) > 0)) return;
  const Vec3 R = reflect(beam.toViewer, N);
  const Material& mirror = job.scene.materials[beam.material];
  Rgb weight;
  for (int c = 0; c < 3; ++c) weight[c] = beam.weight[c] * mirror.mirror[c];
  Frame f = job.frame;
  f.toViewer = {-R.u, -R.v, -R.w};
  f.baseScreen = false;
  perpendicularAxes(f.toViewer, f.screenAxis1, f.screenAxis2);

  // The beam on the new screen.
  thread_local std::vector<ConvexPolygon> windows;
  thread_local std::vector<double> windowWeights;
  windows.clear();
  windowWeights.clear();
  double beamArea = 0;
  for (const Polygon3& p : beam.fragments) {
    ConvexPolygon w;
    for (int v = 0; v < p.count; ++v) w.add(toScreen(f, p.vertex[v]));
    makeCounterClockwise(w);
    const double a = area(w);
    if (!(a > 0)) continue;
    windows.push_back(w);
    windowWeights.push_back(p.weight);
    beamArea += p.weight * a;
  }
  if (!(beamArea > 0)) return;  // seen edge-on: the beam carries no rays
  f.minArea = 1e-13 * beamArea;

  // What the rays can reach: the pieces in front of the mirror (`front`, cut to that side) and every
  // piece for the shadows (`casters`).
  thread_local std::vector<SurfacePiece> pieces, cut;
  thread_local std::vector<std::size_t> origin;  // the piece each cut piece comes from
  thread_local std::vector<Projected> casters, front;
  pieces.clear();
  cut.clear();
  origin.clear();
  if (!buildPiecesOver(job, beamRegion(job, beam, R), f.minArea, false, pieces, stats)) ++stats.incomplete;
  const double mirrorOffset = dot(N, beam.fragments.front().vertex[0]);
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const SurfacePiece c = inFrontOfPlane(pieces[k], N, mirrorOffset, f.depthTolerance);
    if (c.count == 0) continue;
    cut.push_back(c);
    origin.push_back(k);
  }
  casters.clear();
  for (const SurfacePiece& p : pieces) casters.push_back(project(f, p, false));
  front.clear();
  for (const SurfacePiece& c : cut) front.push_back(project(f, c, false));

  RadianceMemo radianceOf(job.scene.materials, f.toViewer, job.lighting);
  thread_local FragmentSet visible;
  ScreenEdges meEdges;
  double caught = 0;
  const double strongest = std::max({weight[0], weight[1], weight[2]});
  for (std::size_t i = 0; i < front.size(); ++i) {
    const Projected& me = front[i];
    if (me.facingViewer <= 1e-12) continue;
    const Material& material = job.scene.materials[me.piece->material];
    const Rgb radiance = radianceOf(me.piece->material, me.piece->normal);
    const bool bounceAgain = material.hasMirror && beam.bounce + 1 < job.lighting.maxBounces;
    meEdges.count = edgeHalfPlanes(me.screen, meEdges.edge);
    AreaBeam child;
    for (std::size_t w = 0; w < windows.size(); ++w) {
      if (!me.screenBox.overlaps(boundsOf(windows[w]))) continue;
      visible.count = 0;
      visible.minArea = f.minArea;
      visible.overflows = 0;
      visiblePart(f, front, i, windows[w], meEdges, visible);
      if (visible.count == 0) continue;
      const double scale = beam.share * windowWeights[w] / beamArea;  // footprint share per unit area here
      const double seen = scale * visible.weightedArea();
      caught += seen;
      if (bounceAgain && seen * strongest > kNegligibleBeam) {
        child.share += seen;
        liftFragments(f, me, visible, windowWeights[w], child.fragments);
      }
      if (isBlack(radiance)) continue;
      litPart(f, me, casters, &pieces[origin[i]], meEdges, visible);
      stats.fragmentOverflows += visible.overflows;
      addWeighted(sum, weight, scale * visible.weightedArea(), radiance);
    }
    if (child.share > 0 && stack.size() < std::size_t(kMaxBeams)) {
      child.normal = me.piece->normal;
      child.material = me.piece->material;
      child.toViewer = f.toViewer;
      child.weight = weight;
      child.bounce = beam.bounce + 1;
      stack.push_back(std::move(child));
    }
  }
  // Rays no piece catches: going up, they leave the surface and see the environment.
  if (R.w > 0) addWeighted(sum, weight, std::max(0.0, beam.share - caught), job.lighting.environment);
}

}  // namespace

// The fragments of `set` (on the screen of frame f) lifted onto piece p's plane, each weight scaled.
void liftFragments(const Frame& f, const Projected& p, const FragmentSet& set, double scale,
                   std::vector<Polygon3>& out) {
  for (int k = 0; k < set.count; ++k) {
    const Fragment& fragment = set.fragment[k];
    Polygon3 lifted;
    for (int v = 0; v < fragment.polygon.count; ++v)
      lifted.vertex[lifted.count++] = seenPoint(f, p, fragment.polygon.vertex[v]);
    lifted.weight = scale * fragment.weight;
    out.push_back(lifted);
  }
}

// What the reflection of a mirror piece seen by the eye adds: its beam and every beam it leads to.
Rgb traceReflections(const Job& job, AreaBeam first, AreaSampleStats& stats) {
  thread_local std::vector<AreaBeam> stack;
  stack.clear();
  stack.push_back(std::move(first));
  Rgb sum{0, 0, 0};
  for (int step = 0; step < kMaxAreaBeamSteps && !stack.empty(); ++step) {
    const AreaBeam beam = std::move(stack.back());
    stack.pop_back();
    followBeam(job, beam, sum, stack, stats);
  }
  return sum;
}

}  // namespace bake::grooves::area_stages
