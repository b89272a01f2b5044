// The independent reference of exact_reference.h. Inside test: the even-odd rule along the ray from p
// towards +r. A query on a vertex's row, on a horizontal piece or on a tangent is made generic by the
// symbolic perturbation p' = p + (e^3, e) (simulation of simplicity, Edelsbrunner & Muecke 1990): every
// predicate is the sign of a polynomial in e, decided by its first non-zero coefficient, so no case is
// ambiguous and every answer is the true one for points off the curve. A straight piece toggles the
// parity when its ends lie on either side of the row (an end exactly on it counts as below) and p' is
// left of it directed upwards (CGAL orientation, exact). An arc toggles it as its chord does, XOR when
// p' lies in the region between chord and arc: inside the circle (the sign of |p' - c|^2 - R^2, with
// the centre c a rational function of the ends and the bulge, evaluated in interval arithmetic and,
// when that cannot decide, in exact rationals) and on the arc's side of the chord line.
// Distance: CGAL's point-segment distance; for an arc, the radial projection onto its circle when that
// lands on the arc's side of the chord, else the nearer end.
#include "revolution/reference/exact_reference.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>

#include "core/parallel.h"

namespace bake::revolution::reference {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using KPoint = Kernel::Point_2;
using Interval = CGAL::Interval_nt_advanced;
using Exact = CGAL::Exact_rational;

KPoint toKernel(Point2 p) { return KPoint(p.r, p.h); }

// Sign of cross(b - a, p' - a) for p' = p + (e^3, e): cross(b - a, p - a) + e (b.r - a.r) - e^3 (b.h - a.h).
int perturbedOrientation(Point2 a, Point2 b, Point2 p) {
  const CGAL::Orientation o = CGAL::orientation(toKernel(a), toKernel(b), toKernel(p));
  if (o == CGAL::LEFT_TURN) return 1;
  if (o == CGAL::RIGHT_TURN) return -1;
  if (b.r != a.r) return b.r > a.r ? 1 : -1;
  if (b.h != a.h) return b.h > a.h ? -1 : 1;
  return 0;
}

// Does the straight piece a-b cross the row of p' to the right of p'?
bool crossesRight(Point2 a, Point2 b, Point2 p) {
  const bool aAbove = a.h > p.h, bAbove = b.h > p.h;
  if (aAbove == bAbove) return false;
  const Point2 low = aAbove ? b : a, high = aAbove ? a : b;
  return perturbedOrientation(low, high, p) > 0;  // p' left of the upward piece
}

// |p - c|^2 - R^2 and p.h - c.h for the circle of the arc a-b with the given bulge. With d = b - a, the
// left normal n = (-d.h, d.r) and k = (1 - bulge^2) / (4 bulge), the centre is c = (a + b) / 2 + k n, so
// a - c = -d / 2 - k n and |p - c|^2 - R^2 = |p - a|^2 + 2 (p - a).(a - c).
template <class NT>
void circleTerms(Point2 a, Point2 b, double bulge, Point2 p, NT& power, NT& offsetH) {
  const NT ar(a.r), ah(a.h), dr = NT(b.r) - ar, dh = NT(b.h) - ah, beta(bulge);
  const NT k = (NT(1) - beta * beta) / (NT(4) * beta);
  const NT acR = -dr / NT(2) + dh * k, acH = -dh / NT(2) - dr * k;
  const NT pr = NT(p.r) - ar, ph = NT(p.h) - ah;
  power = pr * pr + ph * ph + NT(2) * (pr * acR + ph * acH);
  offsetH = ph + acH;
}

int signOf(const Exact& x) { return CGAL::sign(x) == CGAL::POSITIVE ? 1 : (CGAL::sign(x) == CGAL::NEGATIVE ? -1 : 0); }

// Sign of |p' - c|^2 - R^2 = power + 2 e (p.h - c.h) + e^2 + ...
int perturbedPowerSign(Point2 a, Point2 b, double bulge, Point2 p) {
  {
    CGAL::Protect_FPU_rounding<true> rounding;
    Interval power, offsetH;
    circleTerms(a, b, bulge, p, power, offsetH);
    if (power.inf() > 0) return 1;
    if (power.sup() < 0) return -1;
  }
  Exact power, offsetH;
  circleTerms(a, b, bulge, p, power, offsetH);
  if (const int s = signOf(power)) return s;
  if (const int s = signOf(offsetH)) return s;
  return 1;
}

struct Piece {
  Point2 a, b;
  double bulge = 0;
  bool surface = true;
  Point2 lo, hi;  // box holding the piece (conservative for arcs)
};

bool inLens(const Piece& s, Point2 p) {
  const int arcSide = s.bulge > 0 ? -1 : 1;  // a counter-clockwise arc lies right of its chord
  if (perturbedOrientation(s.a, s.b, p) != arcSide) return false;
  return perturbedPowerSign(s.a, s.b, s.bulge, p) < 0;
}

bool togglesParity(const Piece& s, Point2 p) {
  const bool chord = crossesRight(s.a, s.b, p);
  return s.bulge == 0 ? chord : chord != inLens(s, p);
}

Piece prepare(const Segment& segment) {
  Piece s;
  s.a = segment.a;
  s.b = segment.b;
  s.bulge = segment.bulge;
  s.surface = !segment.onAxis;
  s.lo = {std::min(s.a.r, s.b.r), std::min(s.a.h, s.b.h)};
  s.hi = {std::max(s.a.r, s.b.r), std::max(s.a.h, s.b.h)};
  if (s.bulge == 0) return s;
  const double chord = std::hypot(s.b.r - s.a.r, s.b.h - s.a.h);
  const double beta = std::abs(s.bulge);
  double grow;
  if (beta <= 1) {
    grow = 0.5 * chord * beta;  // a minor arc stays within its sagitta of the chord, over the chord
  } else {
    grow = chord * (1 + beta * beta) / (2 * beta);  // a major arc within its circle: one diameter
  }
  grow = grow * (1 + 1e-9) + 1e-12 * (std::abs(s.lo.r) + std::abs(s.hi.r) + std::abs(s.lo.h) + std::abs(s.hi.h) + chord);
  s.lo = {s.lo.r - grow, s.lo.h - grow};
  s.hi = {s.hi.r + grow, s.hi.h + grow};
  return s;
}

std::vector<Piece> preparePieces(const Profile& profile) {
  std::vector<Piece> pieces;
  for (const Contour& contour : profile.contours)
    for (const Segment& segment : contour.segments) pieces.push_back(prepare(segment));
  return pieces;
}

double arcDistance(const Piece& s, Point2 p) {
  using L = long double;
  const L dr = L(s.b.r) - s.a.r, dh = L(s.b.h) - s.a.h, beta = s.bulge;
  const L k = (1 - beta * beta) / (4 * beta);
  const L cr = (L(s.a.r) + s.b.r) / 2 - dh * k, ch = (L(s.a.h) + s.b.h) / 2 + dr * k;
  const L radius = std::sqrt(dr * dr + dh * dh) * (1 + beta * beta) / (4 * std::abs(beta));
  const L vr = p.r - cr, vh = p.h - ch;
  const L len = std::sqrt(vr * vr + vh * vh);
  const L toA = std::hypot(L(p.r) - s.a.r, L(p.h) - s.a.h), toB = std::hypot(L(p.r) - s.b.r, L(p.h) - s.b.h);
  if (len == 0) return double(radius);
  const L qr = cr + vr * radius / len, qh = ch + vh * radius / len;
  const L side = dr * (qh - s.a.h) - dh * (qr - s.a.r);
  const bool onArc = s.bulge > 0 ? side <= 0 : side >= 0;
  if (!onArc) return double(std::min(toA, toB));
  const L par = L(p.r) - s.a.r, pah = L(p.h) - s.a.h;
  const L acR = -dr / 2 + dh * k, acH = -dh / 2 - dr * k;
  const L power = par * par + pah * pah + 2 * (par * acR + pah * acH);
  return double(std::abs(power) / (len + radius));
}

double pieceDistance(const Piece& s, Point2 p) {
  if (s.bulge != 0) return arcDistance(s, p);
  if (s.a.r == s.b.r && s.a.h == s.b.h) return std::hypot(p.r - s.a.r, p.h - s.a.h);
  return std::sqrt(CGAL::to_double(CGAL::squared_distance(toKernel(p), Kernel::Segment_2(toKernel(s.a), toKernel(s.b)))));
}

bool insideOver(const std::vector<const Piece*>& pieces, Point2 p) {
  bool inside = false;
  for (const Piece* s : pieces)
    if (s->hi.r >= p.r && togglesParity(*s, p)) inside = !inside;
  return inside;
}

// Distance from a box to a point set's box (0 when they meet).
double boxGap(Point2 lo1, Point2 hi1, Point2 lo2, Point2 hi2) {
  const double gr = std::max({0.0, lo2.r - hi1.r, lo1.r - hi2.r});
  const double gh = std::max({0.0, lo2.h - hi1.h, lo1.h - hi2.h});
  return std::hypot(gr, gh);
}

}  // namespace

bool insideExact(const Profile& profile, Point2 p) {
  bool inside = false;
  for (const Piece& s : preparePieces(profile))
    if (togglesParity(s, p)) inside = !inside;
  return inside;
}

double distanceToSurface(const Profile& profile, Point2 p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Piece& s : preparePieces(profile))
    if (s.surface) best = std::min(best, pieceDistance(s, p));
  return best;
}

double signedDistanceReference(const Profile& profile, Point2 p) {
  const double d = distanceToSurface(profile, p);
  return insideExact(profile, p) ? -d : d;
}

FieldCheck checkField(const Profile& profile, const ShapeGrid& grid, const std::vector<float>& distance,
                      unsigned threads) {
  const std::vector<Piece> pieces = preparePieces(profile);
  std::vector<const Piece*> surface;
  for (const Piece& s : pieces)
    if (s.surface) surface.push_back(&s);
  constexpr int kTile = 8;
  const double texel = grid.texelSize;
  const int tileRows = (grid.height + kTile - 1) / kTile;
  FieldCheck total;
  double sum = 0, nearSum = 0;
  std::mutex merge;
  parallelFor(std::size_t(tileRows), threads, [&](std::size_t t) {
    const int j0 = int(t) * kTile, j1 = std::min(grid.height, j0 + kTile);
    FieldCheck local;
    double localSum = 0, localNearSum = 0;
    std::vector<const Piece*> rowPieces, candidates;
    for (int i0 = 0; i0 < grid.width; i0 += kTile) {
      const int i1 = std::min(grid.width, i0 + kTile);
      // Candidates for the nearest piece of any texel of the tile: a piece whose box is farther from
      // the tile than some piece's end is from every texel cannot be nearest.
      const Point2 tileLo{grid.centreR(i0), grid.centreH(j0)}, tileHi{grid.centreR(i1 - 1), grid.centreH(j1 - 1)};
      const Point2 centre{0.5 * (tileLo.r + tileHi.r), 0.5 * (tileLo.h + tileHi.h)};
      const double halfDiagonal = 0.5 * std::hypot(tileHi.r - tileLo.r, tileHi.h - tileLo.h);
      double bound = std::numeric_limits<double>::infinity();
      for (const Piece* s : surface) bound = std::min(bound, std::hypot(centre.r - s->a.r, centre.h - s->a.h));
      bound = (bound + halfDiagonal) * (1 + 1e-9);
      candidates.clear();
      for (const Piece* s : surface)
        if (boxGap(tileLo, tileHi, s->lo, s->hi) <= bound) candidates.push_back(s);
      for (int j = j0; j < j1; ++j) {
        const double h = grid.centreH(j);
        rowPieces.clear();
        for (const Piece& s : pieces)
          if (s.lo.h <= h && h <= s.hi.h) rowPieces.push_back(&s);
        for (int i = i0; i < i1; ++i) {
          const Point2 p{grid.centreR(i), h};
          double d = std::numeric_limits<double>::infinity();
          for (const Piece* s : candidates) d = std::min(d, pieceDistance(*s, p));
          if (insideOver(rowPieces, p)) d = -d;
          const double stored = distance[std::size_t(j) * grid.width + i];
          const double error = std::abs(stored - d) / texel;
          ++local.texels;
          localSum += error;
          if (error > local.maxError) {
            local.maxError = error;
            local.worstI = i;
            local.worstJ = j;
          }
          if (std::abs(d) > kSignSlackTexels * texel && ((stored < 0) != (d < 0) || stored == 0)) ++local.signErrors;
          if (std::abs(d) <= 2 * texel) {
            ++local.nearTexels;
            localNearSum += error;
            local.nearMaxError = std::max(local.nearMaxError, error);
          }
        }
      }
    }
    std::lock_guard<std::mutex> lock(merge);
    total.texels += local.texels;
    total.signErrors += local.signErrors;
    total.nearTexels += local.nearTexels;
    sum += localSum;
    nearSum += localNearSum;
    total.nearMaxError = std::max(total.nearMaxError, local.nearMaxError);
    if (local.worstI >= 0 && (total.worstI < 0 || local.maxError > total.maxError)) {
      total.maxError = local.maxError;
      total.worstI = local.worstI;
      total.worstJ = local.worstJ;
    }
  }, 1);
  if (total.texels) total.meanError = sum / double(total.texels);
  if (total.nearTexels) total.nearMeanError = nearSum / double(total.nearTexels);
  return total;
}

}  // namespace bake::revolution::reference
