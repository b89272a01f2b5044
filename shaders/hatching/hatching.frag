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
