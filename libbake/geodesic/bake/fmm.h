// Fast marching on triangle meshes (Kimmel and Sethian 1998): a Dijkstra-ordered front where each
// vertex is updated from the planar wavefront across a triangle; obtuse angles are split by
// unfolding neighbouring triangles until an acute virtual triangle is found.
#pragma once

#include <span>
#include <vector>

#include "bake/geodesic/sources.h"
#include "bake/geodesic/surface.h"

namespace bake::geodesic {

std::vector<double> fastMarchingDistances(const Surface& surface, std::span<const SurfacePoint> sources);

}  // namespace bake::geodesic
