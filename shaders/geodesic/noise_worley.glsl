// Worley (cellular) noise (Worley 1996, "A cellular texture basis function"; seed 003 Appendix B),
// written here from the algorithm: one feature point per unit grid cell, placed at the cell corner
// plus a hashed offset scaled by `jitter` (0: a regular grid, 1: anywhere in the cell). F1 and F2 are
// the distances to the nearest and second-nearest feature points, found among the 3x3(x3) cells
// around the sample. With jitter <= 1, F1 is exact; F2 can rarely miss a point two cells away, which
// shows as nothing worse than a slightly short F2.
// Also the fractal sum of seed 003 Appendix B (sum of (F1, F2)/f over octaves).
#ifndef BAKE_GEODESIC_NOISE_WORLEY_GLSL
#define BAKE_GEODESIC_NOISE_WORLEY_GLSL

#include "hash.glsl"

// Keeps the two smallest squared distances (x <= y) in `best`.
void worleyKeep(inout vec2 best, float d2) {
  if (d2 < best.x) {
    best = vec2(d2, best.x);
  } else if (d2 < best.y) {
    best.y = d2;
  }
}

vec2 worleyNoise2(vec2 p, float jitter) {
  ivec2 cell = ivec2(floor(p));
  vec2 local = p - floor(p);
  vec2 best = vec2(1e9);
  for (int y = -1; y <= 1; ++y) {
    for (int x = -1; x <= 1; ++x) {
      ivec2 neighbour = cell + ivec2(x, y);
      vec2 feature = vec2(x, y) + geoHash2(neighbour) * jitter;
      vec2 d = feature - local;
      worleyKeep(best, dot(d, d));
    }
  }
  return sqrt(best);  // (F1, F2)
}

vec2 worleyNoise3(vec3 p, float jitter) {
  ivec3 cell = ivec3(floor(p));
  vec3 local = p - floor(p);
  vec2 best = vec2(1e9);
  for (int z = -1; z <= 1; ++z) {
    for (int y = -1; y <= 1; ++y) {
      for (int x = -1; x <= 1; ++x) {
        ivec3 neighbour = cell + ivec3(x, y, z);
        vec3 feature = vec3(x, y, z) + geoHash3(neighbour) * jitter;
        vec3 d = feature - local;
        worleyKeep(best, dot(d, d));
      }
    }
  }
  return sqrt(best);  // (F1, F2)
}

vec2 worleyFractalSum(vec3 p, float minFreq, float maxFreq, float gain, float jitter) {
  vec2 value = vec2(0.0);
  float f = minFreq;
  for (int octave = 0; octave < 6 && f < maxFreq; ++octave, f *= gain) value += worleyNoise3(p * f, jitter) / f;
  return value;
}

#endif
