// Footprint clipping and occlusion on the cross-section (seed 000 §5.1, §5.2).
//
// Density (§5.1): the footprint's points F + s1 A1 + s2 A2 (s1, s2 uniform in [-1/2, 1/2]) land on B at
// s1 (A1.B) + s2 (A2.B): the sum of two uniform variables, whose density is a trapezoid (exact for
// straight grooves). The seed instead clips against the segment S = [-projmax, projmax] with uniform
// weight, projmax = max(|A1.B|, |A2.B|) for the axes of its elliptic footprint, which are half-axes;
// our parallelogram's half-edges are A/2, so the seed's segment is [-max/2, max/2] here.
//
// Occlusion (§5.2; the text conversion flattened the expression, reconstructed here from the prose):
// a section point C seen along the direction D' = (D.B, D_w) lies on the line of coordinate
// k(C) = C_b D_w - C_h D_b across D' (for D_w > 0 that is D_w times its projection onto the base line,
// C_b - C_h D_b / D_w, without the division). When D_b > 0, C is hidden exactly when a surface point on
// its right has a smaller k; so the points are walked from the right keeping the running minimum, and
// a facet is visible where its k falls below the minimum of everything walked before it (hidden when
// entirely above, partially visible when the minimum falls inside it, self-hidden when it faces away).
// D_b < 0 is the mirror image (walk from the left, running maximum). The flat base continues to
// infinity on both sides: below the horizon (D_w < 0) it hides everything, which the start value of
// the running extreme says without dividing by D_w.
#include <algorithm>
#include <cmath>
#include <limits>

#include "grooves/oracle/line_sampling_section.h"

namespace bake::grooves {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A box narrower than this fraction of the other is a line: its ramps are below rounding.
constexpr double kThinBox = 1e-12;

}  // namespace

double FootprintLine::cdf(double x) const {
  const double p = wide, q = segment ? 0.0 : narrow;
  if (!(p > 0)) return x < 0 ? 0.0 : (x > 0 ? 1.0 : 0.5);  // a point sample
  if (x <= -(p + q)) return 0;
  if (x >= p + q) return 1;
  if (std::abs(x) <= p - q) return 0.5 + x / (2 * p);
  // The ramps of the trapezoid: the density rises linearly over [-(p+q), -(p-q)].
  const double d = p + q - std::abs(x);
  const double tail = (d / (2 * q)) * (d / (4 * p));
  return x < 0 ? tail : 1 - tail;
}

double FootprintLine::share(double x0, double x1) const { return std::abs(cdf(x1) - cdf(x0)); }

namespace {

// The density of the footprint projected on a direction whose products with A1, A2 are a and c.
void setWidths(FootprintLine& line, double a, double c) {
  a = std::abs(a), c = std::abs(c);
  line.wide = 0.5 * std::max(a, c);
  line.narrow = 0.5 * std::min(a, c);
  if (line.segment || line.narrow <= kThinBox * line.wide) line.narrow = 0;
}

}  // namespace

FootprintLine footprintLine(const Footprint& footprint, Vec2 binormal, FootprintDensity density) {
  const Vec2 tangent{binormal.v, -binormal.u};
  FootprintLine line;
  line.segment = density == FootprintDensity::SeedSegment;
  line.a1b = footprint.axis1.u * binormal.u + footprint.axis1.v * binormal.v;
  line.a2b = footprint.axis2.u * binormal.u + footprint.axis2.v * binormal.v;
  line.a1t = footprint.axis1.u * tangent.u + footprint.axis1.v * tangent.v;
  line.a2t = footprint.axis2.u * tangent.u + footprint.axis2.v * tangent.v;
  setWidths(line, line.a1b, line.a2b);
  return line;
}

double FootprintLine::cdfAcross(double x, double rate) const {
  if (rate == 0) return cdf(x);
  FootprintLine turned = *this;
  setWidths(turned, a1b - rate * a1t, a2b - rate * a2t);
  return turned.cdf(x);
}

SectionDirection inSection(const CrossSection& section, const Vec3& d) {
  const Vec2 B = section.binormal;
  return {d.u * B.u + d.v * B.v, d.u * B.v - d.v * B.u, d.w};
}

// The point of a perturbed section met by the line along d: at travel s along T it has moved to
// (b + rateB s + accelB s^2 / 2, h + rateH s), and the line reaches height h' after s = h' d.t / d.w,
// so s = h d.t / (d.w - rateH d.t) (the second-order term of h is left out). A point's track steeper
// than the line (the denominator below half of d.w) is capped there; below the horizon nothing moves
// (everything but lit walls is hidden). With a travelBase the tracks' slopes are taken there (rateB +
// accelB travelBase): the points' motion relative to the lines' own base line.
SectionPoint movedAlong(const SectionPoint& p, const SectionDirection& d) {
  if (p.h == 0 || !(d.w > 0) || (p.rateB == 0 && p.rateH == 0 && p.accelB == 0)) return p;
  const double travel = p.h * d.t / std::max(d.w - p.rateH * d.t, 0.5 * d.w);
  const double slope = p.rateB + p.accelB * (d.travelBase + 0.5 * travel);
  return {p.b + slope * travel, p.h + p.rateH * travel, p.rateB, p.rateH, p.accelB};
}

double acrossCoordinate(const CrossSection& section, const SectionPoint& point, const SectionDirection& d) {
  // An unperturbed point of a straight section stays where it is (the common case, first).
  if (point.rateB == 0 && point.rateH == 0 && point.accelB == 0 && !std::isfinite(section.centre)) return point.b * d.w - point.h * d.b;
  const SectionPoint p = movedAlong(point, d);
  double b = p.b;
  if (std::isfinite(section.centre) && p.h != 0) {
    // The line along d through the base point F + x B meets height h after a tangential travel
    // s = h d.t / d.w; on a groove curved about the centre, the point of offset b there sits where its
    // circle (radius centre - b) has turned by asin(s / (centre - b)): further along B by
    // (centre - b)(1 - cos) = (centre - b) sin^2 / (1 + cos) (no cancellation for small turns). Past a
    // quarter turn the line has left the circle's side: capped.
    const double radius = section.centre - p.b;
    const double travel = p.h * d.t, span = d.w * radius;
    const double sine = travel == 0 ? 0.0 : (std::abs(travel) >= std::abs(span) ? 1.0 : travel / span);
    b += radius * sine * sine / (1 + std::sqrt(std::max(0.0, 1 - sine * sine)));
  }
  return b * d.w - p.h * d.b;
}

void subdivideFacets(CrossSection& section, int pieces) {
  thread_local std::vector<SectionPoint> points;  // swapped with the section's: no allocation once grown
  thread_local std::vector<std::size_t> material;
  points.clear();
  material.clear();
  points.push_back(section.points.front());
  for (std::size_t i = 0; i < section.facetCount(); ++i) {
    const SectionPoint a = section.points[i], b = section.points[i + 1];
    const int n = a.h == b.h ? 1 : pieces;
    for (int k = 1; k <= n; ++k) {
      const double t = double(k) / n;
      points.push_back(k == n ? b
                              : SectionPoint{a.b + t * (b.b - a.b), a.h + t * (b.h - a.h),
                                             a.rateB + t * (b.rateB - a.rateB), a.rateH + t * (b.rateH - a.rateH),
                                             a.accelB + t * (b.accelB - a.accelB)});
      material.push_back(section.material[i]);
    }
  }
  section.points.swap(points);
  section.material.swap(material);
}

void visibleSpans(const CrossSection& section, const SectionDirection& d, std::vector<FacetSpan>& out,
                  std::vector<double>& across) {
  const double dw = d.w;
  const std::size_t facets = section.facetCount();
  out.assign(facets, FacetSpan{});
  across.resize(section.points.size());
  for (std::size_t i = 0; i < section.points.size(); ++i) across[i] = acrossCoordinate(section, section.points[i], d);
  if (d.b >= 0) {
    // Occluders come from the right: running minimum of k, walking leftwards.
    double lowest = dw < 0 ? -kInfinity : kInfinity;
    for (std::size_t i = facets; i-- > 0;) {
      const double k0 = across[i], k1 = across[i + 1];
      if (k1 > k0 && k0 < lowest) out[i] = {0, std::min(1.0, (lowest - k0) / (k1 - k0))};
      lowest = std::min(lowest, std::min(k0, k1));
    }
  } else {
    // Occluders come from the left: running maximum of k, walking rightwards.
    double highest = dw < 0 ? kInfinity : -kInfinity;
    for (std::size_t i = 0; i < facets; ++i) {
      const double k0 = across[i], k1 = across[i + 1];
      if (k1 > k0 && k1 > highest) out[i] = {std::max(0.0, (highest - k0) / (k1 - k0)), 1};
      highest = std::max(highest, std::max(k0, k1));
    }
  }
}

void visibleSpans(const CrossSection& section, const SectionDirection& d, std::vector<FacetSpan>& out) {
  thread_local std::vector<double> across;
  visibleSpans(section, d, out, across);
}

void facetNormal(const CrossSection& section, std::size_t facet, double& nb, double& nh) {
  const SectionPoint& p = section.points[facet];
  const SectionPoint& q = section.points[facet + 1];
  const double db = q.b - p.b, dh = q.h - p.h;
  const double length = std::sqrt(db * db + dh * dh);
  // The material lies below the polyline (b ascending), so the outward normal is the left normal.
  nb = length > 0 ? -dh / length : 0;
  nh = length > 0 ? db / length : 1;
}

namespace {

// The facet's normal (along T, along B, up). The facet joins two point tracks whose directions per
// unit of travel along T are (1, rateB, rateH); the normal is the cross product of the facet's step
// across the section (0, db, dh) with their mean track: (dh rateB - db rateH, -dh, db), normalised
// (the section normal (-dh, db) when nothing moves).
void facetNormalTilted(const CrossSection& section, std::size_t facet, double& nt, double& nb, double& nh) {
  const SectionPoint& p = section.points[facet];
  const SectionPoint& q = section.points[facet + 1];
  const double db = q.b - p.b, dh = q.h - p.h;
  const double rateB = 0.5 * (p.rateB + q.rateB), rateH = 0.5 * (p.rateH + q.rateH);
  nt = dh * rateB - db * rateH;
  nb = -dh;
  nh = db;
  const double length = std::sqrt(nt * nt + nb * nb + nh * nh);
  if (length > 0) {
    const double inverse = 1 / length;
    nt *= inverse, nb *= inverse, nh *= inverse;
  } else {
    nt = 0, nb = 0, nh = 1;
  }
}

}  // namespace

Vec3 facetNormalSeen(const CrossSection& section, std::size_t facet, const SectionDirection& d, double h) {
  if (!std::isfinite(section.centre) || h == 0 || d.w <= 0) return facetNormal3(section, facet);
  double nt = 0, nb = 0, nh = 1;
  facetNormalTilted(section, facet, nt, nb, nh);
  const SectionPoint& p = section.points[facet];
  const SectionPoint& q = section.points[facet + 1];
  const double b = 0.5 * (p.b + q.b);
  // The point sits at tangential travel s = h d.t / d.w, where the binormal has turned to
  // cos(a) B + sin(a) T with sin(a) = s / (b - centre).
  const double offset = b - section.centre;
  const double travel = h * d.t, span = d.w * offset;
  const double sine = std::clamp(span == 0 ? 0.0 : travel / span, -1.0, 1.0);
  const double cosine = std::sqrt(1 - sine * sine);
  const Vec2 B = section.binormal, T{B.v, -B.u};
  const Vec2 turnedB{cosine * B.u + sine * T.u, cosine * B.v + sine * T.v};
  const Vec2 turnedT{cosine * T.u - sine * B.u, cosine * T.v - sine * B.v};
  return {nb * turnedB.u + nt * turnedT.u, nb * turnedB.v + nt * turnedT.v, nh};
}

Vec3 facetNormal3(const CrossSection& section, std::size_t facet) {
  double nt = 0, nb = 0, nh = 1;
  facetNormalTilted(section, facet, nt, nb, nh);
  const Vec2 B = section.binormal, T{B.v, -B.u};
  return {nb * B.u + nt * T.u, nb * B.v + nt * T.v, nh};
}

}  // namespace bake::grooves
