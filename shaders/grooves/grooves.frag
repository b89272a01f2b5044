// Grooved surfaces (seed 000, Bosch et al. 2008, "A Resolution Independent Approach for the Accurate
// Rendering of Grooved Surfaces", §4-§7), fragment stage. Per fragment: the footprint of the pixel on
// the base plane in domain units (F = TEXCOORD_0 x domain, A1 = dFdx(F), A2 = dFdy(F)); the view and
// light directions in the surface's tangent frame (u, v, w), built from the uv derivatives of the
// position (for the package's preview plane: the plane's own axes); then the seed's method exactly as
// the CPU oracle libbake/grooves/oracle/shade.cpp computes it (line_sampling.glsl; special cases sampled by
// area, area_sampling.glsl). The output is linear radiance (formats/groove-scene.md "Rendering
// model"), no ambient term and no tone mapping.
// Variants: HAS_NORMALS, HAS_TANGENTS (the mesh's TANGENT, glTF's convention, gives u and the
// handedness of v = w · normal × u, as a baked mesh such as `groovebake --apply-to` has), HAS_MIRRORS (a material mirrors: §7 bounces compiled in), HAS_SPECIAL_CASES
// (the package has records), HAS_AREA_SAMPLING (special cases sampled by area), AREA_REFLECTIONS (§7 traced there too), AREA_SLOTS n,
// MAX_PROFILE_POINTS n, MAX_FOUND n, SHADING_INPUTS (also writes F, A1, A2, E, L to colour attachments
// 1-3 and to alpha the special-case flag, 2, or 3 and 4 where area sampling fell back to line
// sampling, for testing against the CPU method). Area sampling cut short by a driver's loop cap is
// redone in retry passes (area_retry.glsl).
#include "line_sampling.glsl"

in vec3 vWorldPosition;
in vec3 vNormal;
in vec2 vTexcoord0;
#ifdef HAS_TANGENTS
in vec4 vTangent;
#endif

uniform vec3 uLightDir;      // towards the light, world space
uniform vec3 uLightColour = vec3(1.0);
uniform vec3 uCameraPos;     // world space
uniform int uMaxBounces = 2;
uniform vec3 uEnvironment = vec3(0.0);  // seen by reflected rays that leave the surface (seed §7)

#ifdef HAS_AREA_SAMPLING
// Hidden fragments are not shaded, so the retry marks are those of the fragments kept.
layout(early_fragment_tests) in;
#endif

layout(location = 0) out vec4 fragColor;
#ifdef SHADING_INPUTS
layout(location = 1) out vec4 inputsCentreAxis1;  // F, A1
layout(location = 2) out vec4 inputsAxis2View;    // A2, E.u, E.v
layout(location = 3) out vec4 inputsViewLight;    // E.w, L
#endif

// The tangent frame (u, v, w): u and v along the position's derivatives with respect to the domain
// coordinates (solved from the screen derivatives), made orthonormal around the normal.
mat3 tangentFrame(vec3 normal, vec2 axis1, vec2 axis2) {
  vec3 dPdx = dFdx(vWorldPosition), dPdy = dFdy(vWorldPosition);
  vec3 perpX = cross(dPdy, normal), perpY = cross(normal, dPdx);
  vec3 alongU = perpX * axis1.x + perpY * axis2.x;
  vec3 alongV = perpX * axis1.y + perpY * axis2.y;
  vec3 u = alongU - normal * dot(normal, alongU);
  u = dot(u, u) > 0.0 ? normalize(u) : normalize(cross(abs(normal.x) < 0.9 ? vec3(1, 0, 0) : vec3(0, 1, 0), normal));
  vec3 v = cross(normal, u);
  if (dot(v, alongV) < 0.0) v = -v;  // a mirrored uv layout
  return mat3(u, v, normal);
}

#ifdef HAS_TANGENTS
// The frame of the interpolated TANGENT, made orthonormal around the normal (Gram-Schmidt).
mat3 meshTangentFrame(vec3 normal) {
  vec3 u = vTangent.xyz - normal * dot(normal, vTangent.xyz);
  u = dot(u, u) > 0.0 ? normalize(u) : normalize(cross(abs(normal.x) < 0.9 ? vec3(1, 0, 0) : vec3(0, 1, 0), normal));
  vec3 v = cross(normal, u) * (vTangent.w < 0.0 ? -1.0 : 1.0);
  return mat3(u, v, normal);
}
#endif

void main() {
  vec2 centre = vTexcoord0 * domainSize();
  vec2 axis1 = dFdx(centre), axis2 = dFdy(centre);
  vec3 geometric = cross(dFdx(vWorldPosition), dFdy(vWorldPosition));
#ifdef HAS_NORMALS
  vec3 normal = normalize(vNormal);
#else
  vec3 normal = normalize(geometric);
#endif
#ifdef HAS_TANGENTS
  mat3 frame = meshTangentFrame(normal);
#else
  mat3 frame = tangentFrame(normal, axis1, axis2);
#endif
  vec3 toViewer = normalize(uCameraPos - vWorldPosition) * frame;  // (E.u, E.v, E.w)
  gLightDir = normalize(normalize(uLightDir) * frame);
  gLightRadiance = uLightColour;
  gMaxBounces = uMaxBounces;
  gEnvironment = uEnvironment;

#ifdef HAS_AREA_SAMPLING
  // After the derivatives, which need the whole quad: a retry pass shades only its own pixels.
  if (isRetryPass() && !retriedHere()) discard;
#endif
  vec3 radiance = vec3(0.0);
  if (toViewer.z > 0.0) radiance = shadeFootprint(centre, axis1, axis2, toViewer);  // the back side: black
#ifdef HAS_AREA_SAMPLING
  markForRetry(gAreaDeferred);
  if (isQuarterPass()) discard;  // a share, summed in the retry buffer: the sum pass writes the pixel
#endif
  fragColor = vec4(radiance, 1.0);
#ifdef SHADING_INPUTS
  fragColor.a = gSpecialCase ? 2.0 : 1.0;  // the §4.2 dispatch, to compare with the CPU's
#ifdef HAS_AREA_SAMPLING
  if (gAreaNoSlot) fragColor.a = 3.0;  // area sampling found no arena slot and line sampled
  if (gAreaCut) fragColor.a = 4.0;     // area sampling was cut short by the driver and line sampled
#endif
  inputsCentreAxis1 = vec4(centre, axis1);
  inputsAxis2View = vec4(axis2, toViewer.xy);
  inputsViewLight = vec4(toViewer.z, gLightDir);
#endif
}
