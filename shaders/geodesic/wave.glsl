// The travelling wave of seed 003 Fig. 5.10-5.12 (Appendix C.6): a packet of sine ripples whose
// leading edge is the front (threshold + speed * time) and which trails `reach` behind it in
// normalised distance. The envelope is two smoothsteps (rising behind, falling at the front); the
// ripples are sin(2 pi (d - front) / wavelength). Heights are in object radii. Shared by every stage
// of the displacement program, so the tessellation level, the displacement and the shading agree.
#ifndef BAKE_GEODESIC_WAVE_GLSL
#define BAKE_GEODESIC_WAVE_GLSL

uniform vec4 uWave;  // (amplitude in object radii, wavelength, reach, unused)
uniform float uWaveFront0;  // front of the wave in each field slot at this time
uniform float uWaveFront1;

float waveEnvelope(float d, float front) {
  float reach = max(uWave.z, 1e-4);
  return smoothstep(front - reach, front - 0.6 * reach, d) * (1.0 - smoothstep(front - 0.15 * reach, front, d));
}

float waveHeight(float d, float front) {
  return uWave.x * waveEnvelope(d, front) * sin(6.28318530718 * (d - front) / max(uWave.y, 1e-4));
}

// Whether any part of [dMin, dMax] lies where the envelope is not zero.
bool waveTouches(float dMin, float dMax, float front) { return dMax > front - uWave.z && dMin < front; }

// Sum over the slots (one wave per field, Fig. 5.12); unreachable distances (2) are never in a wave.
float waveHeightAt(vec2 d) {
#if FIELD_COUNT > 1 && !defined(COMBINE_MIN)
  return waveHeight(d.x, uWaveFront0) + waveHeight(d.y, uWaveFront1);
#else
  return waveHeight(d.x, uWaveFront0);
#endif
}

#endif
