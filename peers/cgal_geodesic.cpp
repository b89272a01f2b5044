// CGAL peers for the geodesic solvers (see cgal_geodesic.h). The input is copied into a CGAL
// Surface_mesh holding only the vertices some triangle uses (isolated vertices would make the heat
// method's matrices singular); add_face refuses non-manifold edges and vertices and inconsistent
// orientation, which we report as invalid input. CGAL's own checks throw (or, in release builds, are
// compiled out), so we validate indices ourselves and catch what CGAL throws.
#include "cgal_geodesic.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <exception>
#include <limits>
#include <numeric>
#include <string>

namespace bake::peers {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using VertexIndex = Mesh::Vertex_index;
using ShortestPathTraits = CGAL::Surface_mesh_shortest_path_traits<Kernel, Mesh>;
using ShortestPath = CGAL::Surface_mesh_shortest_path<ShortestPathTraits>;
using HeatMethod =
    CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<Mesh, CGAL::Heat_method_3::Intrinsic_Delaunay>;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();

// The input as a CGAL mesh, with the maps between input vertices and mesh vertices, and the
// connected component of every input vertex (unreachable vertices are decided here, not by CGAL).
struct PeerMesh {
  Mesh mesh;
  std::vector<std::uint32_t> meshVertexOf;  // input vertex -> mesh vertex index, or kUnused
  std::vector<std::uint32_t> inputVertexOf; // mesh vertex index -> input vertex
  std::vector<std::uint32_t> componentOf;   // input vertex -> component root
};

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t v) {
  while (parent[v] != v) {
    parent[v] = parent[parent[v]];
    v = parent[v];
  }
  return v;
}

std::vector<std::uint32_t> componentsOf(std::size_t vertexCount, const PeerTriangles& triangles) {
  std::vector<std::uint32_t> parent(vertexCount);
  std::iota(parent.begin(), parent.end(), 0u);
  for (const auto& t : triangles)
    for (int i = 1; i < 3; ++i) parent[findRoot(parent, t[i])] = findRoot(parent, t[0]);
  for (std::uint32_t v = 0; v < vertexCount; ++v) parent[v] = findRoot(parent, v);
  return parent;
}

Status checkIndices(std::size_t vertexCount, const PeerTriangles& triangles) {
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    for (std::uint32_t v : tri)
      if (v >= vertexCount) return invalidInput("vertex index out of range", {"", "triangle " + std::to_string(t)});
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
      return invalidInput("repeated corner", {"", "triangle " + std::to_string(t)});
  }
  return Status::ok();
}

Result<std::unique_ptr<PeerMesh>> buildPeerMesh(const PeerPositions& positions, const PeerTriangles& triangles) {
  BAKE_RETURN_IF_ERROR(checkIndices(positions.size(), triangles));
  auto peer = std::make_unique<PeerMesh>();
  peer->meshVertexOf.assign(positions.size(), kUnused);
  for (const auto& tri : triangles)
    for (std::uint32_t v : tri) {
      if (peer->meshVertexOf[v] != kUnused) continue;
      peer->meshVertexOf[v] = static_cast<std::uint32_t>(peer->inputVertexOf.size());
      peer->inputVertexOf.push_back(v);
    }
  peer->mesh.reserve(peer->inputVertexOf.size(), 3 * triangles.size() / 2, triangles.size());
  for (std::uint32_t v : peer->inputVertexOf)
    peer->mesh.add_vertex(Kernel::Point_3(positions[v][0], positions[v][1], positions[v][2]));
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    const auto face = peer->mesh.add_face(VertexIndex(peer->meshVertexOf[tri[0]]),
                                          VertexIndex(peer->meshVertexOf[tri[1]]),
                                          VertexIndex(peer->meshVertexOf[tri[2]]));
    if (face == Mesh::null_face())
      return invalidInput("CGAL's Surface_mesh refuses the triangle (non-manifold edge or vertex, or "
                          "inconsistent orientation)", {"", "triangle " + std::to_string(t)});
  }
  peer->componentOf = componentsOf(positions.size(), triangles);
  return peer;
}

Result<std::vector<VertexIndex>> meshSources(const PeerMesh& peer, const std::vector<std::uint32_t>& sources) {
  std::vector<VertexIndex> result;
  for (std::uint32_t s : sources) {
    if (s >= peer.meshVertexOf.size())
      return invalidInput("source vertex out of range", {"", "vertex " + std::to_string(s)});
    if (peer.meshVertexOf[s] != kUnused) result.push_back(VertexIndex(peer.meshVertexOf[s]));
  }
  return result;
}

// Distances of CGAL's mesh vertices spread back to input vertices: sources get 0, vertices in a
// component without a source get +infinity (whatever CGAL said there).
std::vector<double> toInputVertices(const PeerMesh& peer, const std::vector<std::uint32_t>& sources,
                                    const std::vector<double>& meshDistances) {
  std::vector<char> componentHasSource(peer.componentOf.size(), 0);
  for (std::uint32_t s : sources) componentHasSource[peer.componentOf[s]] = 1;
  std::vector<double> result(peer.meshVertexOf.size(), kInfinity);
  for (std::size_t v = 0; v < result.size(); ++v)
    if (peer.meshVertexOf[v] != kUnused && componentHasSource[peer.componentOf[v]])
      result[v] = meshDistances[peer.meshVertexOf[v]];
  for (std::uint32_t s : sources) result[s] = 0.0;
  return result;
}

Status fromException(const char* method, const std::exception& error) {
  return internalError(std::string(method) + " failed: " + error.what());
}

}  // namespace

Result<std::vector<double>> cgalExactDistances(const PeerPositions& positions, const PeerTriangles& triangles,
                                               const std::vector<std::uint32_t>& sourceVertices) {
  try {
    BAKE_ASSIGN_OR_RETURN(auto peer, buildPeerMesh(positions, triangles));
    BAKE_ASSIGN_OR_RETURN(auto sources, meshSources(*peer, sourceVertices));
    ShortestPath shortestPath(peer->mesh);
    shortestPath.add_source_points(sources.begin(), sources.end());
    shortestPath.build_sequence_tree();
    std::vector<double> meshDistances(peer->inputVertexOf.size(), kInfinity);
    for (VertexIndex v : peer->mesh.vertices()) {
      const double d = shortestPath.shortest_distance_to_source_points(v).first;
      meshDistances[v.idx()] = d < 0.0 ? kInfinity : d;  // CGAL says -1 where it never arrived
    }
    return toInputVertices(*peer, sourceVertices, meshDistances);
  } catch (const std::exception& error) {
    return fromException("CGAL Surface_mesh_shortest_path", error);
  }
}

struct CgalHeatSolver::State {
  std::unique_ptr<PeerMesh> peer;
  std::unique_ptr<HeatMethod> heat;  // refers to peer->mesh, which therefore never moves
};

CgalHeatSolver::CgalHeatSolver(std::unique_ptr<State> state) : state_(std::move(state)) {}
CgalHeatSolver::CgalHeatSolver(CgalHeatSolver&&) noexcept = default;
CgalHeatSolver& CgalHeatSolver::operator=(CgalHeatSolver&&) noexcept = default;
CgalHeatSolver::~CgalHeatSolver() = default;

Result<CgalHeatSolver> CgalHeatSolver::build(const PeerPositions& positions, const PeerTriangles& triangles) {
  try {
    auto state = std::make_unique<State>();
    BAKE_ASSIGN_OR_RETURN(state->peer, buildPeerMesh(positions, triangles));
    state->heat = std::make_unique<HeatMethod>(state->peer->mesh);
    return CgalHeatSolver(std::move(state));
  } catch (const std::exception& error) {
    return fromException("CGAL Heat_method_3", error);
  }
}

Result<std::vector<double>> CgalHeatSolver::distances(const std::vector<std::uint32_t>& sourceVertices) {
  try {
    PeerMesh& peer = *state_->peer;
    BAKE_ASSIGN_OR_RETURN(auto sources, meshSources(peer, sourceVertices));
    std::vector<double> meshDistances(peer.inputVertexOf.size(), kInfinity);
    if (!sources.empty()) {
      state_->heat->clear_sources();
      state_->heat->add_sources(sources);
      auto distanceMap = peer.mesh.add_property_map<VertexIndex, double>("v:peer_distance", 0.0).first;
      state_->heat->estimate_geodesic_distances(distanceMap);
      for (VertexIndex v : peer.mesh.vertices()) meshDistances[v.idx()] = distanceMap[v];
      peer.mesh.remove_property_map(distanceMap);
    }
    return toInputVertices(peer, sourceVertices, meshDistances);
  } catch (const std::exception& error) {
    return fromException("CGAL Heat_method_3", error);
  }
}

}  // namespace bake::peers
