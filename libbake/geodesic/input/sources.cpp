// Source points: construction helpers shared by the solvers and the bake.
#include "bake/geodesic/sources.h"

namespace bake::geodesic {

SurfacePoint vertexPoint(const Surface& surface, std::uint32_t v) {
  SurfacePoint point;
  point.face = surface.facesOfVertex(v).front();
  point.barycentric = {0.0, 0.0, 0.0};
  point.barycentric[surface.cornerOf(point.face, v)] = 1.0;
  return point;
}

}  // namespace bake::geodesic
