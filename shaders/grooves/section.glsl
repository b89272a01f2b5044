// The combined cross-section of parallel grooves and the footprint's density along it (seed 000 §5,
// §5.1), as libbake/grooves/oracle/line_sampling_section.cpp and line_sampling_occlusion.cpp, in fixed-size
// arrays. Along the common binormal B through F, each groove's profile is placed where its centre
// line crosses B (mirrored when its binormal points along -B); between consecutive profile breakpoints
// every groove is linear, and the surface is H = min(0, cuts) + max(0, ridges), split where two pieces
// (or a piece and the mirror of another) cross, so it stays exact. A jump in H is a vertical wall that
// takes the material of its side with the larger |H|. A facet takes the material of the groove with
// the largest |h| (the lower primitive index on a tie; base where every h is 0).
//
// Density (§5.1): the footprint's points F + s1 A1 + s2 A2 land on B at s1 (A1.B) + s2 (A2.B), the sum
// of two uniform variables: a trapezoid (the CPU method's default). A zero-width footprint is a point.
//
// Perturbed grooves (seed 000 §3), as setSectionRates on the CPU: each point moves along the path with
// the groove that shapes the surface there, keeping its normalised profile coordinates, at rateB across
// and rateH up per unit of travel along T (B = T's left normal).
#ifndef BAKE_GROOVES_SECTION_GLSL
#define BAKE_GROOVES_SECTION_GLSL

#include "lookup.glsl"

#ifndef MAX_PROFILE_POINTS
#define MAX_PROFILE_POINTS 8
#endif
#ifndef MAX_SECTION_GROOVES
#define MAX_SECTION_GROOVES MAX_FOUND
#endif
#define MAX_PLACED (MAX_SECTION_GROOVES * MAX_PROFILE_POINTS)
#define MAX_BREAKS (MAX_PLACED + 2)
#ifndef MAX_SECTION_POINTS
#define MAX_SECTION_POINTS (2 * MAX_BREAKS + 16)
#endif
#define MAX_SPLITS 24

const int kWall = -1;  // a facet whose material is resolved after the sweep

// --- Footprint density along B ---------------------------------------------------------------

struct FootprintLine {
  float wide, narrow;  // half-widths of the two boxes
  vec2 alongB, alongT;  // (A1, A2) projected on B and on T
};

vec2 sectionTangent(vec2 binormal) { return vec2(binormal.y, -binormal.x); }

void setWidths(inout FootprintLine line, float a, float c) {
  a = abs(a);
  c = abs(c);
  line.wide = 0.5 * max(a, c);
  line.narrow = 0.5 * min(a, c);
  if (line.narrow <= 1e-12 * line.wide) line.narrow = 0.0;  // a line: its ramps are below rounding
}

FootprintLine footprintLine(vec2 axis1, vec2 axis2, vec2 binormal) {
  FootprintLine line;
  vec2 tangent = sectionTangent(binormal);
  line.alongB = vec2(dot(axis1, binormal), dot(axis2, binormal));
  line.alongT = vec2(dot(axis1, tangent), dot(axis2, tangent));
  setWidths(line, line.alongB.x, line.alongB.y);
  return line;
}

float halfSupport(FootprintLine line) { return line.wide + line.narrow; }

// The share of the footprint projecting onto (-inf, x].
float footprintCdf(FootprintLine line, float x) {
  float p = line.wide, q = line.narrow;
  if (!(p > 0.0)) return x < 0.0 ? 0.0 : (x > 0.0 ? 1.0 : 0.5);
  if (x <= -(p + q)) return 0.0;
  if (x >= p + q) return 1.0;
  if (abs(x) <= p - q) return 0.5 + x / (2.0 * p);
  float d = p + q - abs(x);
  float tail = (d / (2.0 * q)) * (d / (4.0 * p));
  return x < 0.0 ? tail : 1.0 - tail;
}

float footprintShare(FootprintLine line, float x0, float x1) {
  return abs(footprintCdf(line, x1) - footprintCdf(line, x0));
}

// The share on the side x' <= x of the line x' = x + rate t through the footprint (a perturbed groove's
// wall turned away from T): the footprint projected on B - rate T.
float footprintCdfAcross(FootprintLine line, float x, float rate) {
  if (rate == 0.0) return footprintCdf(line, x);
  FootprintLine turned = line;
  vec2 across = line.alongB - rate * line.alongT;
  setWidths(turned, across.x, across.y);
  return footprintCdf(turned, x);
}

// --- The section -------------------------------------------------------------------------------

vec2 gSectionBinormal;
float gSectionB[MAX_SECTION_POINTS], gSectionH[MAX_SECTION_POINTS];
float gSectionRateB[MAX_SECTION_POINTS], gSectionRateH[MAX_SECTION_POINTS];
float gSectionAccelB[MAX_SECTION_POINTS];  // d2b/dT2: the bend of the point's track
bool gSectionBends;                        // some point's gSectionAccelB is not 0
int gFacetMaterial[MAX_SECTION_POINTS];  // facet i joins points i and i + 1
int gSectionPoints;
bool gSectionOverflow;
// Curved sections (line_sampling.glsl): the b of the arcs' common centre on the line F + b B.
bool gSectionCurved;
float gSectionCentre;

int facetCount() { return gSectionPoints > 0 ? gSectionPoints - 1 : 0; }

// The placed profiles: points in section coordinates, b ascending.
float gPlacedB[MAX_PLACED], gPlacedH[MAX_PLACED];
int gPlacedFirst[MAX_SECTION_GROOVES], gPlacedCount[MAX_SECTION_GROOVES];
int gPlacedMaterial[MAX_SECTION_GROOVES];
uint gPlacedPrimitive[MAX_SECTION_GROOVES];
int gPlacedLocal[MAX_SECTION_GROOVES];  // index into gGrooves
float gPlacedCentre[MAX_SECTION_GROOVES];
bool gPlacedReversed[MAX_SECTION_GROOVES];
int gPlacedGrooves;
float gBreaks[MAX_BREAKS];
int gBreakCount;

// Sorted insertion, written as append-then-sink: the form that shifts the tail in a loop from the
// global count down gave wrong arrays on Mesa llvmpipe (LLVM 15), caught by the oracle test.
void addBreak(float x) {
  for (int i = 0; i < gBreakCount; ++i)
    if (gBreaks[i] == x) return;
  if (gBreakCount == MAX_BREAKS) return;  // cannot happen: sized for every point
  int at = gBreakCount++;
  gBreaks[at] = x;
  while (at > 0 && gBreaks[at - 1] > x) {
    gBreaks[at] = gBreaks[at - 1];
    gBreaks[--at] = x;
  }
}

// Places groove gGrooves[index] with its centre line at b = centre (reversed: mirrored profile).
void placeGroove(int index, float centre, bool reversed) {
  LocalGroove g = gGrooves[index];
  if (gPlacedGrooves == MAX_SECTION_GROOVES) {
    gSectionOverflow = true;
    return;
  }
  int n = min(g.profileCount, MAX_PROFILE_POINTS);
  int first = gPlacedGrooves * MAX_PROFILE_POINTS;
  for (int k = 0; k < n; ++k) {
    int j = reversed ? n - 1 - k : k;
    float b = reversed ? centre - profileB(g, j) : centre + profileB(g, j);
    gPlacedB[first + k] = b;
    gPlacedH[first + k] = profileH(g, j);
    addBreak(b);
  }
  gPlacedFirst[gPlacedGrooves] = first;
  gPlacedCount[gPlacedGrooves] = n;
  gPlacedMaterial[gPlacedGrooves] = g.material;
  gPlacedPrimitive[gPlacedGrooves] = g.primitive;
  gPlacedLocal[gPlacedGrooves] = index;
  gPlacedCentre[gPlacedGrooves] = centre;
  gPlacedReversed[gPlacedGrooves] = reversed;
  ++gPlacedGrooves;
}

void startSection(vec2 binormal, float lo, float hi) {
  gSectionBinormal = binormal;
  gSectionPoints = 0;
  gSectionOverflow = false;
  gSectionCurved = false;
  gSectionCentre = 0.0;
  gPlacedGrooves = 0;
  gBreakCount = 0;
  addBreak(lo);
  addBreak(hi);
}

// h of the segment (pb, ph)-(qb, qh) at x, exact at the end points.
float heightOn(float pb, float ph, float qb, float qh, float x) {
  if (x <= pb) return ph;
  if (x >= qb) return qh;
  return ph + (x - pb) / (qb - pb) * (qh - ph);
}

// The pieces over the current interval.
float gPieceLeft[MAX_SECTION_GROOVES], gPieceRight[MAX_SECTION_GROOVES];
int gPieceMaterial[MAX_SECTION_GROOVES];
uint gPiecePrimitive[MAX_SECTION_GROOVES];
int gPieceCount;

float pieceAt(int i, float t) { return t >= 1.0 ? gPieceRight[i] : gPieceLeft[i] + t * (gPieceRight[i] - gPieceLeft[i]); }

float surfaceAt(float t) {
  float cut = 0.0, ridge = 0.0;
  for (int i = 0; i < gPieceCount; ++i) {
    float h = pieceAt(i, t);
    cut = min(cut, h);
    ridge = max(ridge, h);
  }
  return cut + ridge;
}

int materialAt(float t) {
  float largest = 0.0;
  int material = baseMaterial();
  uint primitive = 0u;
  for (int i = 0; i < gPieceCount; ++i) {
    float size = abs(pieceAt(i, t));
    if (size > largest || (size == largest && size > 0.0 && gPiecePrimitive[i] < primitive)) {
      largest = size;
      material = gPieceMaterial[i];
      primitive = gPiecePrimitive[i];
    }
  }
  return material;
}

float gSplits[MAX_SPLITS];
int gSplitCount;

void addSplit(float t) {
  for (int i = 0; i < gSplitCount; ++i)
    if (gSplits[i] == t) return;
  if (gSplitCount == MAX_SPLITS) {
    gSectionOverflow = true;
    return;
  }
  int at = gSplitCount++;
  gSplits[at] = t;
  while (at > 0 && gSplits[at - 1] > t) {
    gSplits[at] = gSplits[at - 1];
    gSplits[--at] = t;
  }
}

// Where f(t) = fa + t (fb - fa) and g cross strictly inside (0, 1).
void addCrossing(float fa, float fb, float ga, float gb) {
  float d0 = fa - ga, d1 = fb - gb;
  if ((d0 < 0.0 && d1 > 0.0) || (d0 > 0.0 && d1 < 0.0)) {
    float t = d0 / (d0 - d1);
    if (t > 0.0 && t < 1.0) addSplit(t);
  }
}

// Appends a point; a facet with `material` joins it to the previous one unless they coincide.
void appendPoint(float b, float h, int material) {
  if (gSectionPoints > 0) {
    if (gSectionB[gSectionPoints - 1] == b && gSectionH[gSectionPoints - 1] == h) return;
    if (gSectionPoints == MAX_SECTION_POINTS) {
      gSectionOverflow = true;
      return;
    }
    gFacetMaterial[gSectionPoints - 1] = material;
  }
  gSectionB[gSectionPoints] = b;
  gSectionH[gSectionPoints] = h;
  gSectionRateB[gSectionPoints] = 0.0;
  gSectionRateH[gSectionPoints] = 0.0;
  gSectionAccelB[gSectionPoints] = 0.0;
  ++gSectionPoints;
}

void appendInterval(float x0, float x1) {
  gSplitCount = 0;
  addSplit(0.0);
  addSplit(1.0);
  for (int i = 0; i < gPieceCount; ++i) {
    addCrossing(gPieceLeft[i], gPieceRight[i], 0.0, 0.0);
    for (int j = i + 1; j < gPieceCount; ++j) {
      addCrossing(gPieceLeft[i], gPieceRight[i], gPieceLeft[j], gPieceRight[j]);
      addCrossing(gPieceLeft[i], gPieceRight[i], -gPieceLeft[j], -gPieceRight[j]);
    }
  }
  for (int k = 0; k + 1 < gSplitCount; ++k) {
    float ta = gSplits[k], tb = gSplits[k + 1];
    float xa = k == 0 ? x0 : x0 + ta * (x1 - x0);
    float xb = k + 2 == gSplitCount ? x1 : x0 + tb * (x1 - x0);
    int material = materialAt(0.5 * (ta + tb));
    appendPoint(xa, surfaceAt(ta), kWall);  // a jump at xa is a wall
    appendPoint(xb, surfaceAt(tb), material);
  }
}

// A wall takes the material of its side with the larger |H| (the left side on a tie).
void resolveWalls() {
  int facets = facetCount();
  for (int i = 0; i < facets; ++i) {
    if (gFacetMaterial[i] != kWall) continue;
    bool leftDeeper = abs(gSectionH[i]) >= abs(gSectionH[i + 1]);
    int side = kWall;
    if (leftDeeper && i > 0) side = gFacetMaterial[i - 1];
    if (side == kWall && i + 1 < facets) side = gFacetMaterial[i + 1];
    if (side == kWall && i > 0) side = gFacetMaterial[i - 1];
    gFacetMaterial[i] = side == kWall ? baseMaterial() : side;
  }
}

// Sweeps the breakpoints: over each interval, every band that covers it contributes its linear piece.
// The polyline starts and ends on the base (h = 0), so an outermost vertical wall is kept.
void buildSection() {
  appendPoint(gBreaks[0], 0.0, kWall);
  for (int k = 0; k + 1 < gBreakCount; ++k) {
    float x0 = gBreaks[k], x1 = gBreaks[k + 1];
    gPieceCount = 0;
    for (int g = 0; g < gPlacedGrooves; ++g) {
      int first = gPlacedFirst[g], count = gPlacedCount[g];
      if (!(gPlacedB[first] <= x0) || gPlacedB[first + count - 1] <= x0) continue;  // not yet, or ended
      int j = 0;
      while (j + 2 < count && gPlacedB[first + j + 1] <= x0) ++j;  // skips vertical segments too
      float pb = gPlacedB[first + j], ph = gPlacedH[first + j];
      float qb = gPlacedB[first + j + 1], qh = gPlacedH[first + j + 1];
      gPieceLeft[gPieceCount] = heightOn(pb, ph, qb, qh, x0);
      gPieceRight[gPieceCount] = heightOn(pb, ph, qb, qh, x1);
      gPieceMaterial[gPieceCount] = gPlacedMaterial[g];
      gPiecePrimitive[gPieceCount] = gPlacedPrimitive[g];
      ++gPieceCount;
    }
    appendInterval(x0, x1);
  }
  appendPoint(gBreaks[gBreakCount - 1], 0.0, kWall);
  resolveWalls();
}

// A groove's own height at its offset x, or false outside its band (its edges within 1e-4 of its
// width: a rim keeps its rates through rounding, as on the CPU).
bool grooveHeightAt(LocalGroove g, float x, out float h) {
  int n = min(g.profileCount, MAX_PROFILE_POINTS);
  h = 0.0;
  float slack = 1e-4 * (profileB(g, n - 1) - profileB(g, 0));
  if (!(x >= profileB(g, 0) - slack && x <= profileB(g, n - 1) + slack)) return false;
  x = clamp(x, profileB(g, 0), profileB(g, n - 1));
  int k = 0;
  while (k + 2 < n && profileB(g, k + 1) < x) ++k;
  float b0 = profileB(g, k), b1 = profileB(g, k + 1);
  h = b1 > b0 ? profileH(g, k) + (x - b0) / (b1 - b0) * (profileH(g, k + 1) - profileH(g, k)) : profileH(g, k);
  return true;
}

// The rates of every point of a band (rims included: they do not move, but tilt their facets): those
// of the groove whose own height there is nearest the surface's, dx/ds = offset' + scale' q across
// and side scale' h / scale up (side = -1 where the groove runs against T, reversed), and the bend
// side (offset'' + scale'' q) across.
void setSectionRates() {
  gSectionBends = false;
  for (int i = 0; i < gSectionPoints; ++i) {
    int shaping = -1;
    float nearest = 0.0;
    for (int p = 0; p < gPlacedGrooves; ++p) {
      float side = gPlacedReversed[p] ? -1.0 : 1.0, h;
      if (!grooveHeightAt(gGrooves[gPlacedLocal[p]], side * (gSectionB[i] - gPlacedCentre[p]), h)) continue;
      if (shaping < 0 || abs(h - gSectionH[i]) < nearest) {
        shaping = p;
        nearest = abs(h - gSectionH[i]);
      }
    }
    if (shaping < 0) continue;
    LocalGroove g = gGrooves[gPlacedLocal[shaping]];
    if (g.scaleRate == 0.0 && g.offsetRate == 0.0 && g.scaleAccel == 0.0 && g.offsetAccel == 0.0) continue;
    float side = gPlacedReversed[shaping] ? -1.0 : 1.0;
    float q = (side * (gSectionB[i] - gPlacedCentre[shaping]) - g.offset) / g.scale;
    gSectionRateB[i] = g.offsetRate + g.scaleRate * q;
    gSectionRateH[i] = side * g.scaleRate * gSectionH[i] / g.scale;
    gSectionAccelB[i] = side * (g.offsetAccel + g.scaleAccel * q);
    gSectionBends = gSectionBends || gSectionAccelB[i] != 0.0;
  }
}

// Curved sections, as subdivideFacets on the CPU: every facet that changes height is split into
// `pieces`, the new points interpolating position, rates and bend. In place, from the last point back;
// false (the section unchanged) when the arrays cannot hold the result.
bool subdivideFacets(int pieces) {
  int facets = facetCount();
  int total = gSectionPoints;
  for (int i = 0; i < facets; ++i)
    if (gSectionH[i] != gSectionH[i + 1]) total += pieces - 1;
  if (total > MAX_SECTION_POINTS) return false;
  int to = total - 1;
  for (int i = facets - 1; i >= 0; --i) {
    int n = gSectionH[i] != gSectionH[i + 1] ? pieces : 1;
    float b0 = gSectionB[i], h0 = gSectionH[i], rb0 = gSectionRateB[i], rh0 = gSectionRateH[i], a0 = gSectionAccelB[i];
    float b1 = gSectionB[i + 1], h1 = gSectionH[i + 1], rb1 = gSectionRateB[i + 1], rh1 = gSectionRateH[i + 1];
    float a1 = gSectionAccelB[i + 1];
    int material = gFacetMaterial[i];
    // Point i + 1 moves to `to`; the inner points k = n - 1 .. 1 go before it.
    gSectionB[to] = b1; gSectionH[to] = h1; gSectionRateB[to] = rb1; gSectionRateH[to] = rh1; gSectionAccelB[to] = a1;
    for (int k = n - 1; k >= 1; --k) {
      float t = float(k) / float(n);
      --to;
      gSectionB[to] = b0 + t * (b1 - b0);
      gSectionH[to] = h0 + t * (h1 - h0);
      gSectionRateB[to] = rb0 + t * (rb1 - rb0);
      gSectionRateH[to] = rh0 + t * (rh1 - rh0);
      gSectionAccelB[to] = a0 + t * (a1 - a0);
      gFacetMaterial[to] = material;
    }
    gFacetMaterial[to - 1] = material;
    --to;
  }
  gSectionPoints = total;
  return true;
}

// Unit outward normal of facet i in the section plane (b, h).
vec2 facetNormal2(int i) {
  float db = gSectionB[i + 1] - gSectionB[i], dh = gSectionH[i + 1] - gSectionH[i];
  float len = length(vec2(db, dh));
  return len > 0.0 ? vec2(-dh, db) / len : vec2(0.0, 1.0);
}

// In groove space, tilted along T by the points' rates: the cross product of the facet's step
// (0, db, dh) with its ends' mean track (1, rateB, rateH), in (T, B, up).
vec3 facetNormal3(int i) {
  float db = gSectionB[i + 1] - gSectionB[i], dh = gSectionH[i + 1] - gSectionH[i];
  float rateB = 0.5 * (gSectionRateB[i] + gSectionRateB[i + 1]);
  float rateH = 0.5 * (gSectionRateH[i] + gSectionRateH[i + 1]);
  vec3 n = vec3(dh * rateB - db * rateH, -dh, db);  // (T, B, up)
  float len = length(n);
  if (!(len > 0.0)) return vec3(0.0, 0.0, 1.0);
  n /= len;
  return vec3(n.y * gSectionBinormal + n.x * sectionTangent(gSectionBinormal), n.z);
}

#endif
