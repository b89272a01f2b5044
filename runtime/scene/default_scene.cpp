// The bundled example scene shown when bakeplay is given no file: a (2,3) torus knot tube, built in
// code so the runtime needs no data files to show something.
#include <cmath>

#include "scene/scene.h"

namespace bake::play {
namespace {

constexpr float kPi = 3.14159265358979f;

Vec3 knotPoint(float t) {
  const float r = 2.0f + std::cos(3 * t);
  return {r * std::cos(2 * t) * 0.3f, std::sin(3 * t) * 0.3f, r * std::sin(2 * t) * 0.3f};
}

glb::Package torusKnotPackage(int segments, int sides) {
  std::vector<float> positions, normals;
  std::vector<std::uint32_t> indices;
  for (int i = 0; i < segments; ++i) {
    const float t = 2 * kPi * float(i) / float(segments);
    const Vec3 p = knotPoint(t), next = knotPoint(t + 0.01f);
    const Vec3 tangent = normalize(next - p);
    const Vec3 side = normalize(cross(tangent, Vec3{0, 1, 0}));
    const Vec3 up = cross(side, tangent);
    for (int j = 0; j < sides; ++j) {
      const float a = 2 * kPi * float(j) / float(sides);
      const Vec3 n = side * std::cos(a) + up * std::sin(a);
      const Vec3 q = p + n * 0.12f;
      positions.insert(positions.end(), q.begin(), q.end());
      normals.insert(normals.end(), n.begin(), n.end());
      const std::uint32_t i0 = std::uint32_t(i * sides + j), i1 = std::uint32_t(((i + 1) % segments) * sides + j);
      const std::uint32_t j0 = std::uint32_t(i * sides + (j + 1) % sides);
      const std::uint32_t j1 = std::uint32_t(((i + 1) % segments) * sides + (j + 1) % sides);
      indices.insert(indices.end(), {i0, i1, j1, i0, j1, j0});
    }
  }
  glb::Primitive primitive;
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, positions));
  primitive.attributes.push_back(glb::Attribute::fromFloats("NORMAL", 3, normals));
  primitive.indices = std::move(indices);
  primitive.material = 0;
  glb::Package package;
  package.meshes.push_back({"torus knot", {primitive}});
  package.nodes.push_back(glb::Node{"torus knot", 0, {}, std::nullopt});
  package.materials = nlohmann::json::array(
      {{{"name", "clay"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.80, 0.45, 0.30, 1.0}}}}}});
  return package;
}

}  // namespace

Scene defaultScene() {
  Scene scene;
  scene.files.push_back("(bundled example)");
  scene.packages.push_back(torusKnotPackage(256, 24));
  scene.instances.push_back({0, 0, 0, identity()});
  const std::vector<float> p = scene.packages[0].meshes[0].primitives[0].find("POSITION")->toFloats();
  scene.boundsMin = scene.boundsMax = {p[0], p[1], p[2]};
  for (std::size_t v = 0; v + 2 < p.size(); v += 3) {
    for (int k = 0; k < 3; ++k) {
      scene.boundsMin[k] = std::min(scene.boundsMin[k], p[v + k]);
      scene.boundsMax[k] = std::max(scene.boundsMax[k], p[v + k]);
    }
  }
  return scene;
}

}  // namespace bake::play
