// The travelling wave of seed 003 Fig. 5.10-5.12 (Appendix C.6): a packet of sine ripples whose
// leading edge is the front (threshold + speed * time) and which trails `reach` behind it in
// normalised distance d. The envelope is two smoothsteps (rising behind, falling at the front). As in
// C.6.3, the ripples' amplitude and frequency fall with the distance from the source: the height is
//   amplitude * (1 - d) * envelope * sin(2 pi (d - front) (1 - d) / wavelength),
// so the amplitude is (1 - d) of the one given, and the local wavelength, wavelength / (1 + front -
// 2 d), grows as the packet travels out (the thesis' sin(d F (1 - d)) (1 - d), with its phase tied
// to the front). Heights are in object radii. Shared by every stage of the displacement program, so
// the tessellation level, the displacement and the shading agree.
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
  float fade = 1.0 - clamp(d, 0.0, 1.0);
  return uWave.x * fade * waveEnvelope(d, front) * sin(6.28318530718 * (d - front) * fade / max(uWave.y, 1e-4));
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
