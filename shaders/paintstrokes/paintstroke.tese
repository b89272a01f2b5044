// Paintstroke segments, tessellation evaluation stage (seed 002): u runs along the segment, v across.
// The path and the radius are Catmull-Rom interpolants of the four control points, colour, opacity,
// reflectance and shadow are linear between points i and i+1. The vertices lie on the half of the
// generalized cylinder facing the viewer ("the side of the paintstroke closest to the viewer is
// always completely covered by one, two, or four polygons"): at theta = (v - 1/2) pi,
//   position = c + r (sin(theta) side + cos(theta) toViewer),  side = normalize(cross(tangent, toViewer)).
// One polygon across is the seed's flat quality-zero strip (no toViewer term). The breadthwise
// coordinate s = sin(theta) goes to the fragments without perspective correction: on screen, the
// projected cylinder point moves linearly in s (exactly so for an orthographic view).
layout(quads, equal_spacing, ccw) in;

uniform mat4 uProjection;
uniform bool uOrthographic;

in vec4 tcPositionRadius[];
in vec4 tcColour[];
in vec2 tcReflectanceShadow[];
patch in uint tcStyle;

out vec3 vViewPosition;
out vec3 vTangent;
out vec3 vSide;
out vec3 vToViewer;
noperspective out float vS;
out vec4 vColour;
out vec2 vReflectanceShadow;
flat out uint vStyle;

const float kPi = 3.14159265358979;

// A unit vector orthogonal to unit `t` (for a view straight down the path, where toViewer vanishes).
vec3 anyOrthogonal(vec3 t) {
  vec3 a = abs(t.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  return normalize(cross(t, a));
}

void main() {
  float u = gl_TessCoord.x, v = gl_TessCoord.y;
  float u2 = u * u, u3 = u2 * u;
  // Catmull-Rom basis (tension 1/2) and its derivative.
  vec4 w = 0.5 * vec4(-u3 + 2.0 * u2 - u, 3.0 * u3 - 5.0 * u2 + 2.0, -3.0 * u3 + 4.0 * u2 + u, u3 - u2);
  vec4 dw = 0.5 * vec4(-3.0 * u2 + 4.0 * u - 1.0, 9.0 * u2 - 10.0 * u, -9.0 * u2 + 8.0 * u + 1.0, 3.0 * u2 - 2.0 * u);
  vec4 c = w.x * tcPositionRadius[0] + w.y * tcPositionRadius[1] + w.z * tcPositionRadius[2] + w.w * tcPositionRadius[3];
  vec3 dc = (dw.x * tcPositionRadius[0] + dw.y * tcPositionRadius[1] + dw.z * tcPositionRadius[2] +
             dw.w * tcPositionRadius[3]).xyz;
  float radius = max(c.w, 0.0);  // the spline may overshoot below zero near a tapered end

  vec3 chord = tcPositionRadius[2].xyz - tcPositionRadius[1].xyz;
  vec3 tangent = length(dc) > 1e-12 ? normalize(dc) : (length(chord) > 1e-12 ? normalize(chord) : vec3(0.0, 0.0, 1.0));
  vec3 eye = uOrthographic ? vec3(0.0, 0.0, 1.0) : -c.xyz;
  vec3 across = eye - dot(eye, tangent) * tangent;
  // Head-on (the view along the path): any orthogonal frame; the strip is then seen edge-on.
  vec3 toViewer = length(across) > 1e-6 * max(length(eye), 1e-20) ? normalize(across) : anyOrthogonal(tangent);
  vec3 side = normalize(cross(tangent, toViewer));

  float theta = (v - 0.5) * kPi;
  float s = sin(theta);
  vec3 offset = s * side;
#if POLYGONS_ACROSS > 1
  offset += cos(theta) * toViewer;
#endif
  vec3 position = c.xyz + radius * offset;

  vViewPosition = position;
  vTangent = tangent;
  vSide = side;
  vToViewer = toViewer;
  vS = s;
  vColour = mix(tcColour[1], tcColour[2], u);
  vReflectanceShadow = mix(tcReflectanceShadow[1], tcReflectanceShadow[2], u);
  vStyle = tcStyle;
  gl_Position = uProjection * vec4(position, 1.0);
}
