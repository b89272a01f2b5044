// Preset "isolines" (seed 003 Fig. 5.2): the field as a red (source) to blue (far) rainbow with dark
// isolines every uIsolineSpacing; line width is in pixels, from the distance's screen derivative, so
// lines stay crisp at any zoom. The front noise, when set, bends the isolines as in Fig. 5.2(c).
#ifdef PRESET_ISOLINES

uniform float uIsolineSpacing;  // normalised distance between lines
uniform float uIsolineWidth;    // pixels
uniform vec3 uIsolineColour;

// Hue from red (d = 0) through yellow, green and cyan to blue (d = 1), full saturation.
vec3 rainbow(float d) {
  float hue = clamp(d, 0.0, 1.0) * 4.0;  // sextants 0..4 of the hue circle: red .. blue
  return clamp(vec3(2.0 - hue, hue < 2.0 ? hue : 4.0 - hue, hue - 2.0), 0.0, 1.0);
}

GeoSurface isolinesSurface(GeoFragment f) {
  float d = geoNoisyDistance(f.d.x, f.p);
  float spacing = max(uIsolineSpacing, 1e-4);
  float toLine = abs(fract(d / spacing + 0.5) - 0.5) * spacing;  // distance to the nearest isoline
  float pixel = max(fwidth(d), 1e-7);
  float halfWidth = 0.5 * uIsolineWidth * pixel;
  float line = 1.0 - smoothstep(halfWidth, halfWidth + pixel, toLine);
  return GeoSurface(mix(rainbow(d), uIsolineColour, line), 1.0, 0.0, vec3(0.0));
}

#endif
