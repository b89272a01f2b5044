// Hatching (seed 004), geometry stage. Input: T_c = (in[0], in[2], in[4]) and the opposite vertices
// of its neighbours across edges (0,2), (2,4), (4,0) in in[1], in[3], in[5] (figure 5). A boundary
// edge repeats T_c's own opposite vertex, which makes that neighbour coincide with T_c.
//
// §3.2 Algorithm 1, in object space (so the strokes stay on the object): N = normalised
// (V1 - V0) x (V2 - V0); L towards the light: for a directional light its direction brought into object
// space, for a point or spot light L = Lp - G with G the triangle's barycentre (each neighbour its
// own); B = normalise(L - N (L.N)), T = B x N; H = (V.T, V.B). With ACROSS_LIGHT T and B swap roles (figure
// 14). §4: the coordinates are scaled by tilesPerUnit, rotated about N and translated (in tiles).
// §3.3 Algorithm 2: the same for each neighbour T_t, with T_c's vertices projected onto T_t's plane;
// blend factor 1 for T_c, N_c.N_t at the two shared vertices, -1 at T_c's vertex opposite the shared
// edge (the contribution fades across T_c); -1 everywhere when N_c.N_t <= MIN_BLEND_COSINE, for a
// boundary edge and for a degenerate neighbour. Face normals go to the fragment stage for the tone.

layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 vObjectPosition[];

uniform mat4 uModel;
uniform mat4 uViewProj;
uniform mat3 uNormalMatrix;   // inverse transpose of uModel's upper 3x3
uniform vec3 uLightDir;       // towards the light, world space (directional lights)
uniform int uLightKind;       // 0 directional, 1 point, 2 spot
uniform vec3 uLightPosObject; // point and spot lights: the position in object space
uniform float uTilesPerUnit;
uniform vec2 uRotation;       // cos, sin of the rotation about N
uniform vec2 uTranslation;    // tiles along T and B

out vec4 gCoordsCA;   // hatching coordinates in T_c (xy) and T_alpha (zw)
out vec4 gCoordsBG;   // in T_beta (xy) and T_gamma (zw)
out vec3 gBlend;      // blend factors of T_alpha, T_beta, T_gamma (T_c's is 1)
out vec3 gWorldPosition;  // for the fragment-light vector of point and spot lights (§3.4)
flat out vec3 gNormalC, gNormalA, gNormalB, gNormalG;  // world-space unit face normals

struct Frame {
  vec3 t, b, n;
  bool valid;
};

// Algorithm 1's frame of triangle (a, b, c) for the object-space light direction l (directional
// lights; for point and spot lights l is replaced by Lp - G of this triangle).
Frame frameOf(vec3 a, vec3 b, vec3 c, vec3 l) {
  Frame f;
  if (uLightKind != 0) l = uLightPosObject - (a + b + c) / 3.0;
  vec3 e1 = b - a, e2 = c - a;
  vec3 n = cross(e1, e2);
  float len = length(n);
  f.valid = len > 1e-7 * (dot(e1, e1) + dot(e2, e2)) && len > 0.0;
  n = f.valid ? n / len : vec3(0.0, 0.0, 1.0);
  vec3 projected = l - n * dot(l, n);
  if (dot(projected, projected) < 1e-12) {
    // The light is along the normal: any tangent is as good; take the axis least aligned with N.
    vec3 m = abs(n);
    vec3 axis = m.x <= m.y && m.x <= m.z ? vec3(1.0, 0.0, 0.0) : (m.y <= m.z ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0));
    projected = axis - n * dot(axis, n);
  }
  vec3 bt = normalize(projected);
  vec3 tt = cross(bt, n);
#ifdef ACROSS_LIGHT
  f.t = bt;
  f.b = tt;
#else
  f.t = tt;
  f.b = bt;
#endif
  f.n = n;
  return f;
}

// H = (V.T, V.B), then scale, rotation about N and translation (§4).
vec2 hatchingCoords(vec3 v, Frame f) {
  vec2 st = vec2(dot(v, f.t), dot(v, f.b)) * uTilesPerUnit;
  st = vec2(uRotation.x * st.x - uRotation.y * st.y, uRotation.y * st.x + uRotation.x * st.y);
  return st + uTranslation;
}

// V projected onto the plane of a triangle through p with unit normal n (figure 6).
vec3 ontoPlane(vec3 v, vec3 p, vec3 n) { return v - n * dot(v - p, n); }

void main() {
  vec3 v[3] = vec3[3](vObjectPosition[0], vObjectPosition[2], vObjectPosition[4]);
  // Opposite vertex of each neighbour, and T_c's own vertex opposite the shared edge.
  vec3 o[3] = vec3[3](vObjectPosition[1], vObjectPosition[3], vObjectPosition[5]);
  vec3 light = normalize(uLightDir * uNormalMatrix);  // M^-1 L: the light direction in object space

  Frame fc = frameOf(v[0], v[1], v[2], light);
  if (!fc.valid) return;  // zero area: nothing to draw
  // Neighbour k shares edge (v[k], v[k+1]) and is wound (v[k+1], v[k], o[k]) like T_c.
  Frame fn[3];
  float cosine[3];
  for (int k = 0; k < 3; ++k) {
    vec3 a = v[k], b = v[(k + 1) % 3];
    fn[k] = frameOf(b, a, o[k], light);
    bool boundary = o[k] == v[(k + 2) % 3];
    cosine[k] = (fn[k].valid && !boundary) ? dot(fc.n, fn[k].n) : -1.0;
    if (cosine[k] <= MIN_BLEND_COSINE) cosine[k] = -1.0;
  }

  gNormalC = normalize(uNormalMatrix * fc.n);
  gNormalA = fn[0].valid ? normalize(uNormalMatrix * fn[0].n) : gNormalC;
  gNormalB = fn[1].valid ? normalize(uNormalMatrix * fn[1].n) : gNormalC;
  gNormalG = fn[2].valid ? normalize(uNormalMatrix * fn[2].n) : gNormalC;
  for (int i = 0; i < 3; ++i) {
    vec2 h[3];
    float f[3];
    for (int k = 0; k < 3; ++k) {
      h[k] = hatchingCoords(ontoPlane(v[i], v[k], fn[k].n), fn[k]);
      // Vertex i is opposite edge k when i == k + 2 (mod 3).
      f[k] = (i == (k + 2) % 3 || cosine[k] < 0.0) ? -1.0 : cosine[k];
    }
    gCoordsCA = vec4(hatchingCoords(v[i], fc), h[0]);
    gCoordsBG = vec4(h[1], h[2]);
    gBlend = vec3(f[0], f[1], f[2]);
    vec4 world = uModel * vec4(v[i], 1.0);
    gWorldPosition = world.xyz;
    gl_Position = uViewProj * world;
    EmitVertex();
  }
  EndPrimitive();
}
