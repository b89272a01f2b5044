// Cheap structural facts about a triangle mesh (extent, connectivity, boundary and non-manifold edges,
// degenerate faces) for reports, warnings and tests.
#pragma once

#include <cstddef>
#include <vector>

#include "bake/io/mesh.h"

namespace bake {

struct BoundingBox {
  Vec3f min{};
  Vec3f max{};
  bool empty = true;  // no points: min/max are zero

  double diagonal() const;
};

// Over all given points (unreferenced vertices included).
BoundingBox boundingBoxOf(const std::vector<Vec3f>& points);

struct MeshStats {
  BoundingBox bounds;  // over all vertices
  std::size_t unreferencedVertices = 0;
  std::size_t components = 0;           // groups of triangles connected through shared vertices
  std::size_t boundaryEdges = 0;        // edges used by exactly one triangle
  std::size_t nonManifoldEdges = 0;     // edges used by three or more triangles
  std::size_t degenerateTriangles = 0;  // zero area: repeated index, coincident or collinear corners
};

// Edges are undirected vertex-index pairs, so unwelded seams count as boundary. "Zero area" means the
// cross product of two edge vectors, evaluated in double precision, is exactly zero.
MeshStats computeMeshStats(const TriangleMesh& mesh);

}  // namespace bake
