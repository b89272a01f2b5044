// Chaining loose profile segments into contours. Producers (a mesh cut, a marching-squares contour)
// give each segment end the key of the element it lies on (a mesh edge, a lattice edge), so two ends
// meet exactly when their keys are equal: no tolerance, no welding.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "bake/revolution/profile.h"

namespace bake::revolution {

using EndKey = std::uint64_t;

inline EndKey pairKey(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (EndKey(a) << 32) | b;
}
// A key no other end shares: segment `index`'s end on the axis.
inline EndKey axisKey(std::size_t index) { return ~EndKey(0) - index; }

struct KeyedSegment {
  EndKey ends[2];
  Point2 points[2];
};

// Cuts a segment at r = 0 and keeps the r >= 0 part (its new end gets `newKey`); false when nothing
// is left.
bool clipToPositiveR(KeyedSegment& segment, EndKey newKey);

// Contours through shared keys; a chain that returns to its start is closed.
std::vector<Contour> chainKeyedSegments(const std::vector<KeyedSegment>& segments);

}  // namespace bake::revolution
