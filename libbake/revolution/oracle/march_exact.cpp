// The analytic reference the march is measured against: the first intersection of a ray with the
// revolved profile, piece by piece, independent of any sampled field. Along the ray, r(t)^2 =
// |o_xz + t d_xz|^2 is quadratic in t and h(t) is linear. A straight piece from a to b revolves to a
// cone frustum (a cylinder when a.r = b.r): with lambda(t) = (h(t) - a.h) / (b.h - a.h) its surface is
// r(t)^2 = (a.r + lambda(t) (b.r - a.r))^2, a quadratic in t, and roots count when lambda is in
// [0, 1]; a horizontal piece revolves to an annulus in the plane h = a.h. An arc revolves to a piece
// of a torus: D(t) - R = 0 with D the distance of (r(t), h(t)) from the arc's centre. Both r and h
// move at most as fast as t, so D - R is 1-Lipschitz in t: stepping by |D - R| (plus 1e-9 of the
// profile size) cannot jump over a pair of roots more than that apart, a sign change brackets a root,
// and bisection refines it to 1e-13. A root counts when its angle about the centre lies on the arc.
// Pieces on the axis revolve to nothing and are skipped. The smallest root t > 0 is the hit.
#include <algorithm>
#include <cmath>
#include <limits>

#include "bake/core/vec.h"
#include "revolution/oracle/march.h"

namespace bake::revolution {
namespace {
constexpr double kParameterSlack = 1e-12;  // pieces meet exactly; keep their shared rim
// Below this bulge an arc's sagitta is under 5e-10 of its chord: it is its chord (and its centre,
// 1 / (4 bulge) chords away, would cost the distance all its digits).
constexpr double kStraightBulge = 1e-9;

struct RayPlane {
  // r(t)^2 = a t^2 + 2 b t + c; h(t) = h0 + hd t.
  double a, b, c, h0, hd;
  double r(double t) const { return std::sqrt(std::max(0.0, (a * t + 2 * b) * t + c)); }
  double h(double t) const { return h0 + hd * t; }
};

RayPlane toRayPlane(const Ray& ray) {
  const double ox = ray.origin[0], oz = ray.origin[2], dx = ray.direction[0], dz = ray.direction[2];
  return {dx * dx + dz * dz, ox * dx + oz * dz, ox * ox + oz * oz, ray.origin[1], ray.direction[1]};
}

bool isAxisPiece(const Segment& s) {
  return s.onAxis || (std::abs(s.bulge) < kStraightBulge && s.a.r == 0 && s.b.r == 0);
}

void keepIfAhead(double t, double& best) {
  if (t > 0 && t < best) best = t;
}

// Real roots of A t^2 + B t + C = 0 (the stable pair), or the linear root when A vanishes.
int solveQuadratic(double A, double B, double C, double roots[2]) {
  const double scale = std::max({std::abs(A), std::abs(B), std::abs(C)});
  if (scale == 0) return 0;
  if (std::abs(A) <= 1e-14 * scale) {
    if (B == 0) return 0;
    roots[0] = -C / B;
    return 1;
  }
  const double disc = B * B - 4 * A * C;
  if (disc < 0) return 0;
  const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
  roots[0] = q / A;
  roots[1] = q != 0 ? C / q : roots[0];
  return 2;
}

void intersectStraight(const RayPlane& ray, const Segment& s, double& best) {
  const double dh = s.b.h - s.a.h;
  if (dh == 0) {  // annulus in the plane h = a.h
    if (ray.hd == 0) return;
    const double t = (s.a.h - ray.h0) / ray.hd;
    const double r = ray.r(t);
    const double lo = std::min(s.a.r, s.b.r), hi = std::max(s.a.r, s.b.r);
    const double slack = kParameterSlack * std::max(1.0, hi);
    if (r >= lo - slack && r <= hi + slack) keepIfAhead(t, best);
    return;
  }
  // Radius of the line at the ray's height: rl(t) = p t + q.
  const double slope = (s.b.r - s.a.r) / dh;
  const double p = slope * ray.hd;
  const double q = s.a.r + slope * (ray.h0 - s.a.h);
  double roots[2];
  const int n = solveQuadratic(ray.a - p * p, 2 * (ray.b - p * q), ray.c - q * q, roots);
  for (int k = 0; k < n; ++k) {
    const double t = roots[k];
    const double lambda = (ray.h(t) - s.a.h) / dh;
    // Squaring also admits the mirror line rl < 0; rl >= 0 holds on [0, 1] since a.r, b.r >= 0.
    if (lambda >= -kParameterSlack && lambda <= 1 + kParameterSlack && p * t + q >= -kParameterSlack)
      keepIfAhead(t, best);
  }
}

struct Arc {
  double cr, ch, radius, startAngle, sweep;
};

Arc arcOf(const Segment& s) {
  const double dr = s.b.r - s.a.r, dh = s.b.h - s.a.h;
  const double chord = std::hypot(dr, dh);
  // The centre is on the chord's left normal at (chord / 2) cot(sweep / 2) = chord (1 - b^2) / (4 b).
  const double offset = chord * (1 - s.bulge * s.bulge) / (4 * s.bulge);
  Arc arc;
  arc.cr = 0.5 * (s.a.r + s.b.r) - dh / chord * offset;
  arc.ch = 0.5 * (s.a.h + s.b.h) + dr / chord * offset;
  arc.radius = std::hypot(s.a.r - arc.cr, s.a.h - arc.ch);
  arc.startAngle = std::atan2(s.a.h - arc.ch, s.a.r - arc.cr);
  arc.sweep = 4 * std::atan(s.bulge);
  return arc;
}

bool onArc(const Arc& arc, double r, double h) {
  double turned = std::atan2(h - arc.ch, r - arc.cr) - arc.startAngle;
  if (arc.sweep < 0) turned = -turned;
  turned = std::fmod(turned, 2 * kPi);
  if (turned < 0) turned += 2 * kPi;
  const double slack = 1e-9;
  return turned <= std::abs(arc.sweep) + slack || turned >= 2 * kPi - slack;
}

// Ray parameters where the ray can meet the torus piece: inside the cylinder r <= cr + R and the slab
// |h - ch| <= R (a loose but safe box), from t = 0.
bool arcSearchSpan(const RayPlane& ray, const Arc& arc, double& tIn, double& tOut) {
  const double pad = 1e-9 * (arc.radius + std::abs(arc.cr)) + 1e-300;
  tIn = 0;
  tOut = std::numeric_limits<double>::infinity();
  if (ray.hd != 0) {
    double t0 = (arc.ch - arc.radius - pad - ray.h0) / ray.hd, t1 = (arc.ch + arc.radius + pad - ray.h0) / ray.hd;
    if (t0 > t1) std::swap(t0, t1);
    tIn = std::max(tIn, t0), tOut = std::min(tOut, t1);
  } else if (std::abs(ray.h0 - arc.ch) > arc.radius + pad) {
    return false;
  }
  const double outer = arc.cr + arc.radius + pad;
  const double C = ray.c - outer * outer;
  if (ray.a == 0) {
    if (C > 0) return false;
  } else {
    const double disc = ray.b * ray.b - ray.a * C;
    if (disc < 0) return false;
    const double root = std::sqrt(disc);
    tIn = std::max(tIn, (-ray.b - root) / ray.a), tOut = std::min(tOut, (-ray.b + root) / ray.a);
  }
  return tIn <= tOut;
}

void intersectArc(const RayPlane& ray, const Segment& s, double& best) {
  const Arc arc = arcOf(s);
  double t = 0, tEnd = 0;
  if (!arcSearchSpan(ray, arc, t, tEnd)) return;
  tEnd = std::min(tEnd, best);  // a later root cannot improve the hit
  const double size = arc.radius + std::abs(arc.cr) + std::abs(arc.ch);
  const double minStep = 1e-9 * size, rootTolerance = 1e-13 * size;
  auto g = [&](double at) { return std::hypot(ray.r(at) - arc.cr, ray.h(at) - arc.ch) - arc.radius; };
  double gt = g(t);
  for (int guard = 0; guard < 4000000 && t <= tEnd; ++guard) {
    if (gt == 0) {
      if (onArc(arc, ray.r(t), ray.h(t))) return keepIfAhead(t, best);
      gt = g(t += minStep);
      continue;
    }
    const double next = t + std::abs(gt) + minStep;
    const double gn = g(next);
    if ((gn < 0) != (gt < 0) || gn == 0) {
      double lo = t, hi = next, glo = gt;
      while (hi - lo > rootTolerance) {
        const double mid = 0.5 * (lo + hi);
        const double gm = g(mid);
        if ((gm < 0) == (glo < 0) && gm != 0) lo = mid, glo = gm;
        else hi = mid;
      }
      const double root = 0.5 * (lo + hi);
      if (root <= tEnd && onArc(arc, ray.r(root), ray.h(root))) return keepIfAhead(root, best);
    }
    t = next;
    gt = gn;
  }
}

}  // namespace

std::optional<double> intersectExact(const Ray& ray, const Profile& profile) {
  for (int c = 0; c < 3; ++c)
    if (!std::isfinite(ray.origin[c]) || !std::isfinite(ray.direction[c])) return std::nullopt;
  const RayPlane plane = toRayPlane(ray);
  double best = std::numeric_limits<double>::infinity();
  for (const Contour& contour : profile.contours)
    for (const Segment& s : contour.segments) {
      if (isAxisPiece(s)) continue;
      if (std::abs(s.bulge) < kStraightBulge || (s.a.r == s.b.r && s.a.h == s.b.h)) intersectStraight(plane, s, best);
      else if (!std::isfinite(s.bulge)) continue;  // validation rejects these; skip rather than guess
      else intersectArc(plane, s, best);
    }
  if (!std::isfinite(best)) return std::nullopt;
  return best;
}

}  // namespace bake::revolution
