// Points on the surface that distances are measured from. A source is a vertex or a point inside a
// face, given by barycentric coordinates; points given in 3D are snapped to their nearest surface
// point once, and the solvers then measure from that (face, barycentric) point exactly, never from a
// re-located copy.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "bake/geodesic/surface.h"

namespace bake::geodesic {

struct SurfacePoint {
  std::uint32_t face = 0;
  // Weights of the face's corners 0, 1, 2; non-negative and summing to 1. A point on a corner has
  // weight exactly 1 there (the solvers treat it as that vertex).
  std::array<double, 3> barycentric{1.0, 0.0, 0.0};

  // The vertex this point sits on, or -1 when it lies inside a face or on an edge.
  std::int64_t vertex(const Surface& surface) const {
    for (int i = 0; i < 3; ++i)
      if (barycentric[i] == 1.0) return surface.triangles[face][i];
    return -1;
  }
  Vec3d position(const Surface& surface) const {
    Vec3d p{0.0, 0.0, 0.0};
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) p[k] += barycentric[i] * surface.positions[surface.triangles[face][i]][k];
    return p;
  }
};

// The point of vertex v (on its first face). Precondition: v has at least one face.
SurfacePoint vertexPoint(const Surface& surface, std::uint32_t v);

}  // namespace bake::geodesic
