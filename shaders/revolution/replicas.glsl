// Revolution mapping: copies of the object in one shape box (seed 001 Eq. 9, and the mirror-and-
// repetition variant of Fig. 13; formats/revolution.md, "Replicas"). The box is cut into cells, one
// copy each: a grid of cells spaced `uGridSpacing` apart (odd cells of a mirrored axis reflected about
// their box's centre), or a ring of wedges of angle 2 pi / n about +y. The paper takes the fractional
// part of the hit point's coordinates; here each cell maps the ray into its copy's own frame (a
// translation, reflection or rotation: an isometry, so ray parameters and distances are kept) and
// runs the one-object march there, over the part of the ray inside the cell. A copy lies inside its
// cell, so no other copy can be hit on that part: walking the cells in order along the ray, the first
// hit is the nearest. The same walk marches the self-shadow ray toward the light.
// Variant: REPLICAS_GRID / REPLICAS_RING (neither: one object, the march unchanged).
#ifndef BAKE_REVOLUTION_REPLICAS_GLSL
#define BAKE_REVOLUTION_REPLICAS_GLSL

#include "shape_march.glsl"

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

// The first hit along o + t d, t >= tStart, through every copy; the copy's frame comes back in `hit`.
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
