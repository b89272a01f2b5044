// Shading a footprint from the far level (far_level.h), as the runtime shader does when more
// primitives lie under a footprint than it holds (shaders/grooves/far_level.glsl): the flat base plus,
// per class, the share of the footprint's bounding box its bands cover times the difference between
// the class's groove shaded alone across its own band (line sampling, §5, with its bounces, §7) and
// the flat base. Without wrap, the share is that of the box's part over the domain (a footprint at
// the edge of the pattern sees the grooves as they run on past it, as the seed's method does).
#include <algorithm>
#include <cmath>

#include "grooves/oracle/line_sampling_section.h"
#include "grooves/oracle/shade.h"

namespace bake::grooves {

Rgb shadeFromFarLevel(const GrooveScene& scene, const GrooveGrid& grid, const Footprint& footprint,
                      const Vec3& toViewer, const Lighting& lighting, const SeedSettings& settings) {
  const Rgb flat = flatBaseRadiance(scene.materials[scene.baseMaterial], toViewer, lighting);
  const FarLevel& far = grid.far;
  const Vec2 extent{0.5 * (std::abs(footprint.axis1.u) + std::abs(footprint.axis2.u)),
                    0.5 * (std::abs(footprint.axis1.v) + std::abs(footprint.axis2.v))};
  if (far.empty() || !(extent.u > 0) || !(extent.v > 0)) return flat;
  Vec2 lower{footprint.centre.u - extent.u, footprint.centre.v - extent.v};
  Vec2 upper{footprint.centre.u + extent.u, footprint.centre.v + extent.v};
  if (!scene.wrapRepeat) {  // the part over the domain, whose density stands for the box's
    lower = {std::max(lower.u, 0.0), std::max(lower.v, 0.0)};
    upper = {std::min(upper.u, scene.domain[0]), std::min(upper.v, scene.domain[1])};
  }
  const double boxArea = (upper.u - lower.u) * (upper.v - lower.v);
  if (!(upper.u > lower.u) || !(upper.v > lower.v)) return flat;
  Rgb sum = flat;
  for (std::size_t c = 0; c < far.classes.size(); ++c) {
    const double cover = far.bandArea(c, lower, upper, scene.wrapRepeat) / boxArea;
    if (!(cover > 0)) continue;
    const FarClass& farClass = far.classes[c];
    LocalGroove groove;
    groove.primitive = farClass.representative;
    groove.profile = &scene.profiles[farClass.profile];
    groove.material = farClass.material;
    groove.foot = footprint.centre;
    groove.tangent = farClass.direction;
    groove.binormal = {-farClass.direction.v, farClass.direction.u};
    // A footprint exactly across the band: a uniform density over [-wmax, wmax] on the section.
    const double width = 2 * farClass.halfWidth;
    const Footprint across{footprint.centre, {width * groove.binormal.u, width * groove.binormal.v},
                           {width * groove.tangent.u, width * groove.tangent.v}};
    const Rgb alone = shadeStraightGroove(scene, groove, across, toViewer, lighting, settings);
    for (int k = 0; k < 3; ++k) sum[k] += cover * (alone[k] - flat[k]);
  }
  for (double& channel : sum) channel = std::max(channel, 0.0);
  return sum;
}

}  // namespace bake::grooves
