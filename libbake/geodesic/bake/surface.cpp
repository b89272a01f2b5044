// Building the geodesic surface: weld, drop faces with a repeated corner and repeated faces, then
// derive edges, incidence lists, components and scale measures. Vertex indices of the input survive
// through vertexMap so fields can be written back per input vertex.
#include "bake/geodesic/surface.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include "mesh/mesh_stats.h"
#include "mesh/weld.h"

namespace bake::geodesic {
namespace {

using Tri = std::array<std::uint32_t, 3>;

double distanceBetween(const Vec3d& a, const Vec3d& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

bool zeroArea(const Surface& s, const Tri& t) {
  const Vec3d& a = s.positions[t[0]];
  const Vec3d& b = s.positions[t[1]];
  const Vec3d& c = s.positions[t[2]];
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2], z = u[0] * v[1] - u[1] * v[0];
  return x == 0.0 && y == 0.0 && z == 0.0;
}

// CSR from (key, value) pairs whose keys are < keyCount; values keep their insertion order per key.
void buildIncidence(std::size_t keyCount, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs,
                    std::vector<std::uint32_t>& offsets, std::vector<std::uint32_t>& values) {
  offsets.assign(keyCount + 1, 0);
  for (const auto& [key, value] : pairs) ++offsets[key + 1];
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  values.resize(pairs.size());
  std::vector<std::uint32_t> cursor(offsets.begin(), offsets.end() - 1);
  for (const auto& [key, value] : pairs) values[cursor[key]++] = value;
}

void buildEdges(Surface& s) {
  const std::size_t faceCount = s.triangles.size();
  // Sort directed corner pairs by their undirected key to number the edges deterministically.
  struct HalfEdge {
    std::uint64_t key;
    std::uint32_t face;
    std::uint32_t local;
  };
  std::vector<HalfEdge> halfEdges;
  halfEdges.reserve(faceCount * 3);
  for (std::uint32_t t = 0; t < faceCount; ++t)
    for (std::uint32_t i = 0; i < 3; ++i) {
      std::uint32_t a = s.triangles[t][i], b = s.triangles[t][(i + 1) % 3];
      if (a > b) std::swap(a, b);
      halfEdges.push_back({(std::uint64_t(a) << 32) | b, t, i});
    }
  std::sort(halfEdges.begin(), halfEdges.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.key != y.key ? x.key < y.key : (x.face != y.face ? x.face < y.face : x.local < y.local);
  });
  s.triangleEdges.assign(faceCount, {0, 0, 0});
  s.edges.clear();
  s.edgeFaceOffsets.assign(1, 0);
  s.edgeFaces.clear();
  for (std::size_t i = 0; i < halfEdges.size(); ++i) {
    if (i == 0 || halfEdges[i].key != halfEdges[i - 1].key) {
      if (i != 0) s.edgeFaceOffsets.push_back(std::uint32_t(s.edgeFaces.size()));
      s.edges.push_back({std::uint32_t(halfEdges[i].key >> 32), std::uint32_t(halfEdges[i].key & 0xffffffffu)});
    }
    const auto e = std::uint32_t(s.edges.size() - 1);
    s.triangleEdges[halfEdges[i].face][halfEdges[i].local] = e;
    s.edgeFaces.push_back(halfEdges[i].face);
  }
  if (!halfEdges.empty()) s.edgeFaceOffsets.push_back(std::uint32_t(s.edgeFaces.size()));
  s.edgeLengths.resize(s.edges.size());
  for (std::size_t e = 0; e < s.edges.size(); ++e)
    s.edgeLengths[e] = distanceBetween(s.positions[s.edges[e][0]], s.positions[s.edges[e][1]]);
}

void buildVertexIncidence(Surface& s) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  pairs.reserve(s.triangles.size() * 3);
  for (std::uint32_t t = 0; t < s.triangles.size(); ++t)
    for (std::uint32_t v : s.triangles[t]) pairs.emplace_back(v, t);
  buildIncidence(s.positions.size(), pairs, s.vertexFaceOffsets, s.vertexFaces);
  pairs.clear();
  for (std::uint32_t e = 0; e < s.edges.size(); ++e) {
    pairs.emplace_back(s.edges[e][0], e);
    pairs.emplace_back(s.edges[e][1], e);
  }
  std::sort(pairs.begin(), pairs.end());
  buildIncidence(s.positions.size(), pairs, s.vertexEdgeOffsets, s.vertexEdges);
}

void buildComponents(Surface& s) {
  const std::size_t n = s.positions.size();
  s.componentOf.assign(n, UINT32_MAX);
  s.componentCount = 0;
  std::vector<std::uint32_t> stack;
  for (std::uint32_t start = 0; start < n; ++start) {
    if (s.componentOf[start] != UINT32_MAX) continue;
    const std::uint32_t id = s.componentCount++;
    s.componentOf[start] = id;
    stack.assign(1, start);
    while (!stack.empty()) {
      const std::uint32_t v = stack.back();
      stack.pop_back();
      for (std::uint32_t e : s.edgesOfVertex(v)) {
        const std::uint32_t w = s.edges[e][0] == v ? s.edges[e][1] : s.edges[e][0];
        if (s.componentOf[w] == UINT32_MAX) {
          s.componentOf[w] = id;
          stack.push_back(w);
        }
      }
    }
  }
}

void buildScales(Surface& s) {
  s.meanEdgeLength = s.edgeLengths.empty()
                         ? 0.0
                         : std::accumulate(s.edgeLengths.begin(), s.edgeLengths.end(), 0.0) /
                               double(s.edgeLengths.size());
  if (s.positions.empty()) {
    s.diagonal = 0.0;
    return;
  }
  Vec3d lo = s.positions[0], hi = s.positions[0];
  for (const Vec3d& p : s.positions)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  s.diagonal = distanceBetween(lo, hi);
}

void finishSurface(Surface& s) {
  buildEdges(s);
  buildVertexIncidence(s);
  buildComponents(s);
  buildScales(s);
}

}  // namespace

Surface makeSurface(std::vector<Vec3d> positions, std::vector<std::array<std::uint32_t, 3>> triangles) {
  Surface s;
  s.positions = std::move(positions);
  s.triangles = std::move(triangles);
  finishSurface(s);
  return s;
}

SurfaceBuild buildSurface(const TriangleMesh& mesh, double weldTolerance) {
  SurfaceBuild build;
  // Weld on positions only: a seam in normals or texture coordinates is not a cut in the surface.
  TriangleMesh positionsOnly;
  positionsOnly.positions = mesh.positions;
  positionsOnly.triangles = mesh.triangles;
  const WeldStats weld = weldVertices(positionsOnly, weldTolerance, &build.vertexMap);
  if (build.vertexMap.empty()) build.vertexMap.resize(mesh.positions.size());  // no vertices at all
  build.stats.verticesWelded = weld.verticesWelded;
  build.stats.degenerateFacesRemoved = weld.degenerateTrianglesRemoved;

  Surface& s = build.surface;
  // Centre the coordinates in double before any arithmetic: a model placed 1e7 away from the origin
  // keeps its full precision for the edge lengths and unfoldings (distances do not change).
  const BoundingBox box = boundingBoxOf(positionsOnly.positions);
  Vec3d centre{0.0, 0.0, 0.0};
  for (int k = 0; k < 3; ++k) centre[k] = 0.5 * (double(box.min[k]) + double(box.max[k]));
  s.positions.reserve(positionsOnly.positions.size());
  for (const Vec3f& p : positionsOnly.positions)
    s.positions.push_back({double(p[0]) - centre[0], double(p[1]) - centre[1], double(p[2]) - centre[2]});
  // The mesh's own origin (a far-off mesh read relative to its centre, io/mesh.h) makes it world space.
  for (int k = 0; k < 3; ++k) s.origin[k] = mesh.origin[k] + centre[k];

  // Repeated faces (same corner set) would make a clean edge look non-manifold.
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> seen;
  s.triangles.reserve(positionsOnly.triangles.size());
  for (const Triangle& t : positionsOnly.triangles) {
    Tri sorted = t;
    std::sort(sorted.begin(), sorted.end());
    const std::uint64_t key = (std::uint64_t(sorted[0]) * 0x9e3779b97f4a7c15ull) ^
                              (std::uint64_t(sorted[1]) << 21) ^ (std::uint64_t(sorted[2]) << 42);
    auto& candidates = seen[key];
    bool duplicate = false;
    for (std::uint32_t other : candidates) {
      Tri o = s.triangles[other];
      std::sort(o.begin(), o.end());
      if (o == sorted) duplicate = true;
    }
    if (duplicate) {
      ++build.stats.duplicateFacesRemoved;
      continue;
    }
    candidates.push_back(std::uint32_t(s.triangles.size()));
    s.triangles.push_back(t);
  }
  finishSurface(s);

  SurfaceCleanStats& st = build.stats;
  for (const Tri& t : s.triangles) st.zeroAreaFaces += zeroArea(s, t) ? 1 : 0;
  for (std::uint32_t v = 0; v < s.positions.size(); ++v)
    st.unreferencedVertices += s.vertexFaceOffsets[v] == s.vertexFaceOffsets[v + 1] ? 1 : 0;
  for (std::uint32_t e = 0; e < s.edges.size(); ++e) {
    const std::size_t faces = s.edgeFaceOffsets[e + 1] - s.edgeFaceOffsets[e];
    st.boundaryEdges += faces == 1 ? 1 : 0;
    st.nonManifoldEdges += faces >= 3 ? 1 : 0;
  }
  std::vector<bool> hasFace(s.componentCount, false);
  for (const Tri& t : s.triangles) hasFace[s.componentOf[t[0]]] = true;
  st.components = std::size_t(std::count(hasFace.begin(), hasFace.end(), true));
  return build;
}

}  // namespace bake::geodesic
