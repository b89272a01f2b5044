// A path in a plane as curve pieces (lines, circular arcs, Archimedean spirals, quadratic and cubic
// Béziers): what SVG path data and groove scenes describe, before any flattening.
#pragma once

#include <cmath>

namespace bake::planar {

struct Vec2 {
  double u = 0, v = 0;
};

// The few operations on plane vectors the path code needs, by name and as operators.
inline Vec2 add(Vec2 a, Vec2 b) { return {a.u + b.u, a.v + b.v}; }
inline Vec2 sub(Vec2 a, Vec2 b) { return {a.u - b.u, a.v - b.v}; }
inline Vec2 scaled(double s, Vec2 a) { return {s * a.u, s * a.v}; }
inline Vec2 operator+(Vec2 a, Vec2 b) { return add(a, b); }
inline Vec2 operator-(Vec2 a, Vec2 b) { return sub(a, b); }
inline Vec2 operator*(double s, Vec2 a) { return scaled(s, a); }
inline double dot(Vec2 a, Vec2 b) { return a.u * b.u + a.v * b.v; }
inline double cross(Vec2 a, Vec2 b) { return a.u * b.v - a.v * b.u; }
inline double length(Vec2 a) { return std::hypot(a.u, a.v); }
inline Vec2 lerp(Vec2 a, Vec2 b, double t) { return {a.u + t * (b.u - a.u), a.v + t * (b.v - a.v)}; }
// The tangent turned a quarter counter-clockwise.
inline Vec2 leftNormal(Vec2 t) { return {-t.v, t.u}; }

struct PathPiece {
  enum class Kind { Line, Arc, Spiral, Quadratic, Cubic };
  Kind kind = Kind::Line;
  Vec2 p[4];                 // control points (line: 2, quadratic: 3, cubic: 4; arc: its two ends)
  Vec2 centre;               // arc / spiral
  double radius = 0;         // arc; spiral: start radius
  double startAngle = 0;     // radians
  double sweep = 0;          // arc / spiral: signed angle swept (radians)
  double pitch = 0;          // spiral: radius change per turn
};

}  // namespace bake::planar
