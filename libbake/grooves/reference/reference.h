// The independent reference: the surface of formats/groove-scene.md ("The surface a scene describes")
// ray-traced exactly (an analytic height-field ray caster over the primitives' regions, so crossings,
// ends and corners need no special case), with stratified supersampling of each footprint, shadow
// rays and mirror bounces. It shares only the scene (the reader and its primitives) with the seed's
// method: no grid, no shading code.
#pragma once

#include <cstdint>

#include "grooves/input/scene.h"
#include "grooves/oracle/render.h"

namespace bake::grooves {

struct ReferenceSettings {
  int samplesPerPixel = 256;  // a square number: sqrt x sqrt strata over the footprint
  std::uint64_t seed = 1;     // jitter inside the strata; two seeds measure the noise floor
  int threads = 0;            // 0 = hardware
};

// The exact height field and its ray queries (exposed for tests).
class ReferenceSurface {
 public:
  explicit ReferenceSurface(const GrooveScene& scene);
  ~ReferenceSurface();
  double height(Vec2 x) const;  // H(x)
  // First hit of the ray origin + t dir, t > 0 (origin above the surface); false if it leaves.
  struct Hit {
    double t = 0;
    Vec3 point, normal;
    std::size_t material = 0;
  };
  bool intersect(const Vec3& origin, const Vec3& dir, Hit& hit) const;

 private:
  struct Impl;
  Impl* impl_;
};

// Radiance along the view line through base-plane point x (formats/groove-scene.md, "Rendering model").
Rgb referenceRadiance(const ReferenceSurface& surface, const GrooveScene& scene, Vec2 x, const Vec3& toViewer,
                      const Lighting& lighting);

Image renderReference(const GrooveScene& scene, const View& view, const Lighting& lighting,
                         const ReferenceSettings& settings);

}  // namespace bake::grooves
