// Masking and shadowing by ordered projection on the cross-section (seed 000 §5.2), and Eq. 1, as
// libbake/groove/line_sampling_occlusion.cpp and line_sampling.cpp shadeSection. A section point C
// seen along D' = (D.B, D_w) lies on the line of coordinate k(C) = C_b D_w - C_h D_b across D' (no
// division, so grazing and downward directions stay finite). For D_b >= 0 occluders come from the
// right: walk leftwards keeping the running minimum of k; a facet is visible where its k falls below
// it. D_b < 0 is the mirror image. The flat base continues to infinity on both sides; below the
// horizon (D_w < 0) it hides everything, which the start value of the running extreme says.
// Eq. 1: pixel = sum_i r_i f_i, r_i the footprint share of the part of facet i both visible and lit,
// measured through its projection on the base line along E.
#ifndef BAKE_GROOVES_OCCLUSION_GLSL
#define BAKE_GROOVES_OCCLUSION_GLSL

#include "material.glsl"
#include "section.glsl"

const float kMinViewW = 1e-12;  // E_w > 0 by the rendering model; guarded anyway

float gVisibleT0[MAX_SECTION_POINTS], gVisibleT1[MAX_SECTION_POINTS];
float gLitT0[MAX_SECTION_POINTS], gLitT1[MAX_SECTION_POINTS];

float acrossCoordinate(int i, float db, float dw) { return gSectionB[i] * dw - gSectionH[i] * db; }

// The visible part [t0, t1] of each facet from (db, dw); `lit` selects the light's arrays.
void visibleSpans(float db, float dw, bool lit) {
  int facets = facetCount();
  for (int i = 0; i < facets; ++i) {
    if (lit) { gLitT0[i] = 0.0; gLitT1[i] = 0.0; } else { gVisibleT0[i] = 0.0; gVisibleT1[i] = 0.0; }
  }
  if (db >= 0.0) {
    float lowest = dw < 0.0 ? -kInfinity : kInfinity;
    for (int i = facets - 1; i >= 0; --i) {
      float k0 = acrossCoordinate(i, db, dw), k1 = acrossCoordinate(i + 1, db, dw);
      if (k1 > k0 && k0 < lowest) {
        float t1 = min(1.0, (lowest - k0) / (k1 - k0));
        if (lit) gLitT1[i] = t1; else gVisibleT1[i] = t1;
      }
      lowest = min(lowest, min(k0, k1));
    }
  } else {
    float highest = dw < 0.0 ? kInfinity : -kInfinity;
    for (int i = 0; i < facets; ++i) {
      float k0 = acrossCoordinate(i, db, dw), k1 = acrossCoordinate(i + 1, db, dw);
      if (k1 > k0 && k1 > highest) {
        float t0 = max(0.0, (highest - k0) / (k1 - k0));
        if (lit) { gLitT0[i] = t0; gLitT1[i] = 1.0; } else { gVisibleT0[i] = t0; gVisibleT1[i] = 1.0; }
      }
      highest = max(highest, max(k0, k1));
    }
  }
}

#include "mirrors.glsl"

// Eq. 1 over the section plus the mirror bounces of §7.
vec3 shadeSection(FootprintLine density, vec3 toViewer) {
  vec2 B = gSectionBinormal;
  float eb = dot(toViewer.xy, B), ew = max(toViewer.z, kMinViewW);
  float lb = dot(gLightDir.xy, B), lw = gLightDir.z;
  visibleSpans(eb, ew, false);
  visibleSpans(lb, lw, true);
  vec3 direct = vec3(0.0);
  int facets = facetCount();
  for (int i = 0; i < facets; ++i) {
    if (!(gVisibleT1[i] > gVisibleT0[i])) continue;
    // Base-line position seen through the facet point at t (projection along E').
    float p0 = acrossCoordinate(i, eb, ew) / ew, p1 = acrossCoordinate(i + 1, eb, ew) / ew;
    float t0 = max(gVisibleT0[i], gLitT0[i]), t1 = min(gVisibleT1[i], gLitT1[i]);
    if (!(t1 > t0)) continue;
    float r = footprintShare(density, p0 + t0 * (p1 - p0), p0 + t1 * (p1 - p0));
    direct += r * directRadiance(gFacetMaterial[i], facetNormal3(i), toViewer);
  }
#ifdef HAS_MIRRORS
  if (gMaxBounces > 0) direct += mirrorBounces(density, toViewer);
#endif
  return direct;
}

#endif
