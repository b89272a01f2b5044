// Revolution mapping: the surface at a hit (seed 001, "Shading" and "Texturing function").
// Normal from the shape map's gradient (Eq. 6, here with the axis along +y): n = (g_r x/r, g_h, g_r z/r).
// Tangent frame (Eq. 7-8): T the unit tangent along the angle (the direction u grows), B = N x T
// along the profile, so (T, B, N) is right-handed and a rising height tilts the normal away from the
// slope as in Blinn's Eq. 1. Texture coordinates by projection: u = (pi - phi) / 2 pi with
// phi = atan2(z, x) (Eq. 12-13, 16-17); v = (h - hMin) / box height (cylindrical, Eq. 13), v = (pi -
// theta) / pi about (0, sphereCentreH, 0) (spherical, Eq. 14-17), or the arc-length map's value.
// Bump mapping (Eq. 4-5): n' = N + D with D = -(H_T T + H_B B), H_T and H_B the height's slopes along
// T and B, from the displacement map's dH/du, dH/dv (object units per texture repeat) and the
// gradients of u and v.
// Variants: PROJECTION_CYLINDRICAL / PROJECTION_SPHERICAL / PROJECTION_ARC_LENGTH, HAS_DISPLACEMENT.
#ifndef BAKE_REVOLUTION_SURFACE_GLSL
#define BAKE_REVOLUTION_SURFACE_GLSL

#include "shape_march.glsl"

layout(binding = 1) uniform sampler2D uDisplacementMap;  // RG unorm16 dH/du, dH/dv; rows from v = 0
layout(binding = 2) uniform sampler2D uArcLengthMap;     // R unorm16 per shape-map texel

uniform vec2 uRepeat;            // texture repeats in u and v
uniform float uSphereCentreH;    // spherical projection centre on the axis
uniform float uDerivativeScale;  // decoded dH/du, dH/dv = (2 x - 1) * scale

const float kPi = 3.14159265358979;

// Radius of p, kept off zero (on the axis the angle has no direction).
float radiusOf(vec3 p) { return max(length(p.xz), 1e-7 * uShapeGrid.z); }

vec3 shapeNormal(vec3 p) {
  vec2 g = decodeGradient(sampleShape(p).rg);
  float r = radiusOf(p);
  vec3 n = vec3(g.x * p.x / r, g.y, g.x * p.z / r);
  return length(n) > 1e-12 ? normalize(n) : vec3(0.0, 1.0, 0.0);
}

// T: along the angle, the direction of growing u = (pi - atan2(z, x)) / 2 pi.
vec3 angularTangent(vec3 p) {
  float r = radiusOf(p);
  return vec3(p.z, 0.0, -p.x) / r;
}

float arcLengthAt(vec3 p) {
  return textureLod(uArcLengthMap, shapeCoordinates(vec2(length(p.xz), p.y)), 0.0).r;
}

// (u, v) of the projection, one repeat over [0, 1].
vec2 projectionCoordinates(vec3 p) {
  float u = (kPi - atan(p.z, p.x)) / (2.0 * kPi);
#if defined(PROJECTION_SPHERICAL)
  vec3 q = p - vec3(0.0, uSphereCentreH, 0.0);
  float theta = acos(clamp(q.y / max(length(q), 1e-20), -1.0, 1.0));
  return vec2(u, (kPi - theta) / kPi);
#elif defined(PROJECTION_ARC_LENGTH)
  return vec2(u, arcLengthAt(p));
#else
  return vec2(u, (p.y - uShapeGrid.w) / (uShapeGrid.y * uShapeGrid.z));
#endif
}

// Object-space gradient of the projection's v.
vec3 gradientOfV(vec3 p) {
#if defined(PROJECTION_SPHERICAL)
  vec3 q = p - vec3(0.0, uSphereCentreH, 0.0);
  float rho2 = max(dot(q, q), 1e-30);
  // v = 1 - theta / pi, grad theta = -(y_hat - q.y q / rho^2) / (rho sin theta), rho sin theta = r.
  return (vec3(0.0, 1.0, 0.0) - q.y * q / rho2) / (kPi * radiusOf(p));
#elif defined(PROJECTION_ARC_LENGTH)
  // Central differences over one texel of the map the values come from.
  float e = uShapeGrid.z;
  vec3 radial = vec3(p.x, 0.0, p.z) / radiusOf(p);
  float dr = (arcLengthAt(p + e * radial) - arcLengthAt(p - e * radial)) / (2.0 * e);
  float dh = (arcLengthAt(p + vec3(0.0, e, 0.0)) - arcLengthAt(p - vec3(0.0, e, 0.0))) / (2.0 * e);
  return dr * radial + vec3(0.0, dh, 0.0);
#else
  return vec3(0.0, 1.0 / (uShapeGrid.y * uShapeGrid.z), 0.0);
#endif
}

// Eq. 4-5: the bumped normal at p, given the geometric normal n and the texture coordinates of one
// repeat `uvTex` (already multiplied by uRepeat).
vec3 bumpedNormal(vec3 p, vec3 n, vec2 uvTex) {
#ifdef HAS_DISPLACEMENT
  vec2 dH = (2.0 * textureLod(uDisplacementMap, uvTex, 0.0).rg - 1.0) * uDerivativeScale;
  vec3 t = angularTangent(p);
  t = normalize(t - n * dot(n, t));
  vec3 b = cross(n, t);
  // du/ds along T is 1 / (2 pi r); dv/ds along B from the projection's gradient.
  float slopeT = dH.x * uRepeat.x / (2.0 * kPi * radiusOf(p));
  float slopeB = dH.y * uRepeat.y * dot(gradientOfV(p), b);
  return normalize(n - slopeT * t - slopeB * b);
#else
  return n;
#endif
}

#endif
