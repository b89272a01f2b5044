// Geometry of the profile's pieces shared by validation, distance, sign and coverage: a straight
// segment or a circular arc given by its bulge (tan of a quarter of the sweep, positive
// counter-clockwise). An arc's centre lies on the chord's perpendicular bisector at
// c(1 - b^2) / (4b) to the left of the chord (c the chord length); its radius is c(1 + b^2) / (4|b|).
// Inside tests use the chord-and-lens identity: a ray crosses an arc an odd number of times exactly
// when it crosses the chord an odd number of times XOR its origin lies in the lens between chord and
// arc, so the even-odd rule needs no arc-ray root finding.
#pragma once

#include <vector>

#include "bake/revolution/profile.h"

namespace bake::revolution {

struct ArcGeometry {
  Point2 centre;
  double radius = 0;
  double startAngle = 0;  // angle of `a` seen from the centre
  double sweep = 0;       // signed: positive counter-clockwise
};

bool isArc(const Segment& s);
ArcGeometry arcGeometry(const Segment& s);
// True when `angle` lies on the arc's sweep, widened by `slack` radians at both ends.
bool angleOnArc(const ArcGeometry& arc, double angle, double slack = 0);

// Nearest point of the piece to p.
Point2 closestPoint(const Segment& s, Point2 p);
// Distance from p to the piece and the unit direction from its nearest point towards p (meaningless
// at distance 0). For arcs it avoids the cancellation of |p - c| - R when the radius is huge
// (nearly straight arcs): |p - c|^2 - R^2 = |p - a|^2 + 2 (p - a).(a - c), as |a - c| = R.
struct PieceDistance {
  double distance = 0;
  Point2 away{1, 0};
};
PieceDistance distanceToPiece(const Segment& s, Point2 p);

// Point at parameter t in [0, 1] (by sweep for arcs), and the unit tangent there.
Point2 pointAt(const Segment& s, double t);
Point2 tangentAt(const Segment& s, double t);

// Axis-aligned box of the piece (arcs include their extreme points).
void segmentBox(const Segment& s, Point2& lo, Point2& hi);

// Signed area the piece adds to its contour's area (shoelace term of the chord plus the signed area
// of the circular segment between chord and arc); positive for counter-clockwise contours.
double areaTerm(const Segment& s);

// Crossing points of the horizontal line h = y that toggle the even-odd parity: a point p on the
// line is inside iff an odd number of the points pushed (over all pieces) lie to the right of p.r.
void parityCrossings(const Segment& s, double y, std::vector<double>& out);
// Even-odd test of p over every piece of every contour (axis pieces included).
bool insideProfile(const Profile& profile, Point2 p);

// Points along the piece (excluding `a`, including `b`) whose polyline is within `tolerance` of it.
void flattenSegment(const Segment& s, double tolerance, std::vector<Point2>& out);

// Intersections of two pieces; `overlap` is set when they share a stretch of positive length.
struct PieceIntersections {
  std::vector<Point2> points;
  bool overlap = false;
  Point2 overlapPoint;
};
PieceIntersections intersectPieces(const Segment& s, const Segment& t, double tolerance);

}  // namespace bake::revolution
