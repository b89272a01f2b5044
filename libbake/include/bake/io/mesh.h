// Reading and writing triangle meshes (mesh/triangle_mesh.h). OBJ, PLY, OFF and STL go through
// OpenMesh's parsers into a polygon soup (no manifold filtering, so nothing is dropped silently);
// glTF/GLB goes through our reader (io/gltf.h). Polygons are fan-triangulated. Malformed input is an error naming the file and the
// line or element at fault.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bake/core/diagnostics.h"
#include "bake/core/status.h"
#include "bake/io/glb.h"
#include "bake/mesh/triangle_mesh.h"

namespace bake {

struct MeshReadOptions {
  // Merge vertices whose positions are equal (within weldTolerance, relative to the bounding-box
  // diagonal; 0 = bit-identical positions only). Attributes of merged vertices must agree for them
  // to merge.
  bool weld = false;
  double weldTolerance = 0.0;
  // Keep a mesh that lies far from the world origin precise: the coordinates are read in double
  // (OBJ, OFF and ASCII PLY text, glTF node transforms) and, when the mesh's centre is farther from
  // the origin than its bounding-box diagonal, stored as floats relative to that centre
  // (TriangleMesh::origin), so that float rounding is relative to the mesh's size, not to its
  // distance from the origin. A reader that sets this must add the origin back to what it writes.
  bool nearOrigin = false;
};

// Counts of what reading changed, for warnings and the report.
struct MeshReadStats {
  std::size_t polygonsTriangulated = 0;
  std::size_t verticesWelded = 0;
  // Faces left with fewer than three distinct vertices (a repeated index in the file, or corners
  // merged by welding); they are removed. Zero-area faces with distinct vertices are kept.
  std::size_t degenerateFacesRemoved = 0;
  // Vertices duplicated because faces gave one position different normals or texture coordinates.
  std::size_t verticesSplit = 0;
  // Normals or texture coordinates given for only some corners are dropped (0, 1 or 2 kinds).
  std::size_t incompleteAttributesDropped = 0;
  // glTF primitives that are points or lines, which a triangle mesh cannot hold.
  std::size_t nonTrianglePrimitivesSkipped = 0;
};

// Reads by extension: .obj .ply .off .stl .gltf .glb (case-insensitive).
Result<TriangleMesh> readMesh(const std::filesystem::path& path, const MeshReadOptions& options = {},
                              MeshReadStats* stats = nullptr);

// Checks indices and finiteness; element names in errors are "triangle N" / "vertex N".
Status validateMesh(const TriangleMesh& mesh, const std::string& name);

}  // namespace bake
