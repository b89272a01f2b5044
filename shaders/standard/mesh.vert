// Standard glTF mesh, vertex stage: world-space position (and normal) for lighting in mesh.frag.
// Variants: HAS_NORMALS (NORMAL attribute present), HAS_TEXCOORD0 (TEXCOORD_0 present).

layout(location = 0) in vec3 aPosition;
#ifdef HAS_NORMALS
layout(location = 1) in vec3 aNormal;
#endif
#ifdef HAS_TEXCOORD0
layout(location = 2) in vec2 aTexcoord0;
#endif

uniform mat4 uModel;
uniform mat4 uViewProj;
uniform mat3 uNormalMatrix;  // inverse transpose of uModel's upper 3x3

out vec3 vWorldPosition;
#ifdef HAS_NORMALS
out vec3 vNormal;
#endif
#ifdef HAS_TEXCOORD0
out vec2 vTexcoord0;
#endif

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorldPosition = world.xyz;
#ifdef HAS_NORMALS
  vNormal = uNormalMatrix * aNormal;
#endif
#ifdef HAS_TEXCOORD0
  vTexcoord0 = aTexcoord0;
#endif
  gl_Position = uViewProj * world;
}
