// Retry passes for area samples that a driver's loop cap cut short (runtime/render/grooves.cpp draws
// them). Mesa's llvmpipe runs the fragment shader for a SIMD group of pixels at once and stops every
// loop once the group has run 65,535 iterations in all. The lanes of a group take different paths
// through the area sampler, so the group pays for close to the sum of their loops (and for one
// iteration of every loop in a branch that no lane takes), and the heaviest special cases overrun
// it. So the first pass lists a pixel cut short, and the renderer draws again once per listed pixel,
// scissored to it: its group then has one lane, which pays for its own loops only. A pixel cut short
// even alone is listed again and shaded by parts of its footprint, the nodes of a quadtree: the whole
// footprint, then the quarters, sixteenths and sixty-fourths (the CPU's deepest split) of only those
// nodes where a draw was cut short again. Each node is drawn beam by beam, one draw per beam of the
// eye's mirror pieces (§7 inter-reflections cost most: a pass traces one beam, the pass of beam 0
// adds the pieces' direct light); its beams' shares are summed in its entry of retryNodes (area and
// beams are additive: the CPU adds the same shares). Beams are numbered per node, so a node cut short
// is replaced by its four children, every beam of them. A last pass per pixel (uAreaRetry 3) adds the
// leaves that were sampled to the end and writes the pixel, line sampled if a sixty-fourth was still
// cut short. In the variant without traced beams (AREA_REFLECTIONS off) a node is one draw (uAreaBeam
// -1), from quarters on. retryMask says which draw of the frame owns each pixel (the last to shade
// it), so that only that one shades it again.
// Drivers without such a cap list nothing and draw no retry pass.
#ifndef BAKE_GROOVES_AREA_RETRY_GLSL
#define BAKE_GROOVES_AREA_RETRY_GLSL

#if !defined(AREA_RETRY_LIST) || !defined(AREA_RETRY_NODES)
#error "AREA_RETRY_LIST and AREA_RETRY_NODES come from the renderer (runtime/render/grooves.cpp)"
#endif

layout(std430, binding = 13) coherent buffer AreaRetry {
  // Per node of the parts' quadtree (AREA_RETRY_NODES: levels 0 to AREA_MAX_SPLIT_LEVEL), level by
  // level, each level pixel by pixel (slot of the second list): the node's beams summed, w: how many
  // of its draws were cut short. The renderer zeroes them before the first retry by parts.
  vec4 retryNodes[AREA_RETRY_LIST * AREA_RETRY_NODES];
  uint retryListCount[2];           // pixels listed: [0] to shade again whole, [1] by quarters
  uint retryList[2 * AREA_RETRY_LIST];  // (y << 16) | x; list k from k * AREA_RETRY_LIST
  uint retryMask[];  // per pixel of the target, row-major: the draw that owns it when listed, else 0
};

uniform int uAreaRetry = 0;     // 0: the first pass; 1: a retry of whole footprints; 2: by parts; 3: the sum
uniform int uAreaPartLevel = 0;  // in a retry by parts: 2^level x 2^level parts (0 to 3)
uniform int uAreaPart = 0;      // in a retry by parts: which part, 0 to 4^level - 1, row-major
uniform int uAreaBeam = -1;     // in a retry by parts: the one eye beam to trace (0 to AREA_EYE_BEAMS - 1), or -1
uniform int uRetrySlot = 0;     // in a retry by parts and the sum: the pixel's place in the second list
uniform int uRetryRootLevel = 0;  // the level of the first retry by parts (1 without traced beams)
uniform int uRetryDraw = 1;    // this draw's number in the frame (from 1)
uniform int uRetryStride = 0;  // the target's width in pixels; 0: no retry buffer bound
// Tests: 1 takes every area sample of the first pass as cut short, 2 also those of the retries of
// whole footprints, 3 also those of the beam-by-beam retries of whole footprints, so that every kind
// of retry runs on any driver; 4 as 2, and by parts node 0 of every level but the deepest, so that
// the leaves are of every level.
uniform int uForceRetries = 0;

const uint kByQuarters = 0x40000000u;  // added to a mark: shade again by parts

int retryIndex() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  int i = p.y * uRetryStride + p.x;
  return uRetryStride > 0 && p.x < uRetryStride && i < retryMask.length() ? i : -1;
}

bool isRetryPass() { return uAreaRetry > 0; }
bool isQuarterPass() { return uAreaRetry == 2; }
bool isSumPass() { return uAreaRetry == 3; }
bool isBeamByBeam() { return isQuarterPass() && uAreaBeam >= 0; }
bool retryForced() {
  if (uForceRetries == 4) return !isQuarterPass() || (uAreaPart == 0 && uAreaPartLevel < AREA_MAX_SPLIT_LEVEL);
  return uForceRetries > uAreaRetry + (isQuarterPass() ? uAreaPartLevel : 0);
}
uint retryMark() { return uint(uRetryDraw) | (isQuarterPass() || isSumPass() ? kByQuarters : 0u); }

// The entry of node `part` (row-major, 2^level x 2^level) at `level` for the pixel in `slot`.
int retryNode(int level, int part, int slot) {
  int before = ((1 << (2 * level)) - 1) / 3;  // nodes of the levels above
  return (before * AREA_RETRY_LIST) + (slot << (2 * level)) + part;
}

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

// In a retry by parts: adds this draw's share (`failed`: it was not sampled to the end) to its node.
void addPart(vec3 share, bool failed) {
  if (gl_HelperInvocation) return;
  int node = retryNode(uAreaPartLevel, uAreaPart, uRetrySlot);
  retryNodes[node] += vec4(share, failed ? 1.0 : 0.0);
}

// In the last pass: the pixel's value summed over the leaves of its quadtree, the nodes drawn (the
// root level, or a child of a node cut short) that were sampled to the end or are at the deepest
// level; w > 0 when one of the deepest was cut short (the pixel is line sampled instead).
vec4 sumOfParts() {
  vec4 sum = vec4(0.0);
  for (int level = uRetryRootLevel; level <= AREA_MAX_SPLIT_LEVEL; ++level) {
    int side = 1 << level;
    for (int part = 0; part < side * side; ++part) {
      int x = part & (side - 1), y = part >> level;
      bool drawn = level == uRetryRootLevel ||
                   retryNodes[retryNode(level - 1, (y >> 1) * (side >> 1) + (x >> 1), uRetrySlot)].w > 0.0;
      vec4 node = retryNodes[retryNode(level, part, uRetrySlot)];
      if (drawn && (node.w == 0.0 || level == AREA_MAX_SPLIT_LEVEL)) sum += node;
    }
  }
  return sum;
}

#endif
