// Internal to the seed's method (shade.cpp, line_sampling.cpp, area_sampling.cpp): a primitive near
// a footprint, straightened at the footprint centre. Seed 000 §4 assumes the geometry under a pixel is
// a set of flat facets: the path is replaced by its tangent line at the foot point of the footprint
// centre, with the perturbation evaluated at that foot point (the local cross-section) and
// linearised there (line_sampling_occlusion.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "grooves/bake/grid.h"
#include "grooves/input/scene.h"
#include "grooves/oracle/render.h"

namespace bake::grooves {

struct LocalGroove {
  std::uint32_t primitive = 0;
  const Profile* profile = nullptr;
  std::size_t material = 0;
  Vec2 foot;               // the foot point of the footprint centre on the primitive's line or circle
  Vec2 tangent, binormal;  // unit; binormal = left normal (b > 0 to the left)
  double offset = 0;       // perturbation frozen at the foot point: b' = (b - offset) / scale
  double scale = 1;
  // Their derivatives along the path at the foot point: the linearised perturbation that moves the
  // section's points along the path (line_sampling_occlusion.cpp) and tilts its facets.
  double offsetRate = 0, scaleRate = 0;
  // And their second derivatives: how the points' tracks bend along the path (a wandering offset
  // curves the groove), over the travel of a line of sight or a shadow ray.
  double offsetAccel = 0, scaleAccel = 0;
  double arcLength = 0;    // s at the foot point
  PrimitiveJoints joints;  // where the primitive's region stops
  // The profile point k in base-plane coordinates relative to the foot: b along binormal, h up.
  double profileB(std::size_t k) const { return offset + scale * profile->points[k].u; }
  double profileH(std::size_t k) const { return scale * profile->points[k].v; }
};

// `at` is the footprint centre; for a wrapping scene, the caller passes the copy of the centre
// nearest the primitive.
LocalGroove localGroove(const GrooveScene& scene, std::uint32_t primitive, Vec2 at);
// The same with the primitive's joints already found.
LocalGroove localGroove(const GrooveScene& scene, std::uint32_t primitive, Vec2 at, const PrimitiveJoints& joints);

double perturbationScale(const Perturbation& perturbation, double arcLength);
double perturbationOffset(const Perturbation& perturbation, double arcLength);
double perturbationScaleRate(const Perturbation& perturbation, double arcLength);  // d scale / ds
double perturbationOffsetRate(const Perturbation& perturbation, double arcLength);  // d offset / ds

// How far a line along the unit direction d travels over the base plane per unit of height,
// |d_uv| / d_w, capped at bake_formats/grooves.h kMaxReach (as the query box caps it).
double travelPerDepth(const Vec3& d);

// §5: line sampling for footprints without special cases (line_sampling.cpp).
Rgb lineSample(const GrooveScene& scene, const std::vector<LocalGroove>& grooves, const Footprint& footprint,
               const Vec3& toViewer, const Lighting& lighting);

// §6: area sampling with polygon clipping where a special-case record is under the box
// (area_sampling.cpp). `traceReflections` (§7 there): mirror pieces' reflections are traced, or (as
// the runtime shader still does) each visible mirror piece adds mirror x environment.
Rgb areaSample(const GrooveScene& scene, const std::vector<LocalGroove>& grooves, const Footprint& footprint,
               const Vec3& toViewer, const Lighting& lighting, bool traceReflections = true);

}  // namespace bake::grooves
