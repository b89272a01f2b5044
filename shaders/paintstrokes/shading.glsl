// Shading of a paintstroke fragment (seed 002), shared by the tessellated strokes and the tube
// reference so both differ only by their geometry: Blinn-Phong with the style's specular and ambient,
// the reflectance scaled by the baked self-shadowing, breadthwise opacity (centre to edge), volume
// opacity (largest when the view runs along the path) and an antialiased silhouette.
#ifndef BAKE_PAINTSTROKES_SHADING_GLSL
#define BAKE_PAINTSTROKES_SHADING_GLSL

uniform vec3 uLightView;    // towards the light, view space, unit
uniform vec3 uLightColour;

struct StrokeSample {
  vec3 normal;       // unit, view space
  float s;           // breadthwise coordinate: -1 and 1 at the silhouettes, 0 facing the viewer
  vec3 toViewer;     // unit, view space
  vec3 tangent;      // unit, view space
  vec4 colour;       // linear rgb, opacity
  float reflectance;
  float shadow;
};

// Coverage of the silhouette: the distance to the edge (|s| = 1) in pixels, from the screen-space
// derivative of s, over a ramp of `softness` pixels centred on the edge.
float edgeCoverage(float s, float softness) {
  float perPixel = length(vec2(dFdx(s), dFdy(s)));
  float pixels = (1.0 - abs(s)) / max(perPixel, 1e-6);
  return clamp(pixels / max(softness, 1e-3) + 0.5, 0.0, 1.0);
}

vec4 shadeStroke(StrokeSample p, Style style) {
  vec3 l = uLightView;
  float diffuse = max(dot(p.normal, l), 0.0);
  vec3 h = normalize(l + p.toViewer);
  float highlight = diffuse > 0.0 ? pow(max(dot(p.normal, h), 0.0), max(style.specular.w, 1.0)) : 0.0;
  float lit = p.reflectance * p.shadow;
  vec3 rgb = p.colour.rgb * (style.shading.x + lit * diffuse * uLightColour) +
             lit * highlight * style.specular.rgb * uLightColour;
  float edge = min(abs(p.s), 1.0);
  // "distinct opacities for the centre and for the edges" (seed 002, breadthwise opacity).
  float breadth = mix(style.opacity.x, style.opacity.y, edge);
  // "maximum value ... when the viewing angle is along the path, and a minimum value when it is
  // orthogonal to it" (seed 002, volume opacity).
  float volume = mix(style.opacity.z, style.opacity.w, abs(dot(p.toViewer, p.tangent)));
  float alpha = p.colour.a * breadth * volume * edgeCoverage(p.s, style.shading.y);
  return vec4(rgb, clamp(alpha, 0.0, 1.0));
}

#endif
