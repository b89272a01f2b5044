// Masking and shadowing by ordered projection on the cross-section (seed 000 §5.2), and Eq. 1, as
// libbake/grooves/oracle/line_sampling_occlusion.cpp and line_sampling.cpp shadeSection. A section point C
// seen along D' = (D.B, D_w) lies on the line of coordinate k(C) = C_b D_w - C_h D_b across D' (no
// division, so grazing and downward directions stay finite). For D_b >= 0 occluders come from the
// right: walk leftwards keeping the running minimum of k; a facet is visible where its k falls below
// it. D_b < 0 is the mirror image. The flat base continues to infinity on both sides; below the
// horizon (D_w < 0) it hides everything, which the start value of the running extreme says.
// Eq. 1: pixel = sum_i r_i f_i, r_i the footprint share of the part of facet i both visible and lit,
// measured through its projection on the base line along E.
// Perturbed sections: a point is first moved along the path to where the line along D meets it (the
// line travels h D_t / D_w along T at height h, so the point travels h D_t / (D_w - rateH D_t), capped
// where its track is steeper than the line), across by (rateB + accelB (base + travel / 2)) travel:
// its track's slope taken at `base` (0 for the view; for the light on a bending section, the travel
// where the light ray from the deepest seen point crosses the base plane, so the shadow a rim casts
// there is exact to second order); nothing moves below the horizon. Curved sections (tight arcs): the
// point is then moved along its circle about the section's centre, and a facet's normal turns with it;
// where it shows, the spans' edges get the rates at which they move with the footprint's travel along
// T (the section turning about its centre), as on the CPU.
#ifndef BAKE_GROOVES_OCCLUSION_GLSL
#define BAKE_GROOVES_OCCLUSION_GLSL

#include "material.glsl"
#include "section.glsl"

const float kMinViewW = 1e-12;  // E_w > 0 by the rendering model; guarded anyway

float gVisibleT0[MAX_SECTION_POINTS], gVisibleT1[MAX_SECTION_POINTS];
float gLitT0[MAX_SECTION_POINTS], gLitT1[MAX_SECTION_POINTS];

float acrossCoordinate(int i, float db, float dt, float dw, float base) {
  float b = gSectionB[i], h = gSectionH[i];
  float rateB = gSectionRateB[i], rateH = gSectionRateH[i], accelB = gSectionAccelB[i];
  if (h != 0.0 && dw > 0.0 && (rateB != 0.0 || rateH != 0.0 || accelB != 0.0)) {
    float travel = h * dt / max(dw - rateH * dt, 0.5 * dw);
    b += (rateB + accelB * (base + 0.5 * travel)) * travel;
    h += rateH * travel;
  }
  if (gSectionCurved && h != 0.0) {
    // On a groove curved about the centre, the line along D meets height h where the point's circle
    // (radius centre - b) has turned by asin(s / radius), s = h D_t / D_w: further along B by
    // radius (1 - cos) = radius sin^2 / (1 + cos); capped at a quarter turn.
    float radius = gSectionCentre - b;
    float travel = h * dt, span = dw * radius;
    float sine = travel == 0.0 ? 0.0 : (abs(travel) >= abs(span) ? 1.0 : travel / span);
    b += radius * sine * sine / (1.0 + sqrt(max(0.0, 1.0 - sine * sine)));
  }
  return b * dw - h * db;
}

// The normal where the line along D meets facet i at height h: on a curved section the binormal has
// turned there to cos(a) B + sin(a) T, sin(a) = s / (b - centre), s = h D_t / D_w (b the facet's middle).
vec3 facetNormalSeen(int i, float dt, float dw, float h) {
  if (!gSectionCurved || h == 0.0 || dw <= 0.0) return facetNormal3(i);
  float db = gSectionB[i + 1] - gSectionB[i], dh = gSectionH[i + 1] - gSectionH[i];
  float rateB = 0.5 * (gSectionRateB[i] + gSectionRateB[i + 1]);
  float rateH = 0.5 * (gSectionRateH[i] + gSectionRateH[i + 1]);
  vec3 n = vec3(dh * rateB - db * rateH, -dh, db);  // (T, B, up)
  float len = length(n);
  n = len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0);
  float offset = 0.5 * (gSectionB[i] + gSectionB[i + 1]) - gSectionCentre;
  float travel = h * dt, span = dw * offset;
  float sine = clamp(span == 0.0 ? 0.0 : travel / span, -1.0, 1.0);
  float cosine = sqrt(1.0 - sine * sine);
  vec2 B = gSectionBinormal, T = sectionTangent(B);
  vec2 turnedB = cosine * B + sine * T, turnedT = cosine * T - sine * B;
  return vec3(n.y * turnedB + n.x * turnedT, n.z);
}

// Where visibleSpans writes: the view's spans, the light's, and the same along the turned view and
// light of a turning section.
const int kSpansSeen = 0, kSpansLit = 1, kSpansSeenTurned = 2, kSpansLitTurned = 3;
float gVisibleTurnedT0[MAX_SECTION_POINTS], gVisibleTurnedT1[MAX_SECTION_POINTS];
float gLitTurnedT0[MAX_SECTION_POINTS], gLitTurnedT1[MAX_SECTION_POINTS];

void setSpan(int target, int i, float t0, float t1) {
  if (target == kSpansSeen) { gVisibleT0[i] = t0; gVisibleT1[i] = t1; }
  else if (target == kSpansLit) { gLitT0[i] = t0; gLitT1[i] = t1; }
  else if (target == kSpansSeenTurned) { gVisibleTurnedT0[i] = t0; gVisibleTurnedT1[i] = t1; }
  else { gLitTurnedT0[i] = t0; gLitTurnedT1[i] = t1; }
}

// The visible part [t0, t1] of each facet from (db, dt, dw), into the arrays of `target`.
void visibleSpans(float db, float dt, float dw, float base, int target) {
  int facets = facetCount();
  for (int i = 0; i < facets; ++i) setSpan(target, i, 0.0, 0.0);
  if (db >= 0.0) {
    float lowest = dw < 0.0 ? -kInfinity : kInfinity;
    for (int i = facets - 1; i >= 0; --i) {
      float k0 = acrossCoordinate(i, db, dt, dw, base), k1 = acrossCoordinate(i + 1, db, dt, dw, base);
      if (k1 > k0 && k0 < lowest) setSpan(target, i, 0.0, min(1.0, (lowest - k0) / (k1 - k0)));
      lowest = min(lowest, min(k0, k1));
    }
  } else {
    float highest = dw < 0.0 ? kInfinity : -kInfinity;
    for (int i = 0; i < facets; ++i) {
      float k0 = acrossCoordinate(i, db, dt, dw, base), k1 = acrossCoordinate(i + 1, db, dt, dw, base);
      if (k1 > k0 && k1 > highest) setSpan(target, i, max(0.0, (highest - k0) / (k1 - k0)), 1.0);
      highest = max(highest, max(k0, k1));
    }
  }
}

// line_sampling.cpp turningShows: a curved section's edges move about travel / rho along B per unit
// along T; their rates are found where that reaches kTurnShows of the footprint's half-support over
// its half-extent along T.
const float kTurn = 1e-3;
const float kTurnShows = 0.2;
const float kMinTurnRadius = 1e-6;

const float kMinBendRadius = 0.5;

// An edge at x moved by the footprint's mean square travel along T over 2 rho: the circles about the
// centre bend towards it.
float bentEdge(float x, float varianceT, FootprintLine density) {
  float radius = gSectionCentre - x;
  return abs(radius) > kMinBendRadius * halfSupport(density) ? x + varianceT / (2.0 * radius) : x;
}

bool turningShows(FootprintLine density, vec3 toViewer) {
  if (!gSectionCurved) return false;
  float travel = longestTravel(toViewer, gLightDir);
  float alongT = 0.5 * (abs(density.alongT.x) + abs(density.alongT.y));
  return travel * alongT > kTurnShows * abs(gSectionCentre) * halfSupport(density);
}

#include "mirrors.glsl"

// Eq. 1 over the section plus the mirror bounces of §7. On a turning section each edge of a visible,
// lit span moves along B with the footprint's travel along T (line_sampling.cpp shadeSection): its
// rate is found by turning the view and the light by kTurn, and its share taken across its line.
vec3 shadeSection(FootprintLine density, vec3 toViewer) {
  vec2 B = gSectionBinormal, T = sectionTangent(B);
  float eb = dot(toViewer.xy, B), et = dot(toViewer.xy, T), ew = max(toViewer.z, kMinViewW);
  float lb = dot(gLightDir.xy, B), lt = dot(gLightDir.xy, T), lw = gLightDir.z;
  // line_sampling.cpp lightDirection: on a bending section the light's tracks are followed from the
  // travel where the light ray from the deepest seen point crosses the base plane.
  float lightBase = 0.0;
  if (gSectionBends && lw > 0.0) {
    float deepest = 0.0;
    for (int i = 0; i < gSectionPoints; ++i) deepest = min(deepest, gSectionH[i]);
    lightBase = deepest * (et / ew - lt / lw);
  }
  bool turning = turningShows(density, toViewer);
  // A direction's (B, T) components turned by kTurn about the normal.
  float turnCos = cos(kTurn), turnSin = sin(kTurn);
  mat2 turn = mat2(turnCos, turnSin, -turnSin, turnCos);
  vec2 seenTurned = turn * vec2(eb, et);
  float ebTurned = seenTurned.x, etTurned = seenTurned.y;
  // The view's and the light's spans, then the turned ones: one call of visibleSpans, so that the
  // compiler inlines it once.
  for (int target = kSpansSeen; target <= (turning ? kSpansLitTurned : kSpansLit); ++target) {
    bool light = target == kSpansLit || target == kSpansLitTurned, turned = target >= kSpansSeenTurned;
    vec2 d = light ? vec2(lb, lt) : vec2(eb, et);
    if (turned) d = turn * d;
    visibleSpans(d.x, d.y, light ? lw : ew, light ? lightBase : 0.0, target);
  }
  float varianceT = (density.alongT.x * density.alongT.x + density.alongT.y * density.alongT.y) / 12.0;
  vec3 direct = vec3(0.0);
  int facets = facetCount();
  for (int i = 0; i < facets; ++i) {
    if (!(gVisibleT1[i] > gVisibleT0[i])) continue;
    // Base-line position seen through the facet point at t (projection along E').
    float p0 = acrossCoordinate(i, eb, et, ew, 0.0) / ew, p1 = acrossCoordinate(i + 1, eb, et, ew, 0.0) / ew;
    float t0 = max(gVisibleT0[i], gLitT0[i]), t1 = min(gVisibleT1[i], gLitT1[i]);
    if (!(t1 > t0)) continue;
    // Each end with the density across its own (turned) line, the section's two ends with the plain
    // one, as on the CPU.
    float r0 = i == 0 ? 0.0 : gSectionRateB[i];
    float r1 = i + 1 == facets ? 0.0 : gSectionRateB[i + 1];
    float x0 = p0 + t0 * (p1 - p0), x1 = p0 + t1 * (p1 - p0);
    float turn0 = 0.0, turn1 = 0.0;
    if (turning && gVisibleTurnedT1[i] > gVisibleTurnedT0[i]) {
      float u0 = max(gVisibleTurnedT0[i], gLitTurnedT0[i]), u1 = min(gVisibleTurnedT1[i], gLitTurnedT1[i]);
      if (u1 > u0) {
        float q0 = acrossCoordinate(i, ebTurned, etTurned, ew, 0.0) / ew;
        float q1 = acrossCoordinate(i + 1, ebTurned, etTurned, ew, 0.0) / ew;
        float radius0 = gSectionCentre - x0, radius1 = gSectionCentre - x1;
        float nearest = kMinTurnRadius * halfSupport(density);
        turn0 = abs(radius0) > nearest ? (q0 + u0 * (q1 - q0) - x0) / (kTurn * radius0) : 0.0;
        turn1 = abs(radius1) > nearest ? (q0 + u1 * (q1 - q0) - x1) / (kTurn * radius1) : 0.0;
      }
    }
    if (turning) {  // and bent with the circles about the centre (line_sampling.cpp shadeSection)
      x0 = bentEdge(x0, varianceT, density);
      x1 = bentEdge(x1, varianceT, density);
    }
    float r = abs(footprintCdfAcross(density, x1, r0 + t1 * (r1 - r0) + turn1) -
                  footprintCdfAcross(density, x0, r0 + t0 * (r1 - r0) + turn0));
    float middle = gSectionH[i] + 0.5 * (t0 + t1) * (gSectionH[i + 1] - gSectionH[i]);
    direct += r * directRadiance(gFacetMaterial[i], facetNormalSeen(i, et, ew, middle), toViewer);
  }
#ifdef HAS_MIRRORS
  if (gMaxBounces > 0) direct += mirrorBounces(density, toViewer);
#endif
  return direct;
}

#endif
