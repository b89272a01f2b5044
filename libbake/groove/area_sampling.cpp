// PLACEHOLDER (replaced by the area sampling of seed §6): keeps the library linking meanwhile.
#include "groove/shade_local.h"
namespace bake::groove {
Rgb areaSample(const GrooveScene&, const std::vector<LocalGroove>&, const Footprint&, const Vec3&, const Lighting&) {
  return {0, 0, 0};
}
}  // namespace bake::groove
