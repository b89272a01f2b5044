// Finding the grooves that can affect a footprint (seed 000 §4.1-§4.2), as libbake/grooves/oracle/shade.cpp:
// the bounding box of the footprint parallelogram enlarged by wmax, and by hmax and dmax projected
// along the view and the light (a ridge stands up to hmax |D_uv| / D_w towards D, a cavity point
// reaches dmax |D_uv| / D_w away from it; towards the light, occluders of a cavity point reach
// (hmax + dmax); the reach is capped at kMaxReach heights so a light at the horizon stays finite). The cells under the box give the primitives (CSR cellStart/primitiveRefs,
// kept sorted and unique here) and the special-case records (recordStart/recordRefs). Each primitive
// is then straightened at the footprint centre (shade_local.h localGroove): its tangent line at the
// foot point of F, the perturbation frozen there. Coordinates are relative to F throughout.
#ifndef BAKE_GROOVES_LOOKUP_GLSL
#define BAKE_GROOVES_LOOKUP_GLSL

#include "package.glsl"

#ifndef MAX_FOUND
#define MAX_FOUND 24
#endif

#ifndef MAX_REACH
#define MAX_REACH 100.0
#endif
const float kMaxReach = MAX_REACH;

struct LocalGroove {
  uint primitive;
  int groove;
  int profileFirst, profileCount;
  int material;
  vec2 foot;                      // relative to F (the copy of the primitive nearest F)
  vec2 tangent, binormal;
  float offset, scale;            // perturbation at the foot point (the local cross-section)
  float offsetRate, scaleRate;    // their derivatives along the path there
  float offsetAccel, scaleAccel;  // and their second derivatives (the bend of the points' tracks)
  vec2 startPoint, startNormal;   // joint lines, relative to F
  vec2 endPoint, endNormal;
  float width;                    // scale * profile wmax
  vec2 arcCentre;                 // an arc's centre, relative to F (the same copy as foot)
  float arcRadius;                // 0 for a segment
};

LocalGroove gGrooves[MAX_FOUND];
int gGrooveCount;
bool gFoundOverflow;  // more primitives under the box than MAX_FOUND: shaded from the far level (far_level.glsl)

// |d_uv| / d_w, capped at kMaxReach: how far a line along d travels over the base plane per unit of
// height (line_sampling.glsl curvatureShows uses it too).
float travelPerDepth(vec3 d) {
  float horizontal = length(d.xy);
  return d.z > horizontal / kMaxReach ? horizontal / d.z : kMaxReach;
}

// The longest travel over the base plane of a view or shadow line below the surface (line_sampling.cpp
// longestTravel); uBounds.y, .z: hmax, dmax.
float longestTravel(vec3 toViewer, vec3 toLight) {
  return (uBounds.y + uBounds.z) * max(travelPerDepth(toViewer), travelPerDepth(toLight));
}

// The query box, relative to F.
void queryBoxAlong(inout vec2 lower, inout vec2 upper, vec2 coreLower, vec2 coreUpper, vec3 d, float ridge,
                   float cavity) {
  float horizontal = length(d.xy);
  if (horizontal == 0.0) return;
  float reach = travelPerDepth(d);
  vec2 unit = d.xy / horizontal;
  float alongs[2] = float[2](ridge * reach, -cavity * reach);
  for (int k = 0; k < 2; ++k) {
    lower = min(lower, min(coreLower + alongs[k] * unit, coreUpper + alongs[k] * unit));
    upper = max(upper, max(coreLower + alongs[k] * unit, coreUpper + alongs[k] * unit));
  }
}

// `width`: wmax to find the bands reaching the footprint, 0 for the special-case records (their boxes
// hold their bands already).
void queryBox(vec2 axis1, vec2 axis2, vec3 toViewer, vec3 toLight, float width, out vec2 lower, out vec2 upper) {
  vec2 extent = 0.5 * (abs(axis1) + abs(axis2)) + vec2(width);
  vec2 coreLower = -extent, coreUpper = extent;
  lower = coreLower;
  upper = coreUpper;
  queryBoxAlong(lower, upper, coreLower, coreUpper, toViewer, uBounds.y, uBounds.z);
  // Towards the light, the shadow ray of a cavity point climbs dmax before it clears the base plane:
  // its occluders lie up to (hmax + dmax) |L_uv| / L_w away.
  queryBoxAlong(lower, upper, coreLower, coreUpper, toLight, uBounds.y + uBounds.z, uBounds.z);
}

// The cell range (absolute cell indices) the relative box covers, per axis; false when empty.
bool cellRange(vec2 lower, vec2 upper, out ivec2 first, out ivec2 last) {
  vec2 size = cellSize();
  // Clamped in float first so that huge reaches stay representable as integers.
  vec2 lo = clamp(floor((gFragLocal + lower) / size), vec2(-1.0e6), vec2(1.0e6));
  vec2 hi = clamp(floor((gFragLocal + upper) / size), vec2(-1.0e6), vec2(1.0e6));
  first = gFragCell + ivec2(lo);
  last = gFragCell + ivec2(hi);
  ivec2 counts = cellCounts();
  if (wrapRepeat()) {
    last = min(last, first + counts - 1);  // every stored cell once is enough
    return true;
  }
  first = max(first, ivec2(0));
  last = min(last, counts - 1);
  return all(lessThanEqual(first, last));
}

int storedCell(ivec2 cell) {
  ivec2 counts = cellCounts();
  if (wrapRepeat()) cell = ((cell % counts) + counts) % counts;
  return cell.y * counts.x + cell.x;
}

uint gFound[MAX_FOUND];
int gFoundCount;

// Sorted insertion (append, then sink); when full, the highest index is dropped.
void insertFound(uint primitive) {
  for (int i = 0; i < gFoundCount; ++i)
    if (gFound[i] == primitive) return;
  int at;
  if (gFoundCount == MAX_FOUND) {
    gFoundOverflow = true;
    if (gFound[MAX_FOUND - 1] < primitive) return;
    at = MAX_FOUND - 1;
  } else {
    at = gFoundCount++;
  }
  gFound[at] = primitive;
  while (at > 0 && gFound[at - 1] > primitive) {
    gFound[at] = gFound[at - 1];
    gFound[--at] = primitive;
  }
}

// Once more primitives than MAX_FOUND are found and the package has a far level, the footprint is
// shaded from that level (far_level.glsl), so the gather stops: a far pixel over thousands of grooves
// costs what its first MAX_FOUND + 1 cost (and stays under a driver's cap on loop iterations).
bool gatherDone() { return gFoundOverflow && uFarCells.z > 0; }

void gatherCells(vec2 lower, vec2 upper) {
  ivec2 first, last;
  if (!cellRange(lower, upper, first, last)) return;
  for (int j = first.y; j <= last.y && !gatherDone(); ++j)
    for (int i = first.x; i <= last.x && !gatherDone(); ++i) {
      int cell = storedCell(ivec2(i, j));
      for (uint k = cellStart[cell]; k < cellStart[cell + 1]; ++k) insertFound(primitiveRefs[k]);
    }
}

// Boxes wider than this many cells both ways read only the cells on their boundary (§4.1: paths are
// rarely shorter than a footprint, so interior cells can be omitted): a far pixel over thousands of
// grooves costs its perimeter, not its area. Grooves lying wholly inside it are missed, as on the CPU.
const float kBoundaryOnlyCells = 8.0;

void gatherPrimitives(vec2 lower, vec2 upper) {
  gFoundCount = 0;
  gFoundOverflow = false;
  vec2 cells = (upper - lower) / cellSize();
  if (!(cells.x > kBoundaryOnlyCells && cells.y > kBoundaryOnlyCells)) {
    gatherCells(lower, upper);
    return;
  }
  gatherCells(lower, vec2(upper.x, lower.y));
  gatherCells(vec2(upper.x, lower.y), upper);
  gatherCells(vec2(lower.x, upper.y), upper);
  gatherCells(lower, vec2(lower.x, upper.y));
}

bool boxesMeet(vec2 lowerA, vec2 upperA, vec2 lowerB, vec2 upperB) {
  return all(lessThanEqual(lowerA, upperB)) && all(lessThanEqual(lowerB, upperA));
}

// §4.2: does a special-case record under the box meet it (or one of its copies, when the scene
// repeats)? Then the CPU method samples the footprint by area (§6).
bool meetsRecord(vec2 lower, vec2 upper, uint index) {
  GrooveRecord r = records[index];
  int copies = wrapRepeat() ? 1 : 0;
  for (int ci = -copies; ci <= copies; ++ci)
    for (int cj = -copies; cj <= copies; ++cj) {
      // The box moved by +copy domains is the record moved by -copy domains.
      ivec2 shift = -ivec2(ci, cj) * cellCounts();
      vec2 recordLower = relativeToCentre(r.anchor.xy, shift, r.box.xy);
      vec2 recordUpper = relativeToCentre(r.anchor.xy, shift, r.box.zw);
      if (boxesMeet(lower, upper, recordLower, recordUpper)) return true;
    }
  return false;
}

// Records anywhere under the box count; when the box covers more cells than there are records,
// testing every record is cheaper than reading the cells.
bool specialCaseUnder(vec2 lower, vec2 upper) {
  vec2 cells = (upper - lower) / cellSize();
  if (cells.x * cells.y > float(recordCount())) {
    for (int r = 0; r < recordCount(); ++r)
      if (meetsRecord(lower, upper, uint(r))) return true;
    return false;
  }
  ivec2 first, last;
  if (!cellRange(lower, upper, first, last)) return false;
  for (int j = first.y; j <= last.y; ++j)
    for (int i = first.x; i <= last.x; ++i) {
      int cell = storedCell(ivec2(i, j));
      for (uint k = recordStart[cell]; k < recordStart[cell + 1]; ++k)
        if (meetsRecord(lower, upper, recordRefs[k])) return true;
    }
  return false;
}

// IEEE remainder by 2 pi (std::remainder): the quotient rounded to even.
float remainderTurn(float x) { return x - 2.0 * kPi * roundEven(x / (2.0 * kPi)); }

// Distance from F (the origin) to a primitive moved by `shift` cells (shade.cpp distanceToPrimitive).
float distanceToPrimitive(GroovePrimitive p, ivec2 shift) {
  vec2 a = relativeToCentre(p.header.xy, shift, p.ends.xy);
  vec2 b = relativeToCentre(p.header.xy, shift, p.ends.zw);
  if ((uint(p.header.w) & kPrimitiveArc) == 0u) {
    vec2 d = b - a;
    float length2 = dot(d, d);
    float t = length2 > 0.0 ? clamp(dot(-a, d) / length2, 0.0, 1.0) : 0.0;
    return length(-a - t * d);
  }
  vec2 centre = relativeToCentre(p.header.xy, shift, p.arc.xy);
  float angle = atan(-centre.y, -centre.x);
  float sweep = p.measure.x;
  float fromMiddle = remainderTurn(angle - (p.arc.w + 0.5 * sweep));
  if (abs(fromMiddle) <= 0.5 * abs(sweep)) return abs(length(centre) - p.arc.z);
  return min(length(a), length(b));
}

// The copy of the primitive nearest F when the scene repeats (shade.cpp nearestCopy, which moves F
// instead: the same copy, in the same order of preference).
ivec2 nearestShift(GroovePrimitive p) {
  if (!wrapRepeat()) return ivec2(0);
  ivec2 best = ivec2(0);
  float bestDistance = distanceToPrimitive(p, best);
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j) {
      ivec2 shift = -ivec2(i, j) * cellCounts();
      float d = distanceToPrimitive(p, shift);
      if (d < bestDistance) {
        bestDistance = d;
        best = shift;
      }
    }
  return best;
}

// a sin(2 pi s / wavelength + phase): the perturbation's sine at arc length s.
float perturbationAt(GrooveInfo g, float arcLength) {
  return g.perturbation.x * sin(2.0 * kPi * arcLength / g.perturbation.y + g.perturbation.z);
}

// Its derivative along the path: a k cos(k s + phase), k = 2 pi / wavelength.
float perturbationRateAt(GrooveInfo g, float arcLength) {
  float k = 2.0 * kPi / g.perturbation.y;
  return g.perturbation.x * k * cos(k * arcLength + g.perturbation.z);
}

// Its second derivative: -a k^2 sin(k s + phase).
float perturbationAccelAt(GrooveInfo g, float arcLength) {
  float k = 2.0 * kPi / g.perturbation.y;
  return -g.perturbation.x * k * k * sin(k * arcLength + g.perturbation.z);
}

// shade_local.h localGroove, relative to F.
LocalGroove localGroove(uint index) {
  GroovePrimitive p = primitives[index];
  ivec2 shift = nearestShift(p);
  GrooveInfo g = grooves[p.header.z];
  GrooveProfile profile = profiles[g.indices.x];
  LocalGroove local;
  local.primitive = index;
  local.groove = p.header.z;
  local.profileFirst = int(profile.points.x);
  local.profileCount = int(profile.points.y);
  local.material = int(g.indices.y);
  vec2 a = relativeToCentre(p.header.xy, shift, p.ends.xy);
  float along;
  if ((uint(p.header.w) & kPrimitiveArc) == 0u) {
    vec2 b = relativeToCentre(p.header.xy, shift, p.ends.zw);
    vec2 t = (b - a) / p.measure.z;
    along = dot(-a, t);
    local.foot = a + along * t;
    local.tangent = t;
    local.arcCentre = vec2(0.0);
    local.arcRadius = 0.0;
  } else {
    vec2 centre = relativeToCentre(p.header.xy, shift, p.arc.xy);
    float sweep = p.measure.x;
    float angle = atan(-centre.y, -centre.x);
    float fromStart = remainderTurn(angle - (p.arc.w + 0.5 * sweep)) + 0.5 * sweep;
    along = p.arc.z * (sweep >= 0.0 ? fromStart : -fromStart);
    float theta = p.arc.w + fromStart;
    local.foot = centre + p.arc.z * vec2(cos(theta), sin(theta));
    float turn = sweep >= 0.0 ? 1.0 : -1.0;
    local.tangent = vec2(-sin(theta), cos(theta)) * turn;
    local.arcCentre = centre;
    local.arcRadius = p.arc.z;
  }
  local.binormal = vec2(-local.tangent.y, local.tangent.x);
  float arcLength = p.measure.y + along;
  local.scale = g.kind.y == kPerturbationScale ? 1.0 + perturbationAt(g, arcLength) : 1.0;
  local.offset = g.kind.y == kPerturbationOffset ? perturbationAt(g, arcLength) : 0.0;
  local.scaleRate = g.kind.y == kPerturbationScale ? perturbationRateAt(g, arcLength) : 0.0;
  local.offsetRate = g.kind.y == kPerturbationOffset ? perturbationRateAt(g, arcLength) : 0.0;
  local.scaleAccel = g.kind.y == kPerturbationScale ? perturbationAccelAt(g, arcLength) : 0.0;
  local.offsetAccel = g.kind.y == kPerturbationOffset ? perturbationAccelAt(g, arcLength) : 0.0;
  local.startPoint = relativeToCentre(p.header.xy, shift, p.jointPoints.xy);
  local.endPoint = relativeToCentre(p.header.xy, shift, p.jointPoints.zw);
  local.startNormal = p.jointNormals.xy;
  local.endNormal = p.jointNormals.zw;
  local.width = local.scale * profile.bounds.x;
  return local;
}

// Profile point k of a groove in base-plane terms: b along its binormal (from its centre line), h up.
float profileB(LocalGroove g, int k) { return g.offset + g.scale * profilePoints[g.profileFirst + k].x; }
float profileH(LocalGroove g, int k) { return g.scale * profilePoints[g.profileFirst + k].y; }

#endif
