// Chaining keyed segments into contours (see profile_chain.h): ends meet when their keys are equal.
// An open chain is walked back to its free end first so it comes out whole and in order.
#include "revolution/input/profile_chain.h"

#include <unordered_map>

namespace bake::revolution {

bool clipToPositiveR(KeyedSegment& segment, EndKey newKey) {
  const double r0 = segment.points[0].r, r1 = segment.points[1].r;
  if (r0 < 0 && r1 < 0) return false;
  if (r0 < 0 || r1 < 0) {
    const int outside = r0 < 0 ? 0 : 1;
    const double s = r0 / (r0 - r1);
    segment.points[outside] = {0.0, segment.points[0].h + s * (segment.points[1].h - segment.points[0].h)};
    segment.ends[outside] = newKey;
  }
  return true;
}

std::vector<Contour> chainKeyedSegments(const std::vector<KeyedSegment>& cuts) {
  std::unordered_map<EndKey, std::vector<std::uint32_t>> byKey;
  for (std::uint32_t s = 0; s < cuts.size(); ++s)
    for (EndKey k : cuts[s].ends) byKey[k].push_back(s);
  std::vector<bool> used(cuts.size(), false);
  auto other = [&](EndKey key, std::uint32_t from) -> long {
    for (std::uint32_t s : byKey[key])
      if (s != from && !used[s]) return s;
    return -1;
  };
  std::vector<Contour> contours;
  std::vector<std::uint32_t> seenIn(cuts.size(), 0);  // walk number that last saw a segment
  for (std::uint32_t start = 0; start < cuts.size(); ++start) {
    if (used[start]) continue;
    // Walk backwards to an open end (if any) so an open chain is taken whole.
    std::uint32_t first = start;
    int firstEnd = 0;  // the end of `first` where the chain begins
    {
      const std::uint32_t walk = start + 1;
      std::uint32_t s = start;
      int enter = 0;
      seenIn[s] = walk;
      while (true) {
        const long prev = other(cuts[s].ends[enter], s);
        if (prev < 0 || seenIn[prev] == walk) break;
        const EndKey shared = cuts[s].ends[enter];
        s = std::uint32_t(prev);
        seenIn[s] = walk;
        enter = cuts[s].ends[0] == shared ? 1 : 0;
      }
      first = s;
      firstEnd = enter;
    }
    Contour contour;
    std::uint32_t s = first;
    int from = firstEnd;
    const EndKey startKey = cuts[first].ends[firstEnd];
    while (true) {
      used[s] = true;
      const int to = 1 - from;
      contour.segments.push_back({cuts[s].points[from], cuts[s].points[to], 0.0, false});
      const EndKey key = cuts[s].ends[to];
      if (key == startKey) {
        contour.closed = true;
        break;
      }
      const long next = other(key, s);
      if (next < 0) break;
      s = std::uint32_t(next);
      from = cuts[s].ends[0] == key ? 0 : 1;
    }
    contours.push_back(std::move(contour));
  }
  return contours;
}


}  // namespace bake::revolution
