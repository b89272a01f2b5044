// The BAKE_paintstrokes arrays as the package stores them (formats/paintstrokes.md; std430 records of
// bake_formats/paintstrokes.h), bound as storage buffers 0-3, the runtime's segment index (binding 4)
// and the decoding of a control point. Shared by the tessellated strokes and the tube reference.
#ifndef BAKE_PAINTSTROKES_PACKAGE_GLSL
#define BAKE_PAINTSTROKES_PACKAGE_GLSL

struct Stroke {
  uvec4 info;    // first point, point count, style, flags
  vec4 origin;   // quantisation origin xyz; radius step
  vec4 stepSize; // quantisation step xyz
  vec4 sphere;   // culling sphere: centre, radius
};
struct Style {
  vec4 opacity;   // centre, edge (breadthwise); across, along (volume)
  vec4 specular;  // rgb, shininess
  vec4 shading;   // ambient, edge softness (pixels)
};

layout(std430, binding = 0) readonly buffer Strokes { Stroke strokes[]; };
layout(std430, binding = 1) readonly buffer Points { uvec4 points[]; };
layout(std430, binding = 2) readonly buffer Styles { Style styles[]; };
layout(std430, binding = 3) readonly buffer Shadows { uint shadows[]; };  // bytes, 4 per word
layout(std430, binding = 4) readonly buffer Segments { uvec2 segments[]; };  // stroke, first point in it

uniform int uShadowCount;                     // directions of the baked table (0: unshadowed)
uniform float uShadowWeight[MAX_SHADOW_DIRECTIONS];  // normalised weight of each direction this frame

// Position (model space) and radius of point `index` (global) of `s`.
vec4 pointPositionRadius(Stroke s, uint index) {
  uvec4 q = points[index];
  vec3 cell = vec3(float(q.x & 0xffffu), float(q.x >> 16), float(q.y & 0xffffu));
  return vec4(s.origin.xyz + cell * s.stepSize.xyz, float(q.y >> 16) * s.origin.w);
}

vec4 pointColour(uint index) { return unpackUnorm4x8(points[index].z); }  // rgb, opacity
float pointReflectance(uint index) { return float(points[index].w & 0xffu) / 255.0; }

// The baked self-shadowing of a point for this frame's light (seed 002, last paragraph): the table
// interpolated over the light direction with the weights the runtime computed once per frame.
float pointShadow(uint index) {
  if (uShadowCount == 0) return 1.0;
  float sum = 0.0;
  for (int k = 0; k < uShadowCount; ++k) {
    uint byteIndex = index * uint(uShadowCount) + uint(k);
    float value = float((shadows[byteIndex >> 2] >> (8u * (byteIndex & 3u))) & 0xffu) / 255.0;
    sum += uShadowWeight[k] * value;
  }
  return sum;
}

#endif
