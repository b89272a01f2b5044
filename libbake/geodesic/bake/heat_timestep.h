// The time step of the heat method. Crane et al. (2013, section 3.2.4) take t = h^2 (h the mean edge
// length), which is right for accuracy but lets the heat underflow far from the source on large
// meshes; heatTimeStep() bounds t from below by the surface's geodesic extent (see the .cpp).
#pragma once

#include "bake/geodesic/surface.h"

namespace bake::geodesic {

// An estimate of the largest geodesic distance within any component: the longest shortest path along
// edges found by a double sweep of Dijkstra's algorithm (exact on trees; at least half the diameter
// in general, and edge paths overestimate geodesics by a bounded factor on reasonable meshes).
double estimateGeodesicExtent(const Surface& surface);

// t = factor * h^2 when factor > 0; otherwise max(h^2, (extent / kMaxDecayLengths)^2).
double heatTimeStep(double meanEdgeLength, double extent, double factor);

// Largest number of decay lengths sqrt(t) a field may span, see heatTimeStep().
inline constexpr double kMaxDecayLengths = 350.0;

}  // namespace bake::geodesic
