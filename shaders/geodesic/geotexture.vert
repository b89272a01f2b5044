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

layout(location = 0) in vec3 aPosition;
#ifdef HAS_NORMALS
layout(location = 1) in vec3 aNormal;
#endif
layout(location = 3) in float aField0;
#if FIELD_COUNT > 1
layout(location = 4) in float aField1;
#endif
#if FIELD_COUNT > 2
layout(location = 5) in float aField2;
#endif
#if FIELD_COUNT > 3
layout(location = 6) in float aField3;
#endif

uniform mat4 uModel;
uniform mat4 uViewProj;
uniform mat3 uNormalMatrix;
uniform vec3 uObjectCentre;   // bounding-box centre, object space
uniform float uObjectRadius;  // bounding-sphere radius around it, object space
uniform vec4 uFieldScale = vec4(1.0);  // stored value -> normalised distance (fields in model units)

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
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorldPosition = world.xyz;
#ifdef HAS_NORMALS
  vNormal = uNormalMatrix * aNormal;
#else
  vNormal = vec3(0.0);  // the fragment stage falls back to face normals
#endif
  vNoisePosition = (aPosition - uObjectCentre) / max(uObjectRadius, 1e-20);

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
