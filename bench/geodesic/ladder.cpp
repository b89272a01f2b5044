// The mesh ladder: each base mesh (the shared real meshes, and an icosphere for the smallest sizes)
// is refined by 1:4 subdivision until the triangle budget (the sphere is re-projected at each level). Plain midpoint subdivision keeps the surface
// itself unchanged, so exact distances between base vertices stay the same on every rung and only the
// approximate methods' errors move; Loop's rules (Loop 1987, "Smooth subdivision surfaces based on
// triangles", section 3.2) optionally smooth it instead. New vertices are appended, so the base
// vertices, and with them the sources, keep their indices on every rung.
#include <algorithm>
#include <cmath>

#include "bake/io/mesh.h"
#include "bench_geodesic.h"
#include "geodesic/input/farthest.h"

namespace bake::bench {
namespace {

using geodesic::Surface;

Vec3d mix(const std::vector<Vec3d>& p, std::initializer_list<std::pair<std::uint32_t, double>> terms) {
  Vec3d r{0.0, 0.0, 0.0};
  for (const auto& [v, w] : terms)
    for (int k = 0; k < 3; ++k) r[k] += w * p[v][k];
  return r;
}

std::uint32_t oppositeCorner(const Surface& s, std::uint32_t face, const std::array<std::uint32_t, 2>& edge) {
  for (std::uint32_t v : s.triangles[face])
    if (v != edge[0] && v != edge[1]) return v;
  return edge[0];
}

// Loop's edge rule (3/8, 3/8, 1/8, 1/8) on interior manifold edges; the midpoint elsewhere.
Vec3d oddVertex(const Surface& s, std::uint32_t e) {
  const auto& edge = s.edges[e];
  const auto faces = s.facesOfEdge(e);
  if (faces.size() != 2) return mix(s.positions, {{edge[0], 0.5}, {edge[1], 0.5}});
  return mix(s.positions, {{edge[0], 0.375}, {edge[1], 0.375},
                           {oppositeCorner(s, faces[0], edge), 0.125}, {oppositeCorner(s, faces[1], edge), 0.125}});
}

// Loop's vertex rule with Warren's weights; boundary vertices follow their boundary curve; vertices on
// non-manifold edges stay put.
Vec3d evenVertex(const Surface& s, std::uint32_t v) {
  std::vector<std::uint32_t> ring, boundaryRing;
  for (std::uint32_t e : s.edgesOfVertex(v)) {
    const std::uint32_t other = s.edges[e][0] == v ? s.edges[e][1] : s.edges[e][0];
    const std::size_t faces = s.facesOfEdge(e).size();
    if (faces > 2) return s.positions[v];
    ring.push_back(other);
    if (faces == 1) boundaryRing.push_back(other);
  }
  if (boundaryRing.size() == 2)
    return mix(s.positions, {{v, 0.75}, {boundaryRing[0], 0.125}, {boundaryRing[1], 0.125}});
  if (!boundaryRing.empty() || ring.size() < 3) return s.positions[v];
  const double n = double(ring.size());
  const double beta = ring.size() == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * n);
  Vec3d r = s.positions[v];
  for (int k = 0; k < 3; ++k) r[k] *= 1.0 - n * beta;
  for (std::uint32_t u : ring)
    for (int k = 0; k < 3; ++k) r[k] += beta * s.positions[u][k];
  return r;
}

// Eight sources spread over the base mesh by farthest-point sampling (the first is the single source).
std::vector<std::uint32_t> spreadSources(const Surface& s) { return geodesic::farthestPointSamples(s, 8); }

}  // namespace

Surface subdivide(const Surface& s, bool loopSmoothing) {
  const auto vertexCount = static_cast<std::uint32_t>(s.vertexCount());
  std::vector<Vec3d> positions(s.vertexCount() + s.edgeCount());
  for (std::uint32_t v = 0; v < vertexCount; ++v)
    positions[v] = loopSmoothing ? evenVertex(s, v) : s.positions[v];
  for (std::uint32_t e = 0; e < s.edgeCount(); ++e)
    positions[vertexCount + e] =
        loopSmoothing ? oddVertex(s, e) : mix(s.positions, {{s.edges[e][0], 0.5}, {s.edges[e][1], 0.5}});
  std::vector<std::array<std::uint32_t, 3>> triangles;
  triangles.reserve(4 * s.triangleCount());
  for (std::size_t t = 0; t < s.triangleCount(); ++t) {
    const auto& [a, b, c] = s.triangles[t];
    // Midpoint of local edge i (corner i to corner i + 1).
    const std::uint32_t ab = vertexCount + s.triangleEdges[t][0];
    const std::uint32_t bc = vertexCount + s.triangleEdges[t][1];
    const std::uint32_t ca = vertexCount + s.triangleEdges[t][2];
    triangles.insert(triangles.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
  }
  return geodesic::makeSurface(std::move(positions), std::move(triangles));
}

Surface icosphere(int levels) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3d> p{{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                       {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  std::vector<std::array<std::uint32_t, 3>> t{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                              {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                              {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                              {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  Surface s = geodesic::makeSurface(std::move(p), std::move(t));
  for (int level = 0; level < levels; ++level) s = subdivide(s, false);
  for (Vec3d& v : s.positions) {
    const double r = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (double& x : v) x /= r;
  }
  return geodesic::makeSurface(std::move(s.positions), std::move(s.triangles));
}

Result<std::vector<LadderBase>> loadBases(const LadderOptions& options) {
  std::vector<LadderBase> bases;
  if (options.sphere) {
    LadderBase sphere{"sphere", icosphere(3), {}};  // 1280 triangles
    sphere.sources = spreadSources(sphere.surface);
    bases.push_back(std::move(sphere));
  }
  for (const auto& path : options.meshes) {
    auto mesh = readMesh(path);
    if (!mesh.isOk()) return mesh.takeStatus().inFile(path.string());
    LadderBase base{path.stem().string(), geodesic::buildSurface(mesh.value()).surface, {}};
    if (base.surface.triangleCount() == 0) return invalidInput("no triangles", {path.string(), ""});
    base.sources = spreadSources(base.surface);
    bases.push_back(std::move(base));
  }
  return bases;
}

std::vector<RungPlan> planLadder(const std::vector<LadderBase>& bases, std::size_t maxTriangles) {
  std::vector<RungPlan> plan;
  for (std::size_t b = 0; b < bases.size(); ++b)
    for (int levels = 0;; ++levels) {
      const std::size_t triangles = bases[b].surface.triangleCount() << (2 * levels);
      if (triangles > maxTriangles) break;
      plan.push_back({b, levels, triangles});
    }
  std::stable_sort(plan.begin(), plan.end(), [](const RungPlan& a, const RungPlan& b) {
    return a.triangles < b.triangles;
  });
  return plan;
}

Rung buildRung(const LadderBase& base, int levels, bool loopSmoothing) {
  Rung rung{base.name + "/" + std::to_string(levels), base.surface, base.sources};
  if (base.name == "sphere") {  // refined on the sphere itself, so that it stays a sphere
    rung.surface = icosphere(3 + levels);
    return rung;
  }
  for (int level = 0; level < levels; ++level) rung.surface = subdivide(rung.surface, loopSmoothing);
  return rung;
}

}  // namespace bake::bench
