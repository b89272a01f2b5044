// PLACEHOLDER (replaced by the line sampling of seed §5): keeps the library linking meanwhile.
#include "groove/shade_local.h"
namespace bake::groove {
Rgb lineSample(const GrooveScene&, const std::vector<LocalGroove>&, const Footprint&, const Vec3&, const Lighting&) {
  return {0, 0, 0};
}
}  // namespace bake::groove
