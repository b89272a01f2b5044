// A path in a plane as curve pieces (lines, circular arcs, Archimedean spirals, quadratic and cubic
// Béziers): what SVG path data and groove scenes describe, before any flattening.
#pragma once

namespace bake::planar {

struct Vec2 {
  double u = 0, v = 0;
};

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
