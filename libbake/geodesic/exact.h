// Exact polyhedral geodesic distances by continuous-Dijkstra window propagation (Mitchell, Mount and
// Papadimitriou 1987, as made practical by Surazhsky et al. 2005, with the vertex-oriented pruning of
// Qin et al. 2016). All sources propagate together, so a combined min-field costs about as much as a
// single source.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "geodesic/sources.h"
#include "geodesic/surface.h"

namespace bake::geodesic {

struct ExactOptions {
  // Stop propagating beyond this distance (vertices farther away get kUnreachable); infinity = all.
  double maxDistance = kUnreachable;
};

struct ExactStats {
  std::size_t windowsCreated = 0;
  std::size_t windowsPropagated = 0;
  std::size_t pseudoSources = 0;  // saddle and boundary vertices that re-emitted
};

std::vector<double> exactDistances(const Surface& surface, std::span<const SurfacePoint> sources,
                                   const ExactOptions& options = {}, ExactStats* stats = nullptr);

}  // namespace bake::geodesic
