// glTF 2.0 as mesh input: every mesh instance of the default scene (or of every root node when the
// file has no scene) is placed in world space by its node's transform and appended to one triangle
// mesh. Normals go through the inverse-transpose of the transform; strips and fans become lists;
// points and lines are counted and skipped. Named nodes become named points (geodesic sources by
// node name). Node graphs with cycles are rejected.
#include <bake_formats/glb.h>

#include <cmath>

#include "bake/io/glb.h"
#include "io/glb_scene.h"
#include "io/gltf.h"
#include "io/mesh_place.h"

namespace bake {
namespace {

using Matrix = std::array<double, 16>;  // column-major

// In double: a node's translation may be far larger than its mesh (io/mesh_place.h).
Vec3d transformPoint(const Matrix& m, const float* p) {
  Vec3d out{};
  for (int r = 0; r < 3; ++r) out[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
  return out;
}

Vec3f toFloat(const Vec3d& p) { return {float(p[0]), float(p[1]), float(p[2])}; }

// Normals transform by the inverse transpose of the upper 3x3 (cofactor matrix; the scale of the
// determinant does not matter since the result is normalised).
Vec3f transformNormal(const Matrix& m, const float* n) {
  const double a[3][3] = {{m[0], m[4], m[8]}, {m[1], m[5], m[9]}, {m[2], m[6], m[10]}};
  double cof[3][3];
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      cof[r][c] = a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1];
    }
  }
  double out[3];
  for (int r = 0; r < 3; ++r) out[r] = cof[r][0] * n[0] + cof[r][1] * n[1] + cof[r][2] * n[2];
  const double length = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
  if (!(length > 0)) return {0, 0, 0};
  return {float(out[0] / length), float(out[1] / length), float(out[2] / length)};
}

std::vector<std::uint32_t> triangleList(const glb::Primitive& primitive) {
  std::vector<std::uint32_t> corners = primitive.indices;
  if (corners.empty()) {
    corners.resize(primitive.vertexCount());
    for (std::size_t i = 0; i < corners.size(); ++i) corners[i] = std::uint32_t(i);
  }
  if (primitive.mode == format::glb::kModeTriangles) {
    corners.resize(corners.size() / 3 * 3);
    return corners;
  }
  std::vector<std::uint32_t> list;
  for (std::size_t i = 2; i < corners.size(); ++i) {
    if (primitive.mode == format::glb::kModeTriangleStrip) {  // alternate winding (glTF 3.7.2.1)
      const bool even = i % 2 == 0;
      list.insert(list.end(), {corners[i - 2], even ? corners[i - 1] : corners[i], even ? corners[i] : corners[i - 1]});
    } else {
      list.insert(list.end(), {corners[0], corners[i - 1], corners[i]});
    }
  }
  return list;
}

bool carriedByTriangleMesh(const std::string& name) {
  return name == "POSITION" || name == "NORMAL" || name == "TEXCOORD_0";
}

bool sameLayout(const glb::Attribute& a, const glb::Attribute& b) {
  return a.componentType == b.componentType && a.components == b.components && a.normalized == b.normalized;
}

// TANGENT xyz follows the transform's upper 3x3 (renormalised); w, the handedness, flips with a mirror.
glb::Attribute transformTangents(const Matrix& m, const glb::Attribute& tangent) {
  std::vector<float> t = tangent.toFloats();
  const double det = m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
                     m[8] * (m[1] * m[6] - m[5] * m[2]);
  for (std::size_t v = 0; v + 3 < t.size(); v += 4) {
    double out[3];
    for (int r = 0; r < 3; ++r) out[r] = m[r] * t[v] + m[4 + r] * t[v + 1] + m[8 + r] * t[v + 2];
    const double length = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
    for (int r = 0; r < 3; ++r) t[v + std::size_t(r)] = length > 0 ? float(out[r] / length) : 0.0f;
    if (det < 0) t[v + 3] = -t[v + 3];
  }
  return glb::Attribute::fromFloats(tangent.name, 4, t);
}

struct Flattener {
  const glb::Package& package;
  const std::string& name;
  TriangleMesh mesh;
  WorldPositions worldPositions;  // the positions and named points in double
  bool allHaveNormals = true;
  bool allHaveTexcoords = true;
  bool firstPrimitive = true;
  std::size_t skipped = 0;

  // Keeps the extra attributes every primitive so far has with one layout, and appends this one's.
  void appendExtras(const glb::Primitive& primitive, const Matrix& world) {
    if (firstPrimitive) {
      for (const glb::Attribute& attribute : primitive.attributes) {
        if (carriedByTriangleMesh(attribute.name)) continue;
        glb::Attribute empty = attribute;
        empty.bytes.clear();
        if (attribute.name == "TANGENT") empty.componentType = glb::ComponentType::F32, empty.normalized = false;
        mesh.extraAttributes.push_back(std::move(empty));
      }
      firstPrimitive = false;
    }
    std::vector<glb::Attribute> kept;
    for (glb::Attribute& extra : mesh.extraAttributes) {
      const glb::Attribute* own = primitive.find(extra.name);
      if (!own) continue;
      const glb::Attribute appended = extra.name == "TANGENT" && own->components == 4 ? transformTangents(world, *own) : *own;
      if (!sameLayout(appended, extra)) continue;
      extra.bytes.insert(extra.bytes.end(), appended.bytes.begin(), appended.bytes.end());
      kept.push_back(std::move(extra));
    }
    mesh.extraAttributes = std::move(kept);
  }

  void appendPrimitive(const glb::Primitive& primitive, const Matrix& world) {
    if (primitive.mode < format::glb::kModeTriangles) {
      ++skipped;
      return;
    }
    const glb::Attribute* position = primitive.find("POSITION");
    if (!position) return;
    const std::vector<float> p = position->toFloats();
    const glb::Attribute* normal = primitive.find("NORMAL");
    const glb::Attribute* texcoord = primitive.find("TEXCOORD_0");
    allHaveNormals = allHaveNormals && normal;
    allHaveTexcoords = allHaveTexcoords && texcoord;
    const std::vector<float> n = normal ? normal->toFloats() : std::vector<float>();
    const std::vector<float> t = texcoord ? texcoord->toFloats() : std::vector<float>();
    const std::uint32_t base = std::uint32_t(mesh.positions.size());
    appendExtras(primitive, world);
    for (std::size_t v = 0; v < position->count(); ++v) {
      worldPositions.vertices.push_back(transformPoint(world, &p[3 * v]));
      mesh.positions.push_back(toFloat(worldPositions.vertices.back()));
      mesh.normals.push_back(normal ? transformNormal(world, &n[3 * v]) : Vec3f{});
      mesh.texcoords.push_back(texcoord ? Vec2f{t[2 * v], t[2 * v + 1]} : Vec2f{});
    }
    const std::vector<std::uint32_t> list = triangleList(primitive);
    for (std::size_t i = 0; i + 2 < list.size(); i += 3) {
      mesh.triangles.push_back({base + list[i], base + list[i + 1], base + list[i + 2]});
    }
  }

  void visit(const glb::Node& node, const Matrix& world) {
    if (!node.name.empty()) {
      worldPositions.namedPoints.push_back({world[12], world[13], world[14]});
      mesh.namedPoints.push_back({node.name, toFloat(worldPositions.namedPoints.back())});
    }
    if (node.mesh >= 0) {
      for (const glb::Primitive& primitive : package.meshes[std::size_t(node.mesh)].primitives) appendPrimitive(primitive, world);
    }
  }
};

constexpr Matrix kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

}  // namespace

Result<TriangleMesh> readGltfMesh(const std::filesystem::path& path, MeshReadStats* stats, bool nearOrigin) {
  BAKE_ASSIGN_OR_RETURN(const glb::Package package, glb::read(path));
  Flattener flattener{package, path.string(), {}, {}};
  if (package.nodes.empty()) {
    for (const glb::Mesh& mesh : package.meshes) {
      for (const glb::Primitive& primitive : mesh.primitives) flattener.appendPrimitive(primitive, kIdentity);
    }
  } else {
    BAKE_RETURN_IF_ERROR(glb::forEachNode(package, path.string(),
                                          [&](const glb::Node& node, const Matrix& world) { flattener.visit(node, world); }));
  }
  TriangleMesh mesh = std::move(flattener.mesh);
  if (nearOrigin) placeNearOrigin(flattener.worldPositions, mesh);
  if (!flattener.allHaveNormals || mesh.positions.empty()) mesh.normals.clear();
  if (!flattener.allHaveTexcoords || mesh.positions.empty()) mesh.texcoords.clear();
  if (stats) stats->nonTrianglePrimitivesSkipped += flattener.skipped;
  if (mesh.triangles.empty()) {
    return invalidInput("the scene contains no triangles", {path.string(), ""});
  }
  return mesh;
}

}  // namespace bake
