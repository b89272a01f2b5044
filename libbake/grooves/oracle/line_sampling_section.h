// Internal to the seed's line sampling (seed 000 §5, §7): the stages shared by line_sampling*.cpp and
// interreflection.cpp, exposed for the tests. Everything here works in one cross-section plane: the
// binormal line B through the footprint centre F (coordinate b, relative to F) and the height h.
//
// Written to port to GLSL: plain arithmetic, bounded loops over the section's points and a
// fixed-size beam stack for the mirror bounces (no recursion).
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include "grooves/oracle/shade.h"
#include "grooves/oracle/shade_local.h"

namespace bake::grooves {

// --- Footprint density along B (§5.1) -------------------------------------------------------------

// The share of the footprint whose points project onto B in (-inf, x]. The exact density of a uniform
// parallelogram F + s1 A1 + s2 A2 (s1, s2 in [-1/2, 1/2]) is the convolution of two boxes of widths
// |A1.B| and |A2.B|: a trapezoid. The seed's segment S = [-projmax, projmax] is uniform (see
// footprintLine for its half-width in our convention). A zero-width footprint is a point sample.
struct FootprintLine {
  double wide = 0;      // half-width of the wider box (trapezoid) or of the segment
  double narrow = 0;    // half-width of the narrower box (trapezoid only)
  bool segment = false;
  // The footprint's edge vectors A1, A2 projected on B and on T (B = left normal of T).
  double a1b = 0, a2b = 0, a1t = 0, a2t = 0;
  double cdf(double x) const;
  double halfSupport() const { return wide + narrow; }
  // Share of the footprint between x0 and x1 (either order).
  double share(double x0, double x1) const;
  // The share on the side x' <= x of the line x' = x + rate t through the footprint (x' its
  // coordinate along B, t along T): the edge of a perturbed groove, which turns away from T as its
  // point moves by `rate` along B per unit along T. The density is then that of the footprint
  // projected on B - rate T; rate 0 is cdf.
  double cdfAcross(double x, double rate) const;
};
FootprintLine footprintLine(const Footprint& footprint, Vec2 binormal, FootprintDensity density);

// --- The combined cross-section (§5, formats/groove-scene.md "The surface a scene describes") -----

// rateB, rateH: how the point moves per unit of travel along T (the section's tangent, B = its left
// normal) under the grooves' linearised perturbation; 0 on unperturbed grooves (setSectionRates).
// accelB: the second derivative of b along T (the track's bend), for the second-order term of the
// travel of a line (line_sampling_occlusion.cpp).
struct SectionPoint {
  double b = 0, h = 0;
  double rateB = 0, rateH = 0;
  double accelB = 0;
};

// A polyline over b (non-decreasing; vertical walls are two points at the same b) with one material
// per facet: facet i joins points i and i + 1.
struct CrossSection {
  Vec2 binormal{0, 1};
  // Curved sections (SeedSettings::curvedSections): the b of the grooves' common centre of curvature
  // (their arcs' centre lies on the line F + b B); infinite for straight grooves.
  double centre = std::numeric_limits<double>::infinity();
  std::vector<SectionPoint> points;
  std::vector<std::size_t> material;
  std::size_t facetCount() const { return points.empty() ? 0 : points.size() - 1; }
};

// One groove placed on the section: its centre line crosses B at b = centre; `reversed` when its own
// binormal points along -B (its profile is then mirrored).
struct SectionGroove {
  const LocalGroove* groove = nullptr;
  double centre = 0;
  bool reversed = false;
};

// Combines the grooves' profiles into one polyline by the surface rule H = min(cuts) + max(ridges),
// split where the pieces cross, extended by flat base to cover [lo, hi].
void buildCrossSection(const GrooveScene& scene, const std::vector<SectionGroove>& grooves, double lo, double hi,
                       CrossSection& out);

// Perturbed grooves (seed 000 §3: the perturbation changes the local cross-section along the path):
// each point of the section moves with the groove that shapes the surface there, which keeps its
// normalised profile coordinates q = (x - offset) / scale, v = h / scale as the path goes on, so
// dx/ds = offset' + scale' q and dh/ds = scale' v at the foot point (x is the groove's own offset).
void setSectionRates(CrossSection& section, const std::vector<SectionGroove>& grooves);

// --- Ordered projection (§5.2) ---------------------------------------------------------------------

// A part [t0, t1] of a facet, t in [0, 1] from point i to point i + 1; empty when t1 <= t0.
struct FacetSpan {
  double t0 = 0, t1 = 0;
  bool empty() const { return !(t1 > t0); }
};

// A direction in the section's frame: along B, along the tangent T (B = left normal of T), up.
// travelBase: on a section whose tracks bend (accelB), the travel along T from the section's line to
// where the light ray from its deepest seen point crosses the base plane. The tracks' slopes are
// taken there, so the shadow a rim casts on those points is exact to second order
// (movedAlong, line_sampling_occlusion.cpp; lightDirection, line_sampling.cpp). 0 for the view.
struct SectionDirection {
  double b = 0, t = 0, w = 1;
  double travelBase = 0;
};
SectionDirection inSection(const CrossSection& section, const Vec3& d);

// The coordinate across the direction d in the section plane: points on one line along (d.b, d.w)
// share it (dw times the base-line position the line reaches). No division, so grazing and
// downward directions stay finite. A perturbed point is first moved along the path to where the
// line along d meets it (the line travels h d.t / d.w along T at height h), and on a curved section
// along its circle by that travel (line_sampling_occlusion.cpp).
double acrossCoordinate(const CrossSection& section, const SectionPoint& p, const SectionDirection& d);

// The part of each facet seen from the direction d (masking for E, shadowing for L), the flat base
// continuing to infinity on both sides. A direction below the horizon (d.w < 0) sees nothing.
// `across` receives every point's acrossCoordinate along d, for callers that need them too.
void visibleSpans(const CrossSection& section, const SectionDirection& d, std::vector<FacetSpan>& out,
                  std::vector<double>& across);
void visibleSpans(const CrossSection& section, const SectionDirection& d, std::vector<FacetSpan>& out);

// Curved sections: splits every facet that changes height into `pieces` (the moved positions are
// interpolated linearly between points).
void subdivideFacets(CrossSection& section, int pieces);

// Unit normal of facet i in the section plane (b, h) and in groove space (the latter tilted along T
// by the points' rates: the facet of the linearised perturbed surface).
void facetNormal(const CrossSection& section, std::size_t facet, double& nb, double& nh);
Vec3 facetNormal3(const CrossSection& section, std::size_t facet);
// On a curved section, the normal where the line along d meets the facet at height h: the section's
// normal turned with the circle through that point; otherwise facetNormal3.
Vec3 facetNormalSeen(const CrossSection& section, std::size_t facet, const SectionDirection& d, double h);

// --- Shading a section (Eq. 1 and §7) --------------------------------------------------------------

struct SectionShading {
  Rgb direct{0, 0, 0};
  Rgb mirrored{0, 0, 0};
  double visibleShare = 0;  // sum of r_i: 1 up to rounding when the section covers the footprint
};

// Eq. 1 over the section, plus the mirror bounces of §7 when lighting.maxBounces > 0.
SectionShading shadeSection(const GrooveScene& scene, const CrossSection& section, const FootprintLine& density,
                            const Vec3& toViewer, const Lighting& lighting);

// §7: the radiance mirrored by the visible portions of mirror facets (interreflection.cpp).
// `visible` and `lit` are the spans of each facet seen from E and from L.
constexpr int kMaxBeams = 64;  // the beam stack's size: the GLSL port's fixed array
Rgb mirrorBounces(const GrooveScene& scene, const CrossSection& section, const FootprintLine& density,
                  const Vec3& toViewer, const Lighting& lighting, const std::vector<FacetSpan>& visible,
                  const std::vector<FacetSpan>& lit);

// lineSample with a chosen footprint density (lineSample uses the trapezoid).
Rgb lineSampleWith(const GrooveScene& scene, const std::vector<LocalGroove>& grooves, const Footprint& footprint,
                   const Vec3& toViewer, const Lighting& lighting, const SeedSettings& settings);

// One straight groove alone on its cross-section (no curved section, whatever the primitive), under
// `footprint`: the far level's per-class radiance (far_shade.cpp).
Rgb shadeStraightGroove(const GrooveScene& scene, const LocalGroove& groove, const Footprint& footprint,
                        const Vec3& toViewer, const Lighting& lighting, const SeedSettings& settings);

}  // namespace bake::grooves
