// Geometry of straight and circular-arc profile pieces (see profile_geometry.h for the conventions).
// Arcs follow the DXF bulge convention (bulge = tan(sweep / 4)); everything here is closed-form:
// nearest points by projection onto the line or the circle, parity crossings by the chord-and-lens
// identity, intersections by the line-circle quadratic and the two-circle radical line.
#include "revolution/input/profile_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bake::revolution {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

Point2 add(Point2 a, Point2 b) { return {a.r + b.r, a.h + b.h}; }
Point2 sub(Point2 a, Point2 b) { return {a.r - b.r, a.h - b.h}; }
Point2 scale(Point2 a, double s) { return {a.r * s, a.h * s}; }
double dot(Point2 a, Point2 b) { return a.r * b.r + a.h * b.h; }
double cross(Point2 a, Point2 b) { return a.r * b.h - a.h * b.r; }
double length(Point2 a) { return std::hypot(a.r, a.h); }

// Angle measured from the arc's start in its own direction of travel, in [0, 2 pi).
double alongSweep(const ArcGeometry& arc, double angle) {
  double delta = arc.sweep >= 0 ? angle - arc.startAngle : arc.startAngle - angle;
  delta = std::fmod(delta, kTwoPi);
  if (delta < 0) delta += kTwoPi;
  return delta;
}

double angleOf(Point2 v) { return std::atan2(v.h, v.r); }

}  // namespace

bool isArc(const Segment& s) { return s.bulge != 0.0; }

ArcGeometry arcGeometry(const Segment& s) {
  const Point2 chord = sub(s.b, s.a);
  const double c = length(chord);
  const Point2 left{-chord.h / c, chord.r / c};
  const Point2 mid = scale(add(s.a, s.b), 0.5);
  ArcGeometry arc;
  arc.centre = add(mid, scale(left, c * (1.0 - s.bulge * s.bulge) / (4.0 * s.bulge)));
  arc.radius = c * (1.0 + s.bulge * s.bulge) / (4.0 * std::abs(s.bulge));
  arc.startAngle = angleOf(sub(s.a, arc.centre));
  arc.sweep = 4.0 * std::atan(s.bulge);
  return arc;
}

bool angleOnArc(const ArcGeometry& arc, double angle, double slack) {
  const double u = alongSweep(arc, angle);
  const double span = std::abs(arc.sweep);
  if (u >= std::max(0.0, -slack) && u <= span + slack) return true;
  return slack > 0 && u >= kTwoPi - slack;  // just before the start
}

Point2 closestPoint(const Segment& s, Point2 p) {
  if (!isArc(s)) {
    const Point2 d = sub(s.b, s.a);
    const double len2 = dot(d, d);
    if (len2 == 0) return s.a;
    const double t = std::clamp(dot(sub(p, s.a), d) / len2, 0.0, 1.0);
    return add(s.a, scale(d, t));
  }
  const ArcGeometry arc = arcGeometry(s);
  const Point2 v = sub(p, arc.centre);
  const double len = length(v);
  if (len > 0 && angleOnArc(arc, angleOf(v))) return add(arc.centre, scale(v, arc.radius / len));
  // Off the sweep (or at the centre): the nearer end.
  const Point2 da = sub(p, s.a), db = sub(p, s.b);
  return dot(da, da) <= dot(db, db) ? s.a : s.b;
}

PieceDistance distanceToPiece(const Segment& s, Point2 p) {
  PieceDistance result;
  auto fromPoint = [&](Point2 q) {
    const Point2 v = sub(p, q);
    result.distance = length(v);
    if (result.distance > 0) result.away = scale(v, 1.0 / result.distance);
    return result;
  };
  if (!isArc(s)) return fromPoint(closestPoint(s, p));
  const ArcGeometry arc = arcGeometry(s);
  const Point2 v = sub(p, arc.centre);
  const double len = length(v);
  if (!(len > 0) || !angleOnArc(arc, angleOf(v))) {
    const Point2 da = sub(p, s.a), db = sub(p, s.b);
    return fromPoint(dot(da, da) <= dot(db, db) ? s.a : s.b);
  }
  const Point2 pa = sub(p, s.a);
  const double powerOfPoint = dot(pa, pa) + 2.0 * dot(pa, sub(s.a, arc.centre));  // |p - c|^2 - R^2
  result.distance = std::abs(powerOfPoint) / (len + arc.radius);
  result.away = scale(v, (powerOfPoint >= 0 ? 1.0 : -1.0) / len);
  return result;
}

Point2 pointAt(const Segment& s, double t) {
  if (t <= 0) return s.a;
  if (t >= 1) return s.b;
  if (!isArc(s)) return add(s.a, scale(sub(s.b, s.a), t));
  const ArcGeometry arc = arcGeometry(s);
  const double angle = arc.startAngle + t * arc.sweep;
  return {arc.centre.r + arc.radius * std::cos(angle), arc.centre.h + arc.radius * std::sin(angle)};
}

Point2 tangentAt(const Segment& s, double t) {
  if (!isArc(s)) {
    const Point2 d = sub(s.b, s.a);
    return scale(d, 1.0 / length(d));
  }
  const ArcGeometry arc = arcGeometry(s);
  const double angle = arc.startAngle + std::clamp(t, 0.0, 1.0) * arc.sweep;
  const double dir = arc.sweep >= 0 ? 1.0 : -1.0;
  return {-dir * std::sin(angle), dir * std::cos(angle)};
}

void segmentBox(const Segment& s, Point2& lo, Point2& hi) {
  lo = {std::min(s.a.r, s.b.r), std::min(s.a.h, s.b.h)};
  hi = {std::max(s.a.r, s.b.r), std::max(s.a.h, s.b.h)};
  if (!isArc(s)) return;
  const ArcGeometry arc = arcGeometry(s);
  for (int k = 0; k < 4; ++k) {
    const double angle = k * std::numbers::pi / 2;
    if (!angleOnArc(arc, angle)) continue;
    const Point2 p{arc.centre.r + arc.radius * std::cos(angle), arc.centre.h + arc.radius * std::sin(angle)};
    lo = {std::min(lo.r, p.r), std::min(lo.h, p.h)};
    hi = {std::max(hi.r, p.r), std::max(hi.h, p.h)};
  }
}

double areaTerm(const Segment& s) {
  double area = 0.5 * cross(s.a, s.b);
  if (isArc(s)) {
    // A positive bulge puts the arc right of the chord: outward for a counter-clockwise contour.
    const ArcGeometry arc = arcGeometry(s);
    const double theta = std::abs(arc.sweep);
    const double lens = 0.5 * arc.radius * arc.radius * (theta - std::sin(theta));
    area += s.bulge > 0 ? lens : -lens;
  }
  return area;
}

void parityCrossings(const Segment& s, double y, std::vector<double>& out) {
  // The chord, by the half-open rule so a vertex on the line is counted once.
  if ((s.a.h > y) != (s.b.h > y))
    out.push_back(s.a.r + (y - s.a.h) * (s.b.r - s.a.r) / (s.b.h - s.a.h));
  if (!isArc(s)) return;
  // The lens (disc on the arc's side of the chord) cuts the line in one interval; its two ends
  // toggle the parity of every point inside it.
  // Roots in coordinates about the chord midpoint m, where |c - m|^2 - R^2 = -(chord / 2)^2 exactly:
  // no cancellation for nearly straight arcs (huge R), the smaller root from the product of roots.
  const ArcGeometry arc = arcGeometry(s);
  const Point2 d = sub(s.b, s.a);
  const Point2 m = scale(add(s.a, s.b), 0.5);
  const Point2 c = sub(arc.centre, m);
  const double yl = y - m.h;
  const double k = -0.25 * dot(d, d) + yl * yl - 2.0 * yl * c.h;  // x^2 - 2 c.r x + k = 0
  const double disc = c.r * c.r - k;
  if (disc <= 0) return;
  const double big = c.r + std::copysign(std::sqrt(disc), c.r);
  const double small = big != 0 ? k / big : 0.0;
  double lo = m.r + std::min(big, small), hi = m.r + std::max(big, small);
  const double arcSide = s.bulge > 0 ? -1.0 : 1.0;  // sign of cross(d, q - a) on the arc's side
  // cross(d, (x - a.r, y - a.h)) = d.r (y - a.h) - d.h (x - a.r): linear in x.
  if (d.h == 0) {
    // A horizontal chord: the lens lies wholly above or below its row. On the chord's own row the
    // half-open rule of the chords (the line read as y + e) decides: the lens counts there when the
    // arc bulges upwards.
    const double side = y - s.a.h;
    if (side == 0 ? arcSide * d.r <= 0 : arcSide * d.r * side <= 0) return;
  } else {
    const double x0 = s.a.r + d.r * (y - s.a.h) / d.h;
    if (arcSide * -d.h > 0) lo = std::max(lo, x0);
    else hi = std::min(hi, x0);
  }
  if (lo < hi) {
    out.push_back(lo);
    out.push_back(hi);
  }
}

bool insideProfile(const Profile& profile, Point2 p) {
  std::vector<double> crossings;
  for (const Contour& contour : profile.contours)
    for (const Segment& s : contour.segments) parityCrossings(s, p.h, crossings);
  int right = 0;
  for (double x : crossings) right += x > p.r ? 1 : 0;
  return (right & 1) != 0;
}

void flattenSegment(const Segment& s, double tolerance, std::vector<Point2>& out) {
  if (!isArc(s)) {
    out.push_back(s.b);
    return;
  }
  const ArcGeometry arc = arcGeometry(s);
  // A chord of angle step D stays within R (1 - cos(D / 2)) of the arc.
  double step = std::numbers::pi / 8;
  if (tolerance < arc.radius) step = std::min(step, 2.0 * std::acos(1.0 - tolerance / arc.radius));
  const int n = std::max(1, int(std::ceil(std::abs(arc.sweep) / step)));
  for (int k = 1; k < n; ++k) out.push_back(pointAt(s, double(k) / n));
  out.push_back(s.b);
}

namespace {

void intersectLines(const Segment& s, const Segment& t, double tol, PieceIntersections& result) {
  const Point2 r = sub(s.b, s.a), q = sub(t.b, t.a);
  const double lr = length(r), lq = length(q);
  const double denom = cross(r, q);
  const Point2 ca = sub(t.a, s.a);
  if (std::abs(denom) <= 1e-12 * lr * lq) {
    if (std::abs(cross(ca, r)) > tol * lr) return;  // parallel, apart
    const double ta = dot(ca, r) / (lr * lr), tb = dot(sub(t.b, s.a), r) / (lr * lr);
    const double lo = std::max(0.0, std::min(ta, tb)), hi = std::min(1.0, std::max(ta, tb));
    if ((hi - lo) * lr > tol) {
      result.overlap = true;
      result.overlapPoint = add(s.a, scale(r, 0.5 * (lo + hi)));
    } else if ((hi - lo) * lr >= -tol) {
      result.points.push_back(add(s.a, scale(r, std::clamp(lo, 0.0, 1.0))));
    }
    return;
  }
  const double u = cross(ca, q) / denom, v = cross(ca, r) / denom;
  const double eu = tol / lr, ev = tol / lq;
  if (u >= -eu && u <= 1 + eu && v >= -ev && v <= 1 + ev) result.points.push_back(add(s.a, scale(r, u)));
}

void intersectLineArc(const Segment& line, const Segment& arcPiece, double tol, PieceIntersections& result) {
  const ArcGeometry arc = arcGeometry(arcPiece);
  const Point2 r = sub(line.b, line.a);
  const Point2 f = sub(line.a, arc.centre);
  const double a = dot(r, r), b = 2 * dot(f, r), c = dot(f, f) - arc.radius * arc.radius;
  double disc = b * b - 4 * a * c;
  if (disc < 0) {
    // Tangent within the tolerance still touches.
    const double lineDistance = std::abs(cross(f, r)) / std::sqrt(a);
    if (lineDistance - arc.radius > tol) return;
    disc = 0;
  }
  const double root = std::sqrt(disc);
  const double eu = tol / std::sqrt(a), slack = tol / arc.radius;
  const double roots[2] = {(-b - root) / (2 * a), (-b + root) / (2 * a)};
  for (int k = 0; k < (root > 0 ? 2 : 1); ++k) {
    const double u = roots[k];
    if (u < -eu || u > 1 + eu) continue;
    const Point2 p = add(line.a, scale(r, u));
    if (angleOnArc(arc, angleOf(sub(p, arc.centre)), slack)) result.points.push_back(p);
  }
}

void intersectArcs(const Segment& s, const Segment& t, double tol, PieceIntersections& result) {
  const ArcGeometry p = arcGeometry(s), q = arcGeometry(t);
  const Point2 between = sub(q.centre, p.centre);
  const double d = length(between);
  const double slackP = tol / p.radius, slackQ = tol / q.radius;
  if (d <= tol && std::abs(p.radius - q.radius) <= tol) {
    // One circle: they overlap when a point strictly inside one sweep lies on the other.
    const Point2 probes[6] = {pointAt(s, 0.5), pointAt(t, 0.5), s.a, s.b, t.a, t.b};
    for (int k = 0; k < 6; ++k) {
      const bool onP = angleOnArc(p, angleOf(sub(probes[k], p.centre)), k < 2 || k >= 4 ? -slackP : slackP);
      const bool onQ = angleOnArc(q, angleOf(sub(probes[k], q.centre)), k < 4 ? -slackQ : slackQ);
      if (onP && onQ) {
        result.overlap = true;
        result.overlapPoint = probes[k];
        return;
      }
    }
    return;
  }
  if (d == 0 || d > p.radius + q.radius + tol || d < std::abs(p.radius - q.radius) - tol) return;
  const double along = (p.radius * p.radius - q.radius * q.radius + d * d) / (2 * d);
  const double across = std::sqrt(std::max(0.0, p.radius * p.radius - along * along));
  const Point2 axis = scale(between, 1.0 / d);
  const Point2 foot = add(p.centre, scale(axis, along));
  const Point2 normal{-axis.h, axis.r};
  const Point2 candidates[2] = {add(foot, scale(normal, across)), sub(foot, scale(normal, across))};
  for (int k = 0; k < (across > tol ? 2 : 1); ++k) {
    const Point2 x = candidates[k];
    if (angleOnArc(p, angleOf(sub(x, p.centre)), slackP) && angleOnArc(q, angleOf(sub(x, q.centre)), slackQ))
      result.points.push_back(x);
  }
}

}  // namespace

PieceIntersections intersectPieces(const Segment& s, const Segment& t, double tolerance) {
  PieceIntersections result;
  if (!isArc(s) && !isArc(t)) intersectLines(s, t, tolerance, result);
  else if (!isArc(s)) intersectLineArc(s, t, tolerance, result);
  else if (!isArc(t)) intersectLineArc(t, s, tolerance, result);
  else intersectArcs(s, t, tolerance, result);
  return result;
}

}  // namespace bake::revolution
