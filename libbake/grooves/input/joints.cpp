// The lines where a primitive's region stops (formats/groove-scene.md, "Region"): the flat cut
// perpendicular to the path at an open end, the mitre line at a joint (its normal is the bisector of
// the two tangents, so at a G1 joint it is the common normal of the two pieces).
#include <cmath>

#include "grooves/bake/grid.h"

namespace bake::grooves {
namespace {

// a is a sum of two unit tangents: no overflow to guard against.
Vec2 unit(Vec2 a) {
  const double n = std::sqrt(a.u * a.u + a.v * a.v);
  return n > 0 ? Vec2{a.u / n, a.v / n} : Vec2{0, 0};
}

// The joint line between `before` (ending there) and `after` (starting there); the normal points
// into `after`'s side.
JointLine mitre(const Primitive& before, const Primitive& after) {
  const Vec2 t1 = before.tangentAt(1), t2 = after.tangentAt(0);
  Vec2 n = unit({t1.u + t2.u, t1.v + t2.v});
  if (n.u == 0 && n.v == 0) n = t2;  // a full reversal: no mitre, cut perpendicular to the new piece
  return {after.a, n, false};
}

JointLine flip(JointLine line) {
  line.normal = {-line.normal.u, -line.normal.v};
  return line;
}

}  // namespace

PrimitiveJoints jointsOf(const GrooveScene& scene, std::size_t primitive) {
  const Primitive& p = scene.primitives[primitive];
  const Groove& g = scene.grooves[p.groove];
  const std::size_t first = g.firstPrimitive, last = g.firstPrimitive + g.primitiveCount - 1;
  PrimitiveJoints joints;
  if (primitive > first)
    joints.start = mitre(scene.primitives[primitive - 1], p);
  else if (g.closed)
    joints.start = mitre(scene.primitives[last], p);
  else
    joints.start = {p.a, p.tangentAt(0), true};
  if (primitive < last) {
    joints.end = flip(mitre(p, scene.primitives[primitive + 1]));
  } else if (g.closed) {
    joints.end = flip(mitre(p, scene.primitives[first]));
  } else {
    const Vec2 t = p.tangentAt(1);
    joints.end = {p.b, {-t.u, -t.v}, true};
  }
  return joints;
}

}  // namespace bake::grooves
