// GENERATED FILE, do not edit: run `node tools/generate-shaders.mjs` in integrations/three.
// GLSL ES 3.00 adaptation of these files under shaders/:
//   geodesic/geotexture.vert
//   geodesic/geotexture.frag
//   common/lighting.glsl
//   geodesic/geotexture_common.glsl
//   geodesic/noise_simplex.glsl
//   geodesic/hash.glsl
//   geodesic/noise_worley.glsl
//   geodesic/wave.glsl
//   geodesic/presets/isolines.glsl
//   geodesic/presets/sand_water.glsl
//   geodesic/presets/moss_granite.glsl
//   geodesic/presets/paint_metal_rust.glsl
//   geodesic/presets/water_lava.glsl
//   geodesic/presets/opacity_front.glsl
//   geodesic/presets/wave_displacement.glsl

export const sources = ["geodesic/geotexture.vert","geodesic/geotexture.frag","common/lighting.glsl","geodesic/geotexture_common.glsl","geodesic/noise_simplex.glsl","geodesic/hash.glsl","geodesic/noise_worley.glsl","geodesic/wave.glsl","geodesic/presets/isolines.glsl","geodesic/presets/sand_water.glsl","geodesic/presets/moss_granite.glsl","geodesic/presets/paint_metal_rust.glsl","geodesic/presets/water_lava.glsl","geodesic/presets/opacity_front.glsl","geodesic/presets/wave_displacement.glsl"];

export const vertexShader = `precision highp float;
precision highp int;
// GeoTextures, vertex stage (seed 003 Appendix C.1): world position and normal for lighting, the
// object-normalised position that drives the noises, and the geodesic distances of the field slots.
// Variants: HAS_NORMALS; FIELD_COUNT 1..4 (attributes _GEODESIC_k bound at locations 3..6);
// FIELD_UNORM16 (fields stored as normalized 16-bit, else float); COMBINE_MIN (the slots merge into
// one min-distance field, section 5.2.3, else slots 0 and 1 stay separate).
// Unreachable vertices (float -1, unorm16 65535 read as 1.0) get distance 2, beyond every front, and
// vUnreachable = 1 when no slot reaches them; the fragment stage paints those in a flat colour.
#ifndef FIELD_COUNT
#define FIELD_COUNT 1
#endif
in vec3 position;
#ifdef HAS_NORMALS
in vec3 normal;
#endif
in float aField0;
#if FIELD_COUNT > 1
in float aField1;
#endif
#if FIELD_COUNT > 2
in float aField2;
#endif
#if FIELD_COUNT > 3
in float aField3;
#endif

uniform mat4 uModel;
uniform mat4 uViewProj;
uniform mat3 uNormalMatrix;
uniform vec3 uObjectCentre;   // bounding-box centre, object space
uniform float uObjectRadius;  // bounding-sphere radius around it, object space
uniform vec4 uFieldScale;  // stored value -> normalised distance (fields in model units)

out vec3 vWorldPosition;
out vec3 vNormal;
out vec3 vNoisePosition;
out vec2 vDistance;
out float vUnreachable;

const float kUnreachableDistance = 2.0;

bool unreachable(float value) {
#ifdef FIELD_UNORM16
  return value > 65534.5 / 65535.0;
#else
  return value < -0.5;
#endif
}

// The value as a normalised distance, and whether it reaches (1) or not (0).
vec2 slot(float value, float scale) {
  return unreachable(value) ? vec2(kUnreachableDistance, 0.0) : vec2(clamp(value * scale, 0.0, 1.0), 1.0);
}

void main() {
  vec4 world = uModel * vec4(position, 1.0);
  vWorldPosition = world.xyz;
#ifdef HAS_NORMALS
  vNormal = uNormalMatrix * normal;
#else
  vNormal = vec3(0.0);  // the fragment stage falls back to face normals
#endif
  vNoisePosition = (position - uObjectCentre) / max(uObjectRadius, 1e-20);

  vec2 s0 = slot(aField0, uFieldScale[0]);
#if FIELD_COUNT > 1
  vec2 s1 = slot(aField1, uFieldScale[1]);
#else
  vec2 s1 = s0;
#endif
#ifdef COMBINE_MIN
  vec2 merged = vec2(min(s0.x, s1.x), max(s0.y, s1.y));
#if FIELD_COUNT > 2
  vec2 s2 = slot(aField2, uFieldScale[2]);
  merged = vec2(min(merged.x, s2.x), max(merged.y, s2.y));
#endif
#if FIELD_COUNT > 3
  vec2 s3 = slot(aField3, uFieldScale[3]);
  merged = vec2(min(merged.x, s3.x), max(merged.y, s3.y));
#endif
  vDistance = vec2(merged.x);
  vUnreachable = 1.0 - merged.y;
#else
  vDistance = vec2(s0.x, s1.x);
  vUnreachable = 1.0 - max(s0.y, s1.y);
#endif
  gl_Position = uViewProj * world;
}
`;

export const fragmentShader = `precision highp float;
precision highp int;
// GeoTextures, fragment stage (seed 003 sections 5.2.4-5.3, Appendix C.2-C.6.4): one procedural
// texture preset chosen by a define (PRESET_ISOLINES, PRESET_SAND_WATER, PRESET_MOSS_GRANITE,
// PRESET_PAINT_METAL_RUST, PRESET_WATER_LAVA, PRESET_OPACITY_FRONT, PRESET_WAVE), shaded with the
// shared Blinn-Phong light. Each preset turns the fragment's distances and noise position into a
// colour, an opacity, a bump height and an emission (presets/*.glsl). Fragments no field reaches are
// painted flat in uUnreachableColour, unlit, so they can never pass for distance 0.
// Transparency: presets with see-through parts are drawn in two passes (uPass 0: opaque fragments
// with depth writes, uPass 1: the translucent rest, blended); cut-outs (alpha < 0.5) are discarded.
// ---- common/lighting.glsl
// Blinn-Phong lighting shared by the techniques: one directional light plus a little ambient.
// All vectors are in world space and normalised by the caller; the result is linear colour.
#ifndef BAKE_COMMON_LIGHTING_GLSL
#define BAKE_COMMON_LIGHTING_GLSL

const float kAmbient = 0.08;
const float kSpecularStrength = 0.25;
const float kShininess = 32.0;

// n: surface normal, l: direction towards the light, v: direction towards the camera, lightColour:
// the light's linear colour (white when a caller has none).
vec3 blinnPhong(vec3 n, vec3 l, vec3 v, vec3 baseColor, vec3 lightColour) {
  float diffuse = max(dot(n, l), 0.0);
  vec3 h = normalize(l + v);
  // No highlight on the side facing away from the light, where h can still align with n.
  float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), kShininess) : 0.0;
  return baseColor * (kAmbient + diffuse * lightColour) + kSpecularStrength * specular * lightColour;
}

#endif
// ---- end of common/lighting.glsl
// ---- geodesic/geotexture_common.glsl
// GeoTextures (seed 003, section 5.2.3-5.2.4): the pieces every preset shares.
//  - fronts: a material covers the surface where the (possibly noisy) normalised geodesic distance
//    is below a threshold; smoothstep over a transition width blends it into the next material, and
//    nested fronts order several materials from the source outward;
//  - the threshold can advance with time (uTime, uSpeed);
//  - noise added to the distance before a front is compared bends that front only (5.3), not the field;
//  - bump mapping: a preset returns a height; the normal is tilted by the height's surface gradient,
//    found from screen-space derivatives of height and position (no tangents or UVs needed).
#ifndef BAKE_GEODESIC_GEOTEXTURE_COMMON_GLSL
#define BAKE_GEODESIC_GEOTEXTURE_COMMON_GLSL

// ---- geodesic/noise_simplex.glsl
// Simplex noise in 2D and 3D (Perlin 2001, "Noise hardware"; the algorithm as explained by
// Gustavson 2005, "Simplex noise demystified"), written here from the algorithm:
//  1. skew the input so the simplex grid becomes a cube grid: s = (x+y+z) * F, cell = floor(p + s);
//  2. unskew the cell origin back (by G = (1 - 1/sqrt(n+1)) / n) and find which simplex of the cube
//     the point lies in by ranking its offset components (the corners are visited in that order);
//  3. each corner contributes (r0^2 - |d|^2)^4 * dot(gradient, d), where d is the offset from the
//     corner and the gradient is chosen by hashing the corner's lattice coordinates;
//  4. the sum is scaled to about [-1, 1].
// Gradients come from an integer hash (hash.glsl), not from permutation or gradient textures.
// Also the spectral sums of seed 003 Appendix A: fractal sum (sum of noise/f) and turbulence
// (sum of |noise|/f) over octaves f = minFreq, minFreq*gain, ... < maxFreq.
#ifndef BAKE_GEODESIC_NOISE_SIMPLEX_GLSL
#define BAKE_GEODESIC_NOISE_SIMPLEX_GLSL

// ---- geodesic/hash.glsl
// Integer hashes for the procedural noises (no textures): lattice points -> well-mixed 32-bit
// values -> floats in [0, 1). Integer arithmetic keeps the result identical on every GPU and on
// llvmpipe, unlike the sin()-based hashes whose precision varies between drivers.
// The mixing step is a permuted congruential step (O'Neill 2014, "PCG") followed by an xorshift.
#ifndef BAKE_GEODESIC_HASH_GLSL
#define BAKE_GEODESIC_HASH_GLSL

uint geoMix(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Distinct odd multipliers per axis, so (x, y, z) and its permutations hash differently.
uint geoHash(ivec2 p) { return geoMix(uint(p.x) * 0x8da6b343u ^ geoMix(uint(p.y) * 0xd8163841u)); }
uint geoHash(ivec3 p) {
  return geoMix(uint(p.x) * 0x8da6b343u ^ geoMix(uint(p.y) * 0xd8163841u ^ geoMix(uint(p.z) * 0xcb1ab31fu)));
}

float geoUnit(uint h) { return float(h >> 8u) * (1.0 / 16777216.0); }  // 24 bits -> [0, 1)

vec2 geoHash2(ivec2 p) {
  uint h = geoHash(p);
  return vec2(geoUnit(h), geoUnit(geoMix(h)));
}
vec3 geoHash3(ivec3 p) {
  uint h = geoHash(p);
  uint g = geoMix(h);
  return vec3(geoUnit(h), geoUnit(g), geoUnit(geoMix(g)));
}

#endif
// ---- end of geodesic/hash.glsl

// 2D: 8 unit gradients around the circle.
vec2 simplexGradient2(ivec2 corner) {
  float angle = float(geoHash(corner) & 7u) * (6.28318530718 / 8.0);
  return vec2(cos(angle), sin(angle));
}

// 3D: the 12 directions to the edge midpoints of a cube (Perlin 2002), which avoid the axis-aligned
// streaks of purely random gradients.
vec3 simplexGradient3(ivec3 corner) {
  uint h = geoHash(corner) % 12u;
  float a = (h & 1u) == 0u ? 1.0 : -1.0;
  float b = (h & 2u) == 0u ? 1.0 : -1.0;
  if (h < 4u) return vec3(a, b, 0.0);
  if (h < 8u) return vec3(a, 0.0, b);
  return vec3(0.0, a, b);
}

float simplexCorner2(vec2 offset, ivec2 corner) {
  float falloff = max(0.5 - dot(offset, offset), 0.0);
  falloff *= falloff;
  return falloff * falloff * dot(simplexGradient2(corner), offset);
}

float simplexNoise2(vec2 p) {
  const float F = 0.36602540378;  // (sqrt(3) - 1) / 2
  const float G = 0.21132486540;  // (3 - sqrt(3)) / 6
  vec2 cell = floor(p + (p.x + p.y) * F);
  vec2 d0 = p - (cell - (cell.x + cell.y) * G);
  // Lower or upper triangle of the skewed square.
  vec2 step1 = d0.x > d0.y ? vec2(1.0, 0.0) : vec2(0.0, 1.0);
  vec2 d1 = d0 - step1 + G;
  vec2 d2 = d0 - 1.0 + 2.0 * G;
  ivec2 c = ivec2(cell);
  float sum = simplexCorner2(d0, c) + simplexCorner2(d1, c + ivec2(step1)) + simplexCorner2(d2, c + ivec2(1));
  return 70.0 * sum;  // the largest possible sum is about 1/70
}

float simplexCorner3(vec3 offset, ivec3 corner) {
  float falloff = max(0.6 - dot(offset, offset), 0.0);
  falloff *= falloff;
  return falloff * falloff * dot(simplexGradient3(corner), offset);
}

float simplexNoise3(vec3 p) {
  const float F = 1.0 / 3.0;
  const float G = 1.0 / 6.0;
  vec3 cell = floor(p + (p.x + p.y + p.z) * F);
  vec3 d0 = p - (cell - (cell.x + cell.y + cell.z) * G);
  // Rank the components: the simplex steps first along the largest, then the middle one.
  vec3 larger = step(d0.yzx, d0.xyz);  // x>=y, y>=z, z>=x
  vec3 smaller = 1.0 - larger;
  vec3 step1 = min(larger, smaller.zxy);  // the largest component
  vec3 step2 = max(larger, smaller.zxy);  // the two largest
  vec3 d1 = d0 - step1 + G;
  vec3 d2 = d0 - step2 + 2.0 * G;
  vec3 d3 = d0 - 1.0 + 3.0 * G;
  ivec3 c = ivec3(cell);
  float sum = simplexCorner3(d0, c) + simplexCorner3(d1, c + ivec3(step1)) + simplexCorner3(d2, c + ivec3(step2)) +
              simplexCorner3(d3, c + ivec3(1));
  return 32.0 * sum;  // scales the extreme sum to about 1
}

// Fractal sum and turbulence over octaves; the loop bound keeps compilers from unrolling forever.
float simplexFractalSum(vec3 p, float minFreq, float maxFreq, float gain) {
  float value = 0.0;
  float f = minFreq;
  for (int octave = 0; octave < 8 && f < maxFreq; ++octave, f *= gain) value += simplexNoise3(p * f) / f;
  return value;
}

float simplexTurbulence(vec3 p, float minFreq, float maxFreq, float gain) {
  float value = 0.0;
  float f = minFreq;
  for (int octave = 0; octave < 8 && f < maxFreq; ++octave, f *= gain) value += abs(simplexNoise3(p * f)) / f;
  return value;
}

#endif
// ---- end of geodesic/noise_simplex.glsl
// ---- geodesic/noise_worley.glsl
// Worley (cellular) noise (Worley 1996, "A cellular texture basis function"; seed 003 Appendix B),
// written here from the algorithm: one feature point per unit grid cell, placed at the cell corner
// plus a hashed offset scaled by \`jitter\` (0: a regular grid, 1: anywhere in the cell). F1 and F2 are
// the distances to the nearest and second-nearest feature points, found among the 3x3(x3) cells
// around the sample. With jitter <= 1, F1 is exact; F2 can rarely miss a point two cells away, which
// shows as nothing worse than a slightly short F2.
// Also the fractal sum of seed 003 Appendix B (sum of (F1, F2)/f over octaves).
#ifndef BAKE_GEODESIC_NOISE_WORLEY_GLSL
#define BAKE_GEODESIC_NOISE_WORLEY_GLSL

// ---- geodesic/hash.glsl
// (geodesic/hash.glsl already included)
// ---- end of geodesic/hash.glsl

// Keeps the two smallest squared distances (x <= y) in \`best\`.
void worleyKeep(inout vec2 best, float d2) {
  if (d2 < best.x) {
    best = vec2(d2, best.x);
  } else if (d2 < best.y) {
    best.y = d2;
  }
}

vec2 worleyNoise2(vec2 p, float jitter) {
  ivec2 cell = ivec2(floor(p));
  vec2 local = p - floor(p);
  vec2 best = vec2(1e9);
  for (int y = -1; y <= 1; ++y) {
    for (int x = -1; x <= 1; ++x) {
      ivec2 neighbour = cell + ivec2(x, y);
      vec2 feature = vec2(x, y) + geoHash2(neighbour) * jitter;
      vec2 d = feature - local;
      worleyKeep(best, dot(d, d));
    }
  }
  return sqrt(best);  // (F1, F2)
}

vec2 worleyNoise3(vec3 p, float jitter) {
  ivec3 cell = ivec3(floor(p));
  vec3 local = p - floor(p);
  vec2 best = vec2(1e9);
  for (int z = -1; z <= 1; ++z) {
    for (int y = -1; y <= 1; ++y) {
      for (int x = -1; x <= 1; ++x) {
        ivec3 neighbour = cell + ivec3(x, y, z);
        vec3 feature = vec3(x, y, z) + geoHash3(neighbour) * jitter;
        vec3 d = feature - local;
        worleyKeep(best, dot(d, d));
      }
    }
  }
  return sqrt(best);  // (F1, F2)
}

vec2 worleyFractalSum(vec3 p, float minFreq, float maxFreq, float gain, float jitter) {
  vec2 value = vec2(0.0);
  float f = minFreq;
  for (int octave = 0; octave < 6 && f < maxFreq; ++octave, f *= gain) value += worleyNoise3(p * f, jitter) / f;
  return value;
}

#endif
// ---- end of geodesic/noise_worley.glsl

uniform float uTime;            // seconds
uniform float uSpeed;           // threshold advance, normalised distance per second
uniform vec4 uThresholds;       // fronts, from the source outward (normalised distance)
uniform vec4 uWidths;           // transition width of each front (normalised distance)
uniform vec2 uFrontNoise;       // (frequency per object radius, amplitude in normalised distance)
uniform float uPatternScale;    // multiplies the frequency of the materials' own patterns
uniform vec3 uColours[4];       // linear RGB of the preset's materials, from the source outward

// What a preset sees of one fragment.
struct GeoFragment {
  vec3 p;   // object position divided by the object's bounding radius (noise space)
  vec2 d;   // normalised distances of the two field slots (unreachable: 2, beyond every front)
  float time;
};

// What a preset makes of it.
struct GeoSurface {
  vec3 colour;    // linear base colour
  float alpha;    // 1 opaque; below 1 see-through (opacity-front) or cut away (paint-metal-rust)
  float height;   // bump height in object radii (0: the interpolated normal)
  vec3 emission;  // added after lighting (glowing lava)
};

float geoThreshold(int front) { return uThresholds[front] + uSpeed * uTime; }

// 1 where the distance is inside the front (nearer the source), 0 beyond it.
float geoCover(float distance, int front) {
  float halfWidth = max(uWidths[front], 1e-4) * 0.5;
  float threshold = geoThreshold(front);
  return 1.0 - smoothstep(threshold - halfWidth, threshold + halfWidth, distance);
}

// The distance with the front noise of Fig. 5.2(c) added.
float geoNoisyDistance(float distance, vec3 p) {
  if (uFrontNoise.y == 0.0) return distance;
  return distance + uFrontNoise.y * simplexNoise3(p * uFrontNoise.x);
}

// Normal tilted by the surface gradient of \`height\` (object radii * heightScale world units).
vec3 geoBumpNormal(vec3 n, vec3 position, float height) {
  vec3 dpdx = dFdx(position), dpdy = dFdy(position);
  float dhdx = dFdx(height), dhdy = dFdy(height);
  vec3 r1 = cross(dpdy, n), r2 = cross(n, dpdx);
  float det = dot(dpdx, r1);
  if (abs(det) < 1e-20) return n;
  return normalize(n - (dhdx * r1 + dhdy * r2) / det);
}

#endif
// ---- end of geodesic/geotexture_common.glsl
// ---- geodesic/wave.glsl
// The travelling wave of seed 003 Fig. 5.10-5.12 (Appendix C.6): a packet of sine ripples whose
// leading edge is the front (threshold + speed * time) and which trails \`reach\` behind it in
// normalised distance d. The envelope is two smoothsteps (rising behind, falling at the front). As in
// C.6.3, the ripples' amplitude and frequency fall with the distance from the source: the height is
//   amplitude * (1 - d) * envelope * sin(2 pi (d - front) (1 - d) / wavelength),
// so the amplitude is (1 - d) of the one given, and the local wavelength, wavelength / (1 + front -
// 2 d), grows as the packet travels out (the thesis' sin(d F (1 - d)) (1 - d), with its phase tied
// to the front). Heights are in object radii. Shared by every stage of the displacement program, so
// the tessellation level, the displacement and the shading agree.
#ifndef BAKE_GEODESIC_WAVE_GLSL
#define BAKE_GEODESIC_WAVE_GLSL

uniform vec4 uWave;  // (amplitude in object radii, wavelength, reach, unused)
uniform float uWaveFront0;  // front of the wave in each field slot at this time
uniform float uWaveFront1;

float waveEnvelope(float d, float front) {
  float reach = max(uWave.z, 1e-4);
  return smoothstep(front - reach, front - 0.6 * reach, d) * (1.0 - smoothstep(front - 0.15 * reach, front, d));
}

float waveHeight(float d, float front) {
  float fade = 1.0 - clamp(d, 0.0, 1.0);
  return uWave.x * fade * waveEnvelope(d, front) * sin(6.28318530718 * (d - front) * fade / max(uWave.y, 1e-4));
}

// Whether any part of [dMin, dMax] lies where the envelope is not zero.
bool waveTouches(float dMin, float dMax, float front) { return dMax > front - uWave.z && dMin < front; }

// Sum over the slots (one wave per field, Fig. 5.12); unreachable distances (2) are never in a wave.
float waveHeightAt(vec2 d) {
#if FIELD_COUNT > 1 && !defined(COMBINE_MIN)
  return waveHeight(d.x, uWaveFront0) + waveHeight(d.y, uWaveFront1);
#else
  return waveHeight(d.x, uWaveFront0);
#endif
}

#endif
// ---- end of geodesic/wave.glsl
// ---- geodesic/presets/isolines.glsl
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
// ---- end of geodesic/presets/isolines.glsl
// ---- geodesic/presets/sand_water.glsl
// Preset "sand-water" (seed 003 Fig. 5.6, Appendix C.2): sand (material 0) inside the front, water
// (material 1) beyond it. Sand grains are high-frequency simplex noise used as bump; the water is a
// fractal sum of Worley noise (ripples at the cell borders) drifting with time so it seems to flow.
#ifdef PRESET_SAND_WATER

GeoSurface sandWaterSurface(GeoFragment f) {
  float shore = geoCover(geoNoisyDistance(f.d.x, f.p), 0);
  float grains = simplexNoise3(f.p * (90.0 * uPatternScale));
  vec3 sand = uColours[0] * (0.92 + 0.08 * grains);
  vec3 flow = vec3(0.0, 0.0, 0.05 * f.time);
  vec2 cells = worleyFractalSum(f.p * (6.0 * uPatternScale) + flow, 1.0, 8.0, 2.0, 0.9);
  vec3 water = uColours[1] * (0.8 + 0.4 * cells.x);
  float height = mix(0.004 * cells.x, 0.0015 * grains, shore);
  return GeoSurface(mix(water, sand, shore), 1.0, height, vec3(0.0));
}

#endif
// ---- end of geodesic/presets/sand_water.glsl
// ---- geodesic/presets/moss_granite.glsl
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
// ---- end of geodesic/presets/moss_granite.glsl
// ---- geodesic/presets/paint_metal_rust.glsl
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
// ---- end of geodesic/presets/paint_metal_rust.glsl
// ---- geodesic/presets/water_lava.glsl
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
// ---- end of geodesic/presets/water_lava.glsl
// ---- geodesic/presets/opacity_front.glsl
// Preset "opacity-front" (seed 003 Fig. 5.7): the surface stays opaque (material 0) inside the front
// and turns see-through beyond it (material 1 at opacity uOpacity), so advancing the threshold
// reveals the inside of complex shapes without moving the camera.
#ifdef PRESET_OPACITY_FRONT

uniform float uOpacity;  // opacity beyond the front, 0..1

GeoSurface opacityFrontSurface(GeoFragment f) {
  float inside = geoCover(geoNoisyDistance(f.d.x, f.p), 0);
  return GeoSurface(mix(uColours[1], uColours[0], inside), mix(uOpacity, 1.0, inside), 0.0, vec3(0.0));
}

#endif
// ---- end of geodesic/presets/opacity_front.glsl
// ---- geodesic/presets/wave_displacement.glsl
// Preset "wave-displacement" (seed 003 Fig. 5.10-5.12, Appendix C.6): a wave packet travels out from
// the source with the front. With the tessellation stages (DISPLACE) the surface is refined and moved
// along its normal, so the silhouette waves; without them the same height only bumps the normal.
// Either way the shading normal is the bump of the wave height over the undisplaced surface, which is
// the normal of the displaced surface to first order. Material 0 is the surface colour, material 1
// tints the crests.
#ifdef PRESET_WAVE

GeoSurface waveSurface(GeoFragment f) {
  float h = waveHeightAt(f.d);
  float crest = clamp(h / max(uWave.x, 1e-6), 0.0, 1.0);
  return GeoSurface(mix(uColours[0], uColours[1], crest), 1.0, h, vec3(0.0));
}

#endif
// ---- end of geodesic/presets/wave_displacement.glsl

in vec3 vWorldPosition;
in vec3 vNormal;
in vec3 vNoisePosition;
in vec2 vDistance;
in float vUnreachable;
#if defined(PRESET_WAVE) && defined(DISPLACE)
in vec3 vBasePosition;  // world position before displacement: the bump is taken over it
#endif

uniform vec3 uLightDir;
uniform vec3 uLightColour;
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
`;
