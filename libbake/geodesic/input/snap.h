// Snapping 3D points onto the surface: the nearest point over all faces (Ericson, "Real-Time
// Collision Detection", 5.1.5: closest point on a triangle by Voronoi regions), returned as a face and
// barycentric weights. A point nearest to a corner gets weight exactly 1 there and one nearest to an
// edge gets an exact 0 on the third corner, so the solvers treat it as that vertex or edge point.
#pragma once

#include <span>
#include <vector>

#include "bake/geodesic/sources.h"
#include "bake/geodesic/surface.h"

namespace bake::geodesic {

struct SnappedPoint {
  SurfacePoint point;
  double distance = 0.0;  // from the given point to the surface
};

// `query` is in the input mesh's coordinates (the surface's origin is subtracted first).
// Precondition: the surface has at least one face.
SnappedPoint snapToSurface(const Surface& surface, const Vec3d& query);

}  // namespace bake::geodesic
