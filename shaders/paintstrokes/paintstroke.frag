// Paintstroke fragments (seed 002), for both the tessellated strokes and the tube reference (TUBES).
// Tessellated: the normal is rebuilt from the breadthwise coordinate s, n = s side + sqrt(1 - s^2)
// toViewer, the normal of the half cylinder facing the viewer, whatever the polygons across.
// Tubes: the interpolated surface normal, and s = dot(n, side) from it and the view direction.
#include "package.glsl"
#include "shading.glsl"

uniform bool uOrthographic;

in vec3 vViewPosition;
in vec3 vTangent;
#ifdef TUBES
in vec3 vNormal;
#else
in vec3 vSide;
in vec3 vToViewer;
noperspective in float vS;
#endif
in vec4 vColour;
in vec2 vReflectanceShadow;
flat in uint vStyle;

layout(location = 0) out vec4 fragColour;

void main() {
  StrokeSample p;
  p.tangent = normalize(vTangent);
  p.toViewer = uOrthographic ? vec3(0.0, 0.0, 1.0) : normalize(-vViewPosition);
#ifdef TUBES
  p.normal = normalize(vNormal);
  vec3 across = p.toViewer - dot(p.toViewer, p.tangent) * p.tangent;
  vec3 side = length(across) > 1e-6 ? normalize(cross(p.tangent, normalize(across))) : vec3(0.0);
  p.s = clamp(dot(p.normal, side), -1.0, 1.0);
#else
  p.s = clamp(vS, -1.0, 1.0);
  p.normal = normalize(p.s * normalize(vSide) + sqrt(max(1.0 - p.s * p.s, 0.0)) * normalize(vToViewer));
#endif
  p.colour = vColour;
  p.reflectance = vReflectanceShadow.x;
  p.shadow = vReflectanceShadow.y;
  vec4 shaded = shadeStroke(p, styles[vStyle]);
  if (!(shaded.a > 0.0)) discard;
  fragColour = shaded;
}
