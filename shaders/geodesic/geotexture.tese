// GeoTextures wave displacement, tessellation evaluation stage (seed 003 Appendix C.6.3): places each
// generated vertex by barycentric interpolation of the patch, evaluates the wave height at its
// interpolated distances and moves it along the interpolated normal (uHeightScale world units per
// object radius). The undisplaced position goes on to the fragment stage, whose bump of the same
// height gives the displaced surface's normal.
layout(triangles, fractional_odd_spacing, ccw) in;

#include "wave.glsl"

in vec3 tcWorldPosition[];
in vec3 tcNormal[];
in vec3 tcNoisePosition[];
in vec2 tcDistance[];
in float tcUnreachable[];

out vec3 vWorldPosition;
out vec3 vNormal;
out vec3 vNoisePosition;
out vec2 vDistance;
out float vUnreachable;
out vec3 vBasePosition;

uniform mat4 uViewProj;
uniform float uHeightScale;

#define GEO_INTERPOLATE(a) (gl_TessCoord.x * a[0] + gl_TessCoord.y * a[1] + gl_TessCoord.z * a[2])

void main() {
  vec3 base = GEO_INTERPOLATE(tcWorldPosition);
  vec3 normal = GEO_INTERPOLATE(tcNormal);
#ifndef HAS_NORMALS
  // No vertex normals: the face normal of the patch.
  normal = cross(tcWorldPosition[1] - tcWorldPosition[0], tcWorldPosition[2] - tcWorldPosition[0]);
#endif
  normal = length(normal) > 0.0 ? normalize(normal) : vec3(0.0);
  vDistance = GEO_INTERPOLATE(tcDistance);
  vUnreachable = GEO_INTERPOLATE(tcUnreachable);
  vNoisePosition = GEO_INTERPOLATE(tcNoisePosition);
  vNormal = normal;
  vBasePosition = base;
  vWorldPosition = base + normal * (waveHeightAt(vDistance) * uHeightScale);
  gl_Position = uViewProj * vec4(vWorldPosition, 1.0);
}
