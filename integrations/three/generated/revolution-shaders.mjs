// GENERATED FILE, do not edit: run `node tools/generate-shaders.mjs` in integrations/three.
// GLSL ES 3.00 adaptation of these files under shaders/:
//   revolution/revolution.vert
//   revolution/revolution.frag
//   common/lighting.glsl
//   revolution/surface.glsl
//   revolution/shape_march.glsl
//   revolution/replicas.glsl

export const sources = ["revolution/revolution.vert","revolution/revolution.frag","common/lighting.glsl","revolution/surface.glsl","revolution/shape_march.glsl","revolution/replicas.glsl"];

export const vertexShader = `precision highp float;
precision highp int;
// Revolution mapping, vertex stage (seed 001, "Shape box"): places the shape box. The fragment stage
// rebuilds each pixel's ray itself from gl_FragCoord, so nothing but the position is passed on.
in vec3 position;

uniform mat4 uObjectToClip;  // projection * view * model

void main() {
  gl_Position = uObjectToClip * vec4(position, 1.0);
}
`;

export const fragmentShader = `precision highp float;
precision highp int;
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
// ---- common/lighting.glsl
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
// ---- end of common/lighting.glsl
// ---- revolution/surface.glsl
// Revolution mapping: the surface at a hit (seed 001, "Shading" and "Texturing function").
// Normal from the shape map's gradient (Eq. 6, here with the axis along +y): n = (g_r x/r, g_h, g_r z/r).
// Tangent frame (Eq. 7-8): T the unit tangent along the angle (the direction u grows), B = N x T
// along the profile, so (T, B, N) is right-handed and a rising height tilts the normal away from the
// slope as in Blinn's Eq. 1. Texture coordinates by projection: u = (pi - phi) / 2 pi with
// phi = atan2(z, x) (Eq. 12-13, 16-17); v = (h - hMin) / box height (cylindrical, Eq. 13), v = (pi -
// theta) / pi about (0, sphereCentreH, 0) (spherical, Eq. 14-17), or the arc-length map's value.
// Bump mapping (Eq. 4-5): n' = N + D with D = -(H_T T + H_B B), H_T and H_B the height's slopes along
// T and B, from the displacement map's dH/du, dH/dv (object units per texture repeat) and the
// gradients of u and v.
// Variants: PROJECTION_CYLINDRICAL / PROJECTION_SPHERICAL / PROJECTION_ARC_LENGTH, HAS_DISPLACEMENT.
#ifndef BAKE_REVOLUTION_SURFACE_GLSL
#define BAKE_REVOLUTION_SURFACE_GLSL

// ---- revolution/shape_march.glsl
// Revolution mapping: the ray march of formats/revolution.md ("Sampling and marching"), in object
// space (axis +y). The shape map is sampled bilinearly at (r, h) = (|p.xz|, p.y) on its encoded
// values and decoded after filtering; the safety margin is subtracted from every sample. The march
// enters the proxy bands (else the box) and runs over-relaxed sphere tracing (Keinert et al. 2014,
// "Enhanced Sphere Tracing", section 3.1): step omega * d, and when the new sample's sphere and the
// previous one do not overlap (d_prev + |d| < step), or the sample lies inside the solid, or the step
// left the march interval, go back and take the plain step d_prev from the previous point with
// omega = 1 from then on. libbake/revolution/march.cpp runs the same loop on the CPU.
// Variants: ENCODING_FLOAT / ENCODING_UNORM16 / ENCODING_SQRT8; MAX_PROXY_BANDS n.
#ifndef BAKE_REVOLUTION_SHAPE_MARCH_GLSL
#define BAKE_REVOLUTION_SHAPE_MARCH_GLSL

#ifndef MAX_PROXY_BANDS
#define MAX_PROXY_BANDS 64
#endif

uniform sampler2D uShapeMap;  // S mirrored repeat (the axis), T clamped

uniform vec4 uShapeGrid;       // width, height (texels), texelSize, hMin (object units)
uniform float uDistanceScale;  // S of the integer encodings
uniform float uSafetyMargin;
uniform float uHitEpsilon;
uniform float uOverRelaxation;
uniform int uIterations;
uniform vec3 uBoxMin, uBoxMax;  // where the march may run (object space)
uniform int uBandCount;
uniform vec3 uBands[MAX_PROXY_BANDS];  // hMin, hMax, rMax

// Texture coordinates of (r, h). r stays at or inside the centre of the last column, so the bilinear
// footprint never reaches past the outer edge (where a repeat would wrap back to the axis).
vec2 shapeCoordinates(vec2 rh) {
  float r = clamp(rh.x, 0.0, (uShapeGrid.x - 0.5) * uShapeGrid.z);
  return vec2(r / (uShapeGrid.x * uShapeGrid.z), (rh.y - uShapeGrid.w) / (uShapeGrid.y * uShapeGrid.z));
}

vec4 sampleShape(vec3 p) {
  return textureLod(uShapeMap, shapeCoordinates(vec2(length(p.xz), p.y)), 0.0);
}

// Signed distance (object units) from a filtered B value.
float decodeDistance(float b) {
#if defined(ENCODING_FLOAT)
  return b;
#elif defined(ENCODING_SQRT8)
  float e = 2.0 * b - 1.0;
  return sign(e) * e * e * uDistanceScale;
#else
  return (2.0 * b - 1.0) * uDistanceScale;
#endif
}

// Unit gradient (d/dr, d/dh) from filtered R, G values.
vec2 decodeGradient(vec2 rg) {
#if defined(ENCODING_FLOAT)
  return rg;
#else
  return 2.0 * rg - 1.0;
#endif
}

// The march's distance: decoded, less the safety margin.
float marchDistance(vec3 p) { return decodeDistance(sampleShape(p).b) - uSafetyMargin; }

// Ray parameters of the slab lo <= o + t d <= hi along one axis.
vec2 slab(float o, float d, float lo, float hi) {
  if (abs(d) < 1e-12) return (o >= lo && o <= hi) ? vec2(-1e30, 1e30) : vec2(1e30, -1e30);
  float a = (lo - o) / d, b = (hi - o) / d;
  return vec2(min(a, b), max(a, b));
}

vec2 boxInterval(vec3 o, vec3 d) {
  vec2 x = slab(o.x, d.x, uBoxMin.x, uBoxMax.x);
  vec2 y = slab(o.y, d.y, uBoxMin.y, uBoxMax.y);
  vec2 z = slab(o.z, d.z, uBoxMin.z, uBoxMax.z);
  return vec2(max(x.x, max(y.x, z.x)), min(x.y, min(y.y, z.y)));
}

// Ray parameters inside one band: the finite cylinder r <= rMax, hMin <= h <= hMax.
vec2 bandInterval(vec3 o, vec3 d, vec3 band) {
  vec2 inside = slab(o.y, d.y, band.x, band.y);
  float a = dot(d.xz, d.xz), b = dot(o.xz, d.xz), c = dot(o.xz, o.xz) - band.z * band.z;
  if (a < 1e-12) {
    if (c > 0.0) return vec2(1e30, -1e30);  // parallel to the axis, outside the cylinder
  } else {
    float disc = b * b - a * c;
    if (disc < 0.0) return vec2(1e30, -1e30);
    float root = sqrt(disc);
    inside = vec2(max(inside.x, (-b - root) / a), min(inside.y, (-b + root) / a));
  }
  return inside;
}

// The interval the march covers, from tStart on: the box, narrowed to the union of the bands' hull
// (first entry to last exit) when the package has bands. Empty when x > y.
vec2 marchInterval(vec3 o, vec3 d, float tStart) {
  vec2 box = boxInterval(o, d);
  box.x = max(box.x, tStart);
  if (uBandCount == 0) return box;
  vec2 hull = vec2(1e30, -1e30);
  for (int i = 0; i < uBandCount && i < MAX_PROXY_BANDS; ++i) {
    vec2 band = bandInterval(o, d, uBands[i]);
    band.x = max(band.x, box.x);
    if (band.x <= band.y) hull = vec2(min(hull.x, band.x), max(hull.y, band.y));
  }
  return vec2(max(box.x, hull.x), min(box.y, hull.y));
}

// Set by marchRay when the budget ran out before the ray hit or left its interval.
bool gMarchExhausted = false;

// Over-relaxed sphere tracing over [interval.x, interval.y]; true with the hit's t on a hit.
bool marchRay(vec3 o, vec3 d, vec2 interval, out float tHit) {
  gMarchExhausted = false;
  tHit = interval.x;
  if (interval.x > interval.y) return false;
  float omega = uOverRelaxation;
  float t = interval.x;
  float previousT = t, previousD = 0.0, step = 0.0;
  for (int i = 0; i < uIterations; ++i) {
    if (t > interval.y) {
      // An over-relaxed step past the exit may have jumped over the solid (the bands' exit hugs it,
      // unlike a far plane): take the plain step from the previous point instead.
      if (!(omega > 1.0 && step > previousD)) return false;
      omega = 1.0;
      step = previousD;
      t = previousT + step;
      if (t > interval.y) return false;
    }
    float dist = marchDistance(o + t * d);
    if (omega > 1.0 && step > 0.0 && (dist < 0.0 || previousD + abs(dist) < step)) {
      // The relaxed step left the sphere known to be empty, or landed inside the solid: back to the
      // previous point and a plain step (an overshoot into the solid is never a hit).
      omega = 1.0;
      step = previousD;
      t = previousT + step;
      continue;
    }
    if (dist < uHitEpsilon) {
      tHit = t;
      return true;
    }
    previousT = t;
    previousD = dist;
    step = omega * dist;
    t += step;
  }
  gMarchExhausted = true;
  return false;
}

#endif
// ---- end of revolution/shape_march.glsl

uniform sampler2D uDisplacementMap;  // RG unorm16 dH/du, dH/dv; rows from v = 0
uniform sampler2D uArcLengthMap;     // R unorm16 per shape-map texel

uniform vec2 uRepeat;            // texture repeats in u and v
uniform float uSphereCentreH;    // spherical projection centre on the axis
uniform float uDerivativeScale;  // decoded dH/du, dH/dv = (2 x - 1) * scale

const float kPi = 3.14159265358979;

// Radius of p, kept off zero (on the axis the angle has no direction).
float radiusOf(vec3 p) { return max(length(p.xz), 1e-7 * uShapeGrid.z); }

vec3 shapeNormal(vec3 p) {
  vec2 g = decodeGradient(sampleShape(p).rg);
  float r = radiusOf(p);
  vec3 n = vec3(g.x * p.x / r, g.y, g.x * p.z / r);
  return length(n) > 1e-12 ? normalize(n) : vec3(0.0, 1.0, 0.0);
}

// T: along the angle, the direction of growing u = (pi - atan2(z, x)) / 2 pi.
vec3 angularTangent(vec3 p) {
  float r = radiusOf(p);
  return vec3(p.z, 0.0, -p.x) / r;
}

float arcLengthAt(vec3 p) {
  return textureLod(uArcLengthMap, shapeCoordinates(vec2(length(p.xz), p.y)), 0.0).r;
}

// (u, v) of the projection, one repeat over [0, 1].
vec2 projectionCoordinates(vec3 p) {
  float u = (kPi - atan(p.z, p.x)) / (2.0 * kPi);
#if defined(PROJECTION_SPHERICAL)
  vec3 q = p - vec3(0.0, uSphereCentreH, 0.0);
  float theta = acos(clamp(q.y / max(length(q), 1e-20), -1.0, 1.0));
  return vec2(u, (kPi - theta) / kPi);
#elif defined(PROJECTION_ARC_LENGTH)
  return vec2(u, arcLengthAt(p));
#else
  return vec2(u, (p.y - uShapeGrid.w) / (uShapeGrid.y * uShapeGrid.z));
#endif
}

// Object-space gradient of the projection's v.
vec3 gradientOfV(vec3 p) {
#if defined(PROJECTION_SPHERICAL)
  vec3 q = p - vec3(0.0, uSphereCentreH, 0.0);
  float rho2 = max(dot(q, q), 1e-30);
  // v = 1 - theta / pi, grad theta = -(y_hat - q.y q / rho^2) / (rho sin theta), rho sin theta = r.
  return (vec3(0.0, 1.0, 0.0) - q.y * q / rho2) / (kPi * radiusOf(p));
#elif defined(PROJECTION_ARC_LENGTH)
  // Central differences over one texel of the map the values come from.
  float e = uShapeGrid.z;
  vec3 radial = vec3(p.x, 0.0, p.z) / radiusOf(p);
  float dr = (arcLengthAt(p + e * radial) - arcLengthAt(p - e * radial)) / (2.0 * e);
  float dh = (arcLengthAt(p + vec3(0.0, e, 0.0)) - arcLengthAt(p - vec3(0.0, e, 0.0))) / (2.0 * e);
  return dr * radial + vec3(0.0, dh, 0.0);
#else
  return vec3(0.0, 1.0 / (uShapeGrid.y * uShapeGrid.z), 0.0);
#endif
}

// Eq. 4-5: the bumped normal at p, given the geometric normal n and the texture coordinates of one
// repeat \`uvTex\` (already multiplied by uRepeat).
vec3 bumpedNormal(vec3 p, vec3 n, vec2 uvTex) {
#ifdef HAS_DISPLACEMENT
  vec2 dH = (2.0 * textureLod(uDisplacementMap, uvTex, 0.0).rg - 1.0) * uDerivativeScale;
  vec3 t = angularTangent(p);
  t = normalize(t - n * dot(n, t));
  vec3 b = cross(n, t);
  // du/ds along T is 1 / (2 pi r); dv/ds along B from the projection's gradient.
  float slopeT = dH.x * uRepeat.x / (2.0 * kPi * radiusOf(p));
  float slopeB = dH.y * uRepeat.y * dot(gradientOfV(p), b);
  return normalize(n - slopeT * t - slopeB * b);
#else
  return n;
#endif
}

#endif
// ---- end of revolution/surface.glsl
// ---- revolution/replicas.glsl
// Revolution mapping: copies of the object in one shape box (seed 001 Eq. 9, and the mirror-and-
// repetition variant of Fig. 13; formats/revolution.md, "Replicas"). The box is cut into cells, one
// copy each: a grid of cells spaced \`uGridSpacing\` apart (odd cells of a mirrored axis reflected about
// their box's centre), or a ring of wedges of angle 2 pi / n about +y. The paper takes the fractional
// part of the hit point's coordinates; here each cell maps the ray into its copy's own frame (a
// translation, reflection or rotation: an isometry, so ray parameters and distances are kept) and
// runs the one-object march there, over the part of the ray inside the cell. A copy lies inside its
// cell, so no other copy can be hit on that part: walking the cells in order along the ray, the first
// hit is the nearest. The same walk marches the self-shadow ray toward the light.
// Variant: REPLICAS_GRID / REPLICAS_RING (neither: one object, the march unchanged).
#ifndef BAKE_REVOLUTION_REPLICAS_GLSL
#define BAKE_REVOLUTION_REPLICAS_GLSL

// ---- revolution/shape_march.glsl
// (revolution/shape_march.glsl already included)
// ---- end of revolution/shape_march.glsl

uniform ivec3 uGridCount;
uniform vec3 uGridSpacing;
uniform ivec3 uGridMirror;   // 1 on a mirrored axis
uniform int uRingCount;
uniform float uRingRadius;
uniform int uCellBudget;     // most cells a ray crosses
uniform vec3 uReplicaBoxMin, uReplicaBoxMax;  // every copy's box together

// A copy's frame: local = toLocal * p + offset (toLocal orthonormal).
struct Cell {
  mat3 toLocal;
  vec3 offset;
  float tExit;  // where the ray leaves the cell
};

vec3 toCell(Cell cell, vec3 p) { return cell.toLocal * p + cell.offset; }
vec3 fromCellDirection(Cell cell, vec3 v) { return transpose(cell.toLocal) * v; }

Cell oneObject() { return Cell(mat3(1.0), vec3(0.0), 1e30); }

#if defined(REPLICAS_GRID)
// The grid cell holding o + t d: on each axis the cell of copy i spans its box's centre +- spacing / 2
// (the end cells open outward; the replica box bounds them).
Cell cellAt(vec3 o, vec3 d, float t) {
  vec3 p = o + t * d;
  vec3 centre = 0.5 * (uBoxMin + uBoxMax);
  Cell cell;
  cell.toLocal = mat3(1.0);
  cell.tExit = 1e30;
  for (int a = 0; a < 3; ++a) {
    float lo = centre[a] - 0.5 * uGridSpacing[a];
    float i = clamp(floor((p[a] - lo) / uGridSpacing[a]), 0.0, float(uGridCount[a] - 1));
    float flip = (uGridMirror[a] == 1 && mod(i, 2.0) == 1.0) ? -1.0 : 1.0;
    cell.toLocal[a][a] = flip;
    cell.offset[a] = centre[a] - flip * (i * uGridSpacing[a] + centre[a]);
    float cellLo = i == 0.0 ? -1e30 : lo + i * uGridSpacing[a];
    float cellHi = i == float(uGridCount[a] - 1) ? 1e30 : lo + (i + 1.0) * uGridSpacing[a];
    if (abs(d[a]) > 1e-12) cell.tExit = min(cell.tExit, ((d[a] > 0.0 ? cellHi : cellLo) - o[a]) / d[a]);
  }
  return cell;
}
#elif defined(REPLICAS_RING)
// The wedge holding o + t d: copy k stands at angle 2 pi k / n, its wedge spans +- pi / n about it.
Cell cellAt(vec3 o, vec3 d, float t) {
  vec3 p = o + t * d;
  float wedge = 2.0 * 3.14159265358979 / float(uRingCount);
  float k = mod(floor(atan(p.z, p.x) / wedge + 0.5), float(uRingCount));
  float angle = k * wedge;
  float c = cos(angle), s = sin(angle);
  Cell cell;
  cell.toLocal = mat3(vec3(c, 0.0, -s), vec3(0.0, 1.0, 0.0), vec3(s, 0.0, c));  // turns angle to 0
  cell.offset = vec3(-uRingRadius, 0.0, 0.0);
  cell.tExit = 1e30;
  // The two boundary half-planes {rho (cos b, 0, sin b), rho >= 0}: the ray leaves through one whose
  // crossing lies ahead and on the half-plane's own side of the axis.
  for (int side = -1; side <= 1; side += 2) {
    float b = angle + float(side) * 0.5 * wedge;
    vec3 along = vec3(cos(b), 0.0, sin(b));
    vec3 normal = vec3(-along.z, 0.0, along.x);
    float dn = dot(normal, d);
    if (abs(dn) < 1e-12) continue;
    float tb = -dot(normal, o) / dn;
    if (tb > t && dot(along, o + tb * d) >= 0.0) cell.tExit = min(cell.tExit, tb);
  }
  return cell;
}
#endif

// The first hit along o + t d, t >= tStart, through every copy; the copy's frame comes back in \`hit\`.
// A budget that runs out in a cell ends the walk (gMarchExhausted stays set): a farther copy must not
// show through a nearer one the march gave up on.
bool marchCopies(vec3 o, vec3 d, float tStart, out float tHit, out Cell hit) {
  hit = oneObject();
#if defined(REPLICAS_GRID) || defined(REPLICAS_RING)
  tHit = tStart;
  vec2 outer = slab(o.x, d.x, uReplicaBoxMin.x, uReplicaBoxMax.x);
  vec2 y = slab(o.y, d.y, uReplicaBoxMin.y, uReplicaBoxMax.y);
  vec2 z = slab(o.z, d.z, uReplicaBoxMin.z, uReplicaBoxMax.z);
  outer = vec2(max(max(outer.x, y.x), max(z.x, tStart)), min(outer.y, min(y.y, z.y)));
  // A nudge past a cell's boundary, so the next cell is the one looked up: a quarter texel, well
  // above float rounding at the box's distances and inside the padding every copy keeps from its
  // cell's walls (only the lookup moves; the march starts at the boundary itself).
  float nudge = 0.25 * uShapeGrid.z;
  float t = outer.x;
  for (int c = 0; c < uCellBudget && t <= outer.y; ++c) {
    Cell cell = cellAt(o, d, t + nudge);
    float tEnd = min(cell.tExit, outer.y);
    vec3 localOrigin = toCell(cell, o);
    vec3 localDirection = cell.toLocal * d;
    vec2 span = marchInterval(localOrigin, localDirection, t);
    span.y = min(span.y, tEnd);
    if (marchRay(localOrigin, localDirection, span, tHit)) {
      hit = cell;
      return true;
    }
    if (gMarchExhausted) return false;
    t = max(tEnd, t + nudge);
  }
  return false;
#else
  return marchRay(o, d, marchInterval(o, d, tStart), tHit);
#endif
}

#endif
// ---- end of revolution/replicas.glsl

uniform sampler2D uBaseColorTexture;  // sRGB, decoded to linear by the sampler

uniform mat4 uClipToObject;  // inverse of uObjectToClip
uniform mat4 uObjectToClip;
uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform vec2 uViewport;      // pixels
uniform vec4 uBaseColor;     // linear RGBA factor
uniform vec3 uLightDir;      // towards the light, world space
uniform vec3 uLightColour;
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
`;
