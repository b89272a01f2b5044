// Exact geodesic distances on the shared meshes: the planar stress grids (perturbed, needle, obtuse and
// zero-area triangulations) against the Euclidean distance in the plane; the degenerate stress meshes
// between the straight-line lower bound and the edge-path upper bound; the real meshes against CGAL's
// exact Surface_mesh_shortest_path (peers/cgal_geodesic.h) to 1e-6 relative, with one and eight sources.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <queue>

#include "bake/io/mesh.h"
#include "cgal_geodesic.h"
#include "geodesic/bake/exact.h"
#include "support/data.h"

namespace bake::geodesic {
namespace {

Surface loadSurface(const std::string& relative) {
  auto mesh = readMesh(test::dataDir() / "meshes" / relative);
  EXPECT_TRUE(mesh.isOk()) << relative;
  if (!mesh.isOk()) return {};
  return buildSurface(mesh.value()).surface;
}

SurfacePoint atVertex(const Surface& s, std::uint32_t v) {
  SurfacePoint p;
  p.face = s.facesOfVertex(v).front();
  p.barycentric = {0.0, 0.0, 0.0};
  p.barycentric[s.cornerOf(p.face, v)] = 1.0;
  return p;
}

// Deterministic, spread-out vertices that have faces.
std::vector<std::uint32_t> pickSources(const Surface& s, std::size_t count) {
  std::vector<std::uint32_t> out;
  for (std::size_t k = 0; out.size() < count && k < 10 * count + s.vertexCount(); ++k) {
    const auto v = std::uint32_t((k * 2654435761ull + 12345) % s.vertexCount());
    if (!s.facesOfVertex(v).empty() && std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
  }
  return out;
}

double euclidean(const Vec3d& a, const Vec3d& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

std::vector<double> edgePathDistances(const Surface& s, std::uint32_t source) {
  std::vector<double> d(s.vertexCount(), kUnreachable);
  using Item = std::pair<double, std::uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  d[source] = 0.0;
  queue.push({0.0, source});
  while (!queue.empty()) {
    const auto [dist, v] = queue.top();
    queue.pop();
    if (dist > d[v]) continue;
    for (std::uint32_t e : s.edgesOfVertex(v)) {
      const std::uint32_t w = s.edges[e][0] == v ? s.edges[e][1] : s.edges[e][0];
      if (dist + s.edgeLengths[e] < d[w]) queue.push({d[w] = dist + s.edgeLengths[e], w});
    }
  }
  return d;
}

class DataGeodesicExactGrid : public testing::TestWithParam<std::string> {};

TEST_P(DataGeodesicExactGrid, PlanarStressGridIsEuclidean) {
  BAKE_SKIP_WITHOUT_DATA();
  const Surface s = loadSurface("stress/" + GetParam());
  ASSERT_GT(s.triangleCount(), 0u);
  for (std::uint32_t source : pickSources(s, 3)) {
    const auto d = exactDistances(s, std::vector<SurfacePoint>{atVertex(s, source)});
    double worst = 0.0;
    for (std::uint32_t v = 0; v < s.vertexCount(); ++v) {
      if (s.facesOfVertex(v).empty()) continue;
      worst = std::max(worst, std::fabs(d[v] - euclidean(s.positions[v], s.positions[source])));
    }
    EXPECT_LT(worst, 1e-9 * s.diagonal) << GetParam() << " source " << source;
  }
  // A point inside a face, and one on an edge.
  for (const std::array<double, 3> weights : {std::array<double, 3>{0.3, 0.3, 0.4}, {0.5, 0.5, 0.0}}) {
    SurfacePoint p;
    p.face = std::uint32_t(s.triangleCount() / 3);
    p.barycentric = weights;
    const auto d = exactDistances(s, std::vector<SurfacePoint>{p});
    double worst = 0.0;
    for (std::uint32_t v = 0; v < s.vertexCount(); ++v)
      if (!s.facesOfVertex(v).empty())
        worst = std::max(worst, std::fabs(d[v] - euclidean(s.positions[v], p.position(s))));
    EXPECT_LT(worst, 1e-9 * s.diagonal) << GetParam();
  }
}

INSTANTIATE_TEST_SUITE_P(DataStress, DataGeodesicExactGrid,
                         testing::Values("grid_flat_64.off", "grid_needles.off", "grid_obtuse.off",
                                         "grid_zero_area.off"),
                         [](const auto& info) { return info.param.substr(0, info.param.find('.')); });

class DataGeodesicExactDegenerate : public testing::TestWithParam<std::string> {};

TEST_P(DataGeodesicExactDegenerate, BetweenStraightLineAndEdgePath) {
  BAKE_SKIP_WITHOUT_DATA();
  const Surface s = loadSurface("stress/" + GetParam());
  for (std::uint32_t source = 0; source < s.vertexCount(); ++source) {
    if (s.facesOfVertex(source).empty()) continue;
    const auto d = exactDistances(s, std::vector<SurfacePoint>{atVertex(s, source)});
    const auto upper = edgePathDistances(s, source);
    for (std::uint32_t v = 0; v < s.vertexCount(); ++v) {
      ASSERT_FALSE(std::isnan(d[v]));
      if (upper[v] == kUnreachable) {
        EXPECT_EQ(d[v], kUnreachable);
        continue;
      }
      const double tolerance = 1e-9 * std::max(1.0, s.diagonal);
      EXPECT_LE(d[v], upper[v] + tolerance) << GetParam() << " " << source << " -> " << v;
      EXPECT_GE(d[v], euclidean(s.positions[v], s.positions[source]) - tolerance);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(DataStress, DataGeodesicExactDegenerate,
                         testing::Values("all_degen.off", "degtri_nullface_bis.off", "non_manifold_face_graph.off"),
                         [](const auto& info) { return info.param.substr(0, info.param.find('.')); });

class DataGeodesicExactReal : public testing::TestWithParam<std::string> {};

TEST_P(DataGeodesicExactReal, AgreesWithCgal) {
  BAKE_SKIP_WITHOUT_DATA();
  const Surface s = loadSurface("real/" + GetParam());
  ASSERT_GT(s.triangleCount(), 0u);
  for (std::size_t count : {std::size_t(1), std::size_t(8)}) {
    const auto sources = pickSources(s, count);
    std::vector<SurfacePoint> points;
    for (std::uint32_t v : sources) points.push_back(atVertex(s, v));
    const auto start = std::chrono::steady_clock::now();
    ExactStats stats;
    const auto ours = exactDistances(s, points, {}, &stats);
    const auto middle = std::chrono::steady_clock::now();
    auto reference = peers::cgalExactDistances(s.positions, s.triangles, sources);
    const auto end = std::chrono::steady_clock::now();
    if (!reference.isOk()) {
      // CGAL refuses non-manifold input (the teapot): check the bounds every path length obeys instead.
      std::cout << GetParam() << ": CGAL refused (" << reference.status().message()
                << "); checking straight-line and edge-path bounds\n";
      const auto upper = edgePathDistances(s, sources.front());
      const auto single = exactDistances(s, std::vector<SurfacePoint>{points.front()});
      for (std::uint32_t v = 0; v < s.vertexCount(); ++v) {
        ASSERT_FALSE(std::isnan(ours[v]));
        EXPECT_LE(ours[v], single[v] + 1e-9 * s.diagonal);
        if (upper[v] == kUnreachable) {
          EXPECT_EQ(single[v], kUnreachable) << v;
          continue;
        }
        const double tolerance = 1e-9 * s.diagonal;
        EXPECT_LE(single[v], upper[v] + tolerance) << v;
        EXPECT_GE(single[v], euclidean(s.positions[v], s.positions[sources.front()]) - tolerance) << v;
      }
      continue;
    }
    const double oursMs = std::chrono::duration<double, std::milli>(middle - start).count();
    const double cgalMs = std::chrono::duration<double, std::milli>(end - middle).count();
    std::cout << GetParam() << " sources " << count << ": exact " << oursMs << " ms, CGAL " << cgalMs
              << " ms, windows " << stats.windowsCreated << " created " << stats.windowsPropagated
              << " propagated, " << stats.windowsPeak << " held at most, pseudo-sources " << stats.pseudoSources << "\n";
    // Edges behind the front give their windows back: the most held at once is a small part of all
    // the windows made (memory follows the front's band, not the mesh).
    EXPECT_LT(stats.windowsPeak * 4, stats.windowsCreated) << GetParam() << " sources " << count;
    double worst = 0.0;
    std::uint32_t worstVertex = 0;
    for (std::uint32_t v = 0; v < s.vertexCount(); ++v) {
      const double ref = (*reference)[v];
      if (s.facesOfVertex(v).empty()) continue;
      if (ref == kUnreachable) {
        EXPECT_EQ(ours[v], kUnreachable) << v;
        continue;
      }
      const double error = std::fabs(ours[v] - ref) / std::max(ref, s.meanEdgeLength);
      if (error > worst) worst = error, worstVertex = v;
    }
    EXPECT_LT(worst, 1e-6) << GetParam() << " sources " << count << " worst vertex " << worstVertex
                           << " ours " << ours[worstVertex] << " CGAL " << (*reference)[worstVertex];
  }
}

INSTANTIATE_TEST_SUITE_P(DataReal, DataGeodesicExactReal,
                         testing::Values("camelhead.off", "fertility.off", "nefertiti.obj", "stanford-bunny.obj",
                                         "teapot.obj"),
                         [](const auto& info) {
                           std::string name = info.param.substr(0, info.param.find('.'));
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace bake::geodesic
