// The surface of `groovebake --apply-to` (grooves/package/surface.h): read, give it normals and
// tangent frames, and put it in the package in place of the preview plane.
#include "grooves/package/surface.h"

#include <algorithm>
#include <filesystem>

#include "bake/io/mesh.h"

namespace bake::grooves {

Result<GrooveSurface> readGrooveSurface(const std::string& path) {
  GrooveSurface surface;
  surface.name = std::filesystem::path(path).stem().string();
  BAKE_ASSIGN_OR_RETURN(surface.mesh, readMesh(path));
  BAKE_RETURN_IF_ERROR(validateMesh(surface.mesh, path));
  if (surface.mesh.triangles.empty()) return invalidInput("the mesh has no triangles", {path, ""});
  if (surface.mesh.texcoords.size() != surface.mesh.positions.size())
    return invalidInput("the mesh has no texture coordinates (TEXCOORD_0, OBJ vt): grooves are laid out in UV, so "
                        "--apply-to needs a UV-mapped mesh",
                        {path, ""});
  surface.tangents = usableTangents(surface.mesh, surface.tangentProblem);
  // The mesh's own frames only with its own normals: a computed normal would not match them.
  if (!surface.tangents.empty() && surface.mesh.normals.size() == surface.mesh.positions.size()) {
    surface.tangentsFromMesh = true;
    for (Vec3f& n : surface.mesh.normals) {
      const Vec3d unit = vec::unit({n[0], n[1], n[2]}, {0, 0, 1});
      n = {float(unit[0]), float(unit[1]), float(unit[2])};
    }
    return surface;
  }
  if (!surface.tangents.empty()) surface.tangentProblem = "the mesh has TANGENT but no NORMAL";
  Result<TangentFrames> frames = computeTangentFrames(surface.mesh);
  if (!frames.isOk()) return frames.takeStatus().inFile(path);
  surface.computed = std::move(frames).value();
  surface.tangents = surface.computed.tangents;
  return surface;
}

void applySurface(glb::Package& package, const GrooveSurface& surface) {
  const TriangleMesh& mesh = surface.mesh;
  std::vector<float> positions, normals, texcoords, tangents;
  for (const Vec3f& p : mesh.positions)
    for (int k = 0; k < 3; ++k) positions.push_back(float(double(p[std::size_t(k)]) + mesh.origin[std::size_t(k)]));
  for (const Vec3f& n : mesh.normals) normals.insert(normals.end(), n.begin(), n.end());
  for (const Vec2f& uv : mesh.texcoords) texcoords.insert(texcoords.end(), uv.begin(), uv.end());
  for (const auto& t : surface.tangents) tangents.insert(tangents.end(), t.begin(), t.end());
  glb::Primitive primitive;
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, positions));
  primitive.attributes.push_back(glb::Attribute::fromFloats("NORMAL", 3, normals));
  primitive.attributes.push_back(glb::Attribute::fromFloats("TEXCOORD_0", 2, texcoords));
  primitive.attributes.push_back(glb::Attribute::fromFloats("TANGENT", 4, tangents));
  for (const Triangle& t : mesh.triangles) primitive.indices.insert(primitive.indices.end(), t.begin(), t.end());
  primitive.material = 0;
  package.meshes.clear();
  package.meshes.push_back({surface.name, {std::move(primitive)}});
  package.nodes.clear();
  glb::Node node;
  node.name = surface.name;
  node.mesh = 0;
  package.nodes.push_back(node);
}

}  // namespace bake::grooves
