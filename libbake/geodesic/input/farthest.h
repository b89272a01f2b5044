// Farthest-point sampling of sources (Eldar et al. 1997; Peyré and Cohen 2006 for geodesic distance):
// start from the vertex farthest from vertex 0, then repeatedly add the vertex farthest from all
// chosen ones. Unreachable vertices count as farthest, so every component receives a source before
// any component receives a second one. Distances come from fast marching, which is plenty to spread
// sources evenly.
#pragma once

#include <cstdint>
#include <vector>

#include "bake/geodesic/surface.h"

namespace bake::geodesic {

// Surface vertices with at least one face; ties go to the lowest index (deterministic).
std::vector<std::uint32_t> farthestPointSamples(const Surface& surface, unsigned count);

}  // namespace bake::geodesic
