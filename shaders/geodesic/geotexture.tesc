// GeoTextures wave displacement, tessellation control stage (seed 003 Appendix C.6.2): how finely to
// split each triangle. An edge is split only where the wave packet touches it (its distance range
// overlaps the packet), and then into pieces of about uPixelsPerEdge pixels on screen, at most
// uMaxLevel; elsewhere it stays whole (the unperturbed part of the mesh is not refined, section 5.3).
// Each outer level depends only on its edge's two end points, taken in a fixed order, so the two
// triangles sharing an edge agree and no cracks open.
layout(vertices = 3) out;

#include "wave.glsl"

in vec3 vWorldPosition[];
in vec3 vNormal[];
in vec3 vNoisePosition[];
in vec2 vDistance[];
in float vUnreachable[];

out vec3 tcWorldPosition[];
out vec3 tcNormal[];
out vec3 tcNoisePosition[];
out vec2 tcDistance[];
out float tcUnreachable[];

uniform mat4 uViewProj;
uniform vec2 uViewport;        // pixels
uniform float uPixelsPerEdge;  // target length of a tessellated edge on screen
uniform float uMaxLevel;       // largest tessellation level

vec2 toPixels(vec3 world) {
  vec4 clip = uViewProj * vec4(world, 1.0);
  return clip.xy / max(clip.w, 1e-6) * 0.5 * uViewport;
}

bool touched(vec2 a, vec2 b) {
  vec2 lo = min(a, b), hi = max(a, b);
  bool first = waveTouches(lo.x, hi.x, uWaveFront0);
#if FIELD_COUNT > 1 && !defined(COMBINE_MIN)
  return first || waveTouches(lo.y, hi.y, uWaveFront1);
#else
  return first;
#endif
}

float edgeLevel(int a, int b) {
  if (!touched(vDistance[a], vDistance[b])) return 1.0;
  float pixels = length(toPixels(vWorldPosition[a]) - toPixels(vWorldPosition[b]));
  return clamp(pixels / max(uPixelsPerEdge, 1.0), 1.0, uMaxLevel);
}

void main() {
  tcWorldPosition[gl_InvocationID] = vWorldPosition[gl_InvocationID];
  tcNormal[gl_InvocationID] = vNormal[gl_InvocationID];
  tcNoisePosition[gl_InvocationID] = vNoisePosition[gl_InvocationID];
  tcDistance[gl_InvocationID] = vDistance[gl_InvocationID];
  tcUnreachable[gl_InvocationID] = vUnreachable[gl_InvocationID];
  if (gl_InvocationID == 0) {
    // Outer level i belongs to the edge opposite vertex i.
    float e0 = edgeLevel(1, 2), e1 = edgeLevel(2, 0), e2 = edgeLevel(0, 1);
    gl_TessLevelOuter[0] = e0;
    gl_TessLevelOuter[1] = e1;
    gl_TessLevelOuter[2] = e2;
    gl_TessLevelInner[0] = max(e0, max(e1, e2));
  }
}
