// The package of `tambake --apply-to MESH --package OUT.glb` (formats/tam.md, "The BAKE_hatching
// material extension"): the mesh with POSITION, NORMAL and indices; one node placing it (translation,
// uniform scale); one material whose standard baseColorFactor is the colour the hatching multiplies
// (what a viewer without the extension shows) and whose BAKE_hatching object points at the TAM (and
// the threshold texture) embedded as images with mimeType image/ktx2 in their own bufferViews. The
// hatching parameters follow seed 004 section 4 (scale, rotation, translation of the hatching
// coordinates) and section 3.2 (orientation toward or across the light).
#include <cmath>
#include <filesystem>
#include <numbers>

#include "bake_formats/tam.h"
#include "hatching/bake/bake_stages.h"

namespace bake::hatching {
namespace {

namespace fmt = format::tam;
using nlohmann::json;

glb::Mesh packageMesh(const TriangleMesh& mesh, const std::string& name) {
  std::vector<float> positions, normals;
  positions.reserve(mesh.positions.size() * 3);
  normals.reserve(mesh.normals.size() * 3);
  for (const Vec3f& p : mesh.positions) positions.insert(positions.end(), p.begin(), p.end());
  for (const Vec3f& n : mesh.normals) normals.insert(normals.end(), n.begin(), n.end());
  glb::Primitive primitive;
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, positions));
  primitive.attributes.push_back(glb::Attribute::fromFloats("NORMAL", 3, normals));
  primitive.indices.reserve(mesh.triangles.size() * 3);
  for (const Triangle& t : mesh.triangles) primitive.indices.insert(primitive.indices.end(), t.begin(), t.end());
  primitive.material = 0;
  glb::Mesh out;
  out.name = name;
  out.primitives.push_back(std::move(primitive));
  return out;
}

}  // namespace

std::size_t ensureUnitNormals(TriangleMesh& mesh) {
  std::size_t computed = 0;
  if (mesh.normals.size() != mesh.positions.size()) {
    // Sum of the unnormalised face normals (|cross| = twice the area): area-weighted smooth normals.
    std::vector<std::array<double, 3>> sum(mesh.positions.size(), {0, 0, 0});
    for (const Triangle& t : mesh.triangles) {
      const Vec3f& a = mesh.positions[t[0]];
      const Vec3f& b = mesh.positions[t[1]];
      const Vec3f& c = mesh.positions[t[2]];
      const double e1[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
      const double e2[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
      const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
      for (std::uint32_t v : t)
        for (int k = 0; k < 3; ++k) sum[v][k] += n[k];
    }
    mesh.normals.assign(mesh.positions.size(), Vec3f{0, 0, 1});
    for (std::size_t v = 0; v < sum.size(); ++v)
      mesh.normals[v] = {float(sum[v][0]), float(sum[v][1]), float(sum[v][2])};
    computed = mesh.positions.size();
  }
  for (Vec3f& n : mesh.normals) {
    const double length = std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]);
    if (!(length > 1e-30) || !std::isfinite(length)) {
      n = {0, 0, 1};
      continue;
    }
    for (float& c : n) c = float(c / length);
  }
  return computed;
}

Result<glb::Package> buildPackage(const Settings& settings, const BakeState& state) {
  if (!state.mesh) return internalError("no mesh to package");
  const MaterialSettings& m = settings.material;
  glb::Package package;

  package.blobs.push_back({state.tamBytes, 16});
  package.images.push_back({{"name", "tonal art map"}, {"bufferView", 0}, {"mimeType", fmt::kKtx2MimeType}});
  json extension = {{"version", fmt::kVersion}, {fmt::kTamImage, 0}};
  if (!state.thresholdBytes.empty()) {
    extension[fmt::kThresholdImage] = package.images.size();
    package.images.push_back({{"name", "threshold texture"}, {"bufferView", package.blobs.size()}, {"mimeType", fmt::kKtx2MimeType}});
    package.blobs.push_back({state.thresholdBytes, 16});
  }
  extension["tones"] = state.tam.targets;
  extension["tilesPerUnit"] = m.tilesPerUnit;
  extension["rotation"] = m.rotationDegrees * std::numbers::pi / 180.0;
  extension["translation"] = {m.translation[0], m.translation[1]};
  extension["orientation"] = m.orientation;
  extension["baseColor"] = {m.baseColour[0], m.baseColour[1], m.baseColour[2]};

  package.materials.push_back({{"name", "hatching"},
                               {"pbrMetallicRoughness", {{"baseColorFactor", {m.baseColour[0], m.baseColour[1], m.baseColour[2], 1.0}},
                                                         {"metallicFactor", 0.0},
                                                         {"roughnessFactor", 1.0}}},
                               {"extensions", {{fmt::kExtension, extension}}}});

  const std::string name = std::filesystem::path(m.mesh).stem().string();
  package.meshes.push_back(packageMesh(*state.mesh, name));
  glb::Node node;
  node.name = name;
  node.mesh = 0;
  node.translation = m.position;
  node.scale = {m.scale, m.scale, m.scale};
  package.nodes.push_back(node);
  return package;
}

}  // namespace bake::hatching
