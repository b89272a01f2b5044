// Exact signed distance to a profile (profile.h, shape_map.h). The distance of a 3D point to a
// surface of revolution is the distance of its (r, h) image to the profile curve (seed 001, "Shape
// and displacement map"), so it is the minimum over the surface pieces (axis pieces excluded: they
// are inside the solid) of the distance to a segment or circular arc, by projection. The sign comes
// from the even-odd rule over all pieces, axis closures included; the gradient is the unit vector
// from the nearest point, flipped inside. Points with r < 0 are mirrored, as the solid is symmetric.
#include <algorithm>
#include <cmath>
#include <limits>

#include "bake/revolution/shape_map.h"
#include "revolution/input/profile_geometry.h"

namespace bake::revolution {

DistanceSample signedDistance(const Profile& profile, Point2 p) {
  const bool mirrored = p.r < 0;
  const Point2 q{std::abs(p.r), p.h};
  double best = std::numeric_limits<double>::infinity();
  const Segment* nearest = nullptr;
  Point2 away;
  for (const Contour& contour : profile.contours)
    for (const Segment& s : contour.segments) {
      if (s.onAxis) continue;
      const PieceDistance d = distanceToPiece(s, q);
      if (d.distance < best) {
        best = d.distance;
        nearest = &s;
        away = d.away;
      }
    }
  DistanceSample sample;
  if (!nearest) {
    sample.distance = std::numeric_limits<double>::max();
    return sample;
  }
  const bool inside = insideProfile(profile, q);
  const double dist = best;
  const double sign = inside ? -1.0 : 1.0;
  sample.distance = sign * dist;
  if (dist > 0) {
    sample.gradR = sign * away.r;
    sample.gradH = sign * away.h;
  } else {
    const Point2 foot = closestPoint(*nearest, q);
    // On the surface: the piece's normal, pointed out of the solid (tested just beside it). The
    // parameter of the foot does not matter for a line; for an arc use the direction to the centre.
    Point2 normal;
    if (isArc(*nearest)) {
      const ArcGeometry arc = arcGeometry(*nearest);
      const double len = std::hypot(foot.r - arc.centre.r, foot.h - arc.centre.h);
      normal = {(foot.r - arc.centre.r) / len, (foot.h - arc.centre.h) / len};
    } else {
      const Point2 t = tangentAt(*nearest, 0);
      normal = {t.h, -t.r};
    }
    const double step = 1e-7 * std::max({1.0, std::abs(foot.r), std::abs(foot.h)});
    if (insideProfile(profile, {foot.r + step * normal.r, foot.h + step * normal.h})) {
      normal.r = -normal.r;
      normal.h = -normal.h;
    }
    sample.gradR = normal.r;
    sample.gradH = normal.h;
  }
  if (mirrored) sample.gradR = -sample.gradR;
  return sample;
}

}  // namespace bake::revolution
