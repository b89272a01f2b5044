// Preset "water-lava" (seed 003 Fig. 5.8, Appendix C.5): two fields, two independent fronts. Lava
// (material 1) flows from field slot 1 over burnt rock (material 2), its front bent by low-frequency
// noise as if viscous; water (material 0) flows from slot 0 without noise and covers the lava where
// both reach. Water and lava are fractal Worley noise; the rock is simplex turbulence; the lava glows
// (emission) brightest in the cell interiors.
#ifdef PRESET_WATER_LAVA

GeoSurface waterLavaSurface(GeoFragment f) {
  float water = geoCover(f.d.x, 0);
  float lava = geoCover(geoNoisyDistance(f.d.y, f.p), 1);
  vec2 lavaCells = worleyFractalSum(f.p * (5.0 * uPatternScale) + vec3(0.02 * f.time), 1.0, 4.0, 2.0, 1.0);
  vec2 waterCells = worleyFractalSum(f.p * (6.0 * uPatternScale) + vec3(0.0, 0.0, 0.05 * f.time), 1.0, 8.0, 2.0, 0.9);
  float burnt = simplexTurbulence(f.p * (12.0 * uPatternScale), 1.0, 16.0, 2.0);
  vec3 rock = uColours[2] * (0.6 + 0.6 * burnt);
  float crust = smoothstep(0.25, 0.6, lavaCells.y - lavaCells.x);  // bright inside cells, dark seams
  vec3 lavaColour = uColours[1] * (0.3 + 0.7 * crust);
  vec3 waterColour = uColours[0] * (0.8 + 0.4 * waterCells.x);
  vec3 colour = mix(mix(rock, lavaColour, lava), waterColour, water);
  vec3 glow = uColours[1] * crust * 0.8 * lava * (1.0 - water);
  float height = mix(mix(0.003 * burnt, 0.003 * lavaCells.x, lava), 0.004 * waterCells.x, water);
  return GeoSurface(colour, 1.0, height, glow);
}

#endif
