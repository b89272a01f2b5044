// Placing a mesh read in double precision near the origin (MeshReadOptions::nearOrigin): when its
// centre lies farther from the world origin than its bounding-box diagonal, the float positions are
// stored relative to that centre (TriangleMesh::origin), computed in double, so float rounding is
// relative to the mesh's own size. Meshes near the origin keep the reader's float positions bit for
// bit. Internal to io/, used by the OpenMesh and glTF paths of readMesh.
#pragma once

#include <vector>

#include "bake/io/mesh.h"

namespace bake {

// The world positions of `mesh.positions` and of `mesh.namedPoints`, in double, in the same order.
struct WorldPositions {
  std::vector<Vec3d> vertices;
  std::vector<Vec3d> namedPoints;
};

// The origin a mesh with these world positions is stored relative to: zero when it is near already.
Vec3d nearOriginFor(const std::vector<Vec3d>& vertices);

// Sets mesh.origin and replaces positions and named points by their float offsets from it (nothing
// changes when the origin is zero).
void placeNearOrigin(const WorldPositions& world, TriangleMesh& mesh);

}  // namespace bake
