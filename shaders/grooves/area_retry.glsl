// Retry passes for area samples that a driver's loop cap cut short (runtime/render/grooves.cpp draws
// them). Mesa's llvmpipe runs the fragment shader for a SIMD group of pixels at once and stops every
// loop once the group has run 65,535 iterations in all. The lanes of a group take different paths
// through the area sampler, so the group pays for close to the sum of their loops, and the heaviest
// special cases overrun it although each lane alone stays well inside. So the first pass marks a
// pixel cut short (retryMask = the draw's number) and counts it under its class, (x mod 4, y mod 4);
// the renderer then draws again once per class that has any, and only that class's marked pixels
// are shaded: one lane in every 4 x 4 block, which pays for its own loops only. Drivers without such
// a cap mark nothing and draw no retry pass.
#ifndef BAKE_GROOVES_AREA_RETRY_GLSL
#define BAKE_GROOVES_AREA_RETRY_GLSL

layout(std430, binding = 11) coherent buffer AreaRetry {
  uint retryCounts[16];  // pixels marked in the frame, per class
  uint retryMask[];      // per pixel of the target, row-major: the draw that marked it, 0 for none
};

uniform int uAreaRetry = 0;    // 0: the first pass; k > 0: the retry pass of class k - 1
uniform int uRetryDraw = 1;    // this draw's number in the frame (from 1)
uniform int uRetryStride = 0;  // the target's width in pixels; 0: no retry buffer bound

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

// In a retry pass: whether this fragment is one of those to shade again.
bool retriedHere() {
  int i = retryIndex();
  return i >= 0 && retryClass() == uAreaRetry - 1 && retryMask[i] == uint(uRetryDraw);
}

// In the first pass, every fragment shaded writes its mark (a later draw over the same pixel replaces
// an earlier draw's): this draw's number when `cut`, else 0.
void markForRetry(bool cut) {
  int i = retryIndex();
  if (i < 0 || gl_HelperInvocation) return;
  retryMask[i] = cut ? uint(uRetryDraw) : 0u;
  if (cut) atomicAdd(retryCounts[retryClass()], 1u);
}

#endif
