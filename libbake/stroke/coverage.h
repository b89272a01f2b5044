// Exact box-filtered coverage for the paintstroke rasterizer. A unit pixel square seen along a unit
// direction n = (nx, ny) projects onto the line of n as a trapezoid: the convolution of two boxes of
// widths a = max(|nx|, |ny|) and b = min(|nx|, |ny|), of unit area. The area of the pixel that lies in a
// straight band {lo <= (p - c).n <= hi} is therefore W(hi - d) - W(lo - d), with d the pixel centre's
// offset and W the trapezoid's cumulative distribution; a linear ink density across the band needs the
// first moment M of the trapezoid too. Because the pixels tile the plane, the ink so computed sums over
// any row of pixels to exactly the band's width times its density, at every angle and sub-pixel offset:
// this is what keeps thin strokes from losing or gaining ink (the point-sampled "clamp(0.5 - distance)"
// rule does not). The end discs use the exact area of a disc inside an axis-aligned square, from the
// integral of the circle's chord (area = x y inside the circle, else a circular segment).
#pragma once

#include <algorithm>
#include <cmath>

namespace bake::stroke::detail {

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
    if (v > 0) return 1 - cdf(-v);
    if (v < -k_) {
      const double s = v + h_;
      return 0.5 * s * s * invAB_;
    }
    return 0.5 * b_ * invA_ + (v + k_) * invA_;
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
    return 0.5 * (t * std::sqrt(std::max(0.0, r * r - t * t)) + r * r * std::asin(std::clamp(t / r, -1.0, 1.0)));
  };
  return sign * (y * t0 + chord(x) - chord(t0));
}

// Area of the disc of radius r centred at (cx, cy) inside the pixel whose centre is (px, py).
inline double discInPixel(double px, double py, double cx, double cy, double r) {
  if (!(r > 0)) return 0;
  const double dist = std::sqrt((px - cx) * (px - cx) + (py - cy) * (py - cy));
  constexpr double kHalfDiagonal = 0.70710678118654757;
  if (dist >= r + kHalfDiagonal) return 0;
  if (dist + kHalfDiagonal <= r) return 1;
  if (r > 64) return std::clamp(0.5 + r - dist, 0.0, 1.0);  // the area differences would lose precision
  const double x0 = px - 0.5 - cx, x1 = px + 0.5 - cx, y0 = py - 0.5 - cy, y1 = py + 0.5 - cy;
  const double area = discQuadrant(x1, y1, r) - discQuadrant(x0, y1, r) - discQuadrant(x1, y0, r) + discQuadrant(x0, y0, r);
  return std::clamp(area, 0.0, 1.0);
}

}  // namespace bake::stroke::detail
