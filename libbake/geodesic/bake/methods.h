// The three ways of computing a geodesic distance field. All take a set of sources and return, for
// every surface vertex, the distance to the nearest source (a combined min-field); a field per source
// is a call per source. Vertices that no path reaches get kUnreachable.
//
// - exactDistances: exact polyhedral distances by window propagation (exact.h).
// - HeatSolver: the heat method on an intrinsic Delaunay, mollified Laplacian (heat.h).
// - fastMarchingDistances: first-order fast marching with unfolding at obtuse angles (fmm.h).
#pragma once

#include "bake/geodesic/heat.h"
#include "geodesic/bake/exact.h"
#include "geodesic/bake/fmm.h"
