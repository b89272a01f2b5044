// Revolution mapping: the ray march of formats/revolution.md ("Sampling and marching"), in object
// space (axis +y). The shape map is sampled bilinearly at (r, h) = (|p.xz|, p.y) on its encoded
// values and decoded after filtering; the safety margin is subtracted from every sample. The march
// enters the proxy bands (else the box) and runs over-relaxed sphere tracing (Keinert et al. 2014,
// "Enhanced Sphere Tracing", section 3.1): step omega * d, and when the new sample's sphere and the
// previous one do not overlap (d_prev + |d| < step), or the sample lies inside the solid, or the step
// left the march interval, go back and take the plain step d_prev from the previous point with
// omega = 1 from then on. libbake/revolution/march.cpp runs the same loop on the CPU.
// Variants: ENCODING_FLOAT / ENCODING_UNORM16 / ENCODING_SQRT8; MAX_PROXY_BANDS n.
#ifndef BAKE_REVOLUTION_SHAPE_MARCH_GLSL
#define BAKE_REVOLUTION_SHAPE_MARCH_GLSL

#ifndef MAX_PROXY_BANDS
#define MAX_PROXY_BANDS 64
#endif

layout(binding = 0) uniform sampler2D uShapeMap;  // S mirrored repeat (the axis), T clamped

uniform vec4 uShapeGrid;       // width, height (texels), texelSize, hMin (object units)
uniform float uDistanceScale;  // S of the integer encodings
uniform float uSafetyMargin;
uniform float uHitEpsilon;
uniform float uOverRelaxation;
uniform int uIterations;
uniform vec3 uBoxMin, uBoxMax;  // where the march may run (object space)
uniform int uBandCount;
uniform vec3 uBands[MAX_PROXY_BANDS];  // hMin, hMax, rMax

// Texture coordinates of (r, h). r stays at or inside the centre of the last column, so the bilinear
// footprint never reaches past the outer edge (where a repeat would wrap back to the axis).
vec2 shapeCoordinates(vec2 rh) {
  float r = clamp(rh.x, 0.0, (uShapeGrid.x - 0.5) * uShapeGrid.z);
  return vec2(r / (uShapeGrid.x * uShapeGrid.z), (rh.y - uShapeGrid.w) / (uShapeGrid.y * uShapeGrid.z));
}

vec4 sampleShape(vec3 p) {
  return textureLod(uShapeMap, shapeCoordinates(vec2(length(p.xz), p.y)), 0.0);
}

// Signed distance (object units) from a filtered B value.
float decodeDistance(float b) {
#if defined(ENCODING_FLOAT)
  return b;
#elif defined(ENCODING_SQRT8)
  float e = 2.0 * b - 1.0;
  return sign(e) * e * e * uDistanceScale;
#else
  return (2.0 * b - 1.0) * uDistanceScale;
#endif
}

// Unit gradient (d/dr, d/dh) from filtered R, G values.
vec2 decodeGradient(vec2 rg) {
#if defined(ENCODING_FLOAT)
  return rg;
#else
  return 2.0 * rg - 1.0;
#endif
}

// The march's distance: decoded, less the safety margin.
float marchDistance(vec3 p) { return decodeDistance(sampleShape(p).b) - uSafetyMargin; }

// Ray parameters of the slab lo <= o + t d <= hi along one axis.
vec2 slab(float o, float d, float lo, float hi) {
  if (abs(d) < 1e-12) return (o >= lo && o <= hi) ? vec2(-1e30, 1e30) : vec2(1e30, -1e30);
  float a = (lo - o) / d, b = (hi - o) / d;
  return vec2(min(a, b), max(a, b));
}

vec2 boxInterval(vec3 o, vec3 d) {
  vec2 x = slab(o.x, d.x, uBoxMin.x, uBoxMax.x);
  vec2 y = slab(o.y, d.y, uBoxMin.y, uBoxMax.y);
  vec2 z = slab(o.z, d.z, uBoxMin.z, uBoxMax.z);
  return vec2(max(x.x, max(y.x, z.x)), min(x.y, min(y.y, z.y)));
}

// Ray parameters inside one band: the finite cylinder r <= rMax, hMin <= h <= hMax.
vec2 bandInterval(vec3 o, vec3 d, vec3 band) {
  vec2 inside = slab(o.y, d.y, band.x, band.y);
  float a = dot(d.xz, d.xz), b = dot(o.xz, d.xz), c = dot(o.xz, o.xz) - band.z * band.z;
  if (a < 1e-12) {
    if (c > 0.0) return vec2(1e30, -1e30);  // parallel to the axis, outside the cylinder
  } else {
    float disc = b * b - a * c;
    if (disc < 0.0) return vec2(1e30, -1e30);
    float root = sqrt(disc);
    inside = vec2(max(inside.x, (-b - root) / a), min(inside.y, (-b + root) / a));
  }
  return inside;
}

// The interval the march covers, from tStart on: the box, narrowed to the union of the bands' hull
// (first entry to last exit) when the package has bands. Empty when x > y.
vec2 marchInterval(vec3 o, vec3 d, float tStart) {
  vec2 box = boxInterval(o, d);
  box.x = max(box.x, tStart);
  if (uBandCount == 0) return box;
  vec2 hull = vec2(1e30, -1e30);
  for (int i = 0; i < uBandCount && i < MAX_PROXY_BANDS; ++i) {
    vec2 band = bandInterval(o, d, uBands[i]);
    band.x = max(band.x, box.x);
    if (band.x <= band.y) hull = vec2(min(hull.x, band.x), max(hull.y, band.y));
  }
  return vec2(max(box.x, hull.x), min(box.y, hull.y));
}

// Set by marchRay when the budget ran out before the ray hit or left its interval.
bool gMarchExhausted = false;

// Over-relaxed sphere tracing over [interval.x, interval.y]; true with the hit's t on a hit.
bool marchRay(vec3 o, vec3 d, vec2 interval, out float tHit) {
  gMarchExhausted = false;
  tHit = interval.x;
  if (interval.x > interval.y) return false;
  float omega = uOverRelaxation;
  float t = interval.x;
  float previousT = t, previousD = 0.0, step = 0.0;
  for (int i = 0; i < uIterations; ++i) {
    if (t > interval.y) {
      // An over-relaxed step past the exit may have jumped over the solid (the bands' exit hugs it,
      // unlike a far plane): take the plain step from the previous point instead.
      if (!(omega > 1.0 && step > previousD)) return false;
      omega = 1.0;
      step = previousD;
      t = previousT + step;
      if (t > interval.y) return false;
    }
    float dist = marchDistance(o + t * d);
    if (omega > 1.0 && step > 0.0 && (dist < 0.0 || previousD + abs(dist) < step)) {
      // The relaxed step left the sphere known to be empty, or landed inside the solid: back to the
      // previous point and a plain step (an overshoot into the solid is never a hit).
      omega = 1.0;
      step = previousD;
      t = previousT + step;
      continue;
    }
    if (dist < uHitEpsilon) {
      tHit = t;
      return true;
    }
    previousT = t;
    previousD = dist;
    step = omega * dist;
    t += step;
  }
  gMarchExhausted = true;
  return false;
}

#endif
