// GENERATED FILE, do not edit: run `node tools/generate-shaders.mjs` in integrations/three.
// GLSL ES 3.00 adaptation of these files under shaders/:
//   hatching/hatching.frag

export const sources = ["hatching/hatching.frag"];

export const fragmentShader = `precision highp float;
precision highp int;
precision highp sampler2DArray;
// Hatching (seed 004), fragment stage, §3.4 Algorithm 3. For each of the four triangles (T_c and its
// neighbours) the Lambert term of its face normal and the direction to the light (a directional
// light's; for a point or spot light the fragment-light vector FL, the spot's cut-off and exponent
// applied as OpenGL's spot lights do: (cos of the angle off its axis)^exponent inside the cone, none
// outside) gives darkness = 1 - Lambert, which is placed among the TAM's tones (darkness per layer, increasing; below
// the first tone the paper is blended with the first layer): the two nearest layers are sampled at the
// triangle's hatching coordinates and interpolated, so the tone changes continuously as the light
// moves (no popping). The mip level comes from the screen derivatives of each coordinate set
// (textureGrad, taken before any branch). The four colours are blended by their clamped, interpolated
// factors, sum(Color_t f_t) / sum(f_t), and multiply the material's baseColor.
//
// TAM texels are paper brightness as displayed (sRGB-encoded 8-bit values); they are decoded to linear
// so the written frame reproduces the TAM's grey levels. TAM_RGBA: RGB holds the inked colour.
// THRESHOLD_TONE: Webb et al. 2002's fine tone control instead of the two-layer blend: a texel of the
// threshold texture holds the darkness at which it turns to ink (graded by the order the strokes were
// placed); the fragment shows the darkest layer's ink where the darkness asked for has reached the
// threshold, paper elsewhere, over a ramp of uThresholdSoftness. No blended, half-faded strokes.

in vec4 gCoordsCA;
in vec4 gCoordsBG;
in vec3 gBlend;
flat in vec3 gNormalC, gNormalA, gNormalB, gNormalG;
in vec3 gWorldPosition;

uniform sampler2DArray uTam;
uniform int uToneCount;
uniform float uTones[MAX_TONES];
uniform vec3 uLightDir;   // towards the light, world space (directional lights)
uniform int uLightKind;   // 0 directional, 1 point, 2 spot
uniform vec3 uLightPos;   // point and spot lights, world space
uniform vec3 uSpotDirection;  // the way the spot shines, unit
uniform float uSpotCosCutoff;
uniform float uSpotExponent;
uniform vec3 uBaseColor;  // linear RGB

layout(location = 0) out vec4 fragColor;

vec3 srgbToLinear(vec3 c) {
  return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), c));
}

vec3 layerColour(vec2 st, vec2 dx, vec2 dy, int layer) {
  vec4 texel = textureGrad(uTam, vec3(st, float(layer)), dx, dy);
#ifdef TAM_RGBA
  return texel.rgb;
#else
  return texel.rrr;
#endif
}

#ifdef THRESHOLD_TONE
uniform sampler2D uThreshold;  // R8: darkness at which the texel turns to ink; the TAM's size and mips
uniform int bakeLevels_uThreshold;
uniform float uThresholdSoftness;

// Thresholded first, filtered after: each of the four texels around st at one mip level is ink or
// paper by its own threshold (the darkest layer's ink, or white), and those colours are weighted
// bilinearly. Filtering the thresholds instead would mix a thin stroke's low thresholds with its
// paper neighbours' 1.0 and drop its edges (measured: half the tone missing at the first tone).
vec3 thresholdColourAtLevel(vec2 st, float d, int level) {
  ivec2 size = textureSize(uThreshold, level);
  vec2 p = st * vec2(size) - 0.5;
  ivec2 base = ivec2(floor(p));
  vec2 f = p - vec2(base);
  vec3 colour = vec3(0.0);
  for (int k = 0; k < 4; ++k) {
    ivec2 o = ivec2(k & 1, k >> 1);
    ivec2 c = ((base + o) % size + size) % size;  // the TAM repeats
    float w = mix(1.0 - f.x, f.x, float(o.x)) * mix(1.0 - f.y, f.y, float(o.y));
    float ink = clamp((d - texelFetch(uThreshold, c, level).r) / uThresholdSoftness + 0.5, 0.0, 1.0);
    vec4 texel = texelFetch(uTam, ivec3(c, uToneCount - 1), level);
#ifdef TAM_RGBA
    vec3 darkest = texel.rgb;
#else
    vec3 darkest = texel.rrr;
#endif
    colour += w * mix(vec3(1.0), darkest, ink);
  }
  return colour;
}

// Trilinear: the level of detail from the coordinates' screen derivatives, as the sampler would.
vec3 toneColour(vec2 st, vec2 dx, vec2 dy, float d) {
  vec2 size = vec2(textureSize(uThreshold, 0));
  float rho = max(length(dx * size), length(dy * size));
  float lastLevel = float(bakeLevels_uThreshold - 1);
  float lod = clamp(log2(max(rho, 1e-8)), 0.0, lastLevel);
  int level = int(floor(lod));
  vec3 fine = thresholdColourAtLevel(st, d, level);
  if (lod == float(level)) return fine;
  return mix(fine, thresholdColourAtLevel(st, d, min(level + 1, int(lastLevel))), lod - float(level));
}
#else
// The colour of darkness d at coordinates st: between the two tones around d.
vec3 toneColour(vec2 st, vec2 dx, vec2 dy, float d) {
  int above = 0;  // first layer darker than d
  while (above < uToneCount && uTones[above] <= d) ++above;
  if (above == uToneCount) return layerColour(st, dx, dy, uToneCount - 1);
  float lowTone = above == 0 ? 0.0 : uTones[above - 1];
  vec3 low = above == 0 ? vec3(1.0) : layerColour(st, dx, dy, above - 1);
  vec3 high = layerColour(st, dx, dy, above);
  return mix(low, high, clamp((d - lowTone) / (uTones[above] - lowTone), 0.0, 1.0));
}
#endif

// The light reaching the fragment: its unit direction, and the spot's factor (1 for other lights).
float spotFactor(vec3 l) {
  if (uLightKind != 2) return 1.0;
  float c = dot(-l, uSpotDirection);
  return c >= uSpotCosCutoff ? pow(max(c, 0.0), uSpotExponent) : 0.0;
}

float gSpot = 1.0;
float darkness(vec3 n, vec3 l) { return 1.0 - gSpot * clamp(dot(n, l), 0.0, 1.0); }

void main() {
  vec3 l = uLightKind == 0 ? normalize(uLightDir) : normalize(uLightPos - gWorldPosition);
  gSpot = spotFactor(l);
  vec4 dxCA = dFdx(gCoordsCA), dyCA = dFdy(gCoordsCA);
  vec4 dxBG = dFdx(gCoordsBG), dyBG = dFdy(gCoordsBG);
  vec3 f = clamp(gBlend, 0.0, 1.0);

  vec3 colour = toneColour(gCoordsCA.xy, dxCA.xy, dyCA.xy, darkness(gNormalC, l));
  float weight = 1.0;
  if (f.x > 0.0) {
    colour += f.x * toneColour(gCoordsCA.zw, dxCA.zw, dyCA.zw, darkness(gNormalA, l));
    weight += f.x;
  }
  if (f.y > 0.0) {
    colour += f.y * toneColour(gCoordsBG.xy, dxBG.xy, dyBG.xy, darkness(gNormalB, l));
    weight += f.y;
  }
  if (f.z > 0.0) {
    colour += f.z * toneColour(gCoordsBG.zw, dxBG.zw, dyBG.zw, darkness(gNormalG, l));
    weight += f.z;
  }
  fragColor = vec4(uBaseColor * srgbToLinear(colour / weight), 1.0);
}
`;
