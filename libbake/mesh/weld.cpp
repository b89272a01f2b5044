// Vertex welding. Exact mode hashes the bit patterns of position and attributes; tolerance mode
// buckets survivors into a uniform grid whose cells are one tolerance wide, so every candidate within
// reach lies in the 27 cells around a vertex. Both visit vertices in index order and merge into the
// lowest-indexed survivor, which makes the outcome a function of the mesh alone.
#include "mesh/weld.h"

#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <unordered_map>
#include <vector>

#include "mesh/mesh_stats.h"

namespace bake {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
// Below this relative tolerance grid coordinates could overflow; such tolerances are finer than
// float spacing anyway.
constexpr double kSmallestGridTolerance = 1e-15;

std::uint32_t bitsOf(float value) {
  value += 0.0f;  // turns -0 into +0 so that the two zeros weld
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

// Position and attributes of one vertex as raw bits: equal keys weld in exact mode.
using VertexKey = std::array<std::uint32_t, 8>;

struct VertexKeyHash {
  std::size_t operator()(const VertexKey& key) const {
    std::uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a over the words
    for (std::uint32_t word : key) {
      h ^= word;
      h *= 0x100000001b3ull;
    }
    return std::size_t(h);
  }
};

VertexKey keyOf(const TriangleMesh& mesh, std::uint32_t v, bool withPosition) {
  VertexKey key{};
  if (withPosition) {
    for (int i = 0; i < 3; ++i) key[i] = bitsOf(mesh.positions[v][i]);
  }
  if (!mesh.normals.empty()) {
    for (int i = 0; i < 3; ++i) key[3 + i] = bitsOf(mesh.normals[v][i]);
  }
  if (!mesh.texcoords.empty()) {
    for (int i = 0; i < 2; ++i) key[6 + i] = bitsOf(mesh.texcoords[v][i]);
  }
  return key;
}

// For each vertex, the vertex it merges into (itself for survivors), bit-exact positions.
std::vector<std::uint32_t> exactRepresentatives(const TriangleMesh& mesh) {
  const std::uint32_t count = std::uint32_t(mesh.positions.size());
  std::vector<std::uint32_t> representative(count);
  std::unordered_map<VertexKey, std::uint32_t, VertexKeyHash> firstWithKey;
  firstWithKey.reserve(count);
  for (std::uint32_t v = 0; v < count; ++v) {
    representative[v] = firstWithKey.try_emplace(keyOf(mesh, v, true), v).first->second;
  }
  return representative;
}

using Cell = std::array<std::int64_t, 3>;

struct CellHash {
  std::size_t operator()(const Cell& cell) const {
    std::uint64_t h = 0;
    for (std::int64_t c : cell) h = (h ^ std::uint64_t(c)) * 0x9e3779b97f4a7c15ull + (h >> 29);
    return std::size_t(h);
  }
};

double squaredDistance(const Vec3f& a, const Vec3f& b) {
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double d = double(a[i]) - b[i];
    sum += d * d;
  }
  return sum;
}

// For each vertex, the vertex it merges into: the lowest-indexed earlier survivor within `reach` with
// identical attributes.
std::vector<std::uint32_t> gridRepresentatives(const TriangleMesh& mesh, const BoundingBox& box,
                                               double reach) {
  const std::uint32_t count = std::uint32_t(mesh.positions.size());
  // Cells slightly wider than the reach so rounding in the division never pushes a neighbour within
  // reach two cells away.
  const double cellSize = reach * (1.0 + 1e-9);
  auto cellOf = [&](const Vec3f& p) {
    Cell cell;
    for (int i = 0; i < 3; ++i) cell[i] = std::int64_t(std::floor((double(p[i]) - box.min[i]) / cellSize));
    return cell;
  };
  const double reachSquared = reach * reach;
  std::vector<std::uint32_t> representative(count);
  std::unordered_map<Cell, std::vector<std::uint32_t>, CellHash> survivorsInCell;
  for (std::uint32_t v = 0; v < count; ++v) {
    const Cell home = cellOf(mesh.positions[v]);
    const VertexKey attributes = keyOf(mesh, v, false);
    std::uint32_t best = kNone;
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto found = survivorsInCell.find({home[0] + dx, home[1] + dy, home[2] + dz});
          if (found == survivorsInCell.end()) continue;
          for (std::uint32_t candidate : found->second) {
            if (candidate >= best) break;  // lists grow in index order
            if (squaredDistance(mesh.positions[candidate], mesh.positions[v]) <= reachSquared &&
                keyOf(mesh, candidate, false) == attributes) {
              best = candidate;
            }
          }
        }
      }
    }
    if (best == kNone) {
      representative[v] = v;
      survivorsInCell[home].push_back(v);
    } else {
      representative[v] = best;
    }
  }
  return representative;
}

// Drops merged vertices (survivors keep their order) and rewrites `representative` into the new
// index of each old vertex.
void compactVertices(TriangleMesh& mesh, std::vector<std::uint32_t>& representative) {
  std::vector<std::uint32_t> newIndex(representative.size(), kNone);
  std::uint32_t next = 0;
  for (std::uint32_t v = 0; v < representative.size(); ++v) {
    if (representative[v] != v) continue;
    newIndex[v] = next;
    mesh.positions[next] = mesh.positions[v];
    if (!mesh.normals.empty()) mesh.normals[next] = mesh.normals[v];
    if (!mesh.texcoords.empty()) mesh.texcoords[next] = mesh.texcoords[v];
    for (glb::Attribute& extra : mesh.extraAttributes) {  // survivors keep their own values
      const std::size_t size = extra.elementSize();
      std::memmove(extra.bytes.data() + next * size, extra.bytes.data() + std::size_t(v) * size, size);
    }
    ++next;
  }
  mesh.positions.resize(next);
  if (!mesh.normals.empty()) mesh.normals.resize(next);
  if (!mesh.texcoords.empty()) mesh.texcoords.resize(next);
  for (glb::Attribute& extra : mesh.extraAttributes) extra.bytes.resize(next * extra.elementSize());
  for (std::uint32_t& r : representative) r = newIndex[r];
}

std::size_t remapTriangles(TriangleMesh& mesh, const std::vector<std::uint32_t>& newIndex) {
  std::size_t kept = 0;
  for (const Triangle& old : mesh.triangles) {
    const Triangle t{newIndex[old[0]], newIndex[old[1]], newIndex[old[2]]};
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
    mesh.triangles[kept++] = t;
  }
  const std::size_t removed = mesh.triangles.size() - kept;
  mesh.triangles.resize(kept);
  return removed;
}

}  // namespace

WeldStats weldVertices(TriangleMesh& mesh, double relativeTolerance,
                       std::vector<std::uint32_t>* vertexMap) {
  assert(std::isfinite(relativeTolerance) && relativeTolerance >= 0.0);
  WeldStats stats;
  if (vertexMap) vertexMap->clear();
  if (mesh.positions.empty()) return stats;

  const BoundingBox box = boundingBoxOf(mesh.positions);
  const double reach = relativeTolerance * box.diagonal();
  std::vector<std::uint32_t> representative = relativeTolerance < kSmallestGridTolerance || !(reach > 0.0)
                                                  ? exactRepresentatives(mesh)
                                                  : gridRepresentatives(mesh, box, reach);

  const std::size_t before = mesh.positions.size();
  compactVertices(mesh, representative);
  stats.verticesWelded = before - mesh.positions.size();
  stats.degenerateTrianglesRemoved = remapTriangles(mesh, representative);
  if (vertexMap) *vertexMap = std::move(representative);
  return stats;
}

}  // namespace bake
