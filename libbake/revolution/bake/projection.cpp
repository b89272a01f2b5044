// Texture projection chosen by measured distortion. Seed 001 ("Texturing function", Eq. 10-17) maps a
// hit with a cylindrical or a spherical projection and picks one per object by eye; here the choice
// is measured. The profile's surface pieces (segments off the axis, arcs) are sampled by arc length s;
// at each sample the revolved surface has two orthogonal unit directions, along the profile (length
// element ds) and around the axis (length element r dphi). Every candidate map has u = phi / 2pi and
// a v that depends on the profile point only, so its Jacobian in that orthonormal frame is diagonal:
// the stretches are su = 1 / (2 pi r) and sv = |dv/ds|. Cylindrical: v = (h - hMin) / (hMax - hMin);
// spherical about (0, hc) on the axis: v = (pi - theta) / pi (seed Eq. 14-17), hc optimised by a scan
// and a golden-section search; arc length: v = s / L. The u:v repeat ratio that makes texels square on
// average (mean sv / mean su, area-weighted) scales u before the singular values s1 >= s2 are taken.
//
// Per map: degenerate area = share of area with s2 below 1e-3 of the mean stretch (a mean, not a
// median: a plate under the cylindrical map is mostly degenerate, so its median is 0); angle
// distortion = area-weighted mean of min(s1 / s2, 100) over the non-degenerate area; area distortion
// = area-weighted mean of max(a, 1/a), a = s1 s2 / mean(s1 s2). The score, lower is better, is
//   score = 10 * degenerateArea + log(meanAngleDistortion) + log(meanAreaDistortion)
// (a degenerate map smears the texture into lines, so it weighs most; a squashed texel and a
// shrunken one count alike, so a cone keeps its cylindrical map rather than a spherical one that is
// nearly conformal there but shrinks the texture towards the apex by a factor of 4).
// A map of the enum order (cylindrical, spherical, arc length) gives way to a later one only when
// that one scores lower by more than 0.05, i.e. about 5 % less distortion: below that the difference
// does not show, and the earlier map is the simpler one (cylindrical has no parameter and keeps the
// texture's rows level; a pointed cone measures 2 % better under a spherical map centred below it).
#include "bake/core/vec.h"
#include "bake/revolution/projection.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "bake_formats/revolution.h"

namespace bake::revolution {

const char* projectionName(Projection projection) {
  namespace fmt = bake::format::revolution;
  switch (projection) {
    case Projection::Cylindrical: return fmt::kProjectionCylindrical;
    case Projection::Spherical: return fmt::kProjectionSpherical;
    case Projection::ArcLength: return fmt::kProjectionArcLength;
  }
  return fmt::kProjectionCylindrical;
}

namespace {
constexpr int kTotalSamples = 4096;          // spread over the surface pieces by length
constexpr double kDegenerateFraction = 1e-3;  // of the mean stretch
constexpr double kAngleDistortionCap = 100;   // a sample at the pole must not swamp the mean
constexpr double kDegeneratePenalty = 10;
constexpr double kAreaWeight = 1.0;
constexpr double kTieTolerance = 1e-9;
constexpr double kClearWin = 0.05;  // score (log-distortion) a later map must gain to be chosen

// One arc-length sample of the profile: position, unit tangent, its share of length, and the
// cumulative profile length at it (for the arc-length map).
struct SurfaceSample {
  double r = 0, h = 0;
  double tr = 0, th = 0;  // unit tangent (dr/ds, dh/ds)
  double ds = 0;
  double s = 0;
  double area() const { return 2 * kPi * r * ds; }
};

bool isSurface(const Segment& seg) {
  // Pieces on the axis close the solid but revolve to nothing.
  const bool bothOnAxis = std::abs(seg.a.r) < 1e-12 && std::abs(seg.b.r) < 1e-12 && seg.bulge == 0;
  return !seg.onAxis && !bothOnAxis;
}

// Point and unit tangent at parameter f in [0, 1] of a piece (straight or arc by bulge = tan(sweep/4)).
struct PiecePoint {
  double r, h, tr, th;
};
struct PieceGeometry {
  Segment seg;
  double length = 0;
  // Arcs: centre, radius, start angle and signed sweep.
  double cr = 0, ch = 0, radius = 0, startAngle = 0, sweep = 0;
};

PieceGeometry describePiece(const Segment& seg) {
  PieceGeometry g{seg};
  const double dr = seg.b.r - seg.a.r, dh = seg.b.h - seg.a.h;
  const double chord = std::hypot(dr, dh);
  if (seg.bulge == 0 || chord == 0) {
    g.length = chord;
    return g;
  }
  g.sweep = 4 * std::atan(seg.bulge);
  // The centre sits on the chord's left normal (counter-clockwise arcs) at (chord/2) cot(sweep/2).
  const double offset = 0.5 * chord * (1 - seg.bulge * seg.bulge) / (2 * seg.bulge);
  g.cr = 0.5 * (seg.a.r + seg.b.r) - dh / chord * offset;
  g.ch = 0.5 * (seg.a.h + seg.b.h) + dr / chord * offset;
  g.radius = std::hypot(seg.a.r - g.cr, seg.a.h - g.ch);
  g.startAngle = std::atan2(seg.a.h - g.ch, seg.a.r - g.cr);
  g.length = g.radius * std::abs(g.sweep);
  return g;
}

PiecePoint pointAt(const PieceGeometry& g, double f) {
  if (g.sweep == 0) {
    const double dr = g.seg.b.r - g.seg.a.r, dh = g.seg.b.h - g.seg.a.h;
    const double len = std::max(g.length, 1e-300);
    return {g.seg.a.r + f * dr, g.seg.a.h + f * dh, dr / len, dh / len};
  }
  const double angle = g.startAngle + f * g.sweep;
  const double direction = g.sweep > 0 ? 1.0 : -1.0;  // counter-clockwise tangent is (-sin, cos)
  return {g.cr + g.radius * std::cos(angle), g.ch + g.radius * std::sin(angle),
          -std::sin(angle) * direction, std::cos(angle) * direction};
}

struct SurfaceSamples {
  std::vector<SurfaceSample> samples;
  double hMin = 0, hMax = 0, length = 0;  // of the surface pieces themselves, ends included
};

SurfaceSamples sampleSurface(const Profile& profile) {
  std::vector<PieceGeometry> pieces;
  double total = 0;
  for (const Contour& contour : profile.contours)
    for (const Segment& seg : contour.segments)
      if (isSurface(seg)) {
        pieces.push_back(describePiece(seg));
        total += pieces.back().length;
      }
  SurfaceSamples out;
  if (!(total > 0) || !std::isfinite(total)) return out;
  out.hMin = out.hMax = pieces.front().seg.a.h;
  double s = 0;
  for (const PieceGeometry& piece : pieces) {
    const int n = std::max(4, int(std::ceil(kTotalSamples * piece.length / total)));
    const double ds = piece.length / n;
    for (int k = 0; k <= 2 * n; ++k) {  // even k: bounds only; odd k: midpoint-rule samples
      const double f = k / (2.0 * n);
      const PiecePoint p = pointAt(piece, f);
      out.hMin = std::min(out.hMin, p.h), out.hMax = std::max(out.hMax, p.h);
      if (k % 2 == 1) out.samples.push_back({std::max(p.r, 0.0), p.h, p.tr, p.th, ds, s + f * piece.length});
    }
    s += piece.length;
  }
  out.length = s;
  return out;
}

// v's stretch along the profile (|dv/ds|) for one map at one sample.
using StretchV = std::function<double(const SurfaceSample&)>;

struct Distortion {
  double degenerateArea = 1, meanAngle = kAngleDistortionCap, meanArea = kAngleDistortionCap;
  double repeatRatio = 1;
  double score() const {
    return kDegeneratePenalty * degenerateArea + std::log(meanAngle) + kAreaWeight * std::log(meanArea);
  }
};

Distortion measureDistortion(const std::vector<SurfaceSample>& samples, const StretchV& stretchV) {
  Distortion out;
  double areaSum = 0, suSum = 0, svSum = 0;
  std::vector<double> su(samples.size()), sv(samples.size());
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const SurfaceSample& p = samples[k];
    if (p.r <= 0) continue;  // zero area: the pole itself
    su[k] = 1 / (2 * kPi * p.r);
    sv[k] = stretchV(p);
    areaSum += p.area();
    suSum += su[k] * p.area();
    svSum += sv[k] * p.area();
  }
  if (!(areaSum > 0) || !(svSum > 0)) return out;  // everything degenerate
  // Scale u so that the mean stretches match: texels square on average.
  out.repeatRatio = svSum / suSum;
  const double meanStretch = svSum / areaSum;
  double degenerate = 0, goodArea = 0, angleSum = 0, jacobianSum = 0;
  std::vector<double> jacobian(samples.size(), -1);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const SurfaceSample& p = samples[k];
    if (p.r <= 0) continue;
    const double a = su[k] * out.repeatRatio, b = sv[k];
    const double s1 = std::max(a, b), s2 = std::min(a, b);
    if (s2 < kDegenerateFraction * meanStretch) {
      degenerate += p.area();
      continue;
    }
    goodArea += p.area();
    angleSum += std::min(s1 / s2, kAngleDistortionCap) * p.area();
    jacobian[k] = s1 * s2;
    jacobianSum += s1 * s2 * p.area();
  }
  out.degenerateArea = degenerate / areaSum;
  if (!(goodArea > 0)) return out;
  out.meanAngle = angleSum / goodArea;
  const double meanJacobian = jacobianSum / goodArea;
  double areaDistortion = 0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    if (jacobian[k] < 0) continue;
    const double ratio = jacobian[k] / meanJacobian;
    areaDistortion += std::min(std::max(ratio, 1 / ratio), kAngleDistortionCap) * samples[k].area();
  }
  out.meanArea = areaDistortion / goodArea;
  return out;
}

ProjectionScore toScore(Projection projection, const Distortion& d) {
  ProjectionScore score;
  score.projection = projection;
  score.degenerateArea = d.degenerateArea;
  score.meanAngleDistortion = d.meanAngle;
  score.meanAreaDistortion = d.meanArea;
  score.score = d.score();
  score.repeatRatio = d.repeatRatio;
  return score;
}

// The polar angle theta from +h about (0, hc) changes along the profile by
// dtheta/ds = (tr (h - hc) - th r) / rho^2; v = (pi - theta) / pi.
Distortion sphericalDistortion(const std::vector<SurfaceSample>& samples, double hc) {
  return measureDistortion(samples, [hc](const SurfaceSample& p) {
    const double dh = p.h - hc;
    const double rho2 = p.r * p.r + dh * dh;
    if (rho2 <= 0) return 0.0;
    return std::abs(p.tr * dh - p.th * p.r) / rho2 / kPi;
  });
}

// Scan the centre over the profile's height range (and half of it beyond), then refine the best
// bracket by golden-section search. Equal scores go to the centre nearest the middle of the range
// (a sphere maps alike about its centre and its poles, by the inscribed angle theorem, but only the
// centre spreads v over [0, 1]).
double bestSphereCentre(const std::vector<SurfaceSample>& samples, double hMin, double hMax) {
  const double span = std::max(hMax - hMin, 1e-12);
  const double lo = hMin - 0.5 * span, hi = hMax + 0.5 * span, middle = 0.5 * (hMin + hMax);
  constexpr int kScan = 41;
  auto cost = [&](double hc) { return sphericalDistortion(samples, hc).score(); };
  auto scanPoint = [&](int k) { return lo + (hi - lo) * k / (kScan - 1); };
  int best = 0;
  double bestCost = cost(lo);
  for (int k = 1; k < kScan; ++k) {
    const double c = cost(scanPoint(k));
    const bool tie = std::abs(c - bestCost) <= kTieTolerance;
    if (c < bestCost - kTieTolerance || (tie && std::abs(scanPoint(k) - middle) < std::abs(scanPoint(best) - middle)))
      best = k, bestCost = std::min(c, bestCost);
  }
  const double step = (hi - lo) / (kScan - 1);
  double a = lo + step * std::max(best - 1, 0), b = lo + step * std::min(best + 1, kScan - 1);
  const double invPhi = (std::sqrt(5.0) - 1) / 2;
  double x1 = b - invPhi * (b - a), x2 = a + invPhi * (b - a);
  double f1 = cost(x1), f2 = cost(x2);
  for (int it = 0; it < 40; ++it) {
    if (f1 <= f2) {
      b = x2, x2 = x1, f2 = f1;
      x1 = b - invPhi * (b - a), f1 = cost(x1);
    } else {
      a = x1, x1 = x2, f1 = f2;
      x2 = a + invPhi * (b - a), f2 = cost(x2);
    }
  }
  const double refined = 0.5 * (a + b);
  return cost(refined) <= bestCost + kTieTolerance ? refined : scanPoint(best);
}

}  // namespace

ProjectionChoice chooseProjection(const Profile& profile) {
  ProjectionChoice choice;
  const SurfaceSamples surface = sampleSurface(profile);
  const std::vector<SurfaceSample>& samples = surface.samples;
  const double hMin = surface.hMin, hMax = surface.hMax, length = surface.length;
  const double heightRange = hMax - hMin;

  const Distortion cylindrical = measureDistortion(samples, [heightRange](const SurfaceSample& p) {
    return heightRange > 0 ? std::abs(p.th) / heightRange : 0.0;
  });
  const double centre = samples.empty() ? 0 : bestSphereCentre(samples, hMin, hMax);
  const Distortion spherical = sphericalDistortion(samples, centre);
  const Distortion arcLength = measureDistortion(
      samples, [length](const SurfaceSample&) { return length > 0 ? 1 / length : 0.0; });

  choice.scores = {toScore(Projection::Cylindrical, cylindrical), toScore(Projection::Spherical, spherical),
                   toScore(Projection::ArcLength, arcLength)};
  choice.scores[1].sphereCentreH = centre;
  choice.chosen = Projection::Cylindrical;
  double best = choice.scores[0].score;
  for (const ProjectionScore& s : choice.scores)
    if (s.score < best - kClearWin) best = s.score, choice.chosen = s.projection;
  return choice;
}

}  // namespace bake::revolution
