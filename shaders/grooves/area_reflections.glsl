// Inter-reflections (seed 000 §7) in footprints sampled by area, as
// libbake/grooves/oracle/area_reflections.cpp. The visible part of a mirror piece the eye sees, lit or
// not, is a beam: its convex fragments lifted onto the mirror's plane, with the share of the
// footprint they cover. Its rays leave along R, the view mirrored about the mirror's normal, so the
// beam is sampled like a footprint of its own: the view becomes -R, the screen the plane perpendicular
// to R (R may be horizontal or point down), the footprint each fragment projected onto that screen (a
// "window", with its fragment's weight). The pieces are rebuilt over the region the beam's rays cross
// over the grooves' height range; they are seen, and hide one another, only in front of the mirror's
// plane, and shadow whole. A piece facing -R adds weight x (lit share) x its direct radiance seen
// from -R; while bounces remain, a mirror piece's visible part becomes a beam in turn; rays no piece
// catches leave the surface when R points up and see the environment (the seed's 1 - Σ r_i).
// Affine maps between planes keep area ratios, so shares carry over exactly.
// The eye's beams are stored while its pieces are sampled, one per mirror plane and material (the
// coplanar pieces of a mirror send the same rays: the CPU follows them one by one, to the same sum),
// and followed afterwards in passes of their own through the same stages as the eye's
// (area_sampling.glsl sampleParallelogram), since each beam rebuilds the pieces. Beams live in the
// slot (area_surface.glsl's layout, then AREA_MAX_BEAMS + 1 beams: a stack and the one being
// followed, then the eye's planes). The eye's beams may take half of the stack (past that the
// footprint is split, as when pieces overflow; on the last level they are left out), so that their
// own beams find room; a beam that does not fit is dropped, as is one carrying less than
// kNegligibleAreaBeam of the pixel, and at most 4 x AREA_MAX_BEAMS beams are followed per eye beam.
// A beam holds up to AREA_BEAM_FRAGMENTS fragments; what does not fit is left out (its share with
// it). The CPU's bounds are 64 beams per eye beam and no fragment cap. A retry pass may follow one
// eye beam alone (area_retry.glsl).
#ifndef BAKE_GROOVES_AREA_REFLECTIONS_GLSL
#define BAKE_GROOVES_AREA_REFLECTIONS_GLSL

#ifndef AREA_EYE_BEAMS
#error "AREA_EYE_BEAMS comes from the renderer (runtime/render/grooves.cpp kAreaEyeBeams)"
#endif
#define AREA_MAX_BEAMS (2 * AREA_EYE_BEAMS)
#ifndef AREA_BEAM_FRAGMENTS
#define AREA_BEAM_FRAGMENTS 32
#endif

const float kNegligibleAreaBeam = 1e-12;
const int kAreaEyeBeams = AREA_EYE_BEAMS;
const int kAreaBeamStepsPerEyeBeam = 4 * AREA_MAX_BEAMS;

// A beam: the mirror's normal, its material, what looks at it, the product of the reflectances
// applied before it, its share of the footprint, the reflections made before it, then its fragments
// (vertex count, vertices in 3D, weight).
const int kBeamNormal = 0, kBeamMaterial = 3, kBeamToViewer = 4, kBeamWeight = 7, kBeamShare = 10, kBeamBounce = 11,
          kBeamFragmentCount = 12, kBeamFragments = 13;
const int kBeamFragmentSize = 2 + 3 * AREA_MAX_VERTICES;
const int kBeamSize = kBeamFragments + AREA_BEAM_FRAGMENTS * kBeamFragmentSize;
const int kBeams = kAreaSlotSize;
const int kAreaBeamsSize = (AREA_MAX_BEAMS + 1) * kBeamSize + 5 * AREA_EYE_BEAMS;  // and the eye's planes

int gAreaBeamCount;  // on the stack

int areaBeamAt(int b) { return kBeams + b * kBeamSize; }
int beamFragmentCount(int beam) { return int(arenaAt(beam + kBeamFragmentCount)); }
int beamFragmentAt(int beam, int k) { return beam + kBeamFragments + k * kBeamFragmentSize; }
int beamFragmentVertexCount(int fragment) { return int(arenaAt(fragment)); }
vec3 beamFragmentVertex(int fragment, int v) { return arena3(fragment + 1 + 3 * v); }
float beamFragmentWeight(int fragment) { return arenaAt(fragment + 1 + 3 * AREA_MAX_VERTICES); }

// --- Collecting a beam: the visible fragments of a piece, lifted onto its plane --------------------

int gCollectBeam = -1;        // the beam being filled, or -1
float gCollectWeight;         // multiplies each fragment's weight (its window's weight)
float gCollectShare;          // footprint share per unit of weighted area
float gCollectStrongest;      // the strongest channel of the beam's weight; < 0: keep whatever is seen
float gCollectedShare;        // what the fragments kept cover

// Called when piece i's visible part is complete (visibleLitPart).
void collectBeamFragments(int i) {
  if (gCollectBeam < 0) return;
  float seen = gCollectShare * gCollectWeight * fragmentsWeightedArea();
  if (gCollectStrongest >= 0.0 && !(seen * gCollectStrongest > kNegligibleAreaBeam)) return;
  int count = beamFragmentCount(gCollectBeam);
  for (int k = 0; k < gFragmentCount; ++k) {
    if (count == AREA_BEAM_FRAGMENTS) break;  // left out, its share with it
    int from = fragmentAt(k), to = beamFragmentAt(gCollectBeam, count++);
    int n = vertexCount(from);
    setArena(to, float(n));
    for (int v = 0; v < n; ++v) setArena3(to + 1 + 3 * v, seenPoint(i, vertexAt(from, v)));
    float weight = gCollectWeight * fragmentWeight(k);
    setArena(to + 1 + 3 * AREA_MAX_VERTICES, weight);
    gCollectedShare += gCollectShare * weight * polygonArea(from);
  }
  setArena(gCollectBeam + kBeamFragmentCount, float(count));
}

// Starts filling the beam in stack slot `slot` (emptied first when `fresh`).
void startAreaBeam(int slot, bool fresh, float share, float weight, float strongest) {
  gCollectBeam = areaBeamAt(slot);
  if (fresh) {
    setArena(gCollectBeam + kBeamFragmentCount, 0.0);
    setArena(gCollectBeam + kBeamShare, 0.0);
  }
  gCollectShare = share;
  gCollectWeight = weight;
  gCollectStrongest = strongest;
  gCollectedShare = 0.0;
}

// The eye's beams, one per mirror plane and material: coplanar pieces of one mirror (the base
// between grooves, a facet split by a crossing) reflect alike, so one beam holds the fragments of
// all of them (the same rays as a beam each, one pass to follow them). gEyeBeamKeys planes met, each
// (normal, offset, material) in the slot after the beams; beam k of the eye is the k-th plane met.
int gEyeBeamKeys;
int eyeBeamKey(int k) { return kBeams + (AREA_MAX_BEAMS + 1) * kBeamSize + 5 * k; }

// The index of piece i's plane among the eye's beams, added if new; -1 when there is no room.
int eyeBeamIndex(int i) {
  vec4 plane = vec4(pieceNormal(i), piecePlaneOffset(i));
  float material = float(pieceMaterial(i));
  int found = -1;
  for (int k = 0; k < gEyeBeamKeys && found < 0; ++k)
    if (arena4(eyeBeamKey(k)) == plane && arenaAt(eyeBeamKey(k) + 4) == material) found = k;
  if (found >= 0 || gEyeBeamKeys == kAreaEyeBeams) return found;
  setArena4(eyeBeamKey(gEyeBeamKeys), plane);
  setArena(eyeBeamKey(gEyeBeamKeys) + 4, material);
  return gEyeBeamKeys++;
}

// The beam of the eye's mirror piece i; false when the eye has more mirror planes than beams
// (counted: the footprint is split), or when one beam is traced alone (gAreaBeamAlone >= 0, kept in
// slot 0) and this is not the one.
bool startEyeBeam(int i, float footprintArea) {
  int index = eyeBeamIndex(i);
  if (index < 0) ++gAreaOverflows;
  if (index < 0 || (gAreaBeamAlone >= 0 && index != gAreaBeamAlone)) return false;
  int slot = gAreaBeamAlone >= 0 ? 0 : index;
  bool fresh = slot >= gAreaBeamCount;
  gAreaBeamCount = max(gAreaBeamCount, slot + 1);
  startAreaBeam(slot, fresh, 1.0 / footprintArea, 1.0, -1.0);
  return true;
}

// In a beam's pass: whether the piece of `material` sends a beam of its own (it mirrors, bounces
// remain, and the stack has room; else it is dropped), started on top of the stack if so.
bool startChildBeam(AreaPass pass, int material) {
  if (!hasMirror(material) || pass.bounce + 1 >= gMaxBounces || gAreaBeamCount == AREA_MAX_BEAMS) return false;
  startAreaBeam(gAreaBeamCount, true, pass.share / pass.beamArea, 1.0, pass.strongest);
  return true;
}

// The beam being filled, from piece i seen along gAreaView: its fragments' share added, and a child
// pushed if it holds anything (the eye's beams are on the stack from their first piece on; one that
// catches nothing carries no rays and is skipped).
void finishAreaBeam(int i, vec3 weight, int bounce, bool child) {
  int beam = gCollectBeam;
  gCollectBeam = -1;
  setArena3(beam + kBeamNormal, pieceNormal(i));
  setArena(beam + kBeamMaterial, float(pieceMaterial(i)));
  setArena3(beam + kBeamToViewer, gAreaView);
  setArena3(beam + kBeamWeight, weight);
  setArena(beam + kBeamShare, arenaAt(beam + kBeamShare) + gCollectedShare);
  setArena(beam + kBeamBounce, float(bounce));
  if (child && beamFragmentCount(beam) > 0 && gCollectedShare > 0.0) ++gAreaBeamCount;
}

// --- Following a beam -------------------------------------------------------------------------------

// Fragment k of the beam projected onto the current screen, into kFootprint (counter-clockwise).
void projectWindow(int beam, int k) {
  int fragment = beamFragmentAt(beam, k);
  int n = beamFragmentVertexCount(fragment);
  setVertexCount(kFootprint, 0);
  for (int v = 0; v < n; ++v) addVertex(kFootprint, toScreen(beamFragmentVertex(fragment, v)));
  makeCounterClockwise(kFootprint);
}

void copyAreaBeam(int to, int from) {
  for (int k = 0; k < kBeamFragments; ++k) setArena(to + k, arenaAt(from + k));
  int fragments = beamFragmentCount(from);
  for (int f = 0; f < fragments; ++f) {
    int a = beamFragmentAt(from, f), b = beamFragmentAt(to, f);
    int n = beamFragmentVertexCount(a);
    setArena(b, float(n));
    for (int k = 0; k < 3 * n; ++k) setArena(b + 1 + k, arenaAt(a + 1 + k));
    setArena(b + 1 + 3 * AREA_MAX_VERTICES, beamFragmentWeight(a));
  }
}

// The pass of `beam`: the frame along -R, its windows' area and boxes, the region its rays cross
// and the mirror's plane the pieces are cut to; no windows when it carries no rays.
AreaPass beamPass(int beam) {
  AreaPass pass = AreaPass(beam, 0, vec4(vec2(kInfinity), vec2(-kInfinity)), vec3(0.0), 0.0, 0.0, 0, false, 0.0);
  vec3 N = arena3(beam + kBeamNormal), toViewer = arena3(beam + kBeamToViewer);
  float facing = dot(N, toViewer);
  if (!(facing > 0.0)) return pass;
  vec3 R = 2.0 * facing * N - toViewer;
  pass.weight = arena3(beam + kBeamWeight) * materials[int(arenaAt(beam + kBeamMaterial))].mirror.rgb;
  pass.strongest = max(pass.weight.r, max(pass.weight.g, pass.weight.b));
  pass.share = arenaAt(beam + kBeamShare);
  pass.bounce = int(arenaAt(beam + kBeamBounce));
  pass.leaves = R.z > 0.0;
  gAreaView = -R;
  gAreaBaseScreen = false;
  vec3 helper = abs(gAreaView.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
  gAreaScreenAxis1 = normalize(cross(helper, gAreaView));
  gAreaScreenAxis2 = cross(gAreaView, gAreaScreenAxis1);

  // The windows' weighted area and box on the screen, and the fragments' box on the base plane and
  // range of heights.
  int windows = beamFragmentCount(beam);
  vec4 baseBox = pass.windowsBox;
  vec2 heights = vec2(gAreaHeight, -gAreaDepth);
  for (int k = 0; k < windows; ++k) {
    projectWindow(beam, k);
    int fragment = beamFragmentAt(beam, k);
    pass.beamArea += beamFragmentWeight(fragment) * polygonArea(kFootprint);
    pass.windowsBox = boxUnion(pass.windowsBox, polygonBox(kFootprint));
    int n = beamFragmentVertexCount(fragment);
    for (int v = 0; v < n; ++v) {
      vec3 x = beamFragmentVertex(fragment, v);
      baseBox = vec4(min(baseBox.xy, x.xy), max(baseBox.zw, x.xy));
      heights = vec2(min(heights.x, x.z), max(heights.y, x.z));
    }
  }
  if (!(pass.beamArea > 0.0)) return pass;  // seen edge-on: the beam carries no rays
  gAreaMinArea = 1e-8 * pass.beamArea;

  // The pieces the rays can reach and what shadows them: over the fragments' box swept forward along
  // R (up or down) until the rays leave the height range, then along L. A ray from height w0 reaches
  // x0 + s R_uv / |R_w| after a change of height s, at most height - w0 going up, w0 + depth down.
  float e = 1e-5 * gAreaLengthScale, range = gAreaHeight + gAreaDepth + e;
  float climb = R.z > 0.0 ? gAreaHeight - heights.x : (R.z < 0.0 ? heights.y + gAreaDepth : range);
  vec3 level = vec3(R.xy, abs(R.z));  // the same shift per height, up or down
  sweptRegion(baseBox, e, shiftPerHeight(level), vec2(0.0, clamp(climb + e, 0.0, range)), shiftPerHeight(gAreaLight),
              vec2(0.0, range));
  // Seen, and hiding one another, only in front of the mirror (projectPieces); they shadow whole.
  gAreaCutPlane = vec4(N, dot(N, beamFragmentVertex(beamFragmentAt(beam, 0), 0)));
  gAreaCutByPlane = true;
  pass.windows = windows;
  return pass;
}

int gAreaBeamSteps, gAreaBeamStepLimit;

// The pass of the next beam on the stack that carries rays (popped into the slot of the beam
// followed), or none. `fromEye`: the eye's pass has just ended, and its beams are on the stack.
AreaPass nextBeamPass(bool fromEye) {
  if (fromEye) {
    gAreaBeamSteps = 0;
    gAreaBeamStepLimit = gAreaBeamCount * kAreaBeamStepsPerEyeBeam;
  }
  AreaPass pass = AreaPass(-1, 0, vec4(0.0), vec3(0.0), 0.0, 0.0, 0, false, 0.0);
  int current = areaBeamAt(AREA_MAX_BEAMS);
  while (pass.windows == 0 && gAreaBeamCount > 0 && gAreaBeamSteps < gAreaBeamStepLimit) {
    copyAreaBeam(current, areaBeamAt(--gAreaBeamCount));
    ++gAreaBeamSteps;
    pass = beamPass(current);
  }
  return pass;
}

// In a beam's pass: window k into kFootprint, and the footprint share per unit of its area (0 when
// it has none).
float windowShare(AreaPass pass, int k) {
  projectWindow(pass.beam, k);
  if (!(polygonArea(kFootprint) > 0.0)) return 0.0;
  gCollectWeight = beamFragmentWeight(beamFragmentAt(pass.beam, k));
  return pass.share * gCollectWeight / pass.beamArea;
}

#endif
