#include "bake/geodesic/surface.h"

#include <gtest/gtest.h>

#include <cmath>

#include "bake/geodesic/sources.h"

namespace bake::geodesic {
namespace {

TEST(GeodesicSurface, TetrahedronConnectivity) {
  const Surface s = makeSurface({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
  EXPECT_EQ(s.edgeCount(), 6u);
  for (std::uint32_t e = 0; e < s.edgeCount(); ++e) EXPECT_EQ(s.neighbourCountOfEdge(e), 1u);
  for (std::uint32_t v = 0; v < 4; ++v) {
    EXPECT_EQ(s.facesOfVertex(v).size(), 3u);
    EXPECT_EQ(s.edgesOfVertex(v).size(), 3u);
  }
  EXPECT_EQ(s.componentCount, 1u);
  // Local edge i joins corners i and i+1.
  for (std::uint32_t t = 0; t < 4; ++t)
    for (int i = 0; i < 3; ++i) {
      const auto& edge = s.edges[s.triangleEdges[t][i]];
      const std::uint32_t a = s.triangles[t][i], b = s.triangles[t][(i + 1) % 3];
      EXPECT_EQ(edge[0], std::min(a, b));
      EXPECT_EQ(edge[1], std::max(a, b));
    }
  EXPECT_DOUBLE_EQ(s.edgeLengths[s.triangleEdges[3][0]], std::sqrt(2.0));
}

TEST(GeodesicSurface, BuildWeldsCleansAndCountsComponents) {
  TriangleMesh mesh;
  // Two triangles sharing an edge given as a soup (6 vertices), a repeated face, and a far triangle.
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                    {5, 5, 5}, {6, 5, 5}, {5, 6, 5}};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}, {2, 1, 0}, {6, 7, 8}};
  const SurfaceBuild build = buildSurface(mesh);
  EXPECT_EQ(build.stats.verticesWelded, 2u);
  EXPECT_EQ(build.stats.duplicateFacesRemoved, 1u);
  EXPECT_EQ(build.surface.triangleCount(), 3u);
  EXPECT_EQ(build.stats.components, 2u);
  EXPECT_EQ(build.vertexMap[3], build.vertexMap[1]);
  EXPECT_EQ(build.vertexMap[5], build.vertexMap[2]);
  EXPECT_NE(build.surface.componentOf[build.vertexMap[0]], build.surface.componentOf[build.vertexMap[6]]);
  EXPECT_EQ(build.stats.boundaryEdges, 7u);
}

TEST(GeodesicSurface, NonManifoldEdgeKeepsAllFaces) {
  const Surface s = makeSurface({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}},
                                {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  std::size_t nonManifold = 0;
  for (std::uint32_t e = 0; e < s.edgeCount(); ++e) nonManifold += s.neighbourCountOfEdge(e) >= 2;
  EXPECT_EQ(nonManifold, 1u);
}

TEST(GeodesicSurface, VertexPointHasUnitWeight) {
  const Surface s = makeSurface({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  const SurfacePoint p = vertexPoint(s, 2);
  EXPECT_EQ(p.vertex(s), 2);
  EXPECT_EQ(p.position(s)[1], 1.0);
}

}  // namespace
}  // namespace bake::geodesic
