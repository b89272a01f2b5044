// Windows of the exact geodesic propagation (Mitchell, Mount and Papadimitriou 1987; Surazhsky et al.
// 2005, section 3): an interval [b0, b1] on an edge, measured from the edge's first vertex, whose points
// are reached by straight rays from one unfolded pseudo-source. The pseudo-source is stored in the edge's
// frame (first vertex at the origin, the edge along +x) as (sx, sy) with sy >= 0 the distance from the
// edge line, on the side of the face the window came from; it is unfolded into any other face of the
// edge by mirroring it below the edge. sigma is the distance of the pseudo-source from the sources.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

namespace bake::geodesic::exact {

inline constexpr std::uint32_t kNone = 0xffffffffu;

// sqrt(x^2 + y^2) without std::hypot's overflow guards (slow, and lengths here are far from overflow).
inline double length2d(double x, double y) { return std::sqrt(x * x + y * y); }

struct Window {
  double b0 = 0.0, b1 = 0.0;  // interval on the edge
  double sx = 0.0, sy = 0.0;  // pseudo-source in the edge frame, sy >= 0 towards fromFace
  double sigma = 0.0;         // distance of the pseudo-source
  std::uint32_t edge = kNone;
  std::uint32_t fromFace = kNone;  // the face the rays came through; they continue into the others
  // A window's slot is reused once the window is gone (trimmed away or its edge closed); releasing
  // bumps the generation, and queue entries carry the generation they were queued for, so an entry
  // left behind by an earlier occupant is recognised and skipped.
  std::uint32_t generation : 31 = 0;
  std::uint32_t propagated : 1 = 0;

  double distanceAt(double x) const { return sigma + length2d(x - sx, sy); }
  double minDistance() const {
    const double x = std::fmin(std::fmax(sx, b0), b1);
    return distanceAt(x);
  }
};

struct Point2 {
  double x = 0.0, y = 0.0;
};

// A window clipped to one of the two other edges of the face it enters, as a parameter range along
// the segment from `from` (a corner of the window's edge) to the face's third corner.
struct ChildRange {
  bool valid = false;
  double t0 = 0.0, t1 = 0.0;
};

// Rays of window `w` (source mirrored to (sx, -sy)) entering the face whose third corner is `c`
// (c.y >= 0) in the frame of w's edge of length `length`: the ranges they cover on the edges A-C and
// B-C, and whether C itself is reached (the projection of C onto the edge falls inside [b0, b1]).
struct FaceCrossing {
  ChildRange onAC, onBC;
  bool reachesC = false;
};
FaceCrossing crossFace(const Window& w, double length, Point2 c, double tolerance);

// Pseudo-source of a child window on the segment from p to q (edge frame origin at p) given the
// source s in the parent frame: x along p->q, y the distance from that line.
Point2 sourceInFrame(Point2 s, Point2 p, Point2 q);

// Split points where two distance functions over one edge can swap order: up to two roots of
// d_a(x) = d_b(x) strictly inside (lo, hi). Returns the count written to roots (sorted).
int crossingPoints(const Window& a, const Window& b, double lo, double hi, std::array<double, 2>& roots);

}  // namespace bake::geodesic::exact
