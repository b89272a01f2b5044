// The tube reference of the paintstrokes (--stroke-tubes): fixed tubes tessellated on the CPU at load
// (runtime/render/paintstrokes_params.cpp), each vertex carrying its segment's first control point
// and its parameter t along the segment, so colour, opacity, reflectance and shadow are read from the
// same package arrays and interpolated exactly as the tessellated strokes do.
#include "package.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aTangent;
layout(location = 3) in float aT;
layout(location = 4) in uint aPoint;
layout(location = 5) in uint aStroke;

uniform mat4 uModelView;
uniform mat3 uNormalView;  // inverse transpose of uModelView's 3x3
uniform mat4 uProjection;

out vec3 vViewPosition;
out vec3 vTangent;
out vec3 vNormal;
out vec4 vColour;
out vec2 vReflectanceShadow;
flat out uint vStyle;

void main() {
  vec4 view = uModelView * vec4(aPosition, 1.0);
  vViewPosition = view.xyz;
  vNormal = uNormalView * aNormal;
  vTangent = mat3(uModelView) * aTangent;
  vColour = mix(pointColour(aPoint), pointColour(aPoint + 1u), aT);
  vReflectanceShadow = mix(vec2(pointReflectance(aPoint), pointShadow(aPoint)),
                           vec2(pointReflectance(aPoint + 1u), pointShadow(aPoint + 1u)), aT);
  vStyle = strokes[aStroke].info.z;
  gl_Position = uProjection * view;
}
