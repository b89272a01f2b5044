// Exact box-filtered coverage for the paintstroke rasterizer. A unit pixel square seen along a unit
// direction n = (nx, ny) projects onto the line of n as a trapezoid: the convolution of two boxes of
// widths a = max(|nx|, |ny|) and b = min(|nx|, |ny|), of unit area. The area of the pixel that lies in a
// straight band {lo <= (p - c).n <= hi} is therefore W(hi - d) - W(lo - d), with d the pixel centre's
// offset and W the trapezoid's cumulative distribution; a linear ink density across the band needs the
// first moment M of the trapezoid too. Because the pixels tile the plane, the ink so computed sums over
// any row of pixels to exactly the band's width times its density, at every angle and sub-pixel offset:
// this is what keeps thin strokes from losing or gaining ink (the point-sampled "clamp(0.5 - distance)"
// rule does not). The end discs use the exact area of a disc inside an axis-aligned square, from the
// integral of the circle's chord (area = x y inside the circle, else a circular segment). The round caps
// need the pixel square cut by half-planes (Sutherland-Hodgman on a convex polygon), its area (shoelace)
// and its area inside a disc: the sum over its edges of the disc's signed area in the triangle
// (centre, edge), i.e. the triangle's part inside the circle plus circular sectors where it is outside.
#pragma once

#include <algorithm>
#include <cmath>

namespace bake::stroke::detail {

// Half the diagonal of a unit pixel: no point of a pixel lies farther than this from its centre.
constexpr double kPixelHalfDiagonal = 0.70710678118654757;

class PixelFilter {
 public:
  // n need not be normalised; a zero vector gives the axis-aligned filter.
  PixelFilter(double nx, double ny) {
    const double len = std::hypot(nx, ny);
    double ax = len > 0 ? std::abs(nx) / len : 1, ay = len > 0 ? std::abs(ny) / len : 0;
    a_ = std::max(ax, ay);
    b_ = std::min(ax, ay);
    h_ = 0.5 * (a_ + b_);
    k_ = 0.5 * (a_ - b_);
    invA_ = 1 / a_;
    invAB_ = b_ > 0 ? 1 / (a_ * b_) : 0;
    mk_ = (b_ * b_ / 3 - h_ * b_ / 2) * invA_;
  }

  double halfWidth() const { return h_; }

  // The fraction of the pixel at offsets below v (the trapezoid's distribution).
  double cdf(double v) const {
    if (v <= -h_) return 0;
    if (v >= h_) return 1;
    return v > 0 ? 1 - lowerHalf(-v) : lowerHalf(v);  // symmetric about 0; no recursion, so it inlines
  }

  // The trapezoid's first moment below v, integral of t w(t) dt (even in v, never positive).
  double moment(double v) const {
    const double u = -std::abs(v);
    if (u <= -h_) return 0;
    if (u < -k_) {
      const double s = u + h_;
      return (s * s * s / 3 - h_ * s * s / 2) * invAB_;
    }
    return mk_ + 0.5 * (u * u - k_ * k_) * invA_;
  }

  // The pixel's ink from a band of half-width r whose density is `centre` on its centreline and goes
  // linearly to `edge` at |offset| = r; d is the pixel centre's offset from the centreline.
  double band(double d, double r, double centre, double edge) const {
    if (std::abs(d) >= r + h_) return 0;
    if (centre == edge) {
      if (std::abs(d) + h_ <= r) return centre;
      return centre * (cdf(r - d) - cdf(-r - d));
    }
    const double slope = (edge - centre) / r;
    // [0, r]: density centre + slope u; [-r, 0]: centre - slope u; with u = v + d.
    const double right = (centre + slope * d) * (cdf(r - d) - cdf(-d)) + slope * (moment(r - d) - moment(-d));
    const double left = (centre - slope * d) * (cdf(-d) - cdf(-r - d)) - slope * (moment(-d) - moment(-r - d));
    return std::max(0.0, right + left);
  }

 private:
  // cdf on (-h, 0]: the quadratic corner, then the linear middle.
  double lowerHalf(double v) const {
    if (v < -k_) {
      const double s = v + h_;
      return 0.5 * s * s * invAB_;
    }
    return 0.5 * b_ * invA_ + (v + k_) * invA_;
  }

  double a_, b_, h_, k_, invA_, invAB_, mk_;
};

// Area of the disc of radius r centred at the origin inside [0, x] x [0, y], signed by the quadrant.
inline double discQuadrant(double x, double y, double r) {
  const double sign = (x < 0) != (y < 0) ? -1 : 1;
  x = std::min(std::abs(x), r);
  y = std::min(std::abs(y), r);
  if (x * x + y * y <= r * r) return sign * x * y;
  // Columns t < t0 are cut by y, the rest by the circle: area = y t0 + S(x) - S(t0),
  // S(t) = integral of sqrt(r^2 - t^2) = (t sqrt(r^2 - t^2) + r^2 asin(t / r)) / 2.
  const double t0 = std::sqrt(std::max(0.0, r * r - y * y));
  auto chord = [r](double t) {
    // t = r (a corner beyond the disc's square) and t = 0 need no inverse sine: asin(1) is the double
    // nearest pi/2 and asin(0) is 0, so these are the general formula's values bit for bit.
    if (t == r) return 0.5 * (r * r * 1.5707963267948966);
    if (t == 0) return 0.0;
    return 0.5 * (t * std::sqrt(std::max(0.0, r * r - t * t)) + r * r * std::asin(std::clamp(t / r, -1.0, 1.0)));
  };
  return sign * (y * t0 + chord(x) - chord(t0));
}

// Area of the disc of radius r centred at (cx, cy) inside the pixel whose centre is (px, py).
inline double discInPixel(double px, double py, double cx, double cy, double r) {
  if (!(r > 0)) return 0;
  const double dist = std::sqrt((px - cx) * (px - cx) + (py - cy) * (py - cy));
  if (dist >= r + kPixelHalfDiagonal) return 0;
  if (dist + kPixelHalfDiagonal <= r) return 1;
  if (r > 64) return std::clamp(0.5 + r - dist, 0.0, 1.0);  // the area differences would lose precision
  const double x0 = px - 0.5 - cx, x1 = px + 0.5 - cx, y0 = py - 0.5 - cy, y1 = py + 0.5 - cy;
  const double area = discQuadrant(x1, y1, r) - discQuadrant(x0, y1, r) - discQuadrant(x1, y0, r) + discQuadrant(x0, y0, r);
  return std::clamp(area, 0.0, 1.0);
}

// A small convex polygon (a pixel square clipped by a few half-planes).
struct Polygon {
  int count = 0;
  double x[8], y[8];
};

// The pixel square centred at (px, py), counter-clockwise in a y-up frame.
inline Polygon pixelSquare(double px, double py) {
  Polygon q;
  q.count = 4;
  const double xs[4] = {-0.5, 0.5, 0.5, -0.5}, ys[4] = {-0.5, -0.5, 0.5, 0.5};
  for (int i = 0; i < 4; ++i) q.x[i] = px + xs[i], q.y[i] = py + ys[i];
  return q;
}

// Keeps the part of q where nx x + ny y <= c (Sutherland-Hodgman against one half-plane).
inline Polygon clip(const Polygon& q, double nx, double ny, double c) {
  Polygon out;
  for (int i = 0; i < q.count; ++i) {
    const int j = (i + 1) % q.count;
    const double fi = nx * q.x[i] + ny * q.y[i] - c, fj = nx * q.x[j] + ny * q.y[j] - c;
    if (fi <= 0) out.x[out.count] = q.x[i], out.y[out.count] = q.y[i], ++out.count;
    if ((fi < 0 && fj > 0) || (fi > 0 && fj < 0)) {
      const double t = fi / (fi - fj);
      out.x[out.count] = q.x[i] + t * (q.x[j] - q.x[i]);
      out.y[out.count] = q.y[i] + t * (q.y[j] - q.y[i]);
      ++out.count;
    }
  }
  return out;
}

inline double area(const Polygon& q) {
  double a = 0;
  for (int i = 0; i < q.count; ++i) {
    const int j = (i + 1) % q.count;
    a += q.x[i] * q.y[j] - q.x[j] * q.y[i];
  }
  return 0.5 * std::abs(a);
}

// Signed area of the disc of radius r at the origin inside the triangle (origin, a, b): the triangle's
// part inside the circle plus circular sectors where the edge ab runs outside it.
inline double discTriangle(double ax, double ay, double bx, double by, double r) {
  auto sector = [r](double ux, double uy, double vx, double vy) {
    return 0.5 * r * r * std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
  };
  auto triangle = [](double ux, double uy, double vx, double vy) { return 0.5 * (ux * vy - uy * vx); };
  const double r2 = r * r;
  const bool aIn = ax * ax + ay * ay <= r2, bIn = bx * bx + by * by <= r2;
  if (aIn && bIn) return triangle(ax, ay, bx, by);
  // Where a + t (b - a) crosses the circle: |a + t e|^2 = r^2.
  const double ex = bx - ax, ey = by - ay;
  const double qa = ex * ex + ey * ey, qb = ax * ex + ay * ey, qc = ax * ax + ay * ay - r2;
  const double disc = qb * qb - qa * qc;
  if (!(qa > 0) || disc <= 0) return sector(ax, ay, bx, by);
  const double root = std::sqrt(disc);
  const double t1 = (-qb - root) / qa, t2 = (-qb + root) / qa;
  if (aIn) {  // leaves the circle at t2
    const double px = ax + t2 * ex, py = ay + t2 * ey;
    return triangle(ax, ay, px, py) + sector(px, py, bx, by);
  }
  if (bIn) {  // enters at t1
    const double px = ax + t1 * ex, py = ay + t1 * ey;
    return sector(ax, ay, px, py) + triangle(px, py, bx, by);
  }
  if (t1 >= 1 || t2 <= 0) return sector(ax, ay, bx, by);
  const double p1x = ax + t1 * ex, p1y = ay + t1 * ey, p2x = ax + t2 * ex, p2y = ay + t2 * ey;
  return sector(ax, ay, p1x, p1y) + triangle(p1x, p1y, p2x, p2y) + sector(p2x, p2y, bx, by);
}

// Area of the convex polygon q inside the disc of radius r centred at (cx, cy).
inline double discArea(const Polygon& q, double cx, double cy, double r) {
  if (q.count < 3 || !(r > 0)) return 0;
  double a = 0;
  for (int i = 0; i < q.count; ++i) {
    const int j = (i + 1) % q.count;
    a += discTriangle(q.x[i] - cx, q.y[i] - cy, q.x[j] - cx, q.y[j] - cy, r);
  }
  return std::abs(a);
}

}  // namespace bake::stroke::detail
