// Paintstroke segments, tessellation control stage (seed 002, view-dependent tessellation). Patch n
// is segment n (named by the vertex stage): control points i-1, i, i+1, i+2 of its stroke (beyond an end, the point reflected
// through the end point), transformed to view space. Invocation k fetches point k; invocation 0 then
// chooses the levels:
// - 0 (culled) when the stroke's culling sphere is outside the view frustum;
// - along the length, the number of equal pieces n whose chords stay within uTolerance pixels of the
//   Catmull-Rom path and radius: a chord over a parameter step h deviates from a cubic by at most
//   h^2/8 max|c''|, and c'' is linear in u, so max|c''| is at an end; in pixels at the segment's
//   nearest depth, n = ceil(sqrt(max|c''| / (8 tolerance)));
// - across, the quality level's 1, 2 or 4 polygons (kPolygonsAcross).
// The levels along the two edges shared with the neighbouring segments (u = 0 and u = 1) depend only
// on the quality, so neighbours always agree and no cracks open.
layout(vertices = 4) out;

#include "package.glsl"

uniform mat4 uModelView;
uniform mat4 uProjection;
uniform float uRadiusScale;   // model to view units (largest axis scale of the model matrix)
uniform vec2 uPixelScale;     // projection[0][0] * width / 2, projection[1][1] * height / 2
uniform float uTolerance;     // pixels
uniform float uMaxLevel;      // largest level along the length

out vec4 tcPositionRadius[];  // view space; radius in view units
out vec4 tcColour[];
out vec2 tcReflectanceShadow[];
patch out uint tcStyle;

in uint vSegment[];

layout(std430, binding = 5) buffer Counters { uint generatedPolygons; uint generatedVertices; };

// Point `local` of the stroke, reflected through the end point beyond either end (seed 002's
// Catmull-Rom spline needs a neighbour on both sides of every segment).
vec4 controlPoint(Stroke s, int local) {
  int count = int(s.info.y);
  uint first = s.info.x;
  if (local < 0) return 2.0 * pointPositionRadius(s, first) - pointPositionRadius(s, first + 1u);
  if (local >= count)
    return 2.0 * pointPositionRadius(s, first + uint(count - 1)) - pointPositionRadius(s, first + uint(count - 2));
  return pointPositionRadius(s, first + uint(local));
}

float clipW(vec3 p) {
  return dot(vec4(uProjection[0][3], uProjection[1][3], uProjection[2][3], uProjection[3][3]), vec4(p, 1.0));
}

bool sphereVisible(vec3 centre, float radius) {
  // Frustum planes of the projection, in view space: w + x >= 0, w - x >= 0, ... (Gribb-Hartmann).
  mat4 t = transpose(uProjection);
  vec4 planes[6] = vec4[6](t[3] + t[0], t[3] - t[0], t[3] + t[1], t[3] - t[1], t[3] + t[2], t[3] - t[2]);
  for (int i = 0; i < 6; ++i) {
    float scale = length(planes[i].xyz);
    if (scale > 0.0 && dot(planes[i], vec4(centre, 1.0)) < -radius * scale) return false;
  }
  return true;
}

void main() {
  uvec2 segment = segments[vSegment[0]];
  Stroke s = strokes[segment.x];
  int local = int(segment.y) + gl_InvocationID - 1;
  vec4 p = controlPoint(s, local);
  tcPositionRadius[gl_InvocationID] = vec4((uModelView * vec4(p.xyz, 1.0)).xyz, p.w * uRadiusScale);
  uint nearest = s.info.x + uint(clamp(local, 0, int(s.info.y) - 1));
  tcColour[gl_InvocationID] = pointColour(nearest);
  tcReflectanceShadow[gl_InvocationID] = vec2(pointReflectance(nearest), pointShadow(nearest));
  barrier();
  if (gl_InvocationID != 0) return;
  tcStyle = s.info.z;

  vec3 centre = (uModelView * vec4(s.sphere.xyz, 1.0)).xyz;
  if (!sphereVisible(centre, s.sphere.w * uRadiusScale)) {
    gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = gl_TessLevelOuter[3] = 0.0;
    gl_TessLevelInner[0] = gl_TessLevelInner[1] = 0.0;
    return;
  }
  vec4 p0 = tcPositionRadius[0], p1 = tcPositionRadius[1], p2 = tcPositionRadius[2], p3 = tcPositionRadius[3];
  // Second derivatives of the Catmull-Rom segment at u = 0 and u = 1 (path xyz and radius w).
  vec4 second0 = 2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3;
  vec4 second1 = -p0 + 4.0 * p1 - 5.0 * p2 + 2.0 * p3;
  // Pixels per view unit at the segment's nearest end (1/w of the projection; w = 1 orthographic).
  // A segment reaching behind the eye gets the largest level.
  float w = min(clipW(p1.xyz), clipW(p2.xyz));
  float pixelsPerUnit = max(uPixelScale.x, uPixelScale.y) / max(w, 1e-6);
  float curvature = max(max(length(second0.xyz), length(second1.xyz)), max(abs(second0.w), abs(second1.w)));
  float pieces = sqrt(curvature * pixelsPerUnit / (8.0 * max(uTolerance, 1e-3)));
  float along = w > 0.0 ? clamp(ceil(pieces), 1.0, uMaxLevel) : uMaxLevel;
  float across = float(POLYGONS_ACROSS);
  gl_TessLevelOuter[0] = gl_TessLevelOuter[2] = across;
  gl_TessLevelOuter[1] = gl_TessLevelOuter[3] = along;
  // The quad tessellator raises an inner level of 1 to 2 wherever another level exceeds 1. With one
  // polygon across, an inner level 1 across would add a second row (almost quality 1's cost), so
  // both inner levels are 1 and the edges' pieces fan to a single inner vertex (the segment's
  // centre): 2n + 2 triangles. With one piece along and m > 1 across, the raised inner level gives
  // a ring around a line of m - 1 vertices: 4m - 2 triangles. Otherwise a regular n x m grid.
  gl_TessLevelInner[0] = across == 1.0 ? 1.0 : along;
  gl_TessLevelInner[1] = across;
  uint n = uint(along), m = uint(across);
  uint polygons = 2u * n * m, vertices = (n + 1u) * (m + 1u);
  if (m == 1u && n > 1u) {
    polygons = 2u * n + 2u;
    vertices = 2u * (n + 1u) + 1u;
  } else if (n == 1u && m > 1u) {
    polygons = 4u * m - 2u;
    vertices = 3u * m + 1u;
  }
  atomicAdd(generatedPolygons, polygons);
  atomicAdd(generatedVertices, vertices);
}
