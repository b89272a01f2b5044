// Standard glTF mesh, fragment stage: Blinn-Phong with the material's base colour, linear output.
// Without HAS_NORMALS the normal is the flat face normal, from screen-space derivatives of the world
// position; it always faces the camera, so such meshes are lit on both sides. UNLIT (points and
// lines): the base colour.
#include "common/lighting.glsl"

in vec3 vWorldPosition;
#ifdef HAS_NORMALS
in vec3 vNormal;
#endif
#ifdef HAS_TEXCOORD0
in vec2 vTexcoord0;  // not sampled yet; passed through for textured materials
#endif

uniform vec3 uLightDir;   // direction towards the light, world space
uniform vec3 uLightColour = vec3(1.0);  // linear; KHR_lights_punctual colour when the scene has one
uniform vec3 uCameraPos;  // world space
uniform vec4 uBaseColor;  // linear RGBA

layout(location = 0) out vec4 fragColor;

void main() {
#ifdef UNLIT
  fragColor = uBaseColor;  // points and lines: the base colour as it is
  return;
#endif
#ifdef HAS_NORMALS
  vec3 n = normalize(vNormal);  // interpolation shortens it
#else
  vec3 n = normalize(cross(dFdx(vWorldPosition), dFdy(vWorldPosition)));
#endif
  vec3 l = normalize(uLightDir);
  vec3 v = normalize(uCameraPos - vWorldPosition);
  fragColor = vec4(blinnPhong(n, l, v, uBaseColor.rgb, uLightColour), uBaseColor.a);
}
