// Preset "sand-water" (seed 003 Fig. 5.6, Appendix C.2): sand (material 0) inside the front, water
// (material 1) beyond it. Sand grains are high-frequency simplex noise used as bump; the water is a
// fractal sum of Worley noise (ripples at the cell borders) drifting with time so it seems to flow.
#ifdef PRESET_SAND_WATER

GeoSurface sandWaterSurface(GeoFragment f) {
  float shore = geoCover(geoNoisyDistance(f.d.x, f.p), 0);
  float grains = simplexNoise3(f.p * (90.0 * uPatternScale));
  vec3 sand = uColours[0] * (0.92 + 0.08 * grains);
  vec3 flow = vec3(0.0, 0.0, 0.05 * f.time);
  vec2 cells = worleyFractalSum(f.p * (6.0 * uPatternScale) + flow, 1.0, 8.0, 2.0, 0.9);
  vec3 water = uColours[1] * (0.8 + 0.4 * cells.x);
  float height = mix(0.004 * cells.x, 0.0015 * grains, shore);
  return GeoSurface(mix(water, sand, shore), 1.0, height, vec3(0.0));
}

#endif
