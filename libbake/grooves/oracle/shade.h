// The seed's method on the CPU (seed 000 §4-§7), the oracle for the runtime shader: grooves found
// through the grid with the enlarged footprint box (§4.1), line sampling of the footprint projected
// on the cross-section plane for isolated grooves (§5: clipping, masking and shadowing by ordered
// projection, Eq. 1), area sampling with polygon clipping where the box meets a special-case record
// (§6), and mirror inter-reflections by recursion (§7).
#pragma once

#include <cstdint>

#include "grooves/bake/grid.h"
#include "grooves/input/scene.h"
#include "grooves/oracle/render.h"

namespace bake::grooves {

// How line sampling weighs the footprint along the cross-section's binormal (§5.1): the exact density
// of the parallelogram (a trapezoid) or the seed's uniform segment S = [-projmax, projmax].
enum class FootprintDensity { Trapezoid, SeedSegment };

struct SeedSettings {
  FootprintDensity density = FootprintDensity::Trapezoid;
  // Not in the seed: for arcs, each cross-section point is moved along its circle to where the view
  // (light, mirrored) line through the footprint's centre line meets it, instead of straightening the
  // groove at the footprint (exact for arcs; the seed's flat-facet assumption fails for views along
  // tightly curved grooves). Only where the curvature shows (line_sampling.cpp curvatureShows); there
  // the spans' edges turn and bend with the circle across the footprint (line_sampling.cpp
  // shadeSection), and a footprint near an arc's centre is split in sub-footprints (shade.cpp
  // nearArcCentre). The shader does the same.
  bool curvedSections = true;
  // 0: every primitive found under a footprint is shaded (the seed's method). n > 0: as the runtime
  // shader, which holds bake_formats/grooves.h kMaxFoundPerFootprint: a footprint with more than n
  // primitives under its box is shaded from the grid's far level (shadeFromFarLevel). Either way, a
  // footprint wider than the period of a repeating pattern is shaded from the far level (the seed's
  // method straightens each groove at one copy, so it would count the groove once).
  std::size_t foundCap = 0;
  // Mirror inter-reflections in area-sampled footprints (seed §7 in §6's special cases) are traced;
  // false: as the runtime shader still does, each visible mirror piece there adds mirror x environment
  // (what the GL oracle tests compare against).
  bool areaReflections = true;
};

struct ShadeStats {
  bool special = false;       // area sampling was used
  std::uint32_t primitives = 0;  // primitives found under the enlarged box
  bool far = false;           // shaded from the far level (SeedSettings::foundCap)
};

class SeedShader {
 public:
  SeedShader(const GrooveScene& scene, const GrooveGrid& grid, const SeedSettings& settings = {});
  // The pixel value of one footprint seen from `toViewer`.
  Rgb shade(const Footprint& footprint, const Vec3& toViewer, const Lighting& lighting,
            ShadeStats* stats = nullptr) const;

 private:
  const GrooveScene& scene_;
  const GrooveGrid& grid_;
  SeedSettings settings_;
  std::uint64_t serial_;  // unique per shader made: the key of the per-thread gather memos
};

// A footprint shaded from the grid's far level (grooves/bake/far_level.h; far_shade.cpp).
Rgb shadeFromFarLevel(const GrooveScene& scene, const GrooveGrid& grid, const Footprint& footprint,
                      const Vec3& toViewer, const Lighting& lighting, const SeedSettings& settings = {});

Image renderSeed(const GrooveScene& scene, const GrooveGrid& grid, const View& view, const Lighting& lighting,
                    int threads, const SeedSettings& settings = {});

}  // namespace bake::grooves
