// Simplex noise in 2D and 3D (Perlin 2001, "Noise hardware"; the algorithm as explained by
// Gustavson 2005, "Simplex noise demystified"), written here from the algorithm:
//  1. skew the input so the simplex grid becomes a cube grid: s = (x+y+z) * F, cell = floor(p + s);
//  2. unskew the cell origin back (by G = (1 - 1/sqrt(n+1)) / n) and find which simplex of the cube
//     the point lies in by ranking its offset components (the corners are visited in that order);
//  3. each corner contributes (r0^2 - |d|^2)^4 * dot(gradient, d), where d is the offset from the
//     corner and the gradient is chosen by hashing the corner's lattice coordinates;
//  4. the sum is scaled to about [-1, 1].
// Gradients come from an integer hash (hash.glsl), not from permutation or gradient textures.
// Also the spectral sums of seed 003 Appendix A: fractal sum (sum of noise/f) and turbulence
// (sum of |noise|/f) over octaves f = minFreq, minFreq*gain, ... < maxFreq.
#ifndef BAKE_GEODESIC_NOISE_SIMPLEX_GLSL
#define BAKE_GEODESIC_NOISE_SIMPLEX_GLSL

#include "hash.glsl"

// 2D: 8 unit gradients around the circle.
vec2 simplexGradient2(ivec2 corner) {
  float angle = float(geoHash(corner) & 7u) * (6.28318530718 / 8.0);
  return vec2(cos(angle), sin(angle));
}

// 3D: the 12 directions to the edge midpoints of a cube (Perlin 2002), which avoid the axis-aligned
// streaks of purely random gradients.
vec3 simplexGradient3(ivec3 corner) {
  uint h = geoHash(corner) % 12u;
  float a = (h & 1u) == 0u ? 1.0 : -1.0;
  float b = (h & 2u) == 0u ? 1.0 : -1.0;
  if (h < 4u) return vec3(a, b, 0.0);
  if (h < 8u) return vec3(a, 0.0, b);
  return vec3(0.0, a, b);
}

float simplexCorner2(vec2 offset, ivec2 corner) {
  float falloff = max(0.5 - dot(offset, offset), 0.0);
  falloff *= falloff;
  return falloff * falloff * dot(simplexGradient2(corner), offset);
}

float simplexNoise2(vec2 p) {
  const float F = 0.36602540378;  // (sqrt(3) - 1) / 2
  const float G = 0.21132486540;  // (3 - sqrt(3)) / 6
  vec2 cell = floor(p + (p.x + p.y) * F);
  vec2 d0 = p - (cell - (cell.x + cell.y) * G);
  // Lower or upper triangle of the skewed square.
  vec2 step1 = d0.x > d0.y ? vec2(1.0, 0.0) : vec2(0.0, 1.0);
  vec2 d1 = d0 - step1 + G;
  vec2 d2 = d0 - 1.0 + 2.0 * G;
  ivec2 c = ivec2(cell);
  float sum = simplexCorner2(d0, c) + simplexCorner2(d1, c + ivec2(step1)) + simplexCorner2(d2, c + ivec2(1));
  return 70.0 * sum;  // the largest possible sum is about 1/70
}

float simplexCorner3(vec3 offset, ivec3 corner) {
  float falloff = max(0.6 - dot(offset, offset), 0.0);
  falloff *= falloff;
  return falloff * falloff * dot(simplexGradient3(corner), offset);
}

float simplexNoise3(vec3 p) {
  const float F = 1.0 / 3.0;
  const float G = 1.0 / 6.0;
  vec3 cell = floor(p + (p.x + p.y + p.z) * F);
  vec3 d0 = p - (cell - (cell.x + cell.y + cell.z) * G);
  // Rank the components: the simplex steps first along the largest, then the middle one.
  vec3 larger = step(d0.yzx, d0.xyz);  // x>=y, y>=z, z>=x
  vec3 smaller = 1.0 - larger;
  vec3 step1 = min(larger, smaller.zxy);  // the largest component
  vec3 step2 = max(larger, smaller.zxy);  // the two largest
  vec3 d1 = d0 - step1 + G;
  vec3 d2 = d0 - step2 + 2.0 * G;
  vec3 d3 = d0 - 1.0 + 3.0 * G;
  ivec3 c = ivec3(cell);
  float sum = simplexCorner3(d0, c) + simplexCorner3(d1, c + ivec3(step1)) + simplexCorner3(d2, c + ivec3(step2)) +
              simplexCorner3(d3, c + ivec3(1));
  return 32.0 * sum;  // scales the extreme sum to about 1
}

// Fractal sum and turbulence over octaves; the loop bound keeps compilers from unrolling forever.
float simplexFractalSum(vec3 p, float minFreq, float maxFreq, float gain) {
  float value = 0.0;
  float f = minFreq;
  for (int octave = 0; octave < 8 && f < maxFreq; ++octave, f *= gain) value += simplexNoise3(p * f) / f;
  return value;
}

float simplexTurbulence(vec3 p, float minFreq, float maxFreq, float gain) {
  float value = 0.0;
  float f = minFreq;
  for (int octave = 0; octave < 8 && f < maxFreq; ++octave, f *= gain) value += abs(simplexNoise3(p * f)) / f;
  return value;
}

#endif
