// Revolution mapping, fragment stage (seed 001, "Ray tracing", "Shading", "Texturing function";
// formats/revolution.md). The pixel's ray is rebuilt in object space from gl_FragCoord through the
// inverse of projection * view * model, starting on the near plane, so a camera inside the shape box
// works (the box is drawn by its back faces). The ray is marched through the shape map
// (shape_march.glsl); a miss is discarded, a hit is shaded (surface.glsl, Blinn-Phong) and writes its
// own depth, so revolved objects intersect other geometry where their surfaces really cross.
// With replicas the ray walks the copies' cells (replicas.glsl) and the hit is shaded in its copy's
// frame. With SELF_SHADOW a second ray from the hit, lifted off the surface, marches toward the light
// through the same copies; any hit leaves the point to the ambient term (seed 001, "Shading": the
// shadow part of the lighting, here by ray casting rather than a shadow map).
// Variants: ENCODING_*, PROJECTION_*, HAS_DISPLACEMENT, HAS_BASE_COLOR_TEXTURE, MAX_PROXY_BANDS n,
// REPLICAS_GRID / REPLICAS_RING, SELF_SHADOW.
#include "common/lighting.glsl"
#include "surface.glsl"
#include "replicas.glsl"

layout(binding = 3) uniform sampler2D uBaseColorTexture;  // sRGB, decoded to linear by the sampler

uniform mat4 uClipToObject;  // inverse of uObjectToClip
uniform mat4 uObjectToClip;
uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform vec2 uViewport;      // pixels
uniform vec4 uBaseColor;     // linear RGBA factor
uniform vec3 uLightDir;      // towards the light, world space
uniform vec3 uLightColour = vec3(1.0);
uniform vec3 uCameraPos;     // world space
uniform vec3 uLightDirObject;  // towards the light, object space (unit)

layout(location = 0) out vec4 fragColor;

vec3 unproject(vec2 ndc, float z) {
  vec4 p = uClipToObject * vec4(ndc, z, 1.0);
  return p.xyz / p.w;
}

// Derivative of a coordinate that wraps at 1: the smaller of the raw one and that of the coordinate
// shifted by half a period, so the seam at u = 0 does not select the coarsest mip level.
float wrappedDerivative(float du, float duShifted) { return abs(du) <= abs(duShifted) ? du : duShifted; }

void main() {
  vec2 ndc = gl_FragCoord.xy / uViewport * 2.0 - 1.0;
  vec3 origin = unproject(ndc, -1.0);  // on the near plane
  vec3 direction = normalize(unproject(ndc, 1.0) - origin);

  float tHit;
  Cell copy;
  bool hit = marchCopies(origin, direction, 0.0, tHit, copy);
  vec3 pObject = origin + tHit * direction;
  vec3 p = toCell(copy, pObject);  // in the hit copy's own frame: what the maps describe

  // Texture coordinates and their screen derivatives for every fragment of the quad, before any
  // fragment is discarded (derivatives need the whole quad).
  vec2 uvTex = projectionCoordinates(p) * uRepeat;
#ifdef HAS_BASE_COLOR_TEXTURE
  float shifted = fract(uvTex.x + 0.5);
  // Derivatives of the image coordinates (u, 1 - v).
  vec2 dx = vec2(wrappedDerivative(dFdx(uvTex.x), dFdx(shifted)), -dFdx(uvTex.y));
  vec2 dy = vec2(wrappedDerivative(dFdy(uvTex.x), dFdy(shifted)), -dFdy(uvTex.y));
#endif
  if (!hit) discard;

  vec3 geometric = shapeNormal(p);
  vec3 n = fromCellDirection(copy, bumpedNormal(p, geometric, uvTex));
  vec4 base = uBaseColor;
#ifdef HAS_BASE_COLOR_TEXTURE
  // glTF images store their top row first: v = 0 (the bottom of the object) is the image's last row.
  base *= textureGrad(uBaseColorTexture, vec2(uvTex.x, 1.0 - uvTex.y), dx, dy);
#endif
  vec3 world = (uModel * vec4(pObject, 1.0)).xyz;
  vec3 nWorld = normalize(uNormalMatrix * n);
  vec3 l = normalize(uLightDir);
  vec3 v = normalize(uCameraPos - world);
  float visible = 1.0;
#ifdef SELF_SHADOW
  vec3 outward = fromCellDirection(copy, geometric);
  if (dot(outward, uLightDirObject) > 0.0) {
    // Lifted two texels off the surface: the hit lies within the hit epsilon and the safety margin of
    // it, and the shadow ray must not find its own start.
    vec3 start = pObject + outward * (2.0 * uShapeGrid.z + uHitEpsilon + uSafetyMargin);
    float tShadow;
    Cell blocker;
    // A shadow ray that used up its budget has stayed near surfaces all along (a narrow gap, a
    // grazing pass): counted as blocked, where counting it lit speckles such gaps.
    if (marchCopies(start, uLightDirObject, 0.0, tShadow, blocker) || gMarchExhausted) visible = 0.0;
  }
#endif
  fragColor = vec4(blinnPhong(nWorld, l, v, base.rgb, visible * uLightColour), base.a);

  vec4 clip = uObjectToClip * vec4(pObject, 1.0);
  float ndcDepth = clip.z / clip.w;
  gl_FragDepth = ((gl_DepthRange.far - gl_DepthRange.near) * ndcDepth + gl_DepthRange.near + gl_DepthRange.far) * 0.5;
}
