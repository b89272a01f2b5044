// The triangle mesh every baker consumes: positions, triangles and optional per-vertex normals and
// texture coordinates, with the named points and extra glTF attributes a reader found (io/mesh.h
// reads and writes them).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bake/core/vec.h"
#include "bake/io/glb.h"

namespace bake {

using Triangle = std::array<std::uint32_t, 3>;

// A point with a name, e.g. a named glTF node, usable as a geodesic source.
struct NamedPoint {
  std::string name;
  Vec3f position{};
};

struct TriangleMesh {
  // Positions (and named points) are relative to `origin`: world = origin + position. The origin is
  // zero unless the reader was asked to keep a far-off mesh precise (MeshReadOptions::nearOrigin).
  std::vector<Vec3f> positions;
  Vec3d origin{};
  std::vector<Triangle> triangles;
  std::vector<Vec3f> normals;    // empty, or one per vertex
  std::vector<Vec2f> texcoords;  // empty, or one per vertex
  std::vector<NamedPoint> namedPoints;
  // Other per-vertex attributes of a glTF input (COLOR_0, TEXCOORD_1, TANGENT, JOINTS_0, _NAME, ...),
  // carried verbatim so a baker can write them back; only attributes every primitive has, with the
  // same layout, survive. TANGENT is transformed to world space like the positions.
  std::vector<glb::Attribute> extraAttributes;

  std::size_t vertexCount() const { return positions.size(); }
  std::size_t triangleCount() const { return triangles.size(); }
};

}  // namespace bake
