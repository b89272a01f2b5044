// Retry passes for area samples that a driver's loop cap cut short (runtime/render/grooves.cpp draws
// them). Mesa's llvmpipe runs the fragment shader for a SIMD group of pixels at once and stops every
// loop once the group has run 65,535 iterations in all. The lanes of a group take different paths
// through the area sampler, so the group pays for close to the sum of their loops (and for one
// iteration of every loop in a branch that no lane takes), and the heaviest special cases overrun
// it. So the first pass marks a pixel cut short (retryMask = the draw's number) and counts it under
// its class, (x mod 4, y mod 4); the renderer then draws again once per class that has any, and only
// that class's marked pixels are shaded: one lane in every 4 x 4 block, which pays for its own loops
// only. A pixel cut short even alone is marked again and shaded by quarters of its footprint, one
// pass each, the four shares summed in retrySums (area is additive: the CPU's split adds the same
// shares). Drivers without such a cap mark nothing and draw no retry pass.
#ifndef BAKE_GROOVES_AREA_RETRY_GLSL
#define BAKE_GROOVES_AREA_RETRY_GLSL

layout(std430, binding = 11) coherent buffer AreaRetry {
  uint retryCounts[32];  // pixels marked in the frame per class: [0, 16) whole, [16, 32) by quarters
  uint retryMask[];      // per pixel of the target, row-major: the draw that marked it, 0 for none
};
// Per pixel shaded by quarters: the sum of the shares so far, and (w) whether one was cut short.
layout(std430, binding = 12) coherent buffer AreaRetrySums { vec4 retrySums[]; };

uniform int uAreaRetry = 0;     // 0: the first pass; k > 0: a retry pass of class k - 1
uniform int uAreaQuarter = -1;  // in a retry pass: -1 the whole footprint, 0 to 3 that quarter
uniform int uRetryDraw = 1;     // this draw's number in the frame (from 1)
uniform int uRetryStride = 0;   // the target's width in pixels; 0: no retry buffer bound
// Tests: 1 takes every area sample of the first pass as cut short, 2 also those of the retry passes
// of whole footprints, so that either kind of retry runs on any driver.
uniform int uForceRetries = 0;

bool retryForced() { return uAreaQuarter < 0 && uForceRetries > min(uAreaRetry, 1); }

const uint kByQuarters = 0x40000000u;  // added to a mark: shade again by quarters

int retryClass() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  return (p.x & 3) + 4 * (p.y & 3);
}

int retryIndex() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  int i = p.y * uRetryStride + p.x;
  return uRetryStride > 0 && p.x < uRetryStride && i < retryMask.length() ? i : -1;
}

bool isRetryPass() { return uAreaRetry > 0; }
bool isQuarterPass() { return uAreaRetry > 0 && uAreaQuarter >= 0; }

// In a retry pass: whether this fragment is one of those to shade again.
bool retriedHere() {
  int i = retryIndex();
  uint mark = uint(uRetryDraw) | (isQuarterPass() ? kByQuarters : 0u);
  return i >= 0 && retryClass() == uAreaRetry - 1 && retryMask[i] == mark;
}

// In the first pass every fragment shaded writes its mark (a later draw over the same pixel replaces
// an earlier draw's): this draw's number when `cut`, else 0. In a whole-footprint retry pass a
// fragment cut short again is marked to be shaded by quarters.
void markForRetry(bool cut) {
  int i = retryIndex();
  if (i < 0 || gl_HelperInvocation || isQuarterPass()) return;
  if (!isRetryPass()) retryMask[i] = cut ? uint(uRetryDraw) : 0u;
  else if (cut) retryMask[i] = uint(uRetryDraw) | kByQuarters;
  if (cut) atomicAdd(retryCounts[retryClass() + (isRetryPass() ? 16 : 0)], 1u);
}

// In a quarter pass: adds this quarter's share (`failed`: it was not sampled to the end) to the
// pixel's sum, which comes back in `sum`; true for the last quarter.
bool addQuarter(vec3 share, bool failed, out vec4 sum) {
  int i = retryIndex();
  sum = (uAreaQuarter == 0 ? vec4(0.0) : retrySums[i]) + vec4(share, failed ? 1.0 : 0.0);
  if (!gl_HelperInvocation) retrySums[i] = sum;
  return uAreaQuarter == 3;
}

#endif
