// PLACEHOLDER (replaced by the seed's method): keeps the library linking meanwhile.
#include "groove/shade.h"
namespace bake::groove {
Rgb SeedShader::shade(const Footprint&, const Vec3&, const Lighting&, ShadeStats*) const { return {0, 0, 0}; }
RgbImage renderSeed(const GrooveScene&, const GrooveGrid&, const View&, const Lighting&, int) { return {}; }
}  // namespace bake::groove
