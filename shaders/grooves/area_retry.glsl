// Retry passes for area samples that a driver's loop cap cut short (runtime/render/grooves.cpp draws
// them). Mesa's llvmpipe runs the fragment shader for a SIMD group of pixels at once and stops every
// loop once the group has run 65,535 iterations in all. The lanes of a group take different paths
// through the area sampler, so the group pays for close to the sum of their loops (and for one
// iteration of every loop in a branch that no lane takes), and the heaviest special cases overrun
// it. So the first pass lists a pixel cut short, and the renderer draws again once per listed pixel,
// scissored to it: its group then has one lane, which pays for its own loops only. A pixel cut short
// even alone is listed again and shaded beam by beam, one draw per beam of the eye's mirror pieces
// (§7 inter-reflections cost most: a pass traces one beam, the pass of beam 0 adds the pieces' direct
// light), over the whole footprint, then, where a draw was still cut short, by quarters of it,
// sixteenths, sixty-fourths (the CPU's deepest split), the shares summed in retrySums (area and
// beams are additive: the CPU adds the same shares). In the variant without traced beams
// (AREA_REFLECTIONS off) a retry by parts takes whole parts (uAreaBeam -1), from quarters on. retryMask says which draw of the frame
// owns each pixel (the last to shade it), so that only that one shades it again.
// Drivers without such a cap list nothing and draw no retry pass.
#ifndef BAKE_GROOVES_AREA_RETRY_GLSL
#define BAKE_GROOVES_AREA_RETRY_GLSL

#ifndef AREA_RETRY_LIST
#error "AREA_RETRY_LIST comes from the renderer (runtime/render/grooves.cpp kRetryList)"
#endif

layout(std430, binding = 13) coherent buffer AreaRetry {
  vec4 retrySums[AREA_RETRY_LIST];  // per pixel of the second list: the quarters' sum, w: one was cut
  uint retryListCount[2];           // pixels listed: [0] to shade again whole, [1] by quarters
  uint retryList[2 * AREA_RETRY_LIST];  // (y << 16) | x; list k from k * AREA_RETRY_LIST
  uint retryMask[];  // per pixel of the target, row-major: the draw that owns it when listed, else 0
};

uniform int uAreaRetry = 0;     // 0: the first pass; 1: a retry of whole footprints; 2: by parts
uniform int uAreaPartLevel = 0;  // in a retry by parts: 2^level x 2^level parts (0 to 3)
uniform int uAreaPart = 0;      // in a retry by parts: which part, 0 to 4^level - 1, row-major
uniform int uAreaBeam = -1;     // in a retry by parts: the one eye beam to trace (0 to AREA_EYE_BEAMS - 1), or -1
uniform int uRetrySlot = 0;     // in a retry by parts: the pixel's place in the second list
uniform int uRetryDraw = 1;    // this draw's number in the frame (from 1)
uniform int uRetryStride = 0;  // the target's width in pixels; 0: no retry buffer bound
// Tests: 1 takes every area sample of the first pass as cut short, 2 also those of the retries of
// whole footprints, 3 also those of the beam-by-beam retries of whole footprints, so that every kind
// of retry runs on any driver.
uniform int uForceRetries = 0;

const uint kByQuarters = 0x40000000u;  // added to a mark: shade again by parts

int retryIndex() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  int i = p.y * uRetryStride + p.x;
  return uRetryStride > 0 && p.x < uRetryStride && i < retryMask.length() ? i : -1;
}

bool isRetryPass() { return uAreaRetry > 0; }
bool isQuarterPass() { return uAreaRetry == 2; }
int areaPartCount() { return 1 << (2 * uAreaPartLevel); }
bool isBeamByBeam() { return isQuarterPass() && uAreaBeam >= 0; }
// The last share of the pixel: its last part and, beam by beam, its last beam.
bool isLastPart() { return uAreaPart == areaPartCount() - 1 && (!isBeamByBeam() || uAreaBeam == AREA_EYE_BEAMS - 1); }
// Whether a pixel cut short in this pass is shaded again (by smaller parts).
bool retriedAfterParts() { return uAreaPartLevel < AREA_MAX_SPLIT_LEVEL; }
bool retryForced() { return uForceRetries > uAreaRetry + (isQuarterPass() ? uAreaPartLevel : 0); }
uint retryMark() { return uint(uRetryDraw) | (isQuarterPass() ? kByQuarters : 0u); }

// In a retry pass: whether this fragment is the one to shade again.
bool retriedHere() {
  int i = retryIndex();
  return i >= 0 && retryMask[i] == retryMark();
}

// Lists this fragment to be shaded again (from the first pass: whole; from a whole retry: by
// quarters); false when it cannot be (a helper invocation, or the list is full).
bool listForRetry() {
  if (retryIndex() < 0 || gl_HelperInvocation || isQuarterPass()) return false;
  int list = isRetryPass() ? 1 : 0;
  uint slot = atomicAdd(retryListCount[list], 1u);
  if (slot >= uint(AREA_RETRY_LIST)) return false;
  retryList[list * AREA_RETRY_LIST + int(slot)] = (uint(gl_FragCoord.y) << 16) | uint(gl_FragCoord.x);
  return true;
}

// After shading: in the first pass every fragment writes its mark (a later draw over the same pixel
// replaces an earlier draw's), this draw's number when `listed`, else 0; in a whole retry, a
// fragment listed again is marked for quarters.
void markForRetry(bool listed) {
  int i = retryIndex();
  if (i < 0 || gl_HelperInvocation || isQuarterPass()) return;
  if (!isRetryPass()) retryMask[i] = listed ? uint(uRetryDraw) : 0u;
  else if (listed) retryMask[i] = uint(uRetryDraw) | kByQuarters;
}

// In a retry by parts: adds this part's share (`failed`: it was not sampled to the end) to the
// pixel's sum, which comes back in `sum`; true for the last part. The renderer reads the sums' w to
// shade again, by smaller parts, the pixels where a part failed (below the deepest level).
bool addPart(vec3 share, bool failed, out vec4 sum) {
  bool first = uAreaPart == 0 && uAreaBeam <= 0;
  sum = (first ? vec4(0.0) : retrySums[uRetrySlot]) + vec4(share, failed ? 1.0 : 0.0);
  if (!gl_HelperInvocation) retrySums[uRetrySlot] = sum;
  return isLastPart();
}

#endif
