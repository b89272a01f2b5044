// Per-vertex tangent frames for texture-space shading (the glTF TANGENT attribute: xyz along +u,
// w = ±1 the handedness, bitangent = w · cross(normal, tangent)), in the manner of Mikkelsen 2008,
// "Simulation of Wrinkled Surfaces Revisited" §3-§4: each triangle's dP/du, projected on the vertex
// normal's plane and weighted by the corner angle, is summed per vertex and per handedness; a vertex
// whose triangles disagree on handedness (a mirrored UV island meeting its original) is split, so
// no frame is averaged across a mirror. Normals a mesh lacks are smoothed across UV seams (summed
// over every vertex at the same position), so a seam in the texture is not a crease in the shading.
// Also the texture-space stretch of a UV layout: how much a pattern laid out in texture units looks
// stretched on each triangle.
#pragma once

#include <cstddef>
#include <vector>

#include "bake/core/status.h"
#include "bake/mesh/triangle_mesh.h"

namespace bake {

struct TangentFrames {
  std::vector<std::array<float, 4>> tangents;  // one per vertex of the (possibly split) mesh
  std::size_t splitVertices = 0;       // vertices duplicated where mirrored UVs meet
  std::size_t degenerateTriangles = 0; // triangles with no UV area (they add nothing)
  std::size_t fallbackVertices = 0;    // vertices only such triangles touch: any unit vector ⟂ normal
  std::size_t normalsComputed = 0;     // vertices whose normal was computed (the mesh had none)
};

// Needs texcoords (one per vertex). Computes the normals the mesh lacks, splits vertices where
// handedness disagrees (the mesh gains them, with copies of every per-vertex array) and returns one
// tangent per vertex of the result. Normals are made unit length.
Result<TangentFrames> computeTangentFrames(TriangleMesh& mesh);

// The mesh's own TANGENT attribute when every vector is finite, of unit length within 1e-3 and with
// w = ±1; an empty vector otherwise (`problem` then says why, for the report; it stays empty when the
// mesh has no TANGENT at all).
std::vector<std::array<float, 4>> usableTangents(const TriangleMesh& mesh, std::string& problem);

// The stretch of a texture-space pattern on a mesh. The pattern's texture units map to UV by
// `unitsPerUv` (the groove domain: UV 1 = unitsPerUv texture units); per triangle the Jacobian from
// texture units to world has singular values s1 ≥ s2: stretch s1/s2 (1 = a square stays square) and
// scale √(s1 s2) (world units per texture unit).
struct UvStretch {
  double medianScale = 0;                 // area-weighted median world units per texture unit
  double minScale = 0, maxScale = 0;      // over triangles with UV area
  double maxStretch = 1;                  // largest s1/s2
  std::size_t worstTriangle = 0;          // where maxStretch is
  std::size_t trianglesOver = 0;          // stretch or scale deviation beyond the limit
  double areaShareOver = 0;               // their share of the world area, 0..1
  std::size_t noUvArea = 0;               // triangles with no UV area: the pattern collapses there
};
// `limit`: a triangle is over when its stretch exceeds it or its scale differs from the median by
// more than that factor.
UvStretch measureUvStretch(const TriangleMesh& mesh, const double unitsPerUv[2], double limit);

}  // namespace bake
