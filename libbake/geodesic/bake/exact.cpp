// Entry point of the exact geodesic distances (Mitchell, Mount and Papadimitriou 1987; Surazhsky et
// al. 2005): every source seeds the one continuous Dijkstra of exact_propagate.cpp, so several sources
// give their combined min-field in one pass.
#include "geodesic/bake/exact.h"

#include "geodesic/bake/exact_propagate.h"

namespace bake::geodesic {

std::vector<double> exactDistances(const Surface& surface, std::span<const SurfacePoint> sources,
                                   const ExactOptions& options, ExactStats* stats) {
  exact::Propagator propagator(surface, options);
  for (const SurfacePoint& source : sources) {
    if (source.face < surface.triangleCount()) propagator.addSource(source);
  }
  propagator.run();
  if (stats) *stats = propagator.stats();
  return propagator.takeDistances();
}

}  // namespace bake::geodesic
