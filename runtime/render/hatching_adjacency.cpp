// Triangle adjacency for GL_TRIANGLES_ADJACENCY (seed 004 §3.3, figure 5: each triangle T_c drawn
// with the opposite vertices of its neighbours T_alpha, T_beta, T_gamma; §5: "triangle adjacency can be
// easily deduced ... at the loading step by indexing the model vertices").
//
// Positions are welded first: every vertex gets the id of the first vertex at a bit-identical position
// (-0 and +0 equal), so a seam of split normals or texture coordinates still connects. Each undirected
// edge of welded ids lists the triangles that use it, in index order. For edge (vi, vj) of a triangle
// the neighbour is the first other triangle on that edge, and the adjacency slot holds the neighbour's
// vertex that is not on the edge (its own index, so the attributes the shader reads are its own). An
// edge without a neighbour repeats the triangle's opposite vertex; the geometry stage recognises that
// (the neighbour then coincides with T_c) and gives it no blend. Edges of zero length (degenerate
// triangles) have no neighbour.
#include <cstring>
#include <unordered_map>

#include "render/hatching.h"

namespace bake::play {
namespace {

struct PositionKey {
  std::uint32_t bits[3];
  bool operator==(const PositionKey& o) const {
    return bits[0] == o.bits[0] && bits[1] == o.bits[1] && bits[2] == o.bits[2];
  }
};

struct PositionHash {
  std::size_t operator()(const PositionKey& k) const {
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint32_t b : k.bits) h = (h ^ b) * 1099511628211ull;
    return std::size_t(h);
  }
};

PositionKey keyOf(const float* p) {
  PositionKey key{};
  for (int k = 0; k < 3; ++k) {
    const float v = p[k] == 0.0f ? 0.0f : p[k];  // -0 welds with +0
    std::memcpy(&key.bits[k], &v, sizeof v);
  }
  return key;
}

}  // namespace

TriangleAdjacency buildTriangleAdjacency(const std::vector<float>& positions, const std::vector<std::uint32_t>& indices) {
  const std::size_t vertexCount = positions.size() / 3;
  std::vector<std::uint32_t> welded(vertexCount);
  {
    std::unordered_map<PositionKey, std::uint32_t, PositionHash> first;
    first.reserve(vertexCount);
    for (std::size_t v = 0; v < vertexCount; ++v) {
      welded[v] = first.emplace(keyOf(&positions[3 * v]), std::uint32_t(v)).first->second;
    }
  }
  const std::size_t triangleCount = indices.size() / 3;
  auto id = [&](std::size_t t, int corner) { return welded[indices[3 * t + std::size_t(corner)]]; };
  auto edgeKey = [](std::uint32_t a, std::uint32_t b) {
    return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
  };

  // Undirected edge -> triangles using it, in triangle order.
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> edges;
  edges.reserve(triangleCount * 2);
  for (std::size_t t = 0; t < triangleCount; ++t) {
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = id(t, e), b = id(t, (e + 1) % 3);
      if (a != b) edges[edgeKey(a, b)].push_back(std::uint32_t(t));
    }
  }

  TriangleAdjacency out;
  out.indices.resize(triangleCount * 6);
  for (std::size_t t = 0; t < triangleCount; ++t) {
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = id(t, e), b = id(t, (e + 1) % 3);
      std::uint32_t opposite = indices[3 * t + std::size_t((e + 2) % 3)];  // boundary: T_c's own vertex
      bool found = false;
      if (a != b) {
        const std::vector<std::uint32_t>& users = edges[edgeKey(a, b)];
        for (std::uint32_t other : users) {
          if (other == t) continue;
          for (int c = 0; c < 3; ++c) {
            const std::uint32_t w = id(other, c);
            if (w != a && w != b) {
              opposite = indices[3 * other + std::size_t(c)];
              found = true;
              break;
            }
          }
          if (found) break;
        }
      }
      if (!found) ++out.boundaryEdges;
      out.indices[6 * t + std::size_t(2 * e)] = indices[3 * t + std::size_t(e)];
      out.indices[6 * t + std::size_t(2 * e + 1)] = opposite;
    }
  }
  // Non-manifold edges, each counted once.
  for (const auto& [key, users] : edges) out.nonManifoldEdges += users.size() > 2 ? 1 : 0;
  return out;
}

}  // namespace bake::play
