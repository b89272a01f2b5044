// The seed's method on the CPU (seed 000 §4-§7), the oracle for the runtime shader: grooves found
// through the grid with the enlarged footprint box (§4.1), line sampling of the footprint projected
// on the cross-section plane for isolated grooves (§5: clipping, masking and shadowing by ordered
// projection, Eq. 1), area sampling with polygon clipping where the box meets a special-case record
// (§6), and mirror inter-reflections by recursion (§7).
#pragma once

#include "groove/grid.h"
#include "groove/render.h"
#include "groove/scene.h"

namespace bake::groove {

// How line sampling weighs the footprint along the cross-section's binormal (§5.1): the exact density
// of the parallelogram (a trapezoid) or the seed's uniform segment S = [-projmax, projmax].
enum class FootprintDensity { Trapezoid, SeedSegment };

struct ShadeStats {
  bool special = false;       // area sampling was used
  std::uint32_t primitives = 0;  // primitives found under the enlarged box
};

class SeedShader {
 public:
  SeedShader(const GrooveScene& scene, const GrooveGrid& grid,
             FootprintDensity density = FootprintDensity::Trapezoid)
      : scene_(scene), grid_(grid), density_(density) {}
  // The pixel value of one footprint seen from `toViewer`.
  Rgb shade(const Footprint& footprint, const Vec3& toViewer, const Lighting& lighting,
            ShadeStats* stats = nullptr) const;

 private:
  const GrooveScene& scene_;
  const GrooveGrid& grid_;
  FootprintDensity density_ = FootprintDensity::Trapezoid;
};

RgbImage renderSeed(const GrooveScene& scene, const GrooveGrid& grid, const View& view, const Lighting& lighting,
                    int threads, FootprintDensity density = FootprintDensity::Trapezoid);

}  // namespace bake::groove
