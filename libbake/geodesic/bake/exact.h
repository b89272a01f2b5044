// Exact polyhedral geodesic distances by continuous-Dijkstra window propagation (Mitchell, Mount and
// Papadimitriou 1987, as made practical by Surazhsky et al. 2005, with their endpoint filter: a window
// that cannot beat a path through an endpoint of its edge is dropped). All sources propagate together,
// so a combined min-field costs about as much as a single source. Edges the front has passed give their
// windows back, so memory follows the front's band rather than the whole field. Stages:
// exact_window.cpp (window geometry and unfolding), exact_propagate.cpp (edge lists, trimming, event
// queue, closing edges), exact.cpp (entry).
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "bake/geodesic/sources.h"
#include "bake/geodesic/surface.h"

namespace bake::geodesic {

struct ExactOptions {
  // Stop propagating beyond this distance (vertices farther away get kUnreachable); infinity = all.
  double maxDistance = kUnreachable;
  // Told now and then (every 16384 queue events, and at the end) how many vertices the front has
  // reached, for a progress bar; never changes the result.
  std::function<void(std::size_t reached)> onReached;
  // Safety limit on the windows made (new and split pieces), 0 for the default of 400 per edge plus
  // 10^6: it keeps pathological input finite in time (memory follows the front, not this limit). The
  // 454k-triangle pretzel, full of marching-tetrahedra slivers, needs 53 per edge.
  std::size_t maxWindows = 0;
};

struct ExactStats {
  std::size_t windowsCreated = 0;
  std::size_t windowsPropagated = 0;
  std::size_t windowsSplit = 0;   // extra pieces when a new window cut an existing one in two
  std::size_t windowsPeak = 0;    // most windows held at once (edges behind the front release theirs)
  std::size_t pseudoSources = 0;  // saddle and boundary vertices that re-emitted
  // ExactOptions::maxWindows was reached: the distances are then upper bounds (windows plus
  // edge paths) rather than exact. geobake warns (window-limit) and counts such fields in its report.
  bool windowLimitReached = false;
};

std::vector<double> exactDistances(const Surface& surface, std::span<const SurfacePoint> sources,
                                   const ExactOptions& options = {}, ExactStats* stats = nullptr);

}  // namespace bake::geodesic
