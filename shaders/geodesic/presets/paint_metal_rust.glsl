// Preset "paint-metal-rust" (seed 003 Fig. 5.9(b), Appendix C.4): four layers of one field, from the
// source outward: holes (cut away), rust (material 1), bare stained metal (material 2), paint
// (material 3), separated by fronts 0, 1 and 2 nested as in section 5.2.4. Metal stains and rust are
// fractal sums of simplex noise; only the hole front gets the front noise, so the rust eats the
// surface irregularly while the other fronts stay smooth (section 5.3). Material 0 is unused.
#ifdef PRESET_PAINT_METAL_RUST

GeoSurface paintMetalRustSurface(GeoFragment f) {
  float d = f.d.x;
  float hole = geoCover(geoNoisyDistance(d, f.p), 0);
  float rust = geoCover(d, 1);
  float metal = geoCover(d, 2);
  float stains = simplexFractalSum(f.p * (6.0 * uPatternScale), 1.0, 16.0, 2.0);
  float flakes = simplexFractalSum(f.p * (14.0 * uPatternScale), 1.0, 32.0, 2.0);
  vec3 paint = uColours[3];
  vec3 metalColour = uColours[2] * (0.85 + 0.25 * stains);
  vec3 rustColour = uColours[1] * (0.7 + 0.5 * flakes);
  vec3 colour = mix(mix(paint, metalColour, metal), rustColour, rust);
  // The paint edge is a small ridge; metal is nearly smooth; rust is rough.
  float edge = metal * (1.0 - metal) * 4.0;
  float height = mix(mix(0.0, 0.0005 * stains, metal) + 0.002 * edge, 0.004 * flakes, rust);
  return GeoSurface(colour, 1.0 - hole, height, vec3(0.0));
}

#endif
