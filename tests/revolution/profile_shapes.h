// Profiles with known answers for the revolution tests: circles, rectangles, a half-disc (a sphere
// once revolved) and a vase with arcs, plus independent references built by dense sampling.
#pragma once

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "bake/revolution/profile.h"

namespace bake::revolution::test {

// A contour through `points`; bulges[i] belongs to the piece leaving points[i] (missing: straight).
inline Contour makeContour(const std::vector<Point2>& points, const std::vector<double>& bulges, bool closed) {
  Contour contour;
  contour.closed = closed;
  const std::size_t n = points.size();
  const std::size_t pieces = closed ? n : n - 1;
  for (std::size_t i = 0; i < pieces; ++i) {
    Segment s;
    s.a = points[i];
    s.b = points[(i + 1) % n];
    s.bulge = i < bulges.size() ? bulges[i] : 0.0;
    contour.segments.push_back(s);
  }
  return contour;
}

inline Profile makeProfile(std::vector<Contour> contours) {
  Profile profile;
  profile.contours = std::move(contours);
  profile.source = "test.json";
  return profile;
}

// Circle of radius `radius` about (cr, ch), counter-clockwise, from `arcs` equal arcs.
inline Contour circleContour(double cr, double ch, double radius, int arcs) {
  std::vector<Point2> points;
  std::vector<double> bulges;
  for (int k = 0; k < arcs; ++k) {
    const double angle = 2 * std::numbers::pi * k / arcs;
    points.push_back({cr + radius * std::cos(angle), ch + radius * std::sin(angle)});
    bulges.push_back(std::tan(2 * std::numbers::pi / arcs / 4));
  }
  return makeContour(points, bulges, true);
}

inline Contour rectangleContour(double r0, double h0, double r1, double h1) {
  return makeContour({{r0, h0}, {r1, h0}, {r1, h1}, {r0, h1}}, {}, true);
}

// Open half circle from (0, -R) through (R, 0) to (0, R): closed by the axis, a sphere.
inline Contour halfDiscContour(double radius) { return makeContour({{0, -radius}, {0, radius}}, {1.0}, false); }

// A vase: foot, belly (convex arc), neck (concave arc), lip; open, closed by the axis.
inline Contour vaseContour() {
  return makeContour({{0, 0}, {0.6, 0}, {0.7, 0.1}, {0.8, 1.0}, {0.45, 1.5}, {0.5, 1.9}, {0.55, 2.0}, {0, 2.0}},
                     {0.0, 0.0, 0.35, 0.0, -0.3, 0.0, 0.0}, false);
}

// Signed distance of an axis-aligned box.
inline double boxDistance(double r, double h, double r0, double h0, double r1, double h1) {
  const double cr = 0.5 * (r0 + r1), ch = 0.5 * (h0 + h1);
  const double qx = std::abs(r - cr) - 0.5 * (r1 - r0), qy = std::abs(h - ch) - 0.5 * (h1 - h0);
  const double outside = std::hypot(std::max(qx, 0.0), std::max(qy, 0.0));
  return outside + std::min(std::max(qx, qy), 0.0);
}

// Dense polyline of the surface pieces (axis pieces left out) and the closed polygon of all pieces,
// sampled by angle / length independently of the library's flattening.
struct DenseProfile {
  std::vector<Point2> surface;
  std::vector<std::vector<Point2>> polygons;
};

inline Point2 densePoint(const Segment& s, double t) {
  if (s.bulge == 0) return {s.a.r + t * (s.b.r - s.a.r), s.a.h + t * (s.b.h - s.a.h)};
  // Arc through a and b with sweep 4 atan(bulge): rotate a about the centre.
  const double sweep = 4 * std::atan(s.bulge);
  const double dx = s.b.r - s.a.r, dy = s.b.h - s.a.h, chord = std::hypot(dx, dy);
  const double radius = chord / (2 * std::sin(std::abs(sweep) / 2));
  const double mr = 0.5 * (s.a.r + s.b.r), mh = 0.5 * (s.a.h + s.b.h);
  const double toCentre = std::sqrt(std::max(0.0, radius * radius - 0.25 * chord * chord));
  // Centre to the left of a->b for |sweep| < pi with positive sweep (counter-clockwise travel).
  double side = (sweep > 0) == (std::abs(sweep) < std::numbers::pi) ? 1.0 : -1.0;
  const double cr = mr - side * toCentre * dy / chord, ch = mh + side * toCentre * dx / chord;
  const double start = std::atan2(s.a.h - ch, s.a.r - cr);
  const double angle = start + t * sweep;
  return {cr + radius * std::cos(angle), ch + radius * std::sin(angle)};
}

inline DenseProfile densify(const Profile& profile, int samplesPerPiece) {
  DenseProfile dense;
  for (const Contour& contour : profile.contours) {
    std::vector<Point2> polygon;
    for (const Segment& s : contour.segments)
      for (int k = 0; k < samplesPerPiece; ++k) {
        const Point2 p = densePoint(s, double(k) / samplesPerPiece);
        polygon.push_back(p);
        if (!s.onAxis) dense.surface.push_back(p);
      }
    for (const Segment& s : contour.segments)
      if (!s.onAxis) dense.surface.push_back(s.b);
    dense.polygons.push_back(polygon);
  }
  return dense;
}

inline bool denseInside(const DenseProfile& dense, Point2 p) {
  bool inside = false;
  for (const auto& polygon : dense.polygons)
    for (std::size_t k = 0, n = polygon.size(); k < n; ++k) {
      const Point2 a = polygon[k], b = polygon[(k + 1) % n];
      if ((a.h > p.h) != (b.h > p.h) && p.r < a.r + (p.h - a.h) * (b.r - a.r) / (b.h - a.h)) inside = !inside;
    }
  return inside;
}

// Distance to the dense samples of the surface (an overestimate by at most half the spacing).
inline double denseDistance(const DenseProfile& dense, Point2 p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Point2& q : dense.surface) best = std::min(best, (p.r - q.r) * (p.r - q.r) + (p.h - q.h) * (p.h - q.h));
  return std::sqrt(best);
}

}  // namespace bake::revolution::test
