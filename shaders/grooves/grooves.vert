// Grooved surfaces (seed 000, Bosch et al. 2008), vertex stage: places the mesh (the package's preview
// plane, or any mesh with TEXCOORD_0) and passes on what the fragment stage needs to build the pixel
// footprint and the tangent frame: world position, normal and texture coordinates.
// Variants: HAS_NORMALS (NORMAL attribute present; else the normal comes from position derivatives),
// HAS_TANGENTS (TANGENT present, with NORMAL: the frame follows it instead of the uv derivatives).

layout(location = 0) in vec3 aPosition;
#ifdef HAS_NORMALS
layout(location = 1) in vec3 aNormal;
#endif
layout(location = 2) in vec2 aTexcoord0;
#ifdef HAS_TANGENTS
layout(location = 3) in vec4 aTangent;
out vec4 vTangent;
#endif

uniform mat4 uModel;
uniform mat4 uViewProj;
uniform mat3 uNormalMatrix;  // inverse transpose of uModel's upper 3x3

out vec3 vWorldPosition;
out vec3 vNormal;
out vec2 vTexcoord0;

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorldPosition = world.xyz;
#ifdef HAS_NORMALS
  vNormal = uNormalMatrix * aNormal;
#else
  vNormal = vec3(0.0);
#endif
  vTexcoord0 = aTexcoord0;
#ifdef HAS_TANGENTS
  vTangent = vec4(mat3(uModel) * aTangent.xyz, aTangent.w);
#endif
  gl_Position = uViewProj * world;
}
