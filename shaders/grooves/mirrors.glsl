// Mirror inter-reflections on the cross-section (seed 000 §7), as libbake/grooves/oracle/interreflection.cpp:
// a beam tracing on a fixed stack (no recursion in GLSL). Each visible portion of a mirror facet sends
// a beam along the mirrored view direction R; in the coordinate k across R' = (R.B, R_w) the facets
// past the mirror, walked in the beam's direction of travel, catch the rays whose k lies beyond the
// running extreme of everything walked before. A caught part adds mirror x its direct radiance seen
// from -R (where lit), weighted by its footprint share (the base-line position of a ray is affine in
// k), and while bounces remain becomes a new beam. Rays passing the section's end going up leave the
// surface and see the environment (gEnvironment, the seed's 1 - Σ r_i part; a mirror base reflects
// the rays that reach it beyond the section to the environment too); going down, they reach the flat base beyond it (lit unless the section shadows it). A beam that
// does not fit on the stack, or carries less than 1e-12 of the pixel, is dropped, and at most
// MAX_BEAM_STEPS beams are walked per section, as on the CPU (same sizes).
#ifndef BAKE_GROOVES_MIRRORS_GLSL
#define BAKE_GROOVES_MIRRORS_GLSL

#ifdef HAS_MIRRORS

#define MAX_BEAMS 64
// Bounds of the work per section: beams walked in all, and the share x reflectance below which a
// beam is not followed further (deep mirror cavities stay bounded, as on the CPU).
#define MAX_BEAM_STEPS (4 * MAX_BEAMS)
const float kNegligibleBeam = 1e-12;

struct Beam {
  int facet;
  float t0, t1;   // the part of the facet the rays leave from
  float p0, p1;   // footprint coordinate of the view lines reaching t0, t1
  vec3 toViewer;  // towards what looks at this facet
  vec3 weight;    // product of the mirror reflectances applied so far
  int bounce;
};

Beam gBeams[MAX_BEAMS];
int gBeamCount;

void pushBeam(Beam beam) {
  if (gBeamCount < MAX_BEAMS) gBeams[gBeamCount++] = beam;
}

// The walk of one beam: R', direction of travel, -R, weight, and k -> footprint position.
float wRb, wRt, wRw, wDir;
vec3 wBack, wWeight;
float wKAt0, wKAt1, wP0, wP1;
int wBounce;

float walkKey(int i) { return wDir * acrossCoordinate(i, wRb, wRt, wRw, 0.0); }

float positionOf(float k) {
  float s = clamp((k - wKAt0) / (wKAt1 - wKAt0), 0.0, 1.0);
  return wP0 + s * (wP1 - wP0);
}

// The rays with k in [x, y] reach facet j.
vec3 catchOnFacet(FootprintLine density, Beam beam, int j, float x, float y) {
  float ka = walkKey(j), kb = walkKey(j + 1);
  float sx = clamp((x - ka) / (kb - ka), 0.0, 1.0), sy = clamp((y - ka) / (kb - ka), 0.0, 1.0);
  float s0 = min(sx, sy), s1 = max(sx, sy);
  if (!(s1 > s0)) return vec3(0.0);
  vec3 sum = vec3(0.0);
  int material = gFacetMaterial[j];
  float l0 = max(s0, gLitT0[j]), l1 = min(s1, gLitT1[j]);
  if (l1 > l0) {
    vec3 f = directRadiance(material, facetNormal3(j), wBack);
    sum += wWeight * footprintShare(density, positionOf(ka + l0 * (kb - ka)), positionOf(ka + l1 * (kb - ka))) * f;
  }
  float childShare = footprintShare(density, positionOf(ka + s0 * (kb - ka)), positionOf(ka + s1 * (kb - ka)));
  float strongest = max(wWeight.r, max(wWeight.g, wWeight.b));
  if (hasMirror(material) && beam.bounce + 1 < gMaxBounces && childShare * strongest > kNegligibleBeam) {
    Beam child;
    child.facet = j;
    child.t0 = s0;
    child.t1 = s1;
    child.p0 = positionOf(ka + s0 * (kb - ka));
    child.p1 = positionOf(ka + s1 * (kb - ka));
    child.toViewer = wBack;
    child.weight = wWeight;
    child.bounce = beam.bounce + 1;
    pushBeam(child);
  }
  return sum;
}

// The rays with k in [x, y] pass the section's end going down and reach the flat base beyond it.
vec3 catchOnFarBase(FootprintLine density, float x, float y) {
  // A mirror base reflects these rays up, away from the section: they see the environment.
  vec3 reflected = wBounce + 1 < gMaxBounces
                       ? wWeight * footprintShare(density, positionOf(x), positionOf(y)) * environmentReflection(baseMaterial())
                       : vec3(0.0);
  if (!(gLightDir.z > 0.0)) return reflected;
  float lb = dot(gLightDir.xy, gSectionBinormal), lw = gLightDir.z;
  float lt = dot(gLightDir.xy, sectionTangent(gSectionBinormal));
  float limit = y;
  if (wDir * lb < 0.0) {
    float extreme = wDir > 0.0 ? -kInfinity : kInfinity;
    for (int i = 0; i < gSectionPoints; ++i) {
      float k = acrossCoordinate(i, lb, lt, lw, 0.0);
      extreme = wDir > 0.0 ? max(extreme, k) : min(extreme, k);
    }
    limit = min(y, wDir * (extreme / lw) * wRw);
  }
  if (!(limit > x)) return reflected;
  vec3 f = directRadiance(baseMaterial(), vec3(0.0, 0.0, 1.0), wBack);
  return reflected + wWeight * footprintShare(density, positionOf(x), positionOf(limit)) * f;
}

vec3 traceBeam(FootprintLine density, Beam beam) {
  int f = beam.facet;
  vec3 normal = facetNormal3(f);
  if (!(dot(beam.toViewer, normal) > 0.0)) return vec3(0.0);
  vec3 R = reflectView(beam.toViewer, normal);
  wRb = dot(R.xy, gSectionBinormal);
  wRt = dot(R.xy, sectionTangent(gSectionBinormal));
  wRw = R.z;
  wWeight = beam.weight * materials[gFacetMaterial[f]].mirror.rgb;
  wBounce = beam.bounce;
  if (wRb == 0.0) {  // straight up: every ray leaves the surface
    if (!(wRw > 0.0)) return vec3(0.0);
    return wWeight * footprintShare(density, min(beam.p0, beam.p1), max(beam.p0, beam.p1)) * gEnvironment;
  }
  wDir = wRb > 0.0 ? 1.0 : -1.0;
  wBack = -R;
  float kf0 = walkKey(f), kf1 = walkKey(f + 1);
  wKAt0 = kf0 + beam.t0 * (kf1 - kf0);
  wKAt1 = kf0 + beam.t1 * (kf1 - kf0);
  wP0 = beam.p0;
  wP1 = beam.p1;
  float low = min(wKAt0, wKAt1), high = max(wKAt0, wKAt1);
  if (!(high > low)) return vec3(0.0);

  vec3 sum = vec3(0.0);
  float lowest = wDir > 0.0 ? kf1 : kf0;
  int facets = facetCount();
  for (int walked = 1; walked < facets && lowest > low; ++walked) {
    int j = wDir > 0.0 ? f + walked : f - walked;
    if (j < 0 || j >= facets) break;
    float kNear = walkKey(wDir > 0.0 ? j : j + 1);
    float kFar = walkKey(wDir > 0.0 ? j + 1 : j);
    if (kFar < kNear) {
      float x = max(kFar, low), y = min(lowest, high);
      if (y > x) sum += catchOnFacet(density, beam, j, x, y);
    }
    lowest = min(lowest, kFar);
  }
  if (lowest > low && wRw < 0.0) sum += catchOnFarBase(density, low, min(lowest, high));
  // Rays past the section's end going up leave the surface: they see the environment.
  if (lowest > low && wRw > 0.0) sum += wWeight * footprintShare(density, positionOf(low), positionOf(min(lowest, high))) * gEnvironment;
  return sum;
}

vec3 mirrorBounces(FootprintLine density, vec3 toViewer) {
  vec2 B = gSectionBinormal;
  float eb = dot(toViewer.xy, B), et = dot(toViewer.xy, sectionTangent(B)), ew = max(toViewer.z, 1e-12);
  gBeamCount = 0;
  // The first beams: visible portions of mirror facets, pushed in reverse so facets pop in order.
  for (int i = facetCount() - 1; i >= 0; --i) {
    if (!(gVisibleT1[i] > gVisibleT0[i]) || !hasMirror(gFacetMaterial[i])) continue;
    float q0 = acrossCoordinate(i, eb, et, ew, 0.0) / ew, q1 = acrossCoordinate(i + 1, eb, et, ew, 0.0) / ew;
    Beam beam;
    beam.facet = i;
    beam.t0 = gVisibleT0[i];
    beam.t1 = gVisibleT1[i];
    beam.p0 = q0 + beam.t0 * (q1 - q0);
    beam.p1 = q0 + beam.t1 * (q1 - q0);
    beam.toViewer = toViewer;
    beam.weight = vec3(1.0);
    beam.bounce = 0;
    pushBeam(beam);
  }
  vec3 sum = vec3(0.0);
  for (int walkedBeams = 0; walkedBeams < MAX_BEAM_STEPS && gBeamCount > 0; ++walkedBeams) {
    Beam beam = gBeams[--gBeamCount];
    sum += traceBeam(density, beam);
  }
  return sum;
}

#endif
#endif
