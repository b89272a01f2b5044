// The surface grooves are drawn on (`groovebake --apply-to MESH`, seed 000 Figs. 1, 11 and 13: a
// sphere, columns, a roof): any mesh whose TEXCOORD_0 maps UV [0, 1]^2 to the groove domain (UV 1 =
// the domain's size in texture units). The package gets the mesh with unit normals and a TANGENT per
// vertex (its own when usable, else computed: mesh/tangent_frames.h), so the runtime's tangent frame
// (u, v, w) follows +u, +v and the normal as the seed's shading expects. The stretch of the UV layout
// is measured so a bake can say where the grooves will look distorted.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "bake/core/diagnostics.h"
#include "bake/core/status.h"
#include "bake/io/glb.h"
#include "bake/mesh/triangle_mesh.h"
#include "mesh/tangent_frames.h"

namespace bake::grooves {

struct GrooveSurface {
  std::string name;  // the mesh file's stem: the node's and the mesh's name
  TriangleMesh mesh;
  std::vector<std::array<float, 4>> tangents;
  bool tangentsFromMesh = false;
  TangentFrames computed;  // the counts of the computation, when the tangents were computed
  std::string tangentProblem;  // why the mesh's own tangents were not used, when it had some
};

// Reads and checks the mesh (triangles, TEXCOORD_0), computes its normals and tangents where missing.
Result<GrooveSurface> readGrooveSurface(const std::string& path);

// The package's preview plane replaced by the surface, placed by a node of its own.
void applySurface(glb::Package& package, const GrooveSurface& surface);

}  // namespace bake::grooves
