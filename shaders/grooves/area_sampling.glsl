// Area sampling for the special cases of seed 000 §6 (intersections, ends, corners), as
// libbake/grooves/oracle/area_sampling.cpp: the local surface as planar convex pieces (area_surface.glsl); for
// every piece facing the viewer, its projection along the view onto the base plane clipped to the
// footprint, minus the projections of the pieces in front of it (§6.1, §6.3), minus the shadows of the
// pieces nearer the light (§6.3), and Eq. 1 over the visible, lit shares (§6.4). Occlusion between two
// pieces is decided at one point of their overlap (pieces of a height field keep one order along
// every view line and light ray), or without clipping when one lies wholly on one side of the other's
// plane. The visible part of a mirror piece is a beam whose reflection is traced after the eye's
// pieces (§7, area_reflections.glsl), as on the CPU. Pieces cover the working region: the footprint
// swept along the view over the grooves' depth and height, then along the light over their whole
// range.
// Caps are below the CPU's (160 pieces and 160 cells here, 512 there; 16 fragments per piece, 48
// there; 16 vertices per polygon, 24 there): when they are reached the part that overflows is split
// in 2 x 2 halves, at most three times, as on the CPU (whose caps are reached less often; both are
// exact), and past that what does not fit is left out. A footprint of zero area (no screen-space
// derivatives) is line sampled: a rasterised pixel always has one.
#ifndef BAKE_GROOVES_AREA_SAMPLING_GLSL
#define BAKE_GROOVES_AREA_SAMPLING_GLSL

#include "area_surface.glsl"
#include "material.glsl"

#ifndef AREA_MAX_SPLIT_LEVEL
#error "AREA_MAX_SPLIT_LEVEL comes from the renderer (runtime/render/grooves.cpp kAreaMaxSplitLevel)"
#endif
const int kAreaMaxSplitLevel = AREA_MAX_SPLIT_LEVEL;  // up to 8 x 8 parts, as the CPU's three halvings

vec3 gAreaView, gAreaLight;
vec3 gAreaEyeView;  // E; gAreaView is -R while a reflected beam is sampled
// The screen the view lines are projected onto: the base plane for the eye, the plane through the
// origin perpendicular to the view (axes below) for a reflected beam, whose direction may be
// horizontal or point down.
bool gAreaBaseScreen = true;
vec3 gAreaScreenAxis1, gAreaScreenAxis2;
// While a beam is sampled, the pieces are seen only in front of its mirror's plane (xyz . x > w).
bool gAreaCutByPlane = false;
vec4 gAreaCutPlane;
float gAreaMinArea, gAreaDepthTolerance;
bool gAreaLightAllOccluders;  // light near or below the horizon: back faces occlude too
float gAreaHeight, gAreaDepth, gAreaLengthScale;
// A retry pass may trace the eye's beams one per pass (area_retry.glsl): >= 0, only beam number
// gAreaBeamAlone, with the pieces' direct light in the pass of beam 0 only; -1, everything.
int gAreaBeamAlone = -1;

// --- The fragments of one visible piece (polygon.h FragmentSet) ----------------------------------
// When a subtraction needs more room than there is, the fragment is kept whole with its weight lowered
// so that its weighted area drops by the area of the hole inside it (counted in gAreaOverflows).

int gFragmentCount;
int fragmentAt(int i) { return kFragments + i * AREA_POLY; }
float fragmentWeight(int i) { return arenaAt(kFragmentWeights + i); }
vec4 fragmentBox(int i) { return arena4(kFragmentBoxes + 4 * i); }  // inverted when empty
void updateFragmentBox(int i) { setArena4(kFragmentBoxes + 4 * i, polygonBox(fragmentAt(i))); }
void setFragmentWeight(int i, float w) { setArena(kFragmentWeights + i, w); }

vec4 fragmentsBox() {
  vec4 b = vec4(vec2(kInfinity), vec2(-kInfinity));
  for (int i = 0; i < gFragmentCount; ++i) b = boxUnion(b, fragmentBox(i));
  return b;
}

// Removes polygon `hole` (counter-clockwise) from every fragment.
void subtractFromFragments(int hole) {
  if (negligible(hole, 0.0)) return;
  vec4 holeBox = polygonBox(hole);
  int edgeCount = edgeHalfPlanes(hole, kEdgesHole);
  int original = gFragmentCount;
  float minArea = gAreaMinArea;
  for (int i = 0; i < original; ++i) {
    while (i < original && !boxesOverlap(fragmentBox(i), holeBox)) ++i;  // a loop without loops inside
    if (i == original) break;
    int f = fragmentAt(i);
    int n = subtractEdges(f, kEdgesHole, edgeCount, minArea, kSubtracted, kHoleInside, kSpare);
    float removed = polygonArea(kHoleInside);
    if (negligible(kHoleInside, minArea)) continue;
    float whole = polygonArea(f);
    float weight = fragmentWeight(i);
    float remaining = max(0.0, weight * whole - removed);
    if (removed >= whole - minArea || n == 0) {
      setVertexCount(f, 0);  // fully covered; compacted below
      updateFragmentBox(i);
    } else if (gFragmentCount + n - 1 <= AREA_MAX_FRAGMENTS) {
      float newWeight = weight == 1.0 ? 1.0 : min(1.0, remaining / (whole - removed));
      for (int k = 0; k < n; ++k) {
        int slot = k == 0 ? i : gFragmentCount++;
        copyPolygon(fragmentAt(slot), kSubtracted + AREA_POLY * k);
        setFragmentWeight(slot, newWeight);
        updateFragmentBox(slot);
      }
    } else {
      ++gAreaOverflows;
      setFragmentWeight(i, remaining / whole);
    }
  }
  int kept = 0;
  for (int i = 0; i < gFragmentCount; ++i) {
    if (isEmpty(fragmentAt(i))) continue;
    if (kept != i) {
      copyPolygon(fragmentAt(kept), fragmentAt(i));
      setFragmentWeight(kept, fragmentWeight(i));
      setArena4(kFragmentBoxes + 4 * kept, fragmentBox(i));
    }
    ++kept;
  }
  gFragmentCount = kept;
}

float fragmentsWeightedArea() {
  float sum = 0.0;
  for (int i = 0; i < gFragmentCount; ++i) sum += fragmentWeight(i) * polygonArea(fragmentAt(i));
  return sum;
}

// --- Pieces as the sampler sees them --------------------------------------------------------------

vec2 toScreen(vec3 p) {
  return gAreaBaseScreen ? p.xy - (p.z / gAreaView.z) * gAreaView.xy
                         : vec2(dot(p, gAreaScreenAxis1), dot(p, gAreaScreenAxis2));
}

// The screen point x in 3D.
vec3 fromScreen(vec2 x) { return gAreaBaseScreen ? vec3(x, 0.0) : x.x * gAreaScreenAxis1 + x.y * gAreaScreenAxis2; }

// How far x lies in front of the cutting plane, less the depth tolerance.
float aheadOfCut(vec3 x) { return dot(gAreaCutPlane.xyz, x) - gAreaCutPlane.w - gAreaDepthTolerance; }

// The screen image of piece i into `screen`; while a beam is sampled, of its part in front of the
// mirror's plane (Sutherland-Hodgman in 3D; the piece's own vertices stay whole for the shadows).
void projectPieceScreen(int i, int screen) {
  setVertexCount(screen, 0);
  int n = pieceVertexCount(i);
  for (int k = 0; k < n; ++k) {
    vec3 x = pieceVertex(i, k);
    if (!gAreaCutByPlane) {
      addVertex(screen, toScreen(x));
      continue;
    }
    vec3 next = pieceVertex(i, k + 1 == n ? 0 : k + 1);
    float a = aheadOfCut(x), b = aheadOfCut(next);
    if (a > 0.0) addVertex(screen, toScreen(x));
    if ((a > 0.0) != (b > 0.0)) addVertex(screen, toScreen(mix(x, next, a / (a - b))));
  }
  if (isEmpty(screen)) setVertexCount(screen, 0);
}

void projectPieces() {
  vec3 helper = abs(gAreaLight.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
  vec3 axis1 = normalize(cross(helper, gAreaLight)), axis2 = cross(gAreaLight, axis1);
  for (int i = 0; i < gSurfaceCount; ++i) {
    int piece = pieceAt(i);
    vec3 normal = pieceNormal(i);
    setArena(piece + kPieceFacingLight, dot(normal, gAreaLight));
    int screen = pieceScreen(i);
    projectPieceScreen(i, screen);
    // Wholly behind a beam's mirror: neither seen nor hiding anything (it may still shadow).
    setArena(piece + kPieceFacingViewer, isEmpty(screen) ? 0.0 : dot(normal, gAreaView));
    vec4 lightBox = vec4(vec2(kInfinity), vec2(-kInfinity));
    int n = pieceVertexCount(i);
    for (int k = 0; k < n; ++k) {
      vec3 x = pieceVertex(i, k);
      vec2 l = vec2(dot(x, axis1), dot(x, axis2));
      lightBox = vec4(min(lightBox.xy, l), max(lightBox.zw, l));
    }
    makeCounterClockwise(screen);
    setArena4(piece + kPieceScreenBox, polygonBox(screen));
    setArena4(piece + kPieceLightBox, lightBox);
  }
}

// Distance along the view line through screen point x to piece p's plane.
float viewDepth(int p, vec2 x) { return (piecePlaneOffset(p) - dot(pieceNormal(p), fromScreen(x))) / pieceFacingViewer(p); }

vec3 seenPoint(int p, vec2 x) { return fromScreen(x) + viewDepth(p, x) * gAreaView; }

// Signed distance from q along L to piece p's plane (positive: the plane is towards the light).
float lightDistance(int p, vec3 q) { return (piecePlaneOffset(p) - dot(pieceNormal(p), q)) / pieceFacingLight(p); }

bool occludesLight(int p) {
  return gAreaLightAllOccluders ? abs(pieceFacingLight(p)) > 1e-7 : pieceFacingLight(p) > 1e-7;
}

// Where the vertices of `other` lie against me's plane: .x the least, .y the greatest signed distance
// (positive: the side me's normal points to). No vertex in front (.y <= 0): other hides (shadows)
// nothing of me. All of it in front by more than the tolerance: it does wherever they overlap.
vec2 againstPlaneOf(int me, int other) {
  vec3 normal = pieceNormal(me);
  float offset = piecePlaneOffset(me);
  vec2 range = vec2(kInfinity, -kInfinity);
  int n = pieceVertexCount(other);
  for (int k = 0; k < n; ++k) {
    float d = dot(normal, pieceVertex(other, k)) - offset;
    range = vec2(min(range.x, d), max(range.y, d));
  }
  return range;
}

// Piece `caster`'s shadow on piece `receiver`'s plane, seen on the screen, into kShadow.
void shadowOnScreen(int receiver, int caster) {
  setVertexCount(kShadow, 0);
  int n = pieceVertexCount(caster);
  for (int k = 0; k < n; ++k) {
    vec3 q = pieceVertex(caster, k);
    addVertex(kShadow, toScreen(q + lightDistance(receiver, q) * gAreaLight));
  }
  makeCounterClockwise(kShadow);
}

int stepPiece(int step) { return step < gSurfaceCount ? step : step - gSurfaceCount; }

// Whether piece j may hide (first pass) or shadow (second pass) part of piece i, from what is known
// without a loop: which way it faces and whether the boxes overlap.
bool mayOcclude(int i, int j, bool shadows, vec4 bounds, vec4 lightBox) {
  if (j == i) return false;
  if (shadows) return occludesLight(j) && boxesOverlap(pieceLightBox(j), lightBox);
  return pieceFacingViewer(j) > 1e-7 && boxesOverlap(pieceScreenBox(j), bounds);
}

// Whether piece j hides (shadows) part of piece i; the polygon to subtract is then `hole`.
bool occludes(int i, int j, bool shadows, vec4 bounds, int meEdgeCount, out int hole) {
  bool facesLight = pieceFacingLight(i) > 0.0;
  bool sure;  // wholly in front of i's plane: no need to find a point of the overlap
  vec2 range = !shadows || facesLight ? againstPlaneOf(i, j) : vec2(-kInfinity, kInfinity);
  if (range.y <= 0.0) return false;
  if (!shadows) {
    sure = range.x > gAreaDepthTolerance;
    hole = pieceScreen(j);
  } else {
    shadowOnScreen(i, j);
    if (!isEmpty(kShadow) && !boxesOverlap(polygonBox(kShadow), bounds)) return false;
    sure = facesLight && range.x > gAreaDepthTolerance;
    hole = kShadow;
  }
  if (sure) return true;
  intersectEdgesInto(kOverlap, hole, kEdgesMe, meEdgeCount, kSpare);
  if (negligible(kOverlap, gAreaMinArea)) return false;
  vec2 c = polygonCentroid(kOverlap);
  return shadows ? lightDistance(j, seenPoint(i, c)) > gAreaDepthTolerance
                 : viewDepth(j, c) > viewDepth(i, c) + gAreaDepthTolerance;
}

// The visible, lit part of piece i in the footprint, as fragments: minus the pieces in front of it
// (steps 0 to n - 1), then minus the shadows of those nearer the light (steps n to 2n - 1).
// The steps are scanned in two tiers, a loop without loops inside for the box tests, then the full
// test, and only occluders reach the subtraction: SIMD drivers run a masked-off loop body once with
// every loop inside it (Mesa's llvmpipe does, and counts those runs towards its cap), so a body
// holding the clipping code would cost dozens of iterations for every piece it skips.
float gSeenArea;  // the visible part's weighted area before the shadows were subtracted

// Whether a piece of this material sends a beam (§7): it mirrors and bounces are followed, in the
// variant that traces them (AREA_REFLECTIONS, the renderer's option). Without, the cheaper model: a
// mirror piece adds mirror x environment over its visible part instead.
#if defined(HAS_MIRRORS) && defined(AREA_REFLECTIONS)
#define AREA_BEAMS
bool reflectionTraced(int material) { return hasMirror(material) && gMaxBounces > 0; }
vec3 untracedReflection(int material) { return vec3(0.0); }
#else
bool reflectionTraced(int material) { return false; }
vec3 untracedReflection(int material) { return environmentReflection(material); }
#endif

#ifdef AREA_BEAMS
void collectBeamFragments(int i);  // area_reflections.glsl
#endif

// The visible part is complete (no shadow subtracted yet): its area, and a beam's fragments from it.
void visiblePartDone(int i) {
  gSeenArea = fragmentsWeightedArea();
#ifdef AREA_BEAMS
  collectBeamFragments(i);
#endif
}

// `withShadows`: false where the piece has no direct light (only the visible part matters).
void visibleLitPart(int i, bool withShadows) {
  intersectEdgesInto(fragmentAt(0), pieceScreen(i), kEdgesFootprint, edgeHalfPlanes(kFootprint, kEdgesFootprint),
                     kSpare);
  gFragmentCount = negligible(fragmentAt(0), gAreaMinArea) ? 0 : 1;
  setFragmentWeight(0, 1.0);
  updateFragmentBox(0);
  vec4 bounds = fragmentsBox();
  int meEdgeCount = edgeHalfPlanes(pieceScreen(i), kEdgesMe);
  vec4 lightBox = pieceLightBox(i);
  gSeenArea = -1.0;
  int steps = (withShadows ? 2 : 1) * gSurfaceCount;
  int step = 0;
  bool more = true;
  while (more) {
    int hole = -1;
    while (gFragmentCount > 0 && hole < 0 && step < steps) {
      while (step < steps && !mayOcclude(i, stepPiece(step), step >= gSurfaceCount, bounds, lightBox)) ++step;
      if (step < steps) {
        int found;
        if (occludes(i, stepPiece(step), step >= gSurfaceCount, bounds, meEdgeCount, found)) hole = found;
        ++step;
      }
    }
    // Steps from gSurfaceCount on are shadows: the visible part is complete before the first, or at
    // the end (one call, so that it is compiled once).
    if (gSeenArea < 0.0 && (hole < 0 || step > gSurfaceCount)) visiblePartDone(i);
    more = hole >= 0;
    if (more) {
      subtractFromFragments(hole);
      bounds = fragmentsBox();
    }
  }
}

// How far a line along d travels across the base plane per unit of height (bounded like the query
// box: kMaxReach).
vec2 shiftPerHeight(vec3 d) {
  float horizontal = length(d.xy);
  if (horizontal == 0.0) return vec2(0.0);
  float slope = d.z > horizontal / kMaxReach ? horizontal / d.z : kMaxReach;
  return (slope / horizontal) * d.xy;
}

// The box `start` grown by e, swept by h a for h in aSweep, then by k b for k in bSweep: the rectangle
// around it, cut to the slabs along a and along b that hold the swept set (a long sweep askew to the
// axes covers a small part of its rectangle), into kRegion.
void sweptRegion(vec4 start, float e, vec2 a, vec2 aSweep, vec2 b, vec2 bSweep) {
  vec4 box = vec4(vec2(kInfinity), vec2(-kInfinity));
  vec2 acrossA = vec2(-a.y, a.x), acrossB = vec2(-b.y, b.x);
  vec4 slabs = vec4(kInfinity, -kInfinity, kInfinity, -kInfinity);  // least and greatest across a, b
  for (int corner = 0; corner < 16; ++corner) {
    vec2 c = vec2((corner & 1) != 0 ? start.z + e : start.x - e, (corner & 2) != 0 ? start.w + e : start.y - e);
    vec2 x = c + ((corner & 4) != 0 ? aSweep.y : aSweep.x) * a + ((corner & 8) != 0 ? bSweep.y : bSweep.x) * b;
    box = vec4(min(box.xy, x), max(box.zw, x));
    vec2 across = vec2(dot(acrossA, x), dot(acrossB, x));
    slabs = vec4(min(slabs.x, across.x), max(slabs.y, across.x), min(slabs.z, across.y), max(slabs.w, across.y));
  }
  vec4 b4 = box;
  setVertexCount(kRegion, 0);
  addVertex(kRegion, b4.xy);
  addVertex(kRegion, b4.zy);
  addVertex(kRegion, b4.zw);
  addVertex(kRegion, b4.xw);
  if (a != vec2(0.0)) {
    clipInPlace(kRegion, vec3(acrossA, slabs.x), kSpare);
    clipInPlace(kRegion, vec3(-acrossA, -slabs.y), kSpare);
  }
  if (b != vec2(0.0)) {
    clipInPlace(kRegion, vec3(acrossB, slabs.z), kSpare);
    clipInPlace(kRegion, vec3(-acrossB, -slabs.w), kSpare);
  }
}

// The footprint box swept along the view over [-depth, height], then along the light over
// [0, height + depth] (what is seen in the footprint, hides it or shadows it), into kRegion.
void workingRegion(vec4 footprintBox) {
  float e = 1e-5 * gAreaLengthScale;
  sweptRegion(footprintBox, e, shiftPerHeight(gAreaView), vec2(-gAreaDepth - e, gAreaHeight + e),
              shiftPerHeight(gAreaLight), vec2(0.0, gAreaHeight + gAreaDepth + e));
}

// One pass of a footprint's sampling: the eye's (beam -1) over the footprint, or a reflected beam's
// over its windows (area_reflections.glsl).
struct AreaPass {
  int beam;         // -1: the eye; else the slot of the beam followed
  int windows;      // 0: no pass
  vec4 windowsBox;  // on the screen
  vec3 weight;      // the reflectances applied before what this pass sees
  float share;      // of the footprint (the eye's: 1)
  float beamArea;   // the windows' weighted area on the screen
  int bounce;       // reflections made before this pass's (the eye's: 0)
  bool leaves;      // the rays that reach nothing leave the surface (they go up)
  float strongest;  // the strongest channel of weight
};

// The eye's pass: the view E, the base plane as screen, the footprint's working region.
AreaPass eyePass(float footprintArea, vec4 footprintBox) {
  gAreaView = gAreaEyeView;
  gAreaBaseScreen = true;
  gAreaCutByPlane = false;
  gAreaMinArea = 1e-8 * footprintArea;
  workingRegion(footprintBox);
  return AreaPass(-1, 1, footprintBox, vec3(1.0), 1.0, footprintArea, 0, false, 1.0);
}

#ifdef AREA_BEAMS
#include "area_reflections.glsl"
#else
const int kAreaBeamsSize = 0;
#endif

void footprintParallelogram(int p, vec2 centre, vec2 axis1, vec2 axis2) {
  vec2 h1 = 0.5 * axis1, h2 = 0.5 * axis2;
  setVertexCount(p, 0);
  addVertex(p, centre - h1 - h2);
  addVertex(p, centre + h1 - h2);
  addVertex(p, centre + h1 + h2);
  addVertex(p, centre - h1 + h2);
  makeCounterClockwise(p);
}

// The radiance of one (part of a) footprint; false when a cap was reached (then, unless this is the
// last level, the caller splits; on the last level the value leaves out what did not fit).
bool sampleParallelogram(vec2 centre, vec2 axis1, vec2 axis2, bool lastLevel, out vec3 radiance) {
  radiance = vec3(0.0);
  footprintParallelogram(kFootprint, centre, axis1, axis2);
  float footprintArea = polygonArea(kFootprint);
  vec4 footprintBox = polygonBox(kFootprint);
  bool withDirect = gAreaBeamAlone <= 0;
  bool complete = true;
#ifdef AREA_BEAMS
  gAreaBeamCount = 0;
  gCollectBeam = -1;
  gEyeBeamKeys = 0;
#endif
  // One pass for the eye, then (§7) one per beam, through the same stages: a driver compiles each
  // stage once (GLSL inlines every call).
  AreaPass pass = eyePass(footprintArea, footprintBox);
  while (pass.windows > 0) {
    gAreaOverflows = 0;
    gAreaStopAtCap = pass.beam < 0 && !lastLevel;
    gSurfaceCount = 0;
    gWallCount = 0;
    buildHeightPieces(gAreaMinArea);
    buildWalls(gAreaLengthScale);
    bool split = pass.beam < 0 && gAreaOverflows > 0 && !lastLevel;  // the caller splits: no need to sample
    if (!split) projectPieces();
    gAreaCutByPlane = false;
    // The pieces seen in the windows (the footprint; a beam's fragments) and lit, found by a loop
    // without loops inside (see visibleLitPart).
    int count = split ? 0 : gSurfaceCount;
    float caught = 0.0;
    for (int i = 0; i < count; ++i) {
      while (i < count && !(pieceFacingViewer(i) > 1e-7 && boxesOverlap(pieceScreenBox(i), pass.windowsBox) &&
                            (pass.beam >= 0 ||
                             (withDirect && (directRadiance(pieceMaterial(i), pieceNormal(i), gAreaView) != vec3(0.0) ||
                                             untracedReflection(pieceMaterial(i)) != vec3(0.0))) ||
                             reflectionTraced(pieceMaterial(i)))))
        ++i;
      if (i == count) break;
      vec3 direct = withDirect || pass.beam >= 0 ? directRadiance(pieceMaterial(i), pieceNormal(i), gAreaView) : vec3(0.0);
      vec3 untraced = withDirect && pass.beam < 0 ? untracedReflection(pieceMaterial(i)) : vec3(0.0);
#ifdef AREA_BEAMS
      // The visible part of a mirror piece, lit or not, becomes a beam, traced in a pass of its own.
      bool beam = pass.beam < 0 ? reflectionTraced(pieceMaterial(i)) && startEyeBeam(i, footprintArea)
                                : startChildBeam(pass, pieceMaterial(i));
      if (!beam && direct == vec3(0.0) && untraced == vec3(0.0) && pass.beam < 0) continue;  // another pass's beam
#endif
      for (int k = 0; k < pass.windows; ++k) {
        float share = 1.0 / footprintArea;  // of the footprint per unit of (weighted) area
        if (pass.beam < 0) {
          footprintParallelogram(kFootprint, centre, axis1, axis2);
        } else {
#ifdef AREA_BEAMS
          share = windowShare(pass, k);
          if (!(share > 0.0) || !boxesOverlap(pieceScreenBox(i), polygonBox(kFootprint))) continue;
#endif
        }
        visibleLitPart(i, direct != vec3(0.0));
        caught += share * gSeenArea;
        radiance += pass.weight * (share * fragmentsWeightedArea()) * direct + (share * gSeenArea) * untraced;
      }
#ifdef AREA_BEAMS
      if (beam) finishAreaBeam(i, pass.weight, pass.bounce + (pass.beam < 0 ? 0 : 1), pass.beam >= 0);
#endif
    }
    if (pass.beam < 0) {
      complete = gAreaOverflows == 0;
      if (!complete && !lastLevel) break;
    }
#ifdef AREA_BEAMS
    else {
      // Rays no piece catches: going up, they leave the surface and see the environment.
      if (pass.leaves) radiance += pass.weight * max(0.0, pass.share - caught) * gEnvironment;
    }
    pass = nextBeamPass(pass.beam < 0);
#else
    pass.windows = 0;
#endif
  }
  return complete;
}

// The extent of the local geometry: half-width, height above and depth below the base plane.
float areaExtent() {
  gAreaHeight = 0.0;
  gAreaDepth = 0.0;
  float width = 0.0;
  for (int g = 0; g < gStraightCount; ++g) {
    int count = straightProfileCount(g);
    for (int k = 0; k < count; ++k) {
      vec2 p = straightPoint(g, k);
      width = max(width, abs(p.x));
      gAreaHeight = max(gAreaHeight, p.y);
      gAreaDepth = max(gAreaDepth, -p.y);
    }
  }
  return width;
}

// The footprint split only where its pieces overflow, as the CPU's recursion: a depth-first walk of
// the quadtree of parts (cell (x, y) of 2^level x 2^level), children in the order (0,0) (1,0) (0,1)
// (1,1), with no stack: after a part is done, climb out of every level where it was the last child,
// then step to the next sibling. One loop, so llvmpipe's cap counts only the parts sampled, and a
// part that fits is never sampled again. `part` 0 to 4^partLevel - 1 walks only that part's subtree (a
// retry pass, area_retry.glsl; its share of the footprint's value), -1 the whole tree.
void sampleSplitParts(vec2 axis1, vec2 axis2, int part, int partLevel, out vec3 radiance) {
  radiance = vec3(0.0);
  int root = part < 0 ? 0 : clamp(partLevel, 0, kAreaMaxSplitLevel);
  int level = root;
  ivec2 cell = part < 0 ? ivec2(0) : ivec2(part & ((1 << root) - 1), part >> root);
  bool more = true;
  while (more) {
    float parts = float(1 << level);
    vec2 a1 = axis1 / parts, a2 = axis2 / parts;
    vec2 centre = (float(cell.x) + 0.5 - 0.5 * parts) * a1 + (float(cell.y) + 0.5 - 0.5 * parts) * a2;
    bool last = level == kAreaMaxSplitLevel;
    vec3 partRadiance;
    bool complete = sampleParallelogram(centre, a1, a2, last, partRadiance);
    if (!complete && !last) {
      ++level;  // split this part: its first child comes next
      cell *= 2;
    } else {
      radiance += partRadiance / (parts * parts);
      int lastChildLevels = min(findLSB(~(cell.x & cell.y)), level - root);  // trailing levels at child (1,1)
      level -= lastChildLevels;
      cell >>= lastChildLevels;
      more = level > root;
      if (more) cell = (cell.x & 1) == 0 ? ivec2(cell.x + 1, cell.y) : ivec2(cell.x - 1, cell.y + 1);
    }
  }
}

// The footprint F + s1 A1 + s2 A2 (s1, s2 in [-1/2, 1/2]) relative to F, by area (§6), or the share
// of one of its parts (area_retry.glsl; -1: all of it); false when no arena slot was free (the caller line
// samples).
bool areaSample(vec2 axis1, vec2 axis2, vec3 toViewer, int part, int partLevel, out vec3 radiance) {
  radiance = vec3(0.0);
  // A helper invocation has no side effects (its arena writes and atomics are dropped) and its value
  // is never seen: nothing to do. One exit, no break (see shadeFootprint).
  bool helper = gl_HelperInvocation;
  bool slot = !helper && acquireSlot(kAreaSlotSize + kAreaBeamsSize);
  if (slot) {
    straightenFound();
    float width = areaExtent();
    float span = length(axis1) + length(axis2);
    footprintParallelogram(kFootprint, vec2(0.0), axis1, axis2);
    if (polygonArea(kFootprint) < 1e-8 * span * span) {
      // Parallel axes: a thin parallelogram (the shorter axis gets a small perpendicular part).
      bool firstLonger = length(axis1) >= length(axis2);
      vec2 along = normalize(firstLonger ? axis1 : axis2);
      vec2 nudge = 1e-4 * span * vec2(-along.y, along.x);
      if (firstLonger) axis2 += nudge;
      else axis1 += nudge;
    }
    gAreaLengthScale = max(max(span, width), max(gAreaHeight + gAreaDepth, 1e-30));
    gAreaEyeView = toViewer;
    gAreaLight = gLightDir;
    gAreaDepthTolerance = 1e-5 * gAreaLengthScale;
    gAreaLightAllOccluders = gLightDir.z < 0.05;
    sampleSplitParts(axis1, axis2, part, partLevel, radiance);
    releaseSlot();
  }
  return helper || slot;
}

#endif
