// Structural statistics of a triangle mesh: bounding box, connected components (union-find over
// shared vertices), edge use counts (boundary / non-manifold) and zero-area triangles. Everything is
// computed from sorted or index-ordered data so the numbers never depend on hashing.
#include "mesh/mesh_stats.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace bake {
namespace {

// Disjoint sets over vertex indices; the smaller index becomes the root, which keeps the structure
// identical for identical input.
class UnionFind {
 public:
  explicit UnionFind(std::size_t size) : parent_(size) { std::iota(parent_.begin(), parent_.end(), 0u); }

  std::uint32_t find(std::uint32_t v) {
    while (parent_[v] != v) {
      parent_[v] = parent_[parent_[v]];  // path halving keeps the trees flat
      v = parent_[v];
    }
    return v;
  }

  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (b < a) std::swap(a, b);
    parent_[b] = a;
  }

 private:
  std::vector<std::uint32_t> parent_;
};

std::vector<bool> referencedVertices(const TriangleMesh& mesh) {
  std::vector<bool> used(mesh.positions.size(), false);
  for (const Triangle& t : mesh.triangles) {
    for (std::uint32_t v : t) used[v] = true;
  }
  return used;
}

std::size_t countComponents(const TriangleMesh& mesh, const std::vector<bool>& used) {
  UnionFind sets(mesh.positions.size());
  for (const Triangle& t : mesh.triangles) {
    sets.unite(t[0], t[1]);
    sets.unite(t[1], t[2]);
  }
  std::size_t roots = 0;
  for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
    if (used[v] && sets.find(v) == v) ++roots;
  }
  return roots;
}

// Every triangle side as an undirected key (low index in the high half), self-edges of degenerate
// triangles left out; sorted so equal edges are adjacent.
std::vector<std::uint64_t> sortedEdgeKeys(const TriangleMesh& mesh) {
  std::vector<std::uint64_t> keys;
  keys.reserve(mesh.triangles.size() * 3);
  for (const Triangle& t : mesh.triangles) {
    for (int side = 0; side < 3; ++side) {
      const std::uint32_t a = t[side];
      const std::uint32_t b = t[(side + 1) % 3];
      if (a == b) continue;
      keys.push_back((std::uint64_t(std::min(a, b)) << 32) | std::max(a, b));
    }
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

void countEdgeUses(const TriangleMesh& mesh, MeshStats& stats) {
  const std::vector<std::uint64_t> keys = sortedEdgeKeys(mesh);
  for (std::size_t begin = 0; begin < keys.size();) {
    std::size_t end = begin + 1;
    while (end < keys.size() && keys[end] == keys[begin]) ++end;
    const std::size_t uses = end - begin;
    if (uses == 1) ++stats.boundaryEdges;
    if (uses > 2) ++stats.nonManifoldEdges;
    begin = end;
  }
}

bool hasZeroArea(const TriangleMesh& mesh, const Triangle& t) {
  if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return true;
  const Vec3f& a = mesh.positions[t[0]];
  const Vec3f& b = mesh.positions[t[1]];
  const Vec3f& c = mesh.positions[t[2]];
  const double ux = double(b[0]) - a[0], uy = double(b[1]) - a[1], uz = double(b[2]) - a[2];
  const double vx = double(c[0]) - a[0], vy = double(c[1]) - a[1], vz = double(c[2]) - a[2];
  return uy * vz - uz * vy == 0.0 && uz * vx - ux * vz == 0.0 && ux * vy - uy * vx == 0.0;
}

}  // namespace

double BoundingBox::diagonal() const {
  if (empty) return 0.0;
  const double dx = double(max[0]) - min[0], dy = double(max[1]) - min[1], dz = double(max[2]) - min[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

BoundingBox boundingBoxOf(const std::vector<Vec3f>& points) {
  BoundingBox box;
  if (points.empty()) return box;
  box.empty = false;
  box.min = box.max = points.front();
  for (const Vec3f& p : points) {
    for (int axis = 0; axis < 3; ++axis) {
      box.min[axis] = std::min(box.min[axis], p[axis]);
      box.max[axis] = std::max(box.max[axis], p[axis]);
    }
  }
  return box;
}

MeshStats computeMeshStats(const TriangleMesh& mesh) {
  MeshStats stats;
  stats.bounds = boundingBoxOf(mesh.positions);
  const std::vector<bool> used = referencedVertices(mesh);
  stats.unreferencedVertices = std::size_t(std::count(used.begin(), used.end(), false));
  stats.components = countComponents(mesh, used);
  countEdgeUses(mesh, stats);
  for (const Triangle& t : mesh.triangles) {
    if (hasZeroArea(mesh, t)) ++stats.degenerateTriangles;
  }
  return stats;
}

}  // namespace bake
