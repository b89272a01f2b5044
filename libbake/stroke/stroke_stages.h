// The paintstroke rasterizer's stages (internal to libbake/stroke): the centreline is sampled into short
// straight pieces (spline.cpp), each pixel near a piece gets the exact box-filtered ink of the piece's
// infinite band and the end discs get their exact pixel areas (coverage.h), and rasterize.cpp merges the
// pieces by maximum in a local buffer and folds the periodic copies into the image.
#pragma once

#include <array>
#include <vector>

#include "stroke/paintstroke.h"

namespace bake::stroke::detail {

// One vertex of the sampled centreline: position, radius (taper applied), arc length from the start,
// and the linearly interpolated ink parameters.
struct Sample {
  double x = 0, y = 0;
  double radius = 0;
  double arc = 0;
  double opacity = 1;
  std::array<double, 3> colour{0, 0, 0};
};

// Samples the centreline (spline.cpp): each Catmull-Rom segment is cut into equal parameter steps no
// longer than `maxPieceLength` and whose chords stray at most `maxDeviation` from the curve, the arc
// length accumulated, and the taper applied to the radius by arc length. Returns an empty list when
// the stroke has fewer than two points or a non-finite value, or when it would need more than
// `maxSamples` samples.
std::vector<Sample> sampleCentreline(const Paintstroke& stroke, double maxPieceLength, double maxDeviation,
                                     std::size_t maxSamples);

// The taper factor at arc length `arc` of a stroke `length` long (smoothstep over taper x length).
double taperFactor(double arc, double length, double taper);

}  // namespace bake::stroke::detail
