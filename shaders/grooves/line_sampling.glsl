// The seed's method per footprint (seed 000 §4-§5, §7), as libbake/grooves/oracle/shade.cpp SeedShader::shade
// and line_sampling.cpp: the enlarged box finds the primitives (§4.1); none: the flat base. Otherwise
// each is straightened at F, the ones whose region reaches the footprint are kept (a primitive stops
// at its joint lines; past a joint its neighbour in the chain, when found, takes over), grouped into
// parallel classes (within 1e-6 rad, or drifting apart by less than 1e-3 of a groove width across
// the footprint's reach), and each class is shaded on its combined cross-section (§5), curved about the
// centre of a tight arc (the CPU's curved sections; near the arc's centre the footprint is split, as on
// the CPU). Several classes:
// the flat base plus the sum of each class's difference from it (occlusion between classes neglected,
// as on the CPU).
//
// Special cases (§4.2): where a record's box meets the footprint's box swept along view and light, the
// footprint is sampled by area (§6, area_sampling.glsl, compiled in with HAS_AREA_SAMPLING), as on the
// CPU; gSpecialCase says so (HAS_SPECIAL_CASES alone looks the records up but line samples).
#ifndef BAKE_GROOVES_LINE_SAMPLING_GLSL
#define BAKE_GROOVES_LINE_SAMPLING_GLSL

#include "far_level.glsl"
#include "occlusion.glsl"

#ifndef MAX_CLASSES
#define MAX_CLASSES 4
#endif

const float kParallelSine = 1e-6;  // sin(1e-6 rad)
const float kDriftFraction = 1e-3;

bool gSpecialCase;
int gClassOf[MAX_FOUND];  // -1: not kept
// The footprint is shaded from the far level (far_level.glsl): lineSample runs the package's classes
// instead of the grooves found.
bool gFarMode = false;
bool gClassesDropped = false;  // more directions under the footprint than MAX_CLASSES: some dropped

// foot - F, reduced to the nearest copy when the scene repeats.
vec2 offsetFromCentre(vec2 foot) {
  if (!wrapRepeat()) return foot;
  return foot - domainSize() * round(foot / domainSize());
}

bool foundPrimitive(int primitive) {
  for (int i = 0; i < gGrooveCount; ++i)
    if (int(gGrooves[i].primitive) == primitive) return true;
  return false;
}

// The primitive across a joint of `g` (start or end), or -1 at an open end.
int neighbourAcross(LocalGroove g, bool atStart) {
  GrooveInfo info = grooves[g.groove];
  int first = int(info.indices.z), last = first + int(info.indices.w) - 1;
  bool closed = (info.kind.x & kGrooveClosed) != 0u;
  int p = int(g.primitive);
  if (atStart) return p > first ? p - 1 : (closed ? last : -1);
  return p < last ? p + 1 : (closed ? first : -1);
}

bool reachesFootprint(LocalGroove g, vec2 axis1, vec2 axis2) {
  vec2 centre = g.foot - offsetFromCentre(g.foot);  // F's copy near the primitive
  for (int end = 0; end < 2; ++end) {
    vec2 point = end == 0 ? g.startPoint : g.endPoint;
    vec2 normal = end == 0 ? g.startNormal : g.endNormal;
    if (dot(centre - point, normal) >= 0.0) continue;
    int other = neighbourAcross(g, end == 0);
    if (other >= 0 && foundPrimitive(other)) return false;  // the neighbour covers it
    bool anyInside = false;
    for (int corner = 0; corner < 4; ++corner) {
      float s1 = (corner & 1) != 0 ? 0.5 : -0.5, s2 = (corner & 2) != 0 ? 0.5 : -0.5;
      vec2 x = centre + s1 * axis1 + s2 * axis2;
      anyInside = anyInside || dot(x - point, normal) >= 0.0;
    }
    if (!anyInside) return false;
  }
  return true;
}

bool parallelGrooves(LocalGroove a, LocalGroove b, float reach) {
  float sine = abs(a.tangent.x * b.tangent.y - a.tangent.y * b.tangent.x);
  float drift = kDriftFraction * min(a.width, b.width) / reach;
  return sine <= max(kParallelSine, drift);
}

// Curved sections (line_sampling.cpp curvatureShows): where over the longest travel S of a view or
// shadow line, (hmax + dmax) |D_uv| / D_w, the groove's tightest circle (radius R - w) leaves its
// tangent by more than kCurvedShift of the footprint's width: S^2 / (2 (R - w)).
const float kCurvedShift = 0.02;
const int kCurvedPieces = 4;

bool curvatureShows(LocalGroove g, FootprintLine line, vec3 toViewer) {
  float inner = g.arcRadius - g.width;
  if (!(inner > 0.0)) return true;
  float travel = longestTravel(toViewer, gLightDir);
  return travel * travel / (2.0 * inner) > kCurvedShift * 2.0 * halfSupport(line);
}

vec3 shadeClass(int cls, int front, vec2 axis1, vec2 axis2, vec3 toViewer) {
  vec2 binormal = gGrooves[front].binormal;
  FootprintLine line = footprintLine(axis1, axis2, binormal);
  startSection(binormal, -halfSupport(line), halfSupport(line));
  for (int m = 0; m < gGrooveCount; ++m) {
    if (gClassOf[m] != cls) continue;
    LocalGroove g = gGrooves[m];
    vec2 d = offsetFromCentre(g.foot);
    float along = dot(binormal, g.binormal);
    // Where the groove's centre line crosses the line F + x B (along = +-1 up to the drift).
    placeGroove(m, dot(d, g.binormal) / along, along < 0.0);
  }
  buildSection();
  setSectionRates();
  LocalGroove first = gGrooves[front];
  if (first.arcRadius > 0.0 && curvatureShows(first, line, toViewer)) {
    // The arc's centre lies on the radial line through the foot, which is F + x B.
    gSectionCentre = dot(first.arcCentre - first.foot + offsetFromCentre(first.foot), binormal);
    gSectionCurved = subdivideFacets(kCurvedPieces);
  }
  return shadeSection(line, toViewer);
}

vec3 lineSample(vec2 axis1, vec2 axis2, vec3 toViewer, vec3 flatBase) {
  float reach = 0.5 * (length(axis1) + length(axis2)) + uBounds.x + uBounds.y + uBounds.z;
  int fronts[MAX_CLASSES];
  int classes = 0;
  if (gFarMode) {
    classes = farClassCount();
  } else {
    for (int i = 0; i < gGrooveCount; ++i) {
      gClassOf[i] = -1;
      if (!reachesFootprint(gGrooves[i], axis1, axis2)) continue;
      int cls = 0;
      while (cls < classes && !parallelGrooves(gGrooves[fronts[cls]], gGrooves[i], reach)) ++cls;
      if (cls == classes) {
        if (classes == MAX_CLASSES) {  // more directions than the shader keeps: dropped, and counted
          gClassesDropped = true;
          continue;
        }
        fronts[classes++] = i;
      }
      gClassOf[i] = cls;
    }
  }
  if (classes == 0) return flatBase;
  // One call of shadeClass, so that the compiler inlines it once; the far level's classes go through
  // it too, each as its groove alone across its band, weighted by its share of the footprint.
  vec3 sum = flatBase, value = flatBase;
  for (int c = 0; c < classes; ++c) {
    int cls = c, front = 0;
    vec2 a1 = axis1, a2 = axis2;
    float weight = 1.0;
    if (gFarMode) {
      weight = farCover(c);
      if (!(weight > 0.0)) continue;
      prepareFarGroove(c, a1, a2);
      gClassOf[0] = 0;
      cls = 0;
    } else {
      front = fronts[c];
    }
    value = shadeClass(cls, front, a1, a2, toViewer);
    sum += weight * (value - flatBase);
  }
  return classes == 1 && !gFarMode ? value : max(sum, vec3(0.0));
}

// shade.cpp nearArcCentre: a footprint whose centre lies within kNearCentre half-extents of an arc's
// centre spans too wide a fan of the arc's directions for one section; it is shaded as kCentreSplit x
// kCentreSplit sub-footprints, each with its own foot points.
const int kCentreSplit = 3;
const float kNearCentre = 1.5;

bool nearArcCentre(vec2 axis1, vec2 axis2) {
  float extent = 0.5 * (length(axis1) + length(axis2));
  for (int i = 0; i < gGrooveCount; ++i) {
    bool arc = gGrooves[i].arcRadius > 0.0;
    if (arc && length(offsetFromCentre(gGrooves[i].arcCentre)) < kNearCentre * extent) return true;
  }
  return false;
}

// The grooves found, straightened at the footprint centred at `centre`.
void straightenFound(vec2 centre) {
  setFootprintCentre(centre);
  for (int i = 0; i < gGrooveCount; ++i) gGrooves[i] = localGroove(gFound[i]);
}

// The footprint line sampled whole, or split in kCentreSplit x kCentreSplit parts near an arc's centre
// (one call of lineSample, so that the compiler inlines it once).
vec3 lineSampleParts(vec2 centre, vec2 axis1, vec2 axis2, vec3 toViewer, vec3 flatBase, bool split) {
  int n = split ? kCentreSplit : 1;
  vec2 a1 = axis1 / float(n), a2 = axis2 / float(n);
  vec3 sum = vec3(0.0);
  for (int k = 0; k < n * n; ++k) {
    int i = k / n, j = k - i * n;
    vec2 part = vec2(float(i), float(j)) + 0.5 - 0.5 * float(n);
    if (split) straightenFound(centre + part.x * a1 + part.y * a2);
    sum += lineSample(a1, a2, toViewer, flatBase) / float(n * n);
  }
  if (split) straightenFound(centre);  // back to the whole footprint, for the special cases
  return sum;
}

#ifdef HAS_AREA_SAMPLING
#include "area_sampling.glsl"
#include "area_retry.glsl"

bool gAreaCut = false;
bool gAreaDeferred = false;  // cut short: shaded again in a retry pass (area_retry.glsl)
#endif

// The per-frame counts are the first pass's: a retry pass shades again fragments counted there.
void countFirstPassFragment(int which) {
#ifdef HAS_AREA_SAMPLING
  if (isRetryPass()) return;
#endif
  countFragment(which);
}

#ifdef HAS_AREA_SAMPLING

// True when loops no longer run (a driver's cap on the loop iterations of an invocation was reached):
// a loop of two iterations, its bound unknown to the compiler, runs fewer.
bool loopsCutShort() {
  int ran = 0;
  for (int k = 0; k < 2 + int(uBounds.w); ++k) ++ran;
  return ran < 2;
}
#endif

// The pixel value of the footprint centred at `centre` (domain units) with edges axis1, axis2, seen
// from toViewer (groove space). gLightDir, gLightRadiance and gMaxBounces are set by the caller.
vec3 shadeFootprint(vec2 centre, vec2 axis1, vec2 axis2, vec3 toViewer) {
  setFootprintCentre(centre);
  gSpecialCase = false;
  vec3 flatBase = flatBaseRadiance(toViewer);
  vec2 lower, upper;
  queryBox(axis1, axis2, toViewer, gLightDir, uBounds.x, lower, upper);
  gatherPrimitives(lower, upper);
  if (gFoundCount == 0) return flatBase;
  // More primitives under the box than the shader holds, or a footprint wider than the period of a
  // repeating pattern (each groove straightened at its copy nearest F would count once): the far
  // level, when the package has one, as libbake's SeedShader does; else the rest is dropped, counted.
  bool beyondPeriod = wrapRepeat() && any(greaterThan(abs(axis1) + abs(axis2), domainSize()));
  gFarMode = (gFoundOverflow || beyondPeriod) && hasFarLevel();
  if (gFoundOverflow || beyondPeriod) countFirstPassFragment(gFarMode ? kCountFar : kCountTruncated);
  if (gFarMode) {
    setFarBox(centre, axis1, axis2);  // no special case is looked for: the far level averages them away
  } else {
    gGrooveCount = gFoundCount;
    straightenFound(centre);
  }
  // Line sampled before the area branch, not after: Mesa's llvmpipe stops every loop of a SIMD group
  // once the group has run 65,535 loop iterations in all (drivers of real GPUs have no such cap), and
  // area sampling can use them up; a loop run after it would then do nothing for the whole group.
  vec3 radiance = vec3(0.0);
  bool sampled = false;
#ifdef HAS_SPECIAL_CASES
  if (!gFarMode) {
    vec2 recordLower, recordUpper;
    queryBox(axis1, axis2, toViewer, gLightDir, 0.0, recordLower, recordUpper);
    gSpecialCase = specialCaseUnder(recordLower, recordUpper);
  }
#endif
  // A special case's line sample only stands in for a failed area sample: it is not split (the
  // split's loops would leave the area sample fewer iterations under such a cap).
  bool split = !gFarMode && !gSpecialCase && nearArcCentre(axis1, axis2);
  gClassesDropped = false;
#ifdef HAS_AREA_SAMPLING
  // A retry by parts adds an area share and writes no pixel: no line sample (its loops would count
  // against the driver's cap too).
  vec3 lineSampled = isQuarterPass() ? flatBase : lineSampleParts(centre, axis1, axis2, toViewer, flatBase, split);
#else
  vec3 lineSampled = lineSampleParts(centre, axis1, axis2, toViewer, flatBase, split);
#endif
  if (gClassesDropped) countFirstPassFragment(kCountClassesDropped);
#ifdef HAS_AREA_SAMPLING
  gAreaNoSlot = false;
  gAreaCut = false;
  // A footprint without area (no screen-space derivatives) is line sampled: a rasterised pixel has one.
  if (gSpecialCase && length(axis1) + length(axis2) > 0.0) {
    if (isSumPass()) {
      // The parts drawn before, summed; if this loop too was cut short, the sum is not whole.
      vec4 sum = sumOfParts();
      radiance = sum.rgb;
      gAreaCut = sum.w > 0.0 || loopsCutShort();
      sampled = !gAreaCut;
      atomicAdd(areaCounts[gAreaCut ? 2 : 0], 1u);  // the pixel's outcome, counted once
    } else {
      int part = isQuarterPass() ? uAreaPart : -1;
      gAreaBeamAlone = isBeamByBeam() ? uAreaBeam : -1;
      sampled = areaSample(axis1, axis2, toViewer, part, uAreaPartLevel, radiance);
      gAreaNoSlot = !sampled;  // every arena slot tried was taken: line sampled instead
      // Cut short by such a cap, the area sample misses the pieces it had not reached: the line
      // sample stands in, and gAreaCut says so.
      gAreaCut = sampled && (loopsCutShort() || retryForced());
      if (part >= 0) {
        // A share of one node of the footprint's quadtree (a part without a slot counts as cut
        // short); the renderer counts the pixels it shades again by smaller parts, the sum pass the
        // outcome.
        addPart(radiance, !sampled || gAreaCut);
      } else {
        sampled = sampled && !gAreaCut;
        // Shaded again: alone, then by parts.
        gAreaDeferred = gAreaCut && listForRetry();
        // No effect in helper invocations. A deferred fragment is counted again by its retry.
        atomicAdd(areaCounts[gAreaNoSlot ? 1 : (gAreaDeferred ? 3 : (gAreaCut ? 2 : 0))], 1u);
      }
    }
  }
#endif
  return sampled ? radiance : lineSampled;
}

#endif
