// GeoTextures (seed 003, section 5.2.3-5.2.4): the pieces every preset shares.
//  - fronts: a material covers the surface where the (possibly noisy) normalised geodesic distance
//    is below a threshold; smoothstep over a transition width blends it into the next material, and
//    nested fronts order several materials from the source outward;
//  - the threshold can advance with time (uTime, uSpeed);
//  - noise added to the distance before a front is compared bends that front only (5.3), not the field;
//  - bump mapping: a preset returns a height; the normal is tilted by the height's surface gradient,
//    found from screen-space derivatives of height and position (no tangents or UVs needed).
#ifndef BAKE_GEODESIC_GEOTEXTURE_COMMON_GLSL
#define BAKE_GEODESIC_GEOTEXTURE_COMMON_GLSL

#include "noise_simplex.glsl"
#include "noise_worley.glsl"

uniform float uTime;            // seconds
uniform float uSpeed;           // threshold advance, normalised distance per second
uniform vec4 uThresholds;       // fronts, from the source outward (normalised distance)
uniform vec4 uWidths;           // transition width of each front (normalised distance)
uniform vec2 uFrontNoise;       // (frequency per object radius, amplitude in normalised distance)
uniform float uPatternScale;    // multiplies the frequency of the materials' own patterns
uniform vec3 uColours[4];       // linear RGB of the preset's materials, from the source outward

// What a preset sees of one fragment.
struct GeoFragment {
  vec3 p;   // object position divided by the object's bounding radius (noise space)
  vec2 d;   // normalised distances of the two field slots (unreachable: 2, beyond every front)
  float time;
};

// What a preset makes of it.
struct GeoSurface {
  vec3 colour;    // linear base colour
  float alpha;    // 1 opaque; below 1 see-through (opacity-front) or cut away (paint-metal-rust)
  float height;   // bump height in object radii (0: the interpolated normal)
  vec3 emission;  // added after lighting (glowing lava)
};

float geoThreshold(int front) { return uThresholds[front] + uSpeed * uTime; }

// 1 where the distance is inside the front (nearer the source), 0 beyond it.
float geoCover(float distance, int front) {
  float halfWidth = max(uWidths[front], 1e-4) * 0.5;
  float threshold = geoThreshold(front);
  return 1.0 - smoothstep(threshold - halfWidth, threshold + halfWidth, distance);
}

// The distance with the front noise of Fig. 5.2(c) added.
float geoNoisyDistance(float distance, vec3 p) {
  if (uFrontNoise.y == 0.0) return distance;
  return distance + uFrontNoise.y * simplexNoise3(p * uFrontNoise.x);
}

// Normal tilted by the surface gradient of `height` (object radii * heightScale world units).
vec3 geoBumpNormal(vec3 n, vec3 position, float height) {
  vec3 dpdx = dFdx(position), dpdy = dFdy(position);
  float dhdx = dFdx(height), dhdy = dFdy(height);
  vec3 r1 = cross(dpdy, n), r2 = cross(n, dpdx);
  float det = dot(dpdx, r1);
  if (abs(det) < 1e-20) return n;
  return normalize(n - (dhdx * r1 + dhdy * r2) / det);
}

#endif
