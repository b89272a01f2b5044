// The heat method (Crane, Weischedel and Wardetzky 2013) made robust (Sharp and Crane 2020; Sharp,
// Soliman and Crane 2019): the cotangent Laplacian is built on the intrinsic Delaunay triangulation
// (edge flips on edge lengths) of a mollified, tufted cover of the mesh, so needles, obtuse and
// zero-area faces and non-manifold edges all give a positive semi-definite, well-conditioned system.
// Both systems are factorised once (sparse Cholesky); every field after that costs two solves.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "bake/core/status.h"
#include "bake/geodesic/sources.h"
#include "bake/geodesic/surface.h"

namespace bake::geodesic {

struct HeatOptions {
  // Time step factor m in t = m h^2, h the mean intrinsic edge length; 0 picks it from the mesh so
  // that heat does not underflow far from the source on large meshes.
  double timeFactor = 0.0;
  // Mollification epsilon relative to the mean edge length.
  double mollifyFactor = 1e-6;
  // Threads (0: all cores) for build(), which factorises the two systems at once, and by default for
  // each field's solves; never changes the output.
  unsigned threads = 0;
  // Up to this many sources, the field is the minimum of one field per source (two solves each),
  // which is more accurate than one field from the heat of all sources together.
  std::size_t maxSeparateSources = 8;
  // Otherwise: sources in components with two or more sources are held at exactly 0 by a Dirichlet condition,
  // which costs one extra back-substitution per source; beyond this many the field is only shifted
  // so that its mean over the sources is 0 (then clamped at 0).
  std::size_t maxPinnedSources = 64;
};

struct HeatStats {
  std::size_t edgeFlips = 0;
  double timeStep = 0.0;
  double mollifyEpsilon = 0.0;
  std::size_t tuftedEdges = 0;  // non-manifold edges resolved by the tufted cover
  bool doubledCover = false;    // both sides of every face (boundary, non-manifold or unoriented input)
  double geodesicExtent = 0.0;  // estimated longest geodesic, which bounds the time step from below
  double intrinsicSeconds = 0.0;  // tufted cover, mollification, Delaunay flips, operators
  double factorSeconds = 0.0;     // assembly and sparse Cholesky factorisation of both systems
  // The factors' check (sparse Cholesky through the BLAS found at run time): the worst backward error
  // on a system with a known solution, how many failed it and were computed again without the BLAS,
  // and whether the BLAS, a sequential OpenBLAS, was called from one thread at a time.
  double factorBackwardError = 0.0;
  std::size_t factorsRedoneWithoutBlas = 0;
  bool blasOneAtATime = false;
};

class HeatSolver {
 public:
  static Result<HeatSolver> build(const Surface& surface, const HeatOptions& options = {});
  HeatSolver(HeatSolver&&) noexcept;
  HeatSolver& operator=(HeatSolver&&) noexcept;
  ~HeatSolver();

  // One field from the sources, on up to `threads` threads (0: HeatOptions::threads of build()); the
  // field does not depend on the thread count.
  std::vector<double> distances(std::span<const SurfacePoint> sources, unsigned threads = 0) const;
  const HeatStats& stats() const;

 private:
  struct State;
  explicit HeatSolver(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace bake::geodesic
