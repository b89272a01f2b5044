// CGAL's geodesic solvers as peers and oracles for libbake's own (tests and benchmarks only; CGAL is
// never linked into libbake). Two methods, behind plain std types so that CGAL's slow headers stay in
// one translation unit:
// - cgalExactDistances: Surface_mesh_shortest_path (Xin and Wang 2009, an improved Chen-Han exact
//   algorithm) on a Surface_mesh with the Epick kernel, every source added at once.
// - CgalHeatSolver: Heat_method_3 (Crane, Weischedel and Wardetzky 2013) on the intrinsic Delaunay
//   triangulation (Sharp, Soliman and Crane 2019); the matrices are factorised once at build.
// CGAL's Surface_mesh refuses non-manifold input and CGAL's preconditions throw: both come back as an
// error Status, never as a crash. Vertices no path reaches get +infinity (CGAL itself returns -1 from
// the exact method and DBL_MAX or garbage from the heat method there).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "bake/core/status.h"

namespace bake::peers {

using PeerPositions = std::vector<std::array<double, 3>>;
using PeerTriangles = std::vector<std::array<std::uint32_t, 3>>;

// Exact polyhedral distance from the nearest of `sourceVertices` to every vertex (one per position).
Result<std::vector<double>> cgalExactDistances(const PeerPositions& positions, const PeerTriangles& triangles,
                                               const std::vector<std::uint32_t>& sourceVertices);

class CgalHeatSolver {
 public:
  // Builds the intrinsic Delaunay mesh and factorises both systems.
  static Result<CgalHeatSolver> build(const PeerPositions& positions, const PeerTriangles& triangles);
  CgalHeatSolver(CgalHeatSolver&&) noexcept;
  CgalHeatSolver& operator=(CgalHeatSolver&&) noexcept;
  ~CgalHeatSolver();

  // Heat-method distance from the nearest of `sourceVertices` (all added at once) to every vertex.
  Result<std::vector<double>> distances(const std::vector<std::uint32_t>& sourceVertices);

 private:
  struct State;
  explicit CgalHeatSolver(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace bake::peers
