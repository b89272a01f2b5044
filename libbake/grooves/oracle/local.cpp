// Straightening a primitive at a footprint (seed 000 §4: flat facets under a pixel): the tangent line
// at the foot point of the footprint centre, with the perturbation evaluated there (the local
// cross-section, §3) and its first and second derivatives along the path (how it changes, and how
// its points' tracks bend, under the pixel and along the lines of sight and shadow rays).
#include <cmath>
#include <numbers>

#include "grooves/oracle/shade_local.h"

namespace bake::grooves {

double perturbationScale(const Perturbation& perturbation, double arcLength) {
  if (perturbation.kind != Perturbation::Kind::Scale) return 1;
  return 1 + perturbation.amplitude *
                 std::sin(2 * std::numbers::pi * arcLength / perturbation.wavelength + perturbation.phase);
}

double perturbationOffset(const Perturbation& perturbation, double arcLength) {
  if (perturbation.kind != Perturbation::Kind::Offset) return 0;
  return perturbation.amplitude *
         std::sin(2 * std::numbers::pi * arcLength / perturbation.wavelength + perturbation.phase);
}

// d/ds of the sine above: amplitude k cos(k s + phase), k = 2 pi / wavelength.
double perturbationRate(const Perturbation& perturbation, double arcLength) {
  const double k = 2 * std::numbers::pi / perturbation.wavelength;
  return perturbation.amplitude * k * std::cos(k * arcLength + perturbation.phase);
}

// d/ds of the rate: -amplitude k^2 sin(k s + phase).
double perturbationAccel(const Perturbation& perturbation, double arcLength) {
  const double k = 2 * std::numbers::pi / perturbation.wavelength;
  return -perturbation.amplitude * k * k * std::sin(k * arcLength + perturbation.phase);
}

double perturbationScaleRate(const Perturbation& perturbation, double arcLength) {
  return perturbation.kind == Perturbation::Kind::Scale ? perturbationRate(perturbation, arcLength) : 0;
}

double perturbationOffsetRate(const Perturbation& perturbation, double arcLength) {
  return perturbation.kind == Perturbation::Kind::Offset ? perturbationRate(perturbation, arcLength) : 0;
}

LocalGroove localGroove(const GrooveScene& scene, std::uint32_t primitive, Vec2 at) {
  return localGroove(scene, primitive, at, jointsOf(scene, primitive));
}

LocalGroove localGroove(const GrooveScene& scene, std::uint32_t primitive, Vec2 at, const PrimitiveJoints& joints) {
  const Primitive& p = scene.primitives[primitive];
  const Groove& g = scene.grooves[p.groove];
  LocalGroove local;
  local.primitive = primitive;
  local.profile = &scene.profiles[g.profile];
  local.material = g.material;
  double along = 0;  // arc length from the primitive's start, extended beyond its ends
  if (p.kind == Primitive::Kind::Segment) {
    const Vec2 t{(p.b.u - p.a.u) / p.length, (p.b.v - p.a.v) / p.length};
    along = (at.u - p.a.u) * t.u + (at.v - p.a.v) * t.v;
    local.foot = {p.a.u + along * t.u, p.a.v + along * t.v};
    local.tangent = t;
  } else {
    const double du = at.u - p.centre.u, dv = at.v - p.centre.v;
    const double angle = std::atan2(dv, du);
    // Signed angle from the start, in the arc's direction, wrapped to (-pi, pi] around the arc's middle.
    double delta = angle - (p.startAngle + 0.5 * p.sweep);
    delta = std::remainder(delta, 2 * std::numbers::pi);
    const double fromStart = delta + 0.5 * p.sweep;  // signed, counter-clockwise
    along = p.radius * (p.sweep >= 0 ? fromStart : -fromStart);
    const double a = p.startAngle + fromStart;
    local.foot = {p.centre.u + p.radius * std::cos(a), p.centre.v + p.radius * std::sin(a)};
    const double turn = p.sweep >= 0 ? 1 : -1;
    local.tangent = {-std::sin(a) * turn, std::cos(a) * turn};
  }
  local.binormal = {-local.tangent.v, local.tangent.u};
  local.arcLength = p.arcStart + along;
  local.scale = perturbationScale(g.perturbation, local.arcLength);
  local.offset = perturbationOffset(g.perturbation, local.arcLength);
  local.scaleRate = perturbationScaleRate(g.perturbation, local.arcLength);
  local.offsetRate = perturbationOffsetRate(g.perturbation, local.arcLength);
  if (g.perturbation.kind == Perturbation::Kind::Scale) local.scaleAccel = perturbationAccel(g.perturbation, local.arcLength);
  if (g.perturbation.kind == Perturbation::Kind::Offset) local.offsetAccel = perturbationAccel(g.perturbation, local.arcLength);
  local.joints = joints;
  return local;
}

}  // namespace bake::grooves
