// Paths to primitives (formats/groove-scene.md "Flattening"). Segments and circular arcs are kept
// exactly, as the seed keeps its primitives (seed 000 §3.1). Spirals and Béziers are flattened into
// circular arcs by recursive subdivision: each parameter interval is replaced by the arc through its
// start, middle and end points (a segment when these are collinear), and split in two while that arc
// deviates from the curve by more than 0.9 x the tolerance at any of 15 interior samples, or turns by more
// than 45 degrees. Pieces of one flattened curve meet G1 (no corner); the local radius of curvature
// is checked at every piece's ends and middle against the groove's half-width.
#include <algorithm>
#include <cstdio>
#include <cmath>
#include <functional>
#include <numbers>

#include "bake/core/limits.h"
#include "bake/core/vector_text.h"
#include "bake/core/vec.h"
#include "grooves/input/scene.h"

namespace bake::grooves {
namespace {

using planar::cross;
using planar::length;

std::string showPoint(Vec2 p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.9g, %.9g)", p.u, p.v);
  return text;
}

// A parametric curve on t in [0, 1] with its first and second derivatives.
struct Curve {
  std::function<Vec2(double)> f, d1, d2;
};

Curve curveOf(const PathPiece& piece) {
  Curve c;
  if (piece.kind == PathPiece::Kind::Spiral) {
    // Archimedean: r(theta) = r0 + b theta, b = pitch / (2 pi), theta = sweep t.
    const double r0 = piece.radius, b = piece.pitch / (2 * kPi), s = piece.sweep, a0 = piece.startAngle;
    const Vec2 o = piece.centre;
    // Radius along the sweep's direction of travel: the pitch is per turn, whatever the sense.
    c.f = [=](double t) {
      const double th = s * t, r = r0 + b * std::abs(th);
      return o + Vec2{r * std::cos(a0 + th), r * std::sin(a0 + th)};
    };
    c.d1 = [=](double t) {
      const double th = s * t, r = r0 + b * std::abs(th), sg = s < 0 ? -1.0 : 1.0;
      return s * Vec2{sg * b * std::cos(a0 + th) - r * std::sin(a0 + th), sg * b * std::sin(a0 + th) + r * std::cos(a0 + th)};
    };
    c.d2 = [=](double t) {
      const double th = s * t, r = r0 + b * std::abs(th), sg = s < 0 ? -1.0 : 1.0;
      return (s * s) * Vec2{-2 * sg * b * std::sin(a0 + th) - r * std::cos(a0 + th),
                            2 * sg * b * std::cos(a0 + th) - r * std::sin(a0 + th)};
    };
  } else if (piece.kind == PathPiece::Kind::Quadratic) {
    const Vec2 p0 = piece.p[0], p1 = piece.p[1], p2 = piece.p[2];
    c.f = [=](double t) { return (1 - t) * (1 - t) * p0 + 2 * (1 - t) * t * p1 + t * t * p2; };
    c.d1 = [=](double t) { return 2 * (1 - t) * (p1 - p0) + 2 * t * (p2 - p1); };
    c.d2 = [=](double) { return 2 * (p2 - 2 * p1 + p0); };
  } else {
    const Vec2 p0 = piece.p[0], p1 = piece.p[1], p2 = piece.p[2], p3 = piece.p[3];
    c.f = [=](double t) {
      const double s = 1 - t;
      return s * s * s * p0 + 3 * s * s * t * p1 + 3 * s * t * t * p2 + t * t * t * p3;
    };
    c.d1 = [=](double t) { return 3 * (1 - t) * (1 - t) * (p1 - p0) + 6 * (1 - t) * t * (p2 - p1) + 3 * t * t * (p3 - p2); };
    c.d2 = [=](double t) { return 6 * (1 - t) * (p2 - 2 * p1 + p0) + 6 * t * (p3 - 2 * p2 + p1); };
  }
  return c;
}

// The primitive through a, m, b: an arc, or a segment when the three are (nearly) collinear.
Primitive primitiveThrough(Vec2 a, Vec2 m, Vec2 b) {
  Primitive p;
  p.a = a;
  p.b = b;
  const double chord = length(b - a);
  const double area = cross(m - a, b - a);
  if (chord == 0 || std::abs(area) <= 1e-12 * chord * chord) {
    p.kind = Primitive::Kind::Segment;
    p.length = chord;
    return p;
  }
  // Circumcentre of a, m, b.
  const Vec2 ab = b - a, am = m - a;
  const double d = 2 * cross(am, ab);
  const double am2 = am.u * am.u + am.v * am.v, ab2 = ab.u * ab.u + ab.v * ab.v;
  const Vec2 c = a + Vec2{(ab.v * am2 - am.v * ab2) / d, (am.u * ab2 - ab.u * am2) / d};
  p.kind = Primitive::Kind::Arc;
  p.centre = c;
  p.radius = length(a - c);
  p.startAngle = std::atan2(a.v - c.v, a.u - c.u);
  double delta = std::atan2(b.v - c.v, b.u - c.u) - p.startAngle;
  const bool ccw = area > 0;  // m right of the chord a->b: the centre is on the left, counter-clockwise
  if (ccw) {
    while (delta <= 0) delta += 2 * kPi;
  } else {
    while (delta >= 0) delta -= 2 * kPi;
  }
  p.sweep = delta;
  p.length = p.radius * std::abs(delta);
  return p;
}

double distanceTo(const Primitive& p, Vec2 q) {
  if (p.kind == Primitive::Kind::Arc) return std::abs(length(q - p.centre) - p.radius);
  const Vec2 ab = p.b - p.a;
  const double len2 = ab.u * ab.u + ab.v * ab.v;
  double t = len2 > 0 ? ((q.u - p.a.u) * ab.u + (q.v - p.a.v) * ab.v) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return length(q - (p.a + t * ab));
}

struct Flattener {
  const Curve& curve;
  double tolerance;
  double minRadius;
  std::size_t firstOfGroove;
  const std::string& label;
  const std::string& source;
  std::vector<Primitive>& out;

  Status checkCurvature(double t) const {
    const Vec2 d1 = curve.d1(t), d2 = curve.d2(t);
    const double speed = length(d1);
    const double k = std::abs(cross(d1, d2));
    if (speed == 0) return Status::ok();  // a cusp of zero speed is caught as a corner-free point
    const double radius = speed * speed * speed / k;
    if (k > 0 && radius < minRadius)
      return invalidInput(label + ": segment " + std::to_string(out.size() - firstOfGroove) + " at " +
                              showPoint(curve.f(t)) + ": radius of curvature " + std::to_string(radius) +
                              " is smaller than the groove's half-width " + std::to_string(minRadius),
                          {source, ""});
    return Status::ok();
  }

  Status run(double t0, double t1, int depth) {
    const double tm = 0.5 * (t0 + t1);
    const Vec2 a = curve.f(t0), m = curve.f(tm), b = curve.f(t1);
    Primitive p = primitiveThrough(a, m, b);
    bool fits = depth >= 40 || (p.kind == Primitive::Kind::Segment || std::abs(p.sweep) <= kPi / 4);
    // 15 samples against 90% of the tolerance: the deviation between samples stays within it.
    for (int i = 1; fits && i < 16 && depth < 40; ++i)
      if (distanceTo(p, curve.f(t0 + (t1 - t0) * i / 16.0)) > 0.9 * tolerance) fits = false;
    if (!fits || depth < 2) {
      BAKE_RETURN_IF_ERROR(run(t0, tm, depth + 1));
      return run(tm, t1, depth + 1);
    }
    BAKE_RETURN_IF_ERROR(checkCurvature(t0));
    BAKE_RETURN_IF_ERROR(checkCurvature(tm));
    BAKE_RETURN_IF_ERROR(checkCurvature(t1));
    // A curve far longer than the tolerance allows (a spiral of astronomic radius) would otherwise
    // split down to 2^40 pieces.
    if (out.size() >= budgets().primitives) {
      const Status fits = checkBudget(Budget::Primitives, out.size() + 1, "primitives after flattening", {});
      return invalidInput(label + ": " + fits.message(), {source, ""});
    }
    p.cornerAtStart = false;  // G1 inside one curve
    out.push_back(p);
    return Status::ok();
  }
};

}  // namespace

Vec2 Primitive::pointAt(double t) const {
  if (kind == Kind::Segment) return a + t * (b - a);
  const double angle = startAngle + sweep * t;
  return centre + Vec2{radius * std::cos(angle), radius * std::sin(angle)};
}

Vec2 Primitive::tangentAt(double t) const {
  if (kind == Kind::Segment) {
    const Vec2 d = b - a;
    const double len = std::sqrt(d.u * d.u + d.v * d.v);  // a validated scene's extent: no overflow
    return len > 0 ? (1 / len) * d : Vec2{};
  }
  const double angle = startAngle + sweep * t, s = sweep < 0 ? -1.0 : 1.0;
  return {-s * std::sin(angle), s * std::cos(angle)};
}

Status flattenPath(const std::vector<PathPiece>& pieces, double tolerance, double minRadius, std::size_t grooveIndex,
                   const std::string& label, const std::string& source, std::vector<Primitive>& out) {
  const std::size_t first = out.size();
  Vec2 previousEnd;  // the previous piece's exact end tangent
  for (const PathPiece& piece : pieces) {
    const std::size_t before = out.size();
    Vec2 startTangent, endTangent;
    const std::string segment = "segment " + std::to_string(before - first);
    // Arcs split into pieces of at most 90 degrees, spirals flatten into arcs of at most 45: a sweep of
    // a billion turns is refused before any piece is made.
    if (piece.kind == PathPiece::Kind::Arc || piece.kind == PathPiece::Kind::Spiral) {
      const double least = std::ceil(std::abs(piece.sweep) / (piece.kind == PathPiece::Kind::Arc ? 0.5 * kPi : 0.25 * kPi));
      const std::uint64_t count = least < 1e18 ? std::uint64_t(least) : std::uint64_t(1e18);
      const Status fits = checkBudget(Budget::Primitives, out.size() + count, "primitives after flattening", {});
      if (!fits.isOk()) return invalidInput(label + ": " + segment + ": " + fits.message(), {source, ""});
    }
    if (piece.kind == PathPiece::Kind::Line) {
      Primitive p;
      p.a = piece.p[0];
      p.b = piece.p[1];
      p.length = length(p.b - p.a);
      if (!(p.length > 0))
        return invalidInput(label + ": " + segment + " at " + showPoint(p.a) + ": zero-length segment", {source, ""});
      startTangent = endTangent = p.tangentAt(0);
      out.push_back(p);
    } else if (piece.kind == PathPiece::Kind::Arc) {
      Primitive p;
      p.kind = Primitive::Kind::Arc;
      p.centre = piece.centre;
      p.radius = piece.radius;
      p.startAngle = piece.startAngle;
      p.sweep = piece.sweep;
      p.a = p.pointAt(0);
      p.b = p.pointAt(1);
      p.length = p.radius * std::abs(p.sweep);
      if (!(p.length > 0))
        return invalidInput(label + ": " + segment + " at " + showPoint(p.a) + ": zero-length arc", {source, ""});
      if (p.radius < minRadius)
        return invalidInput(label + ": " + segment + " at " + showPoint(p.a) + ": arc radius " + std::to_string(p.radius) +
                                " is smaller than the groove's half-width " + std::to_string(minRadius),
                            {source, ""});
      startTangent = p.tangentAt(0);
      endTangent = p.tangentAt(1);
      // Arcs are kept exact but split into equal pieces of at most 90 degrees (G1 joints), so that a
      // primitive's region is always bounded by the half-planes of its two end joints.
      const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(p.sweep) / (0.5 * kPi) - 1e-9)));
      for (int k = 0; k < pieces; ++k) {
        Primitive part = p;
        part.startAngle = p.startAngle + p.sweep * k / pieces;
        part.sweep = p.sweep / pieces;
        part.a = part.pointAt(0);
        part.b = part.pointAt(1);
        part.length = p.length / pieces;
        out.push_back(part);
      }
    } else {
      const Curve curve = curveOf(piece);
      double roughLength = 0;  // to refuse degenerate curves
      double magnitude = 0;  // largest coordinate, against the tolerance below
      for (int i = 0; i < 64; ++i) {
        roughLength += length(curve.f((i + 1) / 64.0) - curve.f(i / 64.0));
        magnitude = std::max({magnitude, std::abs(curve.f(i / 64.0).u), std::abs(curve.f(i / 64.0).v)});
      }
      if (!(roughLength > 0))
        return invalidInput(label + ": " + segment + " at " + showPoint(curve.f(0)) + ": zero-length curve", {source, ""});
      // Doubles carry about 16 digits: deviations below 1e-10 of the coordinates are rounding noise,
      // and a curve that far out would only split until the depth limit.
      if (!(tolerance >= 1e-10 * magnitude))
        return invalidInput(label + ": " + segment + " at " + showPoint(curve.f(0)) + ": coordinates as large as " +
                                numberText(magnitude) + " cannot be flattened to within " + numberText(tolerance),
                            {source, ""});
      Flattener flattener{curve, tolerance, minRadius, first, label, source, out};
      BAKE_RETURN_IF_ERROR(flattener.run(0, 1, 0));
      // The curve's own end tangents decide the joints (a Bezier may have a zero derivative at an
      // end: the flattened piece's tangent stands in then).
      const Vec2 d0 = curve.d1(0), d1 = curve.d1(1);
      startTangent = length(d0) > 0 ? (1 / length(d0)) * d0 : out[before].tangentAt(0);
      endTangent = length(d1) > 0 ? (1 / length(d1)) * d1 : out.back().tangentAt(1);
    }
    // The joint with the previous piece: a corner when the tangent turns (polyline vertices).
    if (before > first) {
      const Vec2 t0 = previousEnd, t1 = startTangent;
      out[before].cornerAtStart = std::abs(std::atan2(cross(t0, t1), t0.u * t1.u + t0.v * t1.v)) > 1e-6;
    }
    previousEnd = endTangent;
  }
  double s = 0;
  for (std::size_t i = first; i < out.size(); ++i) {
    out[i].groove = grooveIndex;
    out[i].arcStart = s;
    s += out[i].length;
  }
  return Status::ok();
}

}  // namespace bake::grooves
