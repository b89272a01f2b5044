// Preset "moss-granite" (seed 003 Fig. 5.9(a), Appendix C.3): moss (material 0) spreads over granite
// (material 1). Moss bumps are simplex turbulence plus a fractal sum of Worley noise; the grainy
// granite is simplex turbulence with dark speckles. Front noise makes the moss border irregular.
#ifdef PRESET_MOSS_GRANITE

GeoSurface mossGraniteSurface(GeoFragment f) {
  float moss = geoCover(geoNoisyDistance(f.d.x, f.p), 0);
  float tufts = simplexTurbulence(f.p * (8.0 * uPatternScale), 1.0, 16.0, 2.0);
  vec2 cells = worleyFractalSum(f.p * (10.0 * uPatternScale), 1.0, 4.0, 2.0, 1.0);
  float mossHeight = 0.6 * tufts + 0.4 * cells.x;
  vec3 mossColour = uColours[0] * (0.55 + 0.6 * mossHeight);
  float grain = simplexTurbulence(f.p * (20.0 * uPatternScale), 1.0, 16.0, 2.0);
  float speckle = step(0.55, simplexNoise3(f.p * (60.0 * uPatternScale)));
  vec3 granite = uColours[1] * (0.75 + 0.35 * grain) * (1.0 - 0.45 * speckle);
  float height = mix(0.002 * grain, 0.006 * mossHeight, moss);
  return GeoSurface(mix(granite, mossColour, moss), 1.0, height, vec3(0.0));
}

#endif
