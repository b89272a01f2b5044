// Window geometry for the exact geodesic propagation (Surazhsky et al. 2005, sections 3.2-3.3):
// unfolding a window's rays into the next face and the split points between two windows on an edge.
// Faces with collinear corners need no special case: with the third corner on the edge line (c.y = 0)
// the projections below map every point of the edge to itself, so a window passes through the fold.
#include "geodesic/bake/exact_window.h"

#include <algorithm>
#include <cmath>

namespace bake::geodesic::exact {
namespace {

double safeRatio(double num, double den, double fallback) {
  if (den == 0.0 || !std::isfinite(num / den)) return fallback;
  return num / den;
}

double clamp01(double t) { return std::clamp(t, 0.0, 1.0); }

// Projection of the rays' range [lo, hi] (on the window's edge) onto A-C, as parameters from A.
ChildRange rangeOnAC(const Window& w, Point2 c, double lo, double hi) {
  auto param = [&](double x) {
    return clamp01(safeRatio(w.sy * x, w.sy * c.x - (x - w.sx) * c.y, x <= 0.0 ? 0.0 : 1.0));
  };
  ChildRange r;
  r.valid = true;
  r.t0 = param(lo);
  r.t1 = param(hi);
  if (r.t0 > r.t1) std::swap(r.t0, r.t1);
  return r;
}

// The same onto B-C, as parameters from B.
ChildRange rangeOnBC(const Window& w, double length, Point2 c, double lo, double hi) {
  auto param = [&](double x) {
    return clamp01(safeRatio(w.sy * (length - x), (x - w.sx) * c.y - w.sy * (c.x - length),
                             x >= length ? 0.0 : 1.0));
  };
  ChildRange r;
  r.valid = true;
  r.t0 = param(lo);
  r.t1 = param(hi);
  if (r.t0 > r.t1) std::swap(r.t0, r.t1);
  return r;
}

}  // namespace

FaceCrossing crossFace(const Window& w, double length, Point2 c, double tolerance) {
  FaceCrossing out;
  if (w.sy <= tolerance) {
    // The pseudo-source lies on the edge itself (a source on an edge, or a pseudo-source seen through
    // a fold): rays leave it into the whole face when it sits inside the window, else none enter.
    if (w.sx >= w.b0 - tolerance && w.sx <= w.b1 + tolerance) {
      out.onAC = {true, 0.0, 1.0};
      out.onBC = {true, 0.0, 1.0};
      out.reachesC = true;
    }
    return out;
  }
  // Where the ray from the mirrored source through C crosses the edge line.
  const double xC = w.sx + (c.x - w.sx) * w.sy / (c.y + w.sy);
  out.reachesC = xC >= w.b0 - tolerance && xC <= w.b1 + tolerance;
  const double acLo = std::max(std::min(0.0, xC), w.b0), acHi = std::min(std::max(0.0, xC), w.b1);
  if (acHi - acLo > tolerance) out.onAC = rangeOnAC(w, c, acLo, acHi);
  const double bcLo = std::max(std::min(length, xC), w.b0), bcHi = std::min(std::max(length, xC), w.b1);
  if (bcHi - bcLo > tolerance) out.onBC = rangeOnBC(w, length, c, bcLo, bcHi);
  return out;
}

Point2 sourceInFrame(Point2 s, Point2 p, Point2 q) {
  const double dx = q.x - p.x, dy = q.y - p.y;
  const double len = length2d(dx, dy);
  const double rx = s.x - p.x, ry = s.y - p.y;
  if (len == 0.0) return {0.0, length2d(rx, ry)};
  const double ux = dx / len, uy = dy / len;
  return {rx * ux + ry * uy, std::fabs(ux * ry - uy * rx)};
}

int crossingPoints(const Window& a, const Window& b, double lo, double hi, std::array<double, 2>& roots) {
  // sigma_a + r_a = sigma_b + r_b, squared twice, is a quadratic in x; spurious roots only add split
  // points where both sides keep the same winner, so they are harmless.
  const double s1 = a.sx, s2 = b.sx, ds = b.sigma - a.sigma;
  const double alpha = 2.0 * (s2 - s1);
  const double beta = s1 * s1 - s2 * s2 + a.sy * a.sy - b.sy * b.sy - ds * ds;
  const double qa = alpha * alpha - 4.0 * ds * ds;
  const double qb = 2.0 * alpha * beta + 8.0 * ds * ds * s2;
  const double qc = beta * beta - 4.0 * ds * ds * (s2 * s2 + b.sy * b.sy);
  std::array<double, 2> candidates{};
  int count = 0;
  const double disc = qb * qb - 4.0 * qa * qc;
  if (disc >= 0.0) {
    const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
    if (qa != 0.0) candidates[count++] = q / qa;
    if (q != 0.0) candidates[count++] = qc / q;
  } else if (qa != 0.0) {
    candidates[count++] = -qb / (2.0 * qa);  // nearly tangent: split at the closest approach
  }
  int kept = 0;
  for (int i = 0; i < count; ++i) {
    double x = candidates[i];
    if (!std::isfinite(x)) continue;
    // A few Newton steps on the unsquared difference repair cancellation in the quadratic.
    for (int it = 0; it < 3 && x > lo && x < hi; ++it) {
      const double ra = length2d(x - a.sx, a.sy), rb = length2d(x - b.sx, b.sy);
      const double f = a.sigma + ra - b.sigma - rb;
      const double df = (ra > 0.0 ? (x - a.sx) / ra : 0.0) - (rb > 0.0 ? (x - b.sx) / rb : 0.0);
      if (df == 0.0 || !std::isfinite(f / df)) break;
      x -= f / df;
    }
    if (x > lo && x < hi) roots[kept++] = x;
  }
  if (kept == 2 && roots[0] > roots[1]) std::swap(roots[0], roots[1]);
  return kept;
}

}  // namespace bake::geodesic::exact
