#include <gtest/gtest.h>

#include <fstream>

#include "bake/io/glb.h"
#include "io/gltf.h"
#include "support/golden.h"

namespace bake {
namespace {
namespace fs = std::filesystem;

glb::Primitive triangle(int mode = 4) {
  glb::Primitive primitive;
  primitive.mode = mode;
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  const std::vector<float> normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, positions));
  primitive.attributes.push_back(glb::Attribute::fromFloats("NORMAL", 3, normals));
  return primitive;
}

TEST(GltfMesh, PlacesInstancesInWorldSpace) {
  glb::Package package;
  glb::Primitive list = triangle();
  list.indices = {0, 1, 2};
  package.meshes.push_back({"tri", {list, triangle(5) /* a strip of 4 vertices */, triangle(1) /* lines */}});
  glb::Node parent{"parent", -1, {1}, std::nullopt};
  parent.translation = {10, 0, 0};
  glb::Node child{"child", 0, {}, std::nullopt};
  child.scale = {2, 2, 2};
  child.rotation = {0, 0.70710678118654752, 0, 0.70710678118654752};  // 90 degrees about +y
  package.nodes = {parent, child};
  const fs::path dir = test::freshTempDir("gltf_mesh");
  ASSERT_TRUE(glb::write(dir / "scene.glb", package).isOk());

  MeshReadStats stats;
  auto mesh = readGltfMesh(dir / "scene.glb", &stats);
  ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
  EXPECT_EQ(mesh->triangleCount(), 1u + 2u);  // the list, then the strip's two triangles
  EXPECT_EQ(stats.nonTrianglePrimitivesSkipped, 1u);
  // Vertex (1,0,0): scaled to (2,0,0), rotated about y to (0,0,-2), translated to (10,0,-2).
  EXPECT_NEAR(mesh->positions[1][0], 10.0f, 1e-5);
  EXPECT_NEAR(mesh->positions[1][2], -2.0f, 1e-5);
  // Normal (0,0,1) rotates to (1,0,0) and stays unit length despite the scale.
  ASSERT_EQ(mesh->normals.size(), mesh->positions.size());
  EXPECT_NEAR(mesh->normals[0][0], 1.0f, 1e-5);
  EXPECT_NEAR(mesh->normals[0][2], 0.0f, 1e-5);
  // The strip's second triangle is {v1, v3, v2} (glTF 2.0, 3.7.2.1), keeping the first one's winding.
  EXPECT_EQ(mesh->triangles[2], (Triangle{4 + 1, 4 + 3, 4 + 2}));
  ASSERT_EQ(mesh->namedPoints.size(), 2u);
  EXPECT_EQ(mesh->namedPoints[1].name, "child");
  EXPECT_FLOAT_EQ(mesh->namedPoints[1].position[0], 10.0f);
}

TEST(GltfMesh, CarriesOtherAttributesEveryPrimitiveHas) {
  glb::Primitive first = triangle();
  const std::vector<float> colours = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 1, 1};
  const std::vector<float> tangents = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
  first.attributes.push_back(glb::Attribute::fromFloats("COLOR_0", 4, colours));
  first.attributes.push_back(glb::Attribute::fromFloats("TANGENT", 4, tangents));
  first.attributes.push_back(glb::Attribute::fromFloats("_WEIGHT", 1, std::vector<float>{1, 2, 3, 4}));
  glb::Primitive second = first;
  second.attributes.pop_back();  // no _WEIGHT: it cannot survive
  glb::Package package;
  package.meshes.push_back({"quad", {first, second}});
  glb::Node node{"node", 0, {}, std::nullopt};
  node.rotation = {0, 0, 0.70710678118654752, 0.70710678118654752};  // 90 degrees about +z
  package.nodes = {node};
  const fs::path dir = test::freshTempDir("gltf_mesh_extras");
  ASSERT_TRUE(glb::write(dir / "scene.glb", package).isOk());
  auto mesh = readGltfMesh(dir / "scene.glb");
  ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
  ASSERT_EQ(mesh->extraAttributes.size(), 2u);
  EXPECT_EQ(mesh->extraAttributes[0].name, "COLOR_0");
  EXPECT_EQ(mesh->extraAttributes[0].count(), 8u);
  EXPECT_EQ(mesh->extraAttributes[0].toFloats()[4 * 5 + 1], 1.0f);  // vertex 1 of the second primitive: green
  ASSERT_EQ(mesh->extraAttributes[1].name, "TANGENT");
  const std::vector<float> t = mesh->extraAttributes[1].toFloats();
  EXPECT_NEAR(t[0], 0.0f, 1e-6);  // (1,0,0) turned to (0,1,0)
  EXPECT_NEAR(t[1], 1.0f, 1e-6);
  EXPECT_EQ(t[3], 1.0f);
}

TEST(GltfMesh, RejectsCyclesAndEmptyScenes) {
  glb::Package package;
  package.meshes.push_back({"tri", {triangle()}});
  package.nodes = {glb::Node{"a", 0, {1}, std::nullopt}, glb::Node{"b", -1, {0}, std::nullopt}};
  package.sceneRoots = {0};
  const fs::path dir = test::freshTempDir("gltf_mesh_bad");
  ASSERT_TRUE(glb::write(dir / "cycle.glb", package).isOk());
  const auto cycle = readGltfMesh(dir / "cycle.glb");
  EXPECT_EQ(cycle.status().code(), ExitCode::InvalidInput);
  EXPECT_NE(cycle.status().message().find("cycle"), std::string::npos);

  glb::Package lines;
  lines.meshes.push_back({"lines", {triangle(1)}});
  ASSERT_TRUE(glb::write(dir / "lines.glb", lines).isOk());
  EXPECT_EQ(readGltfMesh(dir / "lines.glb").status().code(), ExitCode::InvalidInput);
}

TEST(GltfMesh, ReadsTextGltfWithDataUri) {
  const fs::path dir = test::freshTempDir("gltf_text");
  // One triangle: 3 float3 positions (36 bytes) as base64.
  const std::string gltf = R"({"asset": {"version": "2.0"},
    "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
  std::ofstream(dir / "tri.gltf") << gltf;
  auto mesh = readGltfMesh(dir / "tri.gltf");
  ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
  ASSERT_EQ(mesh->triangleCount(), 1u);
  EXPECT_EQ(mesh->positions[1], (Vec3f{1, 0, 0}));
  EXPECT_EQ(mesh->positions[2], (Vec3f{0, 1, 0}));
}

}  // namespace
}  // namespace bake
