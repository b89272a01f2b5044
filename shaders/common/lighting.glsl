// Blinn-Phong lighting shared by the techniques: one directional light plus a little ambient.
// All vectors are in world space and normalised by the caller; the result is linear colour.
#ifndef BAKE_COMMON_LIGHTING_GLSL
#define BAKE_COMMON_LIGHTING_GLSL

const float kAmbient = 0.08;
const float kSpecularStrength = 0.25;
const float kShininess = 32.0;

// n: surface normal, l: direction towards the light, v: direction towards the camera, lightColour:
// the light's linear colour (white when a caller has none).
vec3 blinnPhong(vec3 n, vec3 l, vec3 v, vec3 baseColor, vec3 lightColour) {
  float diffuse = max(dot(n, l), 0.0);
  vec3 h = normalize(l + v);
  // No highlight on the side facing away from the light, where h can still align with n.
  float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), kShininess) : 0.0;
  return baseColor * (kAmbient + diffuse * lightColour) + kSpecularStrength * specular * lightColour;
}

#endif
