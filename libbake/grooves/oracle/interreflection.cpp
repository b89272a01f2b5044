// Mirror inter-reflections on a cross-section (seed 000 §7): a kind of beam tracing. Each visible
// portion of a mirror facet sends a beam along the mirrored view direction R; in the section plane the
// beam is the portion's points travelling along R' = (R.B, R_w). Which facets it reaches first is found
// by the same ordered projection as masking (§5.2): in the coordinate k across R' (one value per ray),
// the facets after the mirror, walked in the beam's direction of travel from the mirror's far end, catch
// the rays whose k lies beyond the running extreme of everything walked before (the beam always keeps
// one contiguous range of k, cut from one side). Only facets past the mirror are walked, which is the
// seed's rule that only the visible part of the cross-section may take part in a bounce. A caught part
// adds mirror x (its direct radiance seen from -R, where lit) weighted by its share of the footprint,
// and, while bounces remain, becomes a new beam with -R as its view direction. Rays that pass the
// section's end going up leave the surface and see the environment (Lighting::environment, black by
// default): the part of the new footprint that projects onto no groove, weighted by its share, the
// seed's 1 - Σ r_i; going down, they reach the flat base beyond it (lit unless the section shadows
// it; a mirror base sends them up and away, to the environment, while bounces remain).
//
// A beam carries the footprint measure of its rays: the base-line position p seen through each ray's
// start is affine in k, so a caught range of k maps to a share of the footprint exactly. The beams
// live on an explicit stack of kMaxBeams entries (the shader has no recursion); a child that does not
// fit, or carries less than 1e-12 of the pixel, is dropped (its radiance lost), and at most
// kMaxBeamSteps beams are walked per section, so deep mirror cavities stay bounded.
#include <algorithm>
#include <cmath>

#include "grooves/oracle/line_sampling_section.h"

namespace bake::grooves {
namespace {

double dot3(const Vec3& a, const Vec3& b) { return a.u * b.u + a.v * b.v + a.w * b.w; }

// Bounds of the work per section (the shader's loops must be bounded): beams walked in all, and the
// share x reflectance below which a beam is not followed further.
constexpr int kMaxBeamSteps = 4 * kMaxBeams;
constexpr double kNegligible = 1e-12;

struct Beam {
  std::size_t facet = 0;
  double t0 = 0, t1 = 0;  // the part of the facet the rays leave from
  double p0 = 0, p1 = 0;  // base-line position (footprint coordinate) of the view lines reaching t0, t1
  Vec3 toViewer;          // towards what looks at this facet: E, then back along the previous ray
  Rgb weight{1, 1, 1};    // product of the mirror reflectances already applied
  int bounce = 0;         // reflections made before this one
};

struct BeamStack {
  Beam items[kMaxBeams];
  int size = 0;
  void push(const Beam& beam) {
    if (size < kMaxBeams) items[size++] = beam;
  }
};

// Everything one beam needs while it is walked.
struct Walk {
  const GrooveScene& scene;
  const CrossSection& section;
  const FootprintLine& density;
  const Lighting& lighting;
  const std::vector<FacetSpan>& lit;
  double rb = 0, rw = 0, dir = 1;  // R' and the direction of travel along b
  Vec3 back{};                     // -R
  Rgb weight{};                    // beam weight x this mirror's reflectance
  int bounce = 0;                  // reflections made before this beam's
  // Footprint position as an affine function of the ray coordinate k.
  double kAt0 = 0, kAt1 = 0, p0 = 0, p1 = 0;

  SectionDirection ray{};           // R in the section's frame
  double key(const SectionPoint& p) const { return dir * acrossCoordinate(section, p, ray); }
  double positionOf(double k) const {
    const double s = std::clamp((k - kAt0) / (kAt1 - kAt0), 0.0, 1.0);
    return p0 + s * (p1 - p0);
  }
  void add(double share, const Rgb& radiance, Rgb& sum) const {
    for (int c = 0; c < 3; ++c) sum[c] += weight[c] * share * radiance[c];
  }
};

// The rays with k in [x, y] reach facet j: add its lit radiance and push the bounce.
void catchOnFacet(const Walk& w, const Beam& beam, std::size_t j, double x, double y, Rgb& sum, BeamStack& stack) {
  const SectionPoint& a = w.section.points[j];
  const SectionPoint& b = w.section.points[j + 1];
  const double ka = w.key(a), kb = w.key(b);
  const double sx = std::clamp((x - ka) / (kb - ka), 0.0, 1.0), sy = std::clamp((y - ka) / (kb - ka), 0.0, 1.0);
  const double s0 = std::min(sx, sy), s1 = std::max(sx, sy);
  if (!(s1 > s0)) return;
  auto positionAt = [&](double s) { return w.positionOf(ka + s * (kb - ka)); };
  const Material& material = w.scene.materials[w.section.material[j]];
  const double l0 = std::max(s0, w.lit[j].t0), l1 = std::min(s1, w.lit[j].t1);
  if (l1 > l0) {
    const Rgb f = directRadiance(material, facetNormal3(w.section, j), w.back, w.lighting);
    w.add(w.density.share(positionAt(l0), positionAt(l1)), f, sum);
  }
  const double childShare = w.density.share(positionAt(s0), positionAt(s1));
  const double strongest = std::max({w.weight[0], w.weight[1], w.weight[2]});
  if (material.hasMirror && beam.bounce + 1 < w.lighting.maxBounces && childShare * strongest > kNegligible) {
    Beam child;
    child.facet = j;
    child.t0 = s0;
    child.t1 = s1;
    child.p0 = positionAt(s0);
    child.p1 = positionAt(s1);
    child.toViewer = w.back;
    child.weight = w.weight;
    child.bounce = beam.bounce + 1;
    stack.push(child);
  }
}

// The rays with k in [x, y] pass the section's end going down: they reach the flat base beyond it.
void catchOnFarBase(const Walk& w, double x, double y, Rgb& sum) {
  const Material& base = w.scene.materials[w.scene.baseMaterial];
  // A mirror base reflects these rays up, away from the section: they see the environment.
  if (w.bounce + 1 < w.lighting.maxBounces)
    w.add(w.density.share(w.positionOf(x), w.positionOf(y)), environmentReflection(base, w.lighting), sum);
  const Vec3& L = w.lighting.toLight;
  if (!(L.w > 0)) return;
  const SectionDirection light = inSection(w.section, L);
  const double lb = light.b, lw = light.w;
  // On the far side, a base point at b is shadowed only by the section, when the light comes from the
  // section's side: lit for b beyond the section's shadow line b = extreme / lw.
  double limit = y;
  if (w.dir * lb < 0) {
    double extreme = w.dir > 0 ? -INFINITY : INFINITY;
    for (const SectionPoint& p : w.section.points) {
      const double k = acrossCoordinate(w.section, p, light);
      extreme = w.dir > 0 ? std::max(extreme, k) : std::min(extreme, k);
    }
    // The ray with coordinate k meets h = 0 at b = dir k / rw; lit where dir b >= dir extreme / lw,
    // i.e. k <= dir (extreme / lw) rw (rw < 0 here).
    limit = std::min(y, w.dir * (extreme / lw) * w.rw);
  }
  if (!(limit > x)) return;
  const Rgb f = directRadiance(base, {0, 0, 1}, w.back, w.lighting);
  w.add(w.density.share(w.positionOf(x), w.positionOf(limit)), f, sum);
}

void traceBeam(const GrooveScene& scene, const CrossSection& section, const FootprintLine& density,
               const Lighting& lighting, const std::vector<FacetSpan>& lit, const Beam& beam, Rgb& sum,
               BeamStack& stack) {
  const Material& mirror = scene.materials[section.material[beam.facet]];
  const Vec3 normal = facetNormal3(section, beam.facet);
  if (!(dot3(beam.toViewer, normal) > 0)) return;
  const Vec3 R = reflect(beam.toViewer, normal);
  Walk w{scene, section, density, lighting, lit};
  w.bounce = beam.bounce;
  w.ray = inSection(section, R);
  w.rb = w.ray.b;
  w.rw = w.ray.w;
  for (int c = 0; c < 3; ++c) w.weight[c] = beam.weight[c] * mirror.mirror[c];
  if (w.rb == 0) {  // straight up: every ray leaves the surface
    if (w.rw > 0) w.add(density.share(std::min(beam.p0, beam.p1), std::max(beam.p0, beam.p1)), lighting.environment, sum);
    return;
  }
  w.dir = w.rb > 0 ? 1 : -1;
  w.back = {-R.u, -R.v, -R.w};

  const std::vector<SectionPoint>& pts = section.points;
  const std::size_t f = beam.facet;
  const double kf0 = w.key(pts[f]), kf1 = w.key(pts[f + 1]);
  w.kAt0 = kf0 + beam.t0 * (kf1 - kf0);
  w.kAt1 = kf0 + beam.t1 * (kf1 - kf0);
  w.p0 = beam.p0;
  w.p1 = beam.p1;
  const double low = std::min(w.kAt0, w.kAt1), high = std::max(w.kAt0, w.kAt1);
  if (!(high > low)) return;  // a beam of no width carries no share of the footprint

  // Walk from the mirror's far end in the direction of travel; `lowest` bounds the rays still flying.
  double lowest = w.dir > 0 ? kf1 : kf0;
  const std::size_t facets = section.facetCount();
  for (std::size_t step = 1; step < facets && lowest > low; ++step) {
    const long long jj = w.dir > 0 ? (long long)(f + step) : (long long)f - (long long)step;
    if (jj < 0 || jj >= (long long)facets) break;
    const std::size_t j = std::size_t(jj);
    const double kNear = w.key(w.dir > 0 ? pts[j] : pts[j + 1]);
    const double kFar = w.key(w.dir > 0 ? pts[j + 1] : pts[j]);
    if (kFar < kNear) {
      const double x = std::max(kFar, low), y = std::min(lowest, high);
      if (y > x) catchOnFacet(w, beam, j, x, y, sum, stack);
    }
    lowest = std::min(lowest, kFar);
  }
  if (lowest > low && w.rw < 0) catchOnFarBase(w, low, std::min(lowest, high), sum);
  // Rays past the section's end going up leave the surface: they see the environment.
  if (lowest > low && w.rw > 0) w.add(density.share(w.positionOf(low), w.positionOf(std::min(lowest, high))), lighting.environment, sum);
}

}  // namespace

Rgb mirrorBounces(const GrooveScene& scene, const CrossSection& section, const FootprintLine& density,
                  const Vec3& toViewer, const Lighting& lighting, const std::vector<FacetSpan>& visible,
                  const std::vector<FacetSpan>& lit) {
  Rgb sum{0, 0, 0};
  if (lighting.maxBounces <= 0) return sum;
  SectionDirection e = inSection(section, toViewer);
  e.w = std::max(e.w, 1e-12);
  BeamStack stack;
  const std::vector<SectionPoint>& pts = section.points;
  // The first beams: the visible portions of the mirror facets, in reverse so that facets pop in order.
  for (std::size_t i = section.facetCount(); i-- > 0;) {
    if (visible[i].empty() || !scene.materials[section.material[i]].hasMirror) continue;
    const double q0 = acrossCoordinate(section, pts[i], e) / e.w, q1 = acrossCoordinate(section, pts[i + 1], e) / e.w;
    Beam beam;
    beam.facet = i;
    beam.t0 = visible[i].t0;
    beam.t1 = visible[i].t1;
    beam.p0 = q0 + beam.t0 * (q1 - q0);
    beam.p1 = q0 + beam.t1 * (q1 - q0);
    beam.toViewer = toViewer;
    stack.push(beam);
  }
  for (int step = 0; step < kMaxBeamSteps && stack.size > 0; ++step) {
    const Beam beam = stack.items[--stack.size];
    traceBeam(scene, section, density, lighting, lit, beam, sum, stack);
  }
  return sum;
}

}  // namespace bake::grooves
