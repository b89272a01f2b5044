// Line sampling for footprints without special cases (seed 000 §5): the grooves under the footprint
// are straight (LocalGroove), so the surface is a cross-section along the binormal B, and the footprint
// becomes a density on the line B through its centre F (§5.1, line_sampling_occlusion.cpp).
//
//  1. Keep the grooves whose region reaches the footprint (a primitive stops at its joint lines; past a
//     G1 joint its neighbour in the chain takes over, so the same groove is not counted twice).
//  2. Group them into parallel classes (tangents within 1e-6 rad, or close enough that their relative
//     drift across the footprint's reach stays below 1e-3 of a groove width: concentric arcs, the
//     turns of a flattened spiral).
//  3. Per class: one combined cross-section (line_sampling_section.cpp), masking and shadowing by
//     ordered projection (§5.2), and Eq. 1: pixel = sum_i r_i f_i, r_i the footprint share of the part
//     of facet i that is both visible and lit, measured through its projection on the base line along
//     E; plus the mirror bounces of §7 (interreflection.cpp).
//     On a curved section (a tight arc, not in the seed) the footprint's points off the line through F
//     see the section turned about the arc's centre: the edges of the visible, lit spans get the rate
//     at which they move along B per unit along T (found by turning view and light slightly) and
//     bend with the circles about the centre (shadeSection).
//  4. Several classes (non-parallel grooves with no special-case record under the box, so their bands
//     do not overlap under the footprint): each class is shaded on its own section, and the pixel is the
//     flat base plus the sum of each class's difference from the flat base. This neglects occlusion
//     and shadowing between grooves of different classes (and counts twice a point shadowed by two).
#include <algorithm>
#include <cmath>
#include <limits>

#include "grooves/oracle/line_sampling_section.h"

namespace bake::grooves {
namespace {

constexpr double kParallelAngle = 1e-6;  // rad
constexpr double kDriftFraction = 1e-3;  // of a groove width, across the footprint's reach
constexpr double kMinViewW = 1e-12;      // E_w > 0 by the rendering model; guarded anyway
constexpr double kCurvedShift = 0.02;    // of the footprint's width: the shift a curved section corrects
constexpr double kTurn = 1e-3;          // rad: the turn of a curved section that finds its edges' rates
constexpr double kTurnShows = 0.2;       // see turningShows
constexpr double kMinTurnRadius = 1e-6;  // of the footprint's half-support: nearer the centre, no rate
constexpr double kMinBendRadius = 0.5;   // of the footprint's half-support: nearer the centre, no bend
constexpr int kCurvedPieces = 4;         // facets of a curved section are split so (its moved
                                         // positions, quadratic in h, are interpolated within 1/64)

double dot2(Vec2 a, Vec2 b) { return a.u * b.u + a.v * b.v; }
double cross2(Vec2 a, Vec2 b) { return a.u * b.v - a.v * b.u; }

// foot - F, the nearest copy when the scene repeats.
Vec2 offsetFromCentre(const GrooveScene& scene, Vec2 foot, Vec2 centre) {
  Vec2 d{foot.u - centre.u, foot.v - centre.v};
  if (scene.wrapRepeat) {
    d.u -= scene.domain[0] * std::round(d.u / scene.domain[0]);
    d.v -= scene.domain[1] * std::round(d.v / scene.domain[1]);
  }
  return d;
}

bool inList(const std::vector<LocalGroove>& grooves, std::uint32_t primitive) {
  for (const LocalGroove& g : grooves)
    if (g.primitive == primitive) return true;
  return false;
}

// The primitive across a joint of `p` (start or end), or -1 at an open end.
long long neighbourAcross(const GrooveScene& scene, std::uint32_t p, bool atStart) {
  const Groove& g = scene.grooves[scene.primitives[p].groove];
  const std::size_t first = g.firstPrimitive, last = first + g.primitiveCount - 1;
  if (atStart) return p > first ? (long long)p - 1 : (g.closed ? (long long)last : -1);
  return p < last ? (long long)p + 1 : (g.closed ? (long long)first : -1);
}

double sideOf(const JointLine& line, Vec2 x) {
  return (x.u - line.point.u) * line.normal.u + (x.v - line.point.v) * line.normal.v;
}

// Step 1: does this primitive's region reach the footprint?
bool reachesFootprint(const GrooveScene& scene, const std::vector<LocalGroove>& grooves, const LocalGroove& g,
                      const Footprint& footprint) {
  const Vec2 d = offsetFromCentre(scene, g.foot, footprint.centre);
  const Vec2 centre{g.foot.u - d.u, g.foot.v - d.v};  // the footprint centre's copy near the primitive
  for (int end = 0; end < 2; ++end) {
    const JointLine& line = end == 0 ? g.joints.start : g.joints.end;
    if (sideOf(line, centre) >= 0) continue;
    const long long other = neighbourAcross(scene, g.primitive, end == 0);
    if (other >= 0 && inList(grooves, std::uint32_t(other))) return false;  // the neighbour covers it
    bool anyInside = false;
    for (int corner = 0; corner < 4; ++corner) {
      const double s1 = corner & 1 ? 0.5 : -0.5, s2 = corner & 2 ? 0.5 : -0.5;
      const Vec2 x{centre.u + s1 * footprint.axis1.u + s2 * footprint.axis2.u,
                   centre.v + s1 * footprint.axis1.v + s2 * footprint.axis2.v};
      anyInside = anyInside || sideOf(line, x) >= 0;
    }
    if (!anyInside) return false;
  }
  return true;
}

double grooveWidth(const LocalGroove& g) { return g.scale * g.profile->wmax; }

// Step 2: parallel within 1e-6 rad, or drifting apart by less than kDriftFraction of a width.
bool parallel(const LocalGroove& a, const LocalGroove& b, double reach) {
  const double sine = std::abs(cross2(a.tangent, b.tangent));
  const double drift = kDriftFraction * std::min(grooveWidth(a), grooveWidth(b)) / reach;
  return sine <= std::max(std::sin(kParallelAngle), drift);
}

// The longest travel over the base plane of a view or shadow line below the surface: (hmax + dmax)
// times the larger travel per depth.
double longestTravel(const GrooveScene& scene, const Vec3& toViewer, const Vec3& toLight) {
  return (scene.hmax + scene.dmax) * std::max(travelPerDepth(toViewer), travelPerDepth(toLight));
}

// Curved sections only where the curvature shows: over the longest travel S of a view or shadow line
// among the grooves ((hmax + dmax) times the travel per depth), the groove's tightest circle (radius
// R - w, w its half-width) leaves its tangent by S^2 / (2 (R - w)). Below kCurvedShift of the
// footprint's width across the groove, the straightened section is kept (it is cheaper).
bool curvatureShows(const GrooveScene& scene, const Primitive& arc, const LocalGroove& g, const FootprintLine& line,
                    const Vec3& toViewer, const Vec3& toLight) {
  const double inner = std::abs(arc.radius) - grooveWidth(g);
  if (!(inner > 0)) return true;
  const double travel = longestTravel(scene, toViewer, toLight);
  return travel * travel / (2 * inner) > kCurvedShift * 2 * line.halfSupport();
}

Rgb shadeClass(const GrooveScene& scene, const std::vector<LocalGroove>& grooves, const std::vector<std::size_t>& members,
               const Footprint& footprint, const Vec3& toViewer, const Lighting& lighting,
               const SeedSettings& settings) {
  const Vec2 binormal = grooves[members.front()].binormal;
  thread_local std::vector<SectionGroove> placed;
  thread_local CrossSection section;
  placed.clear();
  for (std::size_t m : members) {
    const LocalGroove& g = grooves[m];
    const Vec2 d = offsetFromCentre(scene, g.foot, footprint.centre);
    const double along = dot2(binormal, g.binormal);
    // Where the groove's centre line crosses the line F + x B (along = +-1 up to the drift).
    placed.push_back({&g, dot2(d, g.binormal) / along, along < 0});
  }
  const FootprintLine line = footprintLine(footprint, binormal, settings.density);
  section.binormal = binormal;
  buildCrossSection(scene, placed, -line.halfSupport(), line.halfSupport(), section);
  setSectionRates(section, placed);
  section.centre = std::numeric_limits<double>::infinity();
  const LocalGroove& first = grooves[members.front()];
  const Primitive& primitive = scene.primitives[first.primitive];
  if (settings.curvedSections && primitive.kind == Primitive::Kind::Arc &&
      curvatureShows(scene, primitive, first, line, toViewer, lighting.toLight)) {
    // The arc's centre lies on the radial line through the foot, which is F + x B.
    const Vec2 d = offsetFromCentre(scene, first.foot, footprint.centre);
    section.centre = dot2({primitive.centre.u - first.foot.u + d.u, primitive.centre.v - first.foot.v + d.v}, binormal);
    subdivideFacets(section, kCurvedPieces);
  }
  const SectionShading s = shadeSection(scene, section, line, toViewer, lighting);
  return {s.direct[0] + s.mirrored[0], s.direct[1] + s.mirrored[1], s.direct[2] + s.mirrored[2]};
}

}  // namespace

namespace {

// The light in the section. On a section whose tracks bend (accelB), a shadow ray leaves a seen point
// at its own travel along T, not at the section's line: the light's lines are followed from the
// travel where the ray from the deepest seen point crosses the base plane (travelBase), so the
// shadow a rim casts there (the floor of a wandering box groove) is exact to second order.
SectionDirection lightDirection(const CrossSection& section, const SectionDirection& e, const Vec3& toLight) {
  SectionDirection l = inSection(section, toLight);
  if (!(l.w > 0) || !std::any_of(section.points.begin(), section.points.end(), [](const SectionPoint& p) { return p.accelB != 0; }))
    return l;
  double deepest = 0;
  for (const SectionPoint& p : section.points) deepest = std::min(deepest, p.h);
  l.travelBase = deepest * (e.t / e.w - l.t / l.w);
  return l;
}

// The turning rates are found where they show: an edge moves about travel / rho along B per unit
// along T (rho = the distance to the centre, travel = the longest travel of a view or shadow line
// below the surface); over the footprint's half-extent along T that must reach kTurnShows of its
// half-support across.
bool turningShows(const GrooveScene& scene, const CrossSection& section, const FootprintLine& density,
                  const Vec3& toViewer, const Vec3& toLight) {
  if (!std::isfinite(section.centre)) return false;
  const double travel = longestTravel(scene, toViewer, toLight);
  const double alongT = 0.5 * (std::abs(density.a1t) + std::abs(density.a2t));
  return travel * alongT > kTurnShows * std::abs(section.centre) * density.halfSupport();
}

// The direction as seen from a section turned by `angle` about the centre.
SectionDirection turnedBy(const SectionDirection& d, double angle) {
  SectionDirection out = d;
  const double c = std::cos(angle), s = std::sin(angle);
  out.b = d.b * c - d.t * s;
  out.t = d.t * c + d.b * s;
  return out;
}

}  // namespace

SectionShading shadeSection(const GrooveScene& scene, const CrossSection& section, const FootprintLine& density,
                            const Vec3& toViewer, const Lighting& lighting) {
  SectionShading out;
  SectionDirection e = inSection(section, toViewer);
  e.w = std::max(e.w, kMinViewW);
  thread_local std::vector<FacetSpan> visible, lit, visibleTurned, litTurned;
  thread_local std::vector<double> seenAt, seenTurned;  // each point's acrossCoordinate along e (turned e)
  const SectionDirection l = lightDirection(section, e, lighting.toLight);
  visibleSpans(section, e, visible, seenAt);
  visibleSpans(section, l, lit);
  // On a curved section, the footprint's points off the line F + x B see the section turned: one at
  // travel a along T lies on the radial line turned by a / (centre - x), where e and l are turned the
  // other way. Every edge of a visible, lit span (a facet end, or where a mask or a shadow cuts it)
  // therefore moves along B as a grows, by a rate found by turning e and l by kTurn: the edge is the
  // line x + rate a through the footprint, and its share is taken across that line (cdfAcross), as
  // for a perturbed groove's tracks.
  const bool turning = turningShows(scene, section, density, toViewer, lighting.toLight);
  SectionDirection eTurned = e;
  if (turning) {
    eTurned = turnedBy(e, kTurn);
    visibleSpans(section, eTurned, visibleTurned, seenTurned);
    visibleSpans(section, turnedBy(l, kTurn), litTurned);
  }
  const double varianceT = (density.a1t * density.a1t + density.a2t * density.a2t) / 12;
  const std::vector<SectionPoint>& pts = section.points;
  RadianceMemo radiance(scene.materials, toViewer, lighting);
  // The footprint's cdf at the last two (x, rate) asked for: consecutive facets share an end.
  struct Known {
    double x = std::numeric_limits<double>::quiet_NaN(), rate = 0, cdf = 0;
  };
  Known known[2];
  auto cdfAt = [&](double x, double rate) {
    for (const Known& k : known)
      if (k.x == x && k.rate == rate) return k.cdf;
    known[0] = known[1];
    known[1] = {x, rate, density.cdfAcross(x, rate)};
    return known[1].cdf;
  };
  for (std::size_t i = 0; i < section.facetCount(); ++i) {
    const FacetSpan& v = visible[i];
    if (v.empty()) continue;
    // Base-line position seen through the facet point at t (projection along E'), and the same along
    // the turned view.
    const double p0 = seenAt[i] / e.w, p1 = seenAt[i + 1] / e.w;
    // Exactly p1 at the facet's end, where the next facet starts: its share's cdf there is then
    // remembered (cdfAt), not computed again.
    auto seen = [&](double t) { return t == 1 ? p1 : p0 + t * (p1 - p0); };
    auto seenWhenTurned = [&](double t) {
      return (seenTurned[i] + t * (seenTurned[i + 1] - seenTurned[i])) / eTurned.w;
    };
    // The edge at t that becomes the edge at tTurned: how far it moves along B per unit along T.
    auto turnRate = [&](double t, double tTurned) {
      const double x = seen(t), radius = section.centre - x;
      if (!(std::abs(radius) > kMinTurnRadius * density.halfSupport())) return 0.0;
      return (seenWhenTurned(tTurned) - x) / (kTurn * radius);
    };
    // The footprint's share between two points of the facet: on a perturbed section the line of the
    // surface through each point turns away from T by its rate, so each end has its own density
    // (the shares of consecutive facets still add up: they meet at the same point). The section's two
    // ends take the plain density, so the shares add up to the whole footprint.
    const double r0 = i == 0 ? 0.0 : pts[i].rateB;
    const double r1 = i + 1 == section.facetCount() ? 0.0 : pts[i + 1].rateB;
    // To second order an edge also bends with the circles about the centre: the footprint's point at
    // travel a along T lies a^2 / (2 rho) nearer the centre than its x says. Over the footprint that
    // moves the edge by the variance of a (the parallelogram's: (A1.T^2 + A2.T^2) / 12) over 2 rho.
    auto bent = [&](double x) {
      const double radius = section.centre - x;
      return turning && std::abs(radius) > kMinBendRadius * density.halfSupport() ? x + varianceT / (2 * radius) : x;
    };
    auto shareBetween = [&](double ta, double tb, double turnA, double turnB) {
      const double a = cdfAt(bent(seen(ta)), r0 + ta * (r1 - r0) + turnA);
      return std::abs(cdfAt(bent(seen(tb)), r0 + tb * (r1 - r0) + turnB) - a);
    };
    const bool seenTurnedToo = turning && !visibleTurned[i].empty();
    const double visibleShare = shareBetween(v.t0, v.t1, seenTurnedToo ? turnRate(v.t0, visibleTurned[i].t0) : 0.0,
                                             seenTurnedToo ? turnRate(v.t1, visibleTurned[i].t1) : 0.0);
    out.visibleShare += visibleShare;
    const double t0 = std::max(v.t0, lit[i].t0), t1 = std::min(v.t1, lit[i].t1);
    if (!(t1 > t0)) continue;
    double r = visibleShare;  // wholly lit and not turning: the same share
    if (turning) {
      const double u0 = std::max(visibleTurned[i].t0, litTurned[i].t0);
      const double u1 = std::min(visibleTurned[i].t1, litTurned[i].t1);
      const bool litTurnedToo = seenTurnedToo && u1 > u0;
      r = shareBetween(t0, t1, litTurnedToo ? turnRate(t0, u0) : 0.0, litTurnedToo ? turnRate(t1, u1) : 0.0);
    } else if (t0 != v.t0 || t1 != v.t1) {
      r = shareBetween(t0, t1, 0, 0);
    }
    const double middle = pts[i].h + 0.5 * (t0 + t1) * (pts[i + 1].h - pts[i].h);
    const Vec3 normal = facetNormalSeen(section, i, e, middle);
    const Rgb f = radiance(section.material[i], normal);
    for (int c = 0; c < 3; ++c) out.direct[c] += r * f[c];
  }
  if (lighting.maxBounces > 0) out.mirrored = mirrorBounces(scene, section, density, toViewer, lighting, visible, lit);
  return out;
}

Rgb lineSampleWith(const GrooveScene& scene, const std::vector<LocalGroove>& grooves, const Footprint& footprint,
                   const Vec3& toViewer, const Lighting& lighting, const SeedSettings& settings) {
  auto flat = [&] { return flatBaseRadiance(scene.materials[scene.baseMaterial], toViewer, lighting); };
  thread_local std::vector<std::size_t> kept;
  kept.clear();
  for (std::size_t i = 0; i < grooves.size(); ++i)
    if (reachesFootprint(scene, grooves, grooves[i], footprint)) kept.push_back(i);
  if (kept.empty()) return flat();

  const double reach = 0.5 * (std::hypot(footprint.axis1.u, footprint.axis1.v) +
                              std::hypot(footprint.axis2.u, footprint.axis2.v)) +
                       scene.wmax + scene.hmax + scene.dmax;
  thread_local std::vector<std::size_t> representatives, classOf, members;
  representatives.clear();
  classOf.clear();
  for (std::size_t i : kept) {
    std::size_t c = 0;
    while (c < representatives.size() && !parallel(grooves[representatives[c]], grooves[i], reach)) ++c;
    if (c == representatives.size()) representatives.push_back(i);
    classOf.push_back(c);
  }
  auto shadeClassNumber = [&](std::size_t c) {
    members.clear();
    for (std::size_t k = 0; k < kept.size(); ++k)
      if (classOf[k] == c) members.push_back(kept[k]);
    return shadeClass(scene, grooves, members, footprint, toViewer, lighting, settings);
  };
  if (representatives.size() == 1) return shadeClassNumber(0);
  const Rgb base = flat();
  Rgb sum = base;
  for (std::size_t c = 0; c < representatives.size(); ++c) {
    const Rgb value = shadeClassNumber(c);
    for (int k = 0; k < 3; ++k) sum[k] += value[k] - base[k];
  }
  for (double& x : sum) x = std::max(0.0, x);
  return sum;
}

Rgb shadeStraightGroove(const GrooveScene& scene, const LocalGroove& groove, const Footprint& footprint,
                        const Vec3& toViewer, const Lighting& lighting, const SeedSettings& settings) {
  thread_local std::vector<LocalGroove> alone;
  alone.assign(1, groove);
  SeedSettings straight = settings;
  straight.curvedSections = false;
  return shadeClass(scene, alone, {0}, footprint, toViewer, lighting, straight);
}

Rgb lineSample(const GrooveScene& scene, const std::vector<LocalGroove>& grooves, const Footprint& footprint,
               const Vec3& toViewer, const Lighting& lighting) {
  return lineSampleWith(scene, grooves, footprint, toViewer, lighting, SeedSettings{});
}

}  // namespace bake::grooves
