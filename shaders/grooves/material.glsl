// The one material model of formats/groove-scene.md ("Rendering model"), as libbake/grooves/oracle/render.cpp
// directRadiance: normalised Blinn-Phong, f = albedo / pi + specular (n + 2) / (8 pi) max(N.H, 0)^n,
// times max(N.L, 0) and the light's radiance. All vectors in groove space (u, v, w up).
#ifndef BAKE_GROOVES_MATERIAL_GLSL
#define BAKE_GROOVES_MATERIAL_GLSL

#include "package.glsl"

vec3 gLightDir;       // towards the light, groove space, unit
vec3 gLightRadiance;
int gMaxBounces;
vec3 gEnvironment;  // what a reflected ray leaving the surface sees (seed §7; black by default)

vec3 normalisedOrSame(vec3 a) {
  float n = length(a);
  return n > 0.0 ? a / n : a;
}

vec3 directRadiance(int material, vec3 normal, vec3 toViewer) {
  float cosLight = dot(normal, gLightDir);
  if (cosLight <= 0.0) return vec3(0.0);
  vec3 halfway = normalisedOrSame(toViewer + gLightDir);
  GrooveMaterial m = materials[material];
  float n = m.albedo.w;
  float lobe = (n + 2.0) / (8.0 * kPi) * pow(max(dot(normal, halfway), 0.0), n);
  return (m.albedo.rgb / kPi + m.specular.rgb * lobe) * cosLight * gLightRadiance;
}

bool hasMirror(int material) { return materials[material].specular.w > 0.5; }

// What a mirror adds by reflecting the environment where its reflection leaves untraced (the flat
// base, area-sampled pieces), while bounces are followed (render.cpp environmentReflection).
vec3 environmentReflection(int material) {
  return hasMirror(material) && gMaxBounces > 0 ? materials[material].mirror.rgb * gEnvironment : vec3(0.0);
}

// The flat base plane: its direct light and, if it mirrors, the environment (render.cpp flatBaseRadiance).
vec3 flatBaseRadiance(vec3 toViewer) {
  return directRadiance(baseMaterial(), vec3(0.0, 0.0, 1.0), toViewer) + environmentReflection(baseMaterial());
}

// The mirrored view direction, unit (render.cpp reflect).
vec3 reflectView(vec3 toViewer, vec3 normal) {
  float d = 2.0 * dot(toViewer, normal);
  return normalisedOrSame(d * normal - toViewer);
}

#endif
