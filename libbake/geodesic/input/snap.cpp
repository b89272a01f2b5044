// Nearest surface point by brute force over the faces (a bake snaps a handful of points; a spatial
// index would cost more to build than it saves). Closest point on a triangle by Voronoi regions of
// its corners, edges and interior (Ericson 2005, 5.1.5), keeping exact 0 and 1 weights in the corner
// and edge regions.
#include "geodesic/input/snap.h"

#include "bake/core/vec.h"

#include <cmath>
#include <limits>

namespace bake::geodesic {
namespace {

using vec::dot;
using vec::sub;

// Barycentric weights of the point of triangle (a, b, c) nearest to p.
std::array<double, 3> closestWeights(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const Vec3d ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {1.0, 0.0, 0.0};
  const Vec3d bp = sub(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return {0.0, 1.0, 0.0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return {1.0 - v, v, 0.0};
  }
  const Vec3d cp = sub(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return {0.0, 0.0, 1.0};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return {1.0 - w, 0.0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0.0, 1.0 - w, w};
  }
  const double denominator = va + vb + vc;
  if (!(denominator > 0.0)) return {1.0, 0.0, 0.0};  // zero-area face: its first corner
  const double v = vb / denominator, w = vc / denominator;
  return {1.0 - v - w, v, w};
}

double squaredDistance(const Vec3d& a, const Vec3d& b) {
  const Vec3d d = sub(a, b);
  return dot(d, d);
}

}  // namespace

SnappedPoint snapToSurface(const Surface& surface, const Vec3d& query) {
  const Vec3d p = sub(query, surface.origin);
  SnappedPoint best;
  double bestSquared = std::numeric_limits<double>::infinity();
  for (std::uint32_t t = 0; t < surface.triangleCount(); ++t) {
    const auto& tri = surface.triangles[t];
    SurfacePoint candidate{t, closestWeights(p, surface.positions[tri[0]], surface.positions[tri[1]],
                                             surface.positions[tri[2]])};
    const double squared = squaredDistance(candidate.position(surface), p);
    if (squared < bestSquared) {
      bestSquared = squared;
      best.point = candidate;
    }
  }
  // A corner hit is reported on the vertex's first face, so equal points give equal sources.
  if (const std::int64_t v = best.point.vertex(surface); v >= 0) best.point = vertexPoint(surface, std::uint32_t(v));
  best.distance = std::sqrt(bestSquared);
  return best;
}

}  // namespace bake::geodesic
