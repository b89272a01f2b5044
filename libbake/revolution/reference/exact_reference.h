// An independent reference for the signed distance a vector profile's shape map stores. It shares no
// code with the code that fills the map (profile_geometry.h, shape_map_vector.cpp): its inside test is
// the even-odd rule decided by exact predicates (CGAL's Exact_predicates_inexact_constructions_kernel
// orientation for straight pieces and chords, an exact rational power-of-a-point test for arcs, both
// under a symbolic perturbation so vertices, tangencies and horizontal pieces on the query's row are
// never ambiguous), and its distance is its own projection onto segments (CGAL) and circles.
#pragma once

#include <cstddef>
#include <vector>

#include "bake/revolution/profile.h"
#include "bake/revolution/shape_map.h"

namespace bake::revolution::reference {

// Even-odd inside test of p over every piece of every contour (axis closures included), exactly.
// A point on the curve itself gets the side of the point displaced by an infinitesimal (e^3, e).
bool insideExact(const Profile& profile, Point2 p);
// Distance from p to the nearest surface piece (pieces on the axis excluded); +inf when none.
double distanceToSurface(const Profile& profile, Point2 p);
// Signed (negative inside) distance: the two above together.
double signedDistanceReference(const Profile& profile, Point2 p);

// A stored distance field measured against the reference at every texel centre.
struct FieldCheck {
  std::size_t texels = 0;
  std::size_t signErrors = 0;  // stored and reference signs differ where |reference| > kSignSlackTexels
  double maxError = 0;         // max |stored - reference|, texels
  double meanError = 0;        // texels
  int worstI = -1, worstJ = -1;  // texel of maxError
  std::size_t nearTexels = 0;    // texels within 2 texels of the surface
  double nearMaxError = 0, nearMeanError = 0;
};
// Below this distance from the curve (texels) a texel may carry either sign: rounding of its centre's
// coordinates alone moves it across.
constexpr double kSignSlackTexels = 1e-6;
FieldCheck checkField(const Profile& profile, const ShapeGrid& grid, const std::vector<float>& distance,
                      unsigned threads);

}  // namespace bake::revolution::reference
