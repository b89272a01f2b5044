// The surface every geodesic method works on: a welded, cleaned triangle mesh in double precision
// with explicit edge and vertex-to-face connectivity. Connectivity is stored as incidence lists
// (CSR), not half-edges, so non-manifold edges (three or more faces) and non-manifold vertices
// (bow-ties) are represented as they are: a geodesic crossing a non-manifold edge may continue into
// every other face of that edge, and a path through a vertex may continue into every face around it.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "bake/core/vec.h"
#include "bake/io/mesh.h"

namespace bake::geodesic {


// Distances of vertices that no path reaches (another connected component) inside the solvers.
// Packages never store it: the field writer replaces it by the recorded flag value.
inline constexpr double kUnreachable = std::numeric_limits<double>::infinity();

struct Surface {
  // Positions relative to `origin` (the input's bounding-box centre, so far-off models keep their
  // precision), the mesh's own origin included: world coordinates = positions + origin.
  std::vector<Vec3d> positions;
  Vec3d origin{0.0, 0.0, 0.0};
  std::vector<std::array<std::uint32_t, 3>> triangles;

  // Undirected edges, edges[e] = {a, b} with a < b.
  std::vector<std::array<std::uint32_t, 2>> edges;
  std::vector<double> edgeLengths;
  // triangleEdges[t][i] is the edge from corner i to corner (i + 1) % 3 of triangle t.
  std::vector<std::array<std::uint32_t, 3>> triangleEdges;

  // Faces around each edge: edgeFaces[edgeFaceOffsets[e] .. edgeFaceOffsets[e + 1]).
  std::vector<std::uint32_t> edgeFaceOffsets;
  std::vector<std::uint32_t> edgeFaces;
  // Faces around each vertex: vertexFaces[vertexFaceOffsets[v] .. vertexFaceOffsets[v + 1]).
  std::vector<std::uint32_t> vertexFaceOffsets;
  std::vector<std::uint32_t> vertexFaces;
  // Edges at each vertex: vertexEdges[vertexEdgeOffsets[v] .. vertexEdgeOffsets[v + 1]).
  std::vector<std::uint32_t> vertexEdgeOffsets;
  std::vector<std::uint32_t> vertexEdges;

  // Connected component of each vertex (through edges); isolated vertices get their own.
  std::vector<std::uint32_t> componentOf;
  std::uint32_t componentCount = 0;

  // Mean edge length (0 without edges) and bounding-box diagonal, for time steps and tolerances.
  double meanEdgeLength = 0.0;
  double diagonal = 0.0;

  std::size_t vertexCount() const { return positions.size(); }
  std::size_t triangleCount() const { return triangles.size(); }
  std::size_t edgeCount() const { return edges.size(); }

  std::span<const std::uint32_t> facesOfEdge(std::uint32_t e) const {
    return {edgeFaces.data() + edgeFaceOffsets[e], edgeFaces.data() + edgeFaceOffsets[e + 1]};
  }
  std::span<const std::uint32_t> facesOfVertex(std::uint32_t v) const {
    return {vertexFaces.data() + vertexFaceOffsets[v], vertexFaces.data() + vertexFaceOffsets[v + 1]};
  }
  std::span<const std::uint32_t> edgesOfVertex(std::uint32_t v) const {
    return {vertexEdges.data() + vertexEdgeOffsets[v], vertexEdges.data() + vertexEdgeOffsets[v + 1]};
  }
  // 0 = boundary edge, 1 = interior manifold edge, >= 2 = non-manifold edge.
  std::size_t neighbourCountOfEdge(std::uint32_t e) const {
    return edgeFaceOffsets[e + 1] - edgeFaceOffsets[e] - 1;
  }
  // Local index (0..2) of vertex v in triangle t, or 3 when v is not a corner of t.
  int cornerOf(std::uint32_t t, std::uint32_t v) const {
    for (int i = 0; i < 3; ++i)
      if (triangles[t][i] == v) return i;
    return 3;
  }
};

// What cleaning changed, for warnings and the report.
struct SurfaceCleanStats {
  std::size_t verticesWelded = 0;             // merged into an identical position
  std::size_t degenerateFacesRemoved = 0;     // repeated corner after welding
  std::size_t duplicateFacesRemoved = 0;      // same three vertices as an earlier face
  std::size_t zeroAreaFaces = 0;              // kept; every method copes with them
  std::size_t unreferencedVertices = 0;       // kept (unreachable unless a source)
  std::size_t boundaryEdges = 0;
  std::size_t nonManifoldEdges = 0;
  std::size_t components = 0;                 // with at least one face
};

// Builds the surface from a triangle mesh. Vertex indices are preserved one to one (the field is
// written per input vertex), so welding happens through `vertexMap`: positions that are
// bit-identical (or within weldTolerance x diagonal) map to one surface vertex.
struct SurfaceBuild {
  Surface surface;
  std::vector<std::uint32_t> vertexMap;  // input vertex -> surface vertex
  SurfaceCleanStats stats;
};
SurfaceBuild buildSurface(const TriangleMesh& mesh, double weldTolerance = 0.0);

// Builds the surface straight from positions and triangles already clean (tests, benchmarks).
Surface makeSurface(std::vector<Vec3d> positions, std::vector<std::array<std::uint32_t, 3>> triangles);

}  // namespace bake::geodesic
