// Vertex welding: merges vertices that sit at the same place and carry the same attributes, so that
// meshes exported as triangle soups (STL, unwelded OBJ) become connected surfaces.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "bake/io/mesh.h"

namespace bake {

struct WeldStats {
  std::size_t verticesWelded = 0;              // vertices merged into another one (and removed)
  std::size_t degenerateTrianglesRemoved = 0;  // triangles left with a repeated corner, removed
};

// Merges vertices whose positions are equal and whose normals and texture coordinates (when the mesh
// has them) are bit-identical.
//
// relativeTolerance = 0: positions must be bit-identical (-0 and +0 count as equal).
// relativeTolerance > 0: positions within relativeTolerance × bounding-box diagonal (Euclidean) are
// equal. Vertices are visited in index order; each merges into the lowest-indexed surviving vertex
// within reach, or survives itself. So every merged vertex lies within the tolerance of the vertex
// that absorbed it, survivors are pairwise farther apart than the tolerance, and the result depends
// only on the mesh, never on hashing or memory layout. Tolerances below 1e-15 weld bit-exactly.
//
// Survivors keep their relative order; triangles are remapped and those whose corners are no longer
// distinct are removed. Named points are untouched. Precondition: relativeTolerance is finite and
// non-negative, and the mesh passed validateMesh.
// vertexMap, when given, receives for every old vertex its index after welding.
WeldStats weldVertices(TriangleMesh& mesh, double relativeTolerance = 0.0,
                       std::vector<std::uint32_t>* vertexMap = nullptr);

}  // namespace bake
