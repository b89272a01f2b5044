// Baked self-shadowing (seed 002, last paragraph: "Each control point of a paintstroke contains a
// user-specified global normal and depth value ... The estimated amount of light penetration at each
// control point is computed using the depth, global normal, and average light direction. The control
// point's reflectance is then scaled accordingly."). The seed names these inputs but gives no
// formula; this is ours.
//
// The strokes fill a volume whose surface, near a control point, is a plane with unit outward normal
// n (the global normal); the point lies at relative depth t (0 at the surface, 1 deepest) below it.
// Light arriving from unit direction d (towards the light) enters that plane and travels in a straight
// line to the point: with c = dot(n, d) > 0 the path inside the volume is t / c long (the depth over
// the cosine of the incidence angle). Inside, light is absorbed at a constant rate, `density` per unit
// of relative depth, so the transmittance is exp(-density * t / c) (Beer-Lambert). At grazing light c
// goes to 0 and the path to infinity; it is clamped at c = 0.05 (about 87 degrees) so a point at the
// very surface (t = 0) stays fully lit whatever c is, and no division blows up. When c <= 0 the light
// comes from behind the surface plane: the point is on the far side of the volume and the light must
// cross all of it, so it gets only the ambient share `minimum`. The reflectance scale is
//     minimum + (1 - minimum) * transmittance,
// which is 1 at the lit surface and never below `minimum`. A point without a global normal (zero
// vector) is not shadowed: its scale is 1.
#include "paintstrokes/bake/shadow.h"

#include <algorithm>
#include <cmath>

namespace bake::paintstrokes {
namespace {

// Smallest cosine of incidence used in the path length (grazing light).
constexpr double kGrazingCosine = 0.05;

}  // namespace

Vec3d defaultLightDirection() {
  const double x = 0.4, y = 0.8, z = 0.45, length = std::sqrt(x * x + y * y + z * z);
  return {x / length, y / length, z / length};
}

double shadowScale(const StrokePoint& point, const Vec3d& d, double density, double minimum) {
  const Vec3d& n = point.globalNormal;
  if (n[0] == 0 && n[1] == 0 && n[2] == 0) return 1;
  const double c = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
  if (c <= 0) return minimum;
  const double transmittance = std::exp(-density * point.depth / std::max(c, kGrazingCosine));
  return std::clamp(minimum + (1 - minimum) * transmittance, 0.0, 1.0);
}

std::vector<double> bakeShadows(const StrokeSet& set, const std::vector<Vec3d>& directions, double density, double minimum) {
  std::vector<double> shadows;
  std::size_t points = 0;
  for (const Stroke& s : set.strokes) points += s.points.size();
  shadows.reserve(points * directions.size());
  for (const Stroke& s : set.strokes)
    for (const StrokePoint& p : s.points)
      for (const Vec3d& d : directions) shadows.push_back(shadowScale(p, d, density, minimum));
  return shadows;
}

}  // namespace bake::paintstrokes
