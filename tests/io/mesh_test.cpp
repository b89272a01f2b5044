// Mesh reading: small OBJ / OFF / PLY / STL files written from inline strings, checked for counts and
// values, and a table of malformed inputs that must fail with a specific exit code, message and line.
#include "bake/io/mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "mesh/mesh_stats.h"
#include "support/golden.h"

namespace bake {
namespace {
namespace fs = std::filesystem;

fs::path writeFile(const fs::path& dir, const std::string& name, const std::string& content) {
  const fs::path path = dir / name;
  std::ofstream(path, std::ios::binary).write(content.data(), std::streamsize(content.size()));
  return path;
}

// A binary STL: 80-byte header, triangle count, then per triangle a normal, three corners and 2 spare
// bytes.
std::string binaryStl(const std::vector<std::array<Vec3f, 3>>& triangles) {
  std::string bytes(80, ' ');
  const std::uint32_t count = std::uint32_t(triangles.size());
  bytes.append(reinterpret_cast<const char*>(&count), 4);
  for (const auto& triangle : triangles) {
    const float normal[3] = {0, 0, 1};
    bytes.append(reinterpret_cast<const char*>(normal), 12);
    for (const Vec3f& corner : triangle) bytes.append(reinterpret_cast<const char*>(corner.data()), 12);
    bytes.append(2, '\0');
  }
  return bytes;
}

Result<TriangleMesh> readText(const std::string& name, const std::string& content,
                              MeshReadStats* stats = nullptr, const MeshReadOptions& options = {}) {
  const fs::path dir = test::freshTempDir("mesh_" + fs::path(name).stem().string());
  return readMesh(writeFile(dir, name, content), options, stats);
}

TEST(MeshRead, ObjQuadNegativeIndicesNormalsAndTexcoords) {
  const std::string obj =
      "# unit square as a quad, then a triangle using relative indices\n"
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
      "vn 0 0 1\n"
      "g square\n"
      "f 1/1/1 2/2/1 3/3/1 4/4/1\n"
      "v 2 0.5 0\n"
      "f -4/2/1 -1/1/1 -3/3/1\n";
  MeshReadStats stats;
  const Result<TriangleMesh> mesh = readText("quad.obj", obj, &stats);
  ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
  EXPECT_EQ(mesh->vertexCount(), 5u);
  EXPECT_EQ(mesh->triangleCount(), 3u);
  EXPECT_EQ(stats.polygonsTriangulated, 1u);
  EXPECT_EQ(stats.verticesSplit, 0u);
  // Fan triangulation from the first corner, then the relative face.
  EXPECT_EQ(mesh->triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(mesh->triangles[1], (Triangle{0, 2, 3}));
  EXPECT_EQ(mesh->triangles[2], (Triangle{1, 4, 2}));
  EXPECT_EQ(mesh->positions[4], (Vec3f{2.0f, 0.5f, 0.0f}));
  ASSERT_EQ(mesh->normals.size(), 5u);
  ASSERT_EQ(mesh->texcoords.size(), 5u);
  for (const Vec3f& n : mesh->normals) EXPECT_EQ(n, (Vec3f{0, 0, 1}));
  EXPECT_EQ(mesh->texcoords[2], (Vec2f{1, 1}));
  EXPECT_EQ(mesh->texcoords[4], (Vec2f{0, 0}));
}

TEST(MeshRead, ObjSplitsVerticesWhoseCornersDisagree) {
  // Vertex 3 is used with texture coordinate 3 in one face and 4 in the other: a UV seam.
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0.5 0.5\n"
      "f 1/1 2/2 3/3\n"
      "f 1/1 3/4 4/4\n";
  MeshReadStats stats;
  const Result<TriangleMesh> mesh = readText("seam.obj", obj, &stats);
  ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
  EXPECT_EQ(stats.verticesSplit, 1u);
  ASSERT_EQ(mesh->vertexCount(), 5u);
  EXPECT_EQ(mesh->triangles[1], (Triangle{0, 4, 3}));
  EXPECT_EQ(mesh->positions[4], mesh->positions[2]);
  EXPECT_EQ(mesh->texcoords[2], (Vec2f{1, 1}));
  EXPECT_EQ(mesh->texcoords[4], (Vec2f{0.5f, 0.5f}));
  EXPECT_TRUE(mesh->normals.empty());
}

TEST(MeshRead, ObjDropsAttributesGivenForSomeCornersOnly) {
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 2 4 3\n";
  MeshReadStats stats;
  const Result<TriangleMesh> mesh = readText("partial.obj", obj, &stats);
  ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
  EXPECT_TRUE(mesh->normals.empty());
  EXPECT_EQ(stats.incompleteAttributesDropped, 1u);
  EXPECT_EQ(mesh->triangleCount(), 2u);
}

TEST(MeshRead, UppercaseExtensionAndUnreferencedVerticesAreKept) {
  const Result<TriangleMesh> mesh = readText("CAPS.OBJ", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\n");
  ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
  EXPECT_EQ(mesh->vertexCount(), 4u);
  EXPECT_EQ(mesh->triangleCount(), 1u);
}

TEST(MeshRead, FacesWithRepeatedVerticesAreRemovedAndCounted) {
  MeshReadStats objStats;
  const Result<TriangleMesh> obj =
      readText("repeat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 2\n", &objStats);
  ASSERT_TRUE(obj.isOk()) << obj.status().describe();
  EXPECT_EQ(obj->triangleCount(), 1u);
  EXPECT_EQ(objStats.degenerateFacesRemoved, 1u);

  MeshReadStats offStats;
  const Result<TriangleMesh> off = readText(
      "repeat.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 2 2 1\n4 1 3 3 2\n", &offStats);
  ASSERT_TRUE(off.isOk()) << off.status().describe();
  // "4 1 3 3 2" loses its repeated corner and stays as the triangle 1 3 2.
  EXPECT_EQ(off->triangleCount(), 2u);
  EXPECT_EQ(off->triangles[1], (Triangle{1, 3, 2}));
  EXPECT_EQ(offStats.degenerateFacesRemoved, 1u);

  const Result<TriangleMesh> none = readText("allrepeat.obj", "v 0 0 0\nv 1 0 0\nf 1 2 2\n");
  EXPECT_EQ(none.status().code(), ExitCode::InvalidInput);
  EXPECT_NE(none.status().message().find("degenerate"), std::string::npos) << none.status().describe();
}

TEST(MeshRead, OffWithQuadAndBlankLines) {
  const std::string off =
      "OFF\n"
      "5 2 0\n"
      "\n"
      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1.25\n"
      "4 0 1 2 3\n"
      "3 0 1 4\n";
  MeshReadStats stats;
  const Result<TriangleMesh> mesh = readText("quad.off", off, &stats);
  ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
  EXPECT_EQ(mesh->vertexCount(), 5u);
  EXPECT_EQ(mesh->triangleCount(), 3u);
  EXPECT_EQ(stats.polygonsTriangulated, 1u);
  EXPECT_EQ(mesh->positions[4], (Vec3f{0.5f, 0.5f, 1.25f}));
  EXPECT_EQ(mesh->triangles[2], (Triangle{0, 1, 4}));
  EXPECT_TRUE(mesh->normals.empty());
}

TEST(MeshRead, NoffKeepsPerVertexNormals) {
  const std::string off = "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 -1\n3 0 1 2\n";
  const Result<TriangleMesh> mesh = readText("normals.off", off);
  ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
  ASSERT_EQ(mesh->normals.size(), 3u);
  EXPECT_EQ(mesh->normals[2], (Vec3f{0, 0, -1}));
}

TEST(MeshRead, NonManifoldOffKeepsEveryFace) {
  // Three triangles on the edge 0-1: OpenMesh's mesh kernel would reject the third.
  const std::string off = "OFF\n5 3 0\n0 0 0\n1 0 0\n0.5 1 0\n0.5 -1 0\n0.5 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n";
  const Result<TriangleMesh> mesh = readText("fin.off", off);
  ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
  EXPECT_EQ(mesh->triangleCount(), 3u);
  EXPECT_EQ(computeMeshStats(*mesh).nonManifoldEdges, 1u);
}

TEST(MeshRead, AsciiPlyWithNormalsAndTexcoords) {
  const std::string ply =
      "ply\n"
      "format ascii 1.0\n"
      "comment made by hand\n"
      "element vertex 4\n"
      "property float x\nproperty float y\nproperty float z\n"
      "property float nx\nproperty float ny\nproperty float nz\n"
      "property float u\nproperty float v\n"
      "element face 1\n"
      "property list uchar int vertex_indices\n"
      "end_header\n"
      "0 0 0 0 0 1 0 0\n"
      "1 0 0 0 0 1 1 0\n"
      "1 1 0 0 0 1 1 1\n"
      "0 1 0 0 0 1 0 1\n"
      "4 0 1 2 3\n";
  MeshReadStats stats;
  const Result<TriangleMesh> mesh = readText("square.ply", ply, &stats);
  ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
  EXPECT_EQ(mesh->vertexCount(), 4u);
  EXPECT_EQ(mesh->triangleCount(), 2u);
  EXPECT_EQ(stats.polygonsTriangulated, 1u);
  ASSERT_EQ(mesh->normals.size(), 4u);
  ASSERT_EQ(mesh->texcoords.size(), 4u);
  EXPECT_EQ(mesh->texcoords[2], (Vec2f{1, 1}));
  EXPECT_EQ(mesh->positions[3], (Vec3f{0, 1, 0}));
}

std::string binaryPly(std::size_t vertexBytesToDrop) {
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const float vertices[9] = {0, 0, 0, 2, 0, 0, 0, 3, 0};
  ply.append(reinterpret_cast<const char*>(vertices), sizeof vertices - vertexBytesToDrop);
  if (vertexBytesToDrop == 0) {
    ply.push_back(char(3));
    const std::int32_t indices[3] = {0, 1, 2};
    ply.append(reinterpret_cast<const char*>(indices), sizeof indices);
  }
  return ply;
}

TEST(MeshRead, BinaryPly) {
  const Result<TriangleMesh> mesh = readText("binary.ply", binaryPly(0));
  ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
  EXPECT_EQ(mesh->vertexCount(), 3u);
  EXPECT_EQ(mesh->triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(mesh->positions[2], (Vec3f{0, 3, 0}));
}

TEST(MeshRead, AsciiStlMergesSharedCorners) {
  const std::string stl =
      "solid square\n"
      "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n      vertex 1 1 0\n"
      "    endloop\n  endfacet\n"
      "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 1 0\n      vertex 0 1 0\n"
      "    endloop\n  endfacet\n"
      "endsolid square\n";
  const Result<TriangleMesh> mesh = readText("square.stl", stl);
  ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
  EXPECT_EQ(mesh->vertexCount(), 4u);
  EXPECT_EQ(mesh->triangleCount(), 2u);
  EXPECT_EQ(computeMeshStats(*mesh).components, 1u);
}

TEST(MeshRead, BinaryStlCountsDroppedDegenerateTriangles) {
  const std::string stl = binaryStl({{Vec3f{0, 0, 0}, Vec3f{1, 0, 0}, Vec3f{1, 1, 0}},
                                     {Vec3f{0, 0, 0}, Vec3f{1, 1, 0}, Vec3f{0, 1, 0}},
                                     {Vec3f{0, 0, 0}, Vec3f{0, 0, 0}, Vec3f{0, 1, 0}}});
  MeshReadStats stats;
  const Result<TriangleMesh> mesh = readText("binary.stl", stl, &stats);
  ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
  EXPECT_EQ(mesh->vertexCount(), 4u);
  EXPECT_EQ(mesh->triangleCount(), 2u);
  EXPECT_EQ(stats.degenerateFacesRemoved, 1u);
  EXPECT_EQ(mesh->positions[1], (Vec3f{1, 0, 0}));
}

TEST(MeshRead, WeldOptionMergesDuplicatePositions) {
  // Two triangles sharing an edge, written as a soup.
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 4 5 6\n";
  MeshReadOptions options;
  options.weld = true;
  MeshReadStats stats;
  const Result<TriangleMesh> mesh = readText("soup.obj", obj, &stats, options);
  ASSERT_TRUE(mesh.isOk()) << mesh.status().describe();
  EXPECT_EQ(stats.verticesWelded, 2u);
  EXPECT_EQ(mesh->vertexCount(), 4u);
  EXPECT_EQ(mesh->triangles[1], (Triangle{0, 2, 3}));

  options.weldTolerance = -1.0;
  EXPECT_EQ(readText("soup.obj", obj, nullptr, options).status().code(), ExitCode::Usage);
}

// ---------------------------------------------------------------------------------------------------

struct MalformedCase {
  const char* label;
  const char* file;
  std::string content;
  ExitCode code;
  const char* messageFragment;
  const char* element;  // expected Location::element ("" = not checked)
};

std::vector<MalformedCase> malformedCases() {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const std::string offHead = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  const std::string plyHead =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string facet =
      "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
  return {
      {"obj non-numeric coordinate", "a.obj", "v 0 0 0\nv 1 x 0\n", ExitCode::InvalidInput,
       "'x' is not a number", "line 2"},
      {"obj NaN coordinate", "a.obj", "v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n", ExitCode::InvalidInput,
       "not a finite", "line 3"},
      {"obj infinite coordinate", "a.obj", "v 0 0 inf\n", ExitCode::InvalidInput, "not a finite", "line 1"},
      {"obj coordinate beyond float", "a.obj", "v 0 0 1e39\n", ExitCode::InvalidInput, "not a finite 32-bit",
       "line 1"},
      {"obj two coordinates", "a.obj", "# c\nv 0 0\n", ExitCode::InvalidInput, "expected 3 coordinates",
       "line 2"},
      {"obj normal with two values", "a.obj", tri + "vn 0 1\n", ExitCode::InvalidInput, "3 normal components",
       "line 4"},
      {"obj index out of range", "a.obj", tri + "f 1 2 4\n", ExitCode::InvalidInput,
       "vertex index 4 is out of range", "line 4"},
      {"obj index zero", "a.obj", tri + "f 0 1 2\n", ExitCode::InvalidInput, "index 0 is invalid", "line 4"},
      {"obj relative index too far back", "a.obj", tri + "f -1 -2 -4\n", ExitCode::InvalidInput,
       "reaches before", "line 4"},
      {"obj relative index counts only earlier vertices", "a.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n",
       ExitCode::InvalidInput, "reaches before", "line 3"},
      {"obj texcoord out of range", "a.obj", tri + "vt 0 0\nf 1/1 2/2 3/1\n", ExitCode::InvalidInput,
       "texture coordinate index 2", "line 5"},
      {"obj normal out of range", "a.obj", tri + "f 1//1 2//1 3//1\n", ExitCode::InvalidInput,
       "normal index 1", "line 4"},
      {"obj face with two vertices", "a.obj", tri + "f 1 2\n", ExitCode::InvalidInput, "at least 3",
       "line 4"},
      {"obj malformed corner", "a.obj", tri + "f 1 2/x 3\n", ExitCode::InvalidInput, "face corner '2/x'",
       "line 4"},
      {"obj 1D texture coordinate", "a.obj", tri + "vt 0.5\n", ExitCode::Unsupported, "1D texture", "line 4"},
      {"obj without faces", "a.obj", tri, ExitCode::InvalidInput, "no faces", ""},
      {"off missing keyword", "a.off", "3 1 0\n0 0 0\n", ExitCode::InvalidInput, "OFF header keyword",
       "line 1"},
      {"off two counts", "a.off", "OFF\n3 1\n", ExitCode::InvalidInput, "three counts", "line 2"},
      {"off counts on the keyword line", "a.off", "OFF 3 1 0\n0 0 0\n", ExitCode::Unsupported, "counts",
       "line 1"},
      {"off non-numeric coordinate", "a.off", "OFF\n3 1 0\n0 0 0\n1 0 zero\n", ExitCode::InvalidInput,
       "'zero' is not a number", "line 4"},
      {"off NaN coordinate", "a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n", ExitCode::InvalidInput,
       "not a finite", "line 5"},
      {"off vertex with four values", "a.off", "OFF\n3 1 0\n0 0 0 1\n", ExitCode::InvalidInput,
       "expected 3 values", "line 3"},
      {"off index out of range", "a.off", offHead + "3 0 1 3\n", ExitCode::InvalidInput,
       "vertex index 3 is out of range", "line 6"},
      {"off negative index", "a.off", offHead + "3 0 -1 2\n", ExitCode::InvalidInput, "out of range",
       "line 6"},
      {"off null face", "a.off", offHead + "0\n", ExitCode::InvalidInput, "face has 0 vertices", "line 6"},
      {"off two-vertex face", "a.off", offHead + "2 0 1\n", ExitCode::InvalidInput, "face has 2 vertices",
       "line 6"},
      {"off face count mismatch", "a.off", offHead + "4 0 1 2\n", ExitCode::InvalidInput,
       "declares 4 vertices but has 3", "line 6"},
      {"off fewer faces than declared", "a.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
       ExitCode::InvalidInput, "ends after 1", "line 2"},
      {"off fewer vertices than declared", "a.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n", ExitCode::InvalidInput,
       "declares 4 vertices", "line 2"},
      {"off more data than declared", "a.off", offHead + "3 0 1 2\n3 2 1 0\n", ExitCode::InvalidInput,
       "data after", "line 7"},
      {"off comment in data", "a.off", "OFF\n3 1 0\n# vertices\n0 0 0\n", ExitCode::Unsupported, "comments",
       "line 3"},
      {"ply without end_header", "a.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n",
       ExitCode::InvalidInput, "end_header", "header"},
      {"ply without z", "a.ply",
       "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nend_header\n",
       ExitCode::InvalidInput, "'z'", "line 3"},
      {"ply unknown keyword", "a.ply", "ply\nformat ascii 1.0\nelemnt vertex 3\nend_header\n",
       ExitCode::InvalidInput, "'elemnt'", "line 3"},
      {"ply NaN coordinate", "a.ply", plyHead + "0 0 0\n1 0 0\n0 NaN 0\n3 0 1 2\n", ExitCode::InvalidInput,
       "not a finite", "line 12"},
      {"ply missing value", "a.ply", plyHead + "0 0 0\n1 0\n0 1 0\n3 0 1 2\n", ExitCode::InvalidInput,
       "too few values", "line 11"},
      {"ply extra value", "a.ply", plyHead + "0 0 0\n1 0 0 7\n0 1 0\n3 0 1 2\n", ExitCode::InvalidInput,
       "too many values", "line 11"},
      {"ply index out of range", "a.ply", plyHead + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", ExitCode::InvalidInput,
       "vertex index 3 is out of range", "line 13"},
      {"ply two-vertex face", "a.ply", plyHead + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n", ExitCode::InvalidInput,
       "face has 2 vertices", "line 13"},
      {"ply fewer faces than declared", "a.ply", plyHead + "0 0 0\n1 0 0\n0 1 0\n", ExitCode::InvalidInput,
       "ends after 0", "line 7"},
      {"ply unsupported list count type", "a.ply",
       "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float "
       "z\nelement face 0\nproperty list uint32 int vertex_indices\nend_header\n",
       ExitCode::Unsupported, "list count type", "line 8"},
      {"ply binary truncated", "a.ply", binaryPly(8), ExitCode::InvalidInput, "truncated", ""},
      {"stl four-corner facet", "a.stl",
       "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 "
       "0\nendloop\nendfacet\nendsolid x\n",
       ExitCode::InvalidInput, "STL facets are triangles", "line 7"},
      {"stl NaN corner", "a.stl",
       "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 nan 0\nvertex 0 1 "
       "0\nendloop\nendfacet\nendsolid x\n",
       ExitCode::InvalidInput, "not a finite", "line 5"},
      {"stl cut inside a facet", "a.stl",
       "solid x\n" + facet + "facet normal 0 0 1\nouter loop\nvertex 0 0 0\n", ExitCode::InvalidInput,
       "ends inside a facet", "line 11"},
      {"stl missing outer loop", "a.stl", "solid x\nfacet normal 0 0 1\nvertex 0 0 0\n",
       ExitCode::InvalidInput, "expected 'outer loop'", "line 3"},
      {"stl neither ascii nor binary", "a.stl", std::string(120, 'x'), ExitCode::InvalidInput,
       "neither ASCII STL", ""},
      {"stl binary with NaN", "a.stl",
       binaryStl({{Vec3f{0, 0, 0}, Vec3f{1, 0, 0}, Vec3f{0, 1, 0}},
                  {Vec3f{0, 0, 0}, Vec3f{1, 0, 0}, Vec3f{0, std::nanf(""), 0}}}),
       ExitCode::InvalidInput, "not finite", "triangle 1"},
      {"stl 'outer' in a name", "a.stl", "solid outer_shell\n" + facet + "endsolid outer_shell\n",
       ExitCode::Unsupported, "'outer'", "line 1"},
      {"empty file", "a.obj", "", ExitCode::InvalidInput, "empty", ""},
      {"unknown extension", "a.xyz", "v 0 0 0\n", ExitCode::Unsupported, "'.xyz'", ""},
      {"no extension", "mesh", "v 0 0 0\n", ExitCode::Unsupported, "without extension", ""},
  };
}

TEST(MeshRead, MalformedInputsFailWithCodeMessageAndPlace) {
  const fs::path dir = test::freshTempDir("mesh_malformed");
  int index = 0;
  for (const MalformedCase& c : malformedCases()) {
    SCOPED_TRACE(c.label);
    const fs::path caseDir = dir / std::to_string(index++);
    fs::create_directories(caseDir);
    const fs::path path = writeFile(caseDir, c.file, c.content);
    const Result<TriangleMesh> mesh = readMesh(path);
    ASSERT_FALSE(mesh.isOk());
    const Status& status = mesh.status();
    EXPECT_EQ(status.code(), c.code) << status.describe();
    EXPECT_NE(status.message().find(c.messageFragment), std::string::npos) << status.describe();
    EXPECT_EQ(status.where().file, path.string());
    if (*c.element) EXPECT_EQ(status.where().element, c.element) << status.describe();
  }
}

TEST(MeshRead, MissingFileAndDirectoryAreIoErrors) {
  const fs::path dir = test::freshTempDir("mesh_io_errors");
  const Result<TriangleMesh> missing = readMesh(dir / "absent.obj");
  EXPECT_EQ(missing.status().code(), ExitCode::Io);
  EXPECT_NE(missing.status().describe().find("absent.obj"), std::string::npos);
  fs::create_directories(dir / "folder.off");
  EXPECT_EQ(readMesh(dir / "folder.off").status().code(), ExitCode::Io);
}

TEST(MeshRead, ErrorDescriptionNamesFileAndLine) {
  const fs::path dir = test::freshTempDir("mesh_describe");
  const fs::path path = writeFile(dir, "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  const std::string text = readMesh(path).status().describe();
  EXPECT_NE(text.find(path.string()), std::string::npos) << text;
  EXPECT_NE(text.find("line 4"), std::string::npos) << text;
}

TEST(MeshValidate, NamesTheOffendingElement) {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  Status status = validateMesh(mesh, "m");
  EXPECT_EQ(status.code(), ExitCode::InvalidInput);
  EXPECT_EQ(status.where().element, "triangle 1");

  mesh.triangles.pop_back();
  mesh.positions[1][2] = std::numeric_limits<float>::infinity();
  status = validateMesh(mesh, "m");
  EXPECT_EQ(status.where().element, "vertex 1");

  mesh.positions[1][2] = 0;
  mesh.texcoords = {{0, 0}, {1, 0}, {0, std::nanf("")}};
  EXPECT_EQ(validateMesh(mesh, "m").where().element, "vertex 2");
  mesh.texcoords.pop_back();
  EXPECT_EQ(validateMesh(mesh, "m").code(), ExitCode::InvalidInput);
  mesh.texcoords.clear();
  EXPECT_TRUE(validateMesh(mesh, "m").isOk());
}

}  // namespace
}  // namespace bake
