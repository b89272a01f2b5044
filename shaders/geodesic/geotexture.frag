// GeoTextures, fragment stage (seed 003 sections 5.2.4-5.3, Appendix C.2-C.6.4): one procedural
// texture preset chosen by a define (PRESET_ISOLINES, PRESET_SAND_WATER, PRESET_MOSS_GRANITE,
// PRESET_PAINT_METAL_RUST, PRESET_WATER_LAVA, PRESET_OPACITY_FRONT, PRESET_WAVE), shaded with the
// shared Blinn-Phong light. Each preset turns the fragment's distances and noise position into a
// colour, an opacity, a bump height and an emission (presets/*.glsl). Fragments no field reaches are
// painted flat in uUnreachableColour, unlit, so they can never pass for distance 0.
// Transparency: presets with see-through parts are drawn in two passes (uPass 0: opaque fragments
// with depth writes, uPass 1: the translucent rest, blended); cut-outs (alpha < 0.5) are discarded.
#include "common/lighting.glsl"
#include "geotexture_common.glsl"
#include "wave.glsl"
#include "presets/isolines.glsl"
#include "presets/sand_water.glsl"
#include "presets/moss_granite.glsl"
#include "presets/paint_metal_rust.glsl"
#include "presets/water_lava.glsl"
#include "presets/opacity_front.glsl"
#include "presets/wave_displacement.glsl"

in vec3 vWorldPosition;
in vec3 vNormal;
in vec3 vNoisePosition;
in vec2 vDistance;
in float vUnreachable;
#if defined(PRESET_WAVE) && defined(DISPLACE)
in vec3 vBasePosition;  // world position before displacement: the bump is taken over it
#endif

uniform vec3 uLightDir;
uniform vec3 uLightColour = vec3(1.0);
uniform vec3 uCameraPos;
uniform float uHeightScale;  // world units per object radius
uniform float uBumpScale;    // strength of the presets' bump heights (0: none)
uniform vec3 uUnreachableColour;
uniform int uPass;           // 0 opaque, 1 translucent
#ifdef ENVIRONMENT_MAP
uniform sampler2D uEnvironmentMap;  // equirectangular, linear RGB; row 0 at +Y

// Seed 003 C.6.4 looks the reflected direction up in a sphere map; here an equirectangular one:
// u = 0.5 + atan2(x, -z) / 2 pi (-Z in the middle), v = acos(y) / pi (+Y on the first row).
vec3 environmentAlong(vec3 r) {
  vec2 uv = vec2(0.5 + atan(r.x, -r.z) / 6.28318530718, acos(clamp(r.y, -1.0, 1.0)) / 3.14159265359);
  return textureLod(uEnvironmentMap, uv, 0.0).rgb;
}
#endif

layout(location = 0) out vec4 fragColor;

#ifdef TRANSLUCENT
const bool kTranslucent = true;   // alpha below 1 blends (second pass)
#else
const bool kTranslucent = false;  // alpha below 0.5 cuts the fragment away
#endif

GeoSurface shadePreset(GeoFragment f) {
#if defined(PRESET_ISOLINES)
  return isolinesSurface(f);
#elif defined(PRESET_SAND_WATER)
  return sandWaterSurface(f);
#elif defined(PRESET_MOSS_GRANITE)
  return mossGraniteSurface(f);
#elif defined(PRESET_PAINT_METAL_RUST)
  return paintMetalRustSurface(f);
#elif defined(PRESET_WATER_LAVA)
  return waterLavaSurface(f);
#elif defined(PRESET_OPACITY_FRONT)
  return opacityFrontSurface(f);
#elif defined(PRESET_WAVE)
  return waveSurface(f);
#else
#error "no GeoTexture preset defined"
#endif
}

void main() {
  GeoSurface surface = shadePreset(GeoFragment(vNoisePosition, vDistance, uTime));
#if defined(PRESET_WAVE) && defined(DISPLACE)
  vec3 bumpBase = vBasePosition;
#else
  vec3 bumpBase = vWorldPosition;
#endif
  // Derivatives are taken before any branch, where every fragment of the quad still runs.
  vec3 faceNormal = normalize(cross(dFdx(bumpBase), dFdy(bumpBase)));
#ifdef HAS_NORMALS
  vec3 n = normalize(vNormal);
#else
  vec3 n = faceNormal;
#endif
  n = geoBumpNormal(n, bumpBase, surface.height * uHeightScale * uBumpScale);

  if (vUnreachable > 0.5) {
    if (uPass != 0) discard;
    fragColor = vec4(uUnreachableColour, 1.0);
    return;
  }
  if (surface.alpha < 0.5 && !kTranslucent) discard;
  bool opaque = !kTranslucent || surface.alpha >= 0.999;
  if (opaque != (uPass == 0)) discard;

  vec3 l = normalize(uLightDir);
  vec3 v = normalize(uCameraPos - vWorldPosition);
  vec3 colour = blinnPhong(n, l, v, surface.colour, uLightColour) + surface.emission;
#ifdef ENVIRONMENT_MAP
  // C.6.4: the environment seen along the view reflected about the displaced surface, plus the
  // light's highlight (the diffuse term is replaced).
  vec3 h = normalize(l + v);
  float specular = dot(n, l) > 0.0 ? kSpecularStrength * pow(max(dot(n, h), 0.0), kShininess) : 0.0;
  colour = environmentAlong(reflect(-v, n)) + specular * uLightColour;
#endif
  fragColor = vec4(colour, opaque ? 1.0 : surface.alpha);
}
