// The local surface under a footprint as planar convex pieces, for the area sampling of seed 000 §6,
// as libbake/grooves/oracle/area_surface.cpp (facets after the seed's intersection removal, §6.2, done by
// clipping) and area_walls.cpp (the walls of open ends and vertical profile segments, §6.5). Every
// found primitive is straightened at F; H = min(cuts) + max(ridges) is built by overlaying the grooves
// one after the other on a list of convex cells, each with a plane per layer (the lower plane wins in
// the cut layer, the higher in the ridge layer, split where they are equal), which are then added.
// (The CPU builds the two layers apart and intersects their cells pairwise; one overlay gives the same
// surface with far fewer loop iterations, which some drivers cap: see area_sampling.glsl.)
// Where H jumps, a vertical wall between its two side limits. Materials as the spec says: the
// primitive with the larger |h|, the earlier one on a tie, else the base material.
// Everything lives in the invocation's arena slot (area_polygon.glsl); its layout is below. Caps
// (AREA_MAX_CELLS cells, AREA_MAX_PIECES pieces, AREA_MAX_BREAKS breaks along a wall line)
// are counted in gAreaOverflows; the sampler splits the footprint when they are reached.
#ifndef BAKE_GROOVES_AREA_SURFACE_GLSL
#define BAKE_GROOVES_AREA_SURFACE_GLSL

#include "area_polygon.glsl"
#include "lookup.glsl"

#ifndef AREA_MAX_CELLS
#define AREA_MAX_CELLS 160
#endif
#ifndef AREA_MAX_PIECES
#define AREA_MAX_PIECES 160
#endif
#ifndef AREA_MAX_BREAKS
#define AREA_MAX_BREAKS 32
#endif
#define AREA_MAX_STRAIGHT_POINTS (2 * MAX_PROFILE_POINTS)

// --- The slot's layout (offsets in floats) ---------------------------------------------------------

// A straight groove: material, foot, tangent, binormal, profile first and count, joint half-planes,
// joint points, open ends.
const int kStraightMaterial = 0, kStraightFoot = 1, kStraightTangent = 3, kStraightBinormal = 5,
          kStraightProfileFirst = 7, kStraightProfileCount = 8, kStraightJoint = 9, kStraightJointPoint = 15,
          kStraightOpenEnd = 19, kStraightSize = 21;
// A strip of one groove's profile: b0, b1, kind (0 keeps the cells' planes, 1 cut, 2 ridge), plane.
const int kStripSize = 6;
// A cell: polygon, the cut layer's plane and owner, the ridge layer's plane and owner, box.
const int kCellPlane = AREA_POLY, kCellRidge = 4, kCellBox = AREA_POLY + 8, kCellSize = AREA_POLY + 12;
// A piece: vertex count, vertices (3D), normal, plane offset, material, N.E, N.L, screen box, light
// box, screen polygon.
const int kPieceVertices = 1, kPieceNormal = 1 + 3 * AREA_MAX_VERTICES, kPieceOffset = kPieceNormal + 3,
          kPieceMaterial = kPieceOffset + 1, kPieceFacingViewer = kPieceMaterial + 1,
          kPieceFacingLight = kPieceFacingViewer + 1, kPieceScreenBox = kPieceFacingLight + 1,
          kPieceLightBox = kPieceScreenBox + 4, kPieceScreen = kPieceLightBox + 4,
          kPieceSize = kPieceScreen + AREA_POLY;

const int kRegion = 0, kBand = kRegion + AREA_POLY, kJointed = kBand + AREA_POLY, kInside = kJointed + AREA_POLY,
          kInBand = kInside + AREA_POLY, kFirst = kInBand + AREA_POLY,
          kFootprint = kFirst + AREA_POLY, kOverlap = kFootprint + AREA_POLY, kShadow = kOverlap + AREA_POLY,
          kHoleInside = kShadow + AREA_POLY, kSpare = kHoleInside + AREA_POLY;
const int kEdgesBand = kSpare + AREA_POLY, kEdgesFootprint = kEdgesBand + AREA_EDGES,
          kEdgesMe = kEdgesFootprint + AREA_EDGES, kEdgesHole = kEdgesMe + AREA_EDGES,
          kEdgesOther = kEdgesHole + AREA_EDGES;
const int kSubtracted = kEdgesOther + AREA_EDGES;  // AREA_MAX_VERTICES polygons
const int kFragments = kSubtracted + AREA_MAX_VERTICES * AREA_POLY;
const int kFragmentWeights = kFragments + AREA_MAX_FRAGMENTS * AREA_POLY;
const int kFragmentBoxes = kFragmentWeights + AREA_MAX_FRAGMENTS;
const int kStraight = kFragmentBoxes + 4 * AREA_MAX_FRAGMENTS;
const int kStraightProfiles = kStraight + MAX_FOUND * kStraightSize;
const int kStrips = kStraightProfiles + 2 * MAX_FOUND * AREA_MAX_STRAIGHT_POINTS;
const int kBreaks = kStrips + kStripSize * AREA_MAX_STRAIGHT_POINTS;
const int kCells = kBreaks + AREA_MAX_BREAKS;  // two banks
const int kPieces = kCells + 2 * AREA_MAX_CELLS * kCellSize;
const int kAreaSlotSize = kPieces + AREA_MAX_PIECES * kPieceSize;

// --- Straightened primitives ---------------------------------------------------------------------

int gStraightCount;

int straightAt(int g) { return kStraight + g * kStraightSize; }
int straightMaterial(int g) { return int(arenaAt(straightAt(g) + kStraightMaterial)); }
vec2 straightFoot(int g) { return arena2(straightAt(g) + kStraightFoot); }
vec2 straightTangent(int g) { return arena2(straightAt(g) + kStraightTangent); }
vec2 straightBinormal(int g) { return arena2(straightAt(g) + kStraightBinormal); }
int straightProfileCount(int g) { return int(arenaAt(straightAt(g) + kStraightProfileCount)); }
vec2 straightPoint(int g, int k) {
  return arena2(kStraightProfiles + 2 * (int(arenaAt(straightAt(g) + kStraightProfileFirst)) + k));
}
vec3 straightJoint(int g, int e) { return arena3(straightAt(g) + kStraightJoint + 3 * e); }
vec2 straightJointPoint(int g, int e) { return arena2(straightAt(g) + kStraightJointPoint + 2 * e); }
bool straightOpenEnd(int g, int e) { return arenaAt(straightAt(g) + kStraightOpenEnd + e) != 0.0; }
float straightFirstB(int g) { return straightPoint(g, 0).x; }
float straightLastB(int g) { return straightPoint(g, straightProfileCount(g) - 1).x; }
float acrossGroove(int g, vec2 x) { return dot(straightBinormal(g), x - straightFoot(g)); }
vec3 atLeastB(int g, float b) { return vec3(straightBinormal(g), dot(straightBinormal(g), straightFoot(g)) + b); }
vec3 atMostB(int g, float b) { return -atLeastB(g, b); }

// The found primitives (gGrooves), each moved to the copy nearest F, with profiles split at h = 0.
void straightenFound() {
  gStraightCount = gGrooveCount;
  int used = 0;
  for (int i = 0; i < gGrooveCount; ++i) {
    LocalGroove l = gGrooves[i];
    vec2 foot = offsetFromCentre(l.foot);
    vec2 shift = l.foot - foot;
    int at = straightAt(i);
    setArena(at + kStraightMaterial, float(l.material));
    setArena2(at + kStraightFoot, foot);
    setArena2(at + kStraightTangent, l.tangent);
    setArena2(at + kStraightBinormal, l.binormal);
    setArena3(at + kStraightJoint, vec3(l.startNormal, dot(l.startNormal, l.startPoint - shift)));
    setArena3(at + kStraightJoint + 3, vec3(l.endNormal, dot(l.endNormal, l.endPoint - shift)));
    setArena2(at + kStraightJointPoint, l.startPoint - shift);
    setArena2(at + kStraightJointPoint + 2, l.endPoint - shift);
    setArena(at + kStraightOpenEnd, neighbourAcross(l, true) < 0 ? 1.0 : 0.0);
    setArena(at + kStraightOpenEnd + 1, neighbourAcross(l, false) < 0 ? 1.0 : 0.0);
    setArena(at + kStraightProfileFirst, float(used));
    int count = 0;
    vec2 prev = vec2(0.0);
    for (int k = 0; k < l.profileCount; ++k) {
      vec2 point = vec2(profileB(l, k), profileH(l, k));
      if (count > 0 && ((prev.y < 0.0 && point.y > 0.0) || (prev.y > 0.0 && point.y < 0.0))) {
        float t = prev.y / (prev.y - point.y);  // split at h = 0
        setArena2(kStraightProfiles + 2 * (used + count++), vec2(prev.x + t * (point.x - prev.x), 0.0));
      }
      setArena2(kStraightProfiles + 2 * (used + count++), point);
      prev = point;
    }
    setArena(at + kStraightProfileCount, float(count));
    used += count;
  }
}

// --- Height pieces (area_surface.cpp) -------------------------------------------------------------

// A plane h = p.x + p.y u + p.z v over the base plane.
float planeHeight(vec3 plane, vec2 x) { return plane.x + plane.y * x.x + plane.z * x.y; }
// The half-plane where plane a <= plane b.
vec3 whereLower(vec3 a, vec3 b) { return vec3(b.yz - a.yz, a.x - b.x); }

int gSurfaceCount;  // pieces
int gWallCount;
bool gAreaStopAtCap;  // stop building at the first overflow (the footprint will be split)

int pieceAt(int i) { return kPieces + i * kPieceSize; }
int pieceVertexCount(int i) { return int(arenaAt(pieceAt(i))); }
vec3 pieceVertex(int i, int k) { return arena3(pieceAt(i) + kPieceVertices + 3 * k); }
vec3 pieceNormal(int i) { return arena3(pieceAt(i) + kPieceNormal); }
float piecePlaneOffset(int i) { return arenaAt(pieceAt(i) + kPieceOffset); }
int pieceMaterial(int i) { return int(arenaAt(pieceAt(i) + kPieceMaterial)); }
float pieceFacingViewer(int i) { return arenaAt(pieceAt(i) + kPieceFacingViewer); }
float pieceFacingLight(int i) { return arenaAt(pieceAt(i) + kPieceFacingLight); }
vec4 pieceScreenBox(int i) { return arena4(pieceAt(i) + kPieceScreenBox); }
vec4 pieceLightBox(int i) { return arena4(pieceAt(i) + kPieceLightBox); }
int pieceScreen(int i) { return pieceAt(i) + kPieceScreen; }

// Cells: bank 0 and 1 take turns as the current and the next list.
int cellAt(int bank, int c) { return kCells + (bank * AREA_MAX_CELLS + c) * kCellSize; }
int layerAt(int cell, bool cuts) { return cell + kCellPlane + (cuts ? 0 : kCellRidge); }
vec3 cellPlane(int cell, bool cuts) { return arena3(layerAt(cell, cuts)); }
int cellOwner(int cell, bool cuts) { return int(arenaAt(layerAt(cell, cuts) + 3)); }
// Kept with the cell so that the loops that skip cells by their box need no loop inside (see
// visibleLitPart in area_sampling.glsl).
vec4 cellBox(int cell) { return arena4(cell + kCellBox); }
int gCellBank, gCellCount, gNextCount;

void copyCell(int to, int from) {
  copyPolygon(to, from);
  setArena4(layerAt(to, true), arena4(layerAt(from, true)));
  setArena4(layerAt(to, false), arena4(layerAt(from, false)));
  setArena4(to + kCellBox, cellBox(from));
}

bool isCutFacet(vec2 a, vec2 b) { return a.y <= 0.0 && b.y <= 0.0 && (a.y < 0.0 || b.y < 0.0); }
bool isRidgeFacet(vec2 a, vec2 b) { return a.y >= 0.0 && b.y >= 0.0 && (a.y > 0.0 || b.y > 0.0); }

vec3 facetPlane(int g, vec2 a, vec2 b) {
  float slope = (b.y - a.y) / (b.x - a.x);
  float footB = dot(straightBinormal(g), straightFoot(g));
  return vec3(a.y - slope * (footB + a.x), slope * straightBinormal(g));
}

// The strips of groove g's profile: a facet of the cut layer (kind 1) or of the ridge layer (kind 2)
// with its plane, or a run of facets that keep the cells' planes (kind 0, facets at h = 0).
int gStripCount;
int stripAt(int s) { return kStrips + s * kStripSize; }

float facetKind(vec2 a, vec2 b) { return isCutFacet(a, b) ? 1.0 : (isRidgeFacet(a, b) ? 2.0 : 0.0); }

void stripsOf(int g) {
  gStripCount = 0;
  int count = straightProfileCount(g);
  for (int k = 0; k + 1 < count; ++k) {
    vec2 a = straightPoint(g, k), b = straightPoint(g, k + 1);
    if (b.x <= a.x) continue;  // a vertical segment: its wall is built apart
    float kind = facetKind(a, b);
    if (kind == 0.0 && gStripCount > 0 && arenaAt(stripAt(gStripCount - 1) + 2) == 0.0) {
      setArena(stripAt(gStripCount - 1) + 1, b.x);  // runs that keep the cells' planes merge
      continue;
    }
    int s = stripAt(gStripCount++);
    setArena3(s, vec3(a.x, b.x, kind));
    setArena3(s + 3, kind != 0.0 ? facetPlane(g, a, b) : vec3(0.0));
  }
}

// Whether groove g changes the height anywhere (a facet off h = 0).
bool changesHeight(int g) {
  int count = straightProfileCount(g);
  for (int k = 0; k + 1 < count; ++k) {
    vec2 a = straightPoint(g, k), b = straightPoint(g, k + 1);
    if (b.x > a.x && facetKind(a, b) != 0.0) return true;
  }
  return false;
}

// Appends polygon p to the next list with the layers of cell `like`, the one of `cuts` set to plane
// and owner.
void pushCell(int p, int like, bool cuts, vec3 plane, int owner, float minArea) {
  if (negligible(p, minArea)) return;
  if (gNextCount == AREA_MAX_CELLS) {
    ++gAreaOverflows;
    return;
  }
  int cell = cellAt(1 - gCellBank, gNextCount++);
  copyPolygon(cell, p);
  setArena4(layerAt(cell, !cuts), arena4(layerAt(like, !cuts)));
  setArena4(layerAt(cell, cuts), vec4(plane, float(owner)));
  setArena4(cell + kCellBox, polygonBox(p));
}

// Appends polygon p to the next list with the layers of cell `like`.
void pushPartOf(int p, int like, float minArea) {
  pushCell(p, like, true, cellPlane(like, true), cellOwner(like, true), minArea);
}

// -1: outside some edge, 1: inside every edge, 0: across.
int sideOfEdges(int p, int edges, int edgeCount) {
  bool inside = true;
  for (int e = 0; e < edgeCount; ++e) {
    int side = sideOfPlane(p, edgeAt(edges, e));
    if (side < 0) return -1;
    inside = inside && side > 0;
  }
  return inside ? 1 : 0;
}

// The part `inside` of a cell (clipped to a strip) against the strip's plane: the lower (cuts) or
// higher (ridges) wins, the cell's own on a tie; where neither wins everywhere, split where they are
// equal (both halves pushed in one loop).
void resolveCell(int cell, int inside, vec3 stripPlane, int owner, bool cuts, float minArea) {
  vec3 plane = cellPlane(cell, cuts);
  float lowest = kInfinity, highest = -kInfinity;
  int n = vertexCount(inside);
  for (int i = 0; i < n; ++i) {
    vec2 x = vertexAt(inside, i);
    float d = planeHeight(plane, x) - planeHeight(stripPlane, x);
    lowest = min(lowest, d);
    highest = max(highest, d);
  }
  bool cellWins = cuts ? highest <= 0.0 : lowest >= 0.0;
  bool stripWins = cuts ? lowest >= 0.0 : highest <= 0.0;
  vec3 cellLower = whereLower(plane, stripPlane);
  for (int side = 0; side < 2; ++side) {
    bool cellHalf = side == 0;
    if (cellWins ? !cellHalf : (stripWins && cellHalf)) continue;  // the cell's own on a tie
    int part = inside;
    if (!cellWins && !stripWins) {
      clipInto(kSpare, inside, (cellHalf == cuts) ? cellLower : -cellLower);
      part = kSpare;
    }
    pushCell(part, cell, cuts, cellHalf ? plane : stripPlane, cellHalf ? cellOwner(cell, cuts) : owner, minArea);
  }
}

// Both layers into bank gCellBank: the region overlaid with every groove in turn.
void buildLayers(float minArea) {
  gCellBank = 0;
  gCellCount = 1;
  copyPolygon(cellAt(0, 0), kRegion);
  setArena4(layerAt(cellAt(0, 0), true), vec4(0.0, 0.0, 0.0, -1.0));
  setArena4(layerAt(cellAt(0, 0), false), vec4(0.0, 0.0, 0.0, -1.0));
  setArena4(cellAt(0, 0) + kCellBox, polygonBox(kRegion));
  for (int g = 0; g < gStraightCount; ++g) {
    if (gAreaStopAtCap && gAreaOverflows > 0) return;
    if (!changesHeight(g)) continue;
    vec3 lines[4] = vec3[4](straightJoint(g, 0), straightJoint(g, 1), atLeastB(g, straightFirstB(g)),
                            atMostB(g, straightLastB(g)));
    copyPolygon(kBand, kRegion);
    for (int k = 0; k < 4; ++k) clipInPlace(kBand, lines[k], kSpare);
    if (negligible(kBand, minArea)) continue;
    vec4 bandBox = polygonBox(kBand);
    // The band as the groove's own lines that cut the region (no edge along the region's border).
    int bandEdgeCount = 0;
    bool jointCuts[2] = bool[2](false, false);
    for (int k = 0; k < 4; ++k) {
      if (!cutsPolygon(lines[k], kRegion)) continue;
      setArena3(kEdgesBand + 3 * bandEdgeCount++, lines[k]);
      if (k < 2) jointCuts[k] = true;
    }
    stripsOf(g);
    gNextCount = 0;
    for (int c = 0; c < gCellCount; ++c) {
      // Cells away from the band's box are kept whole, in a loop that holds only their copy.
      for (; c < gCellCount && !boxesOverlap(cellBox(cellAt(gCellBank, c)), bandBox); ++c) {
        if (gNextCount == AREA_MAX_CELLS) ++gAreaOverflows;
        else copyCell(cellAt(1 - gCellBank, gNextCount++), cellAt(gCellBank, c));
      }
      if (c == gCellCount) break;
      int cell = cellAt(gCellBank, c);
      int side = sideOfEdges(cell, kEdgesBand, bandEdgeCount);
      int n = 0;
      if (side == 0) {
        n = subtractEdges(cell, kEdgesBand, bandEdgeCount, minArea, kSubtracted, kInBand, kSpare);
        if (negligible(kInBand, minArea)) side = -1;
      }
      if (side < 0) {  // the band misses the cell: kept whole
        if (gNextCount == AREA_MAX_CELLS) ++gAreaOverflows;
        else copyCell(cellAt(1 - gCellBank, gNextCount++), cell);
        continue;
      }
      for (int i = 0; i < n; ++i) pushPartOf(kSubtracted + AREA_POLY * i, cell, minArea);
      copyPolygon(kJointed, cell);
      for (int e = 0; e < 2; ++e)
        if (jointCuts[e]) clipInPlace(kJointed, straightJoint(g, e), kSpare);
      if (isEmpty(kJointed)) continue;
      float bLow = kInfinity, bHigh = -kInfinity;
      int count = vertexCount(kJointed);
      for (int i = 0; i < count; ++i) {
        float b = acrossGroove(g, vertexAt(kJointed, i));
        bLow = min(bLow, b);
        bHigh = max(bHigh, b);
      }
      float slack = 1e-5 * (abs(bLow) + abs(bHigh) + (bHigh - bLow));
      for (int s = 0; s < gStripCount; ++s) {
        vec3 strip = arena3(stripAt(s));
        if (strip.y < bLow - slack || strip.x > bHigh + slack) continue;
        copyPolygon(kInside, kJointed);
        for (int e = 0; e < 2; ++e) clipInPlace(kInside, e == 0 ? atLeastB(g, strip.x) : atMostB(g, strip.y), kSpare);
        if (isEmpty(kInside)) continue;
        if (strip.z == 0.0)
          pushPartOf(kInside, cell, minArea);
        else
          resolveCell(cell, kInside, arena3(stripAt(s) + 3), g, strip.z == 1.0, minArea);
      }
    }
    gCellBank = 1 - gCellBank;
    gCellCount = gNextCount;
  }
}

void emitPiece(int polygon, vec3 plane, int material) {
  if (gSurfaceCount == AREA_MAX_PIECES) {
    ++gAreaOverflows;
    return;
  }
  int piece = pieceAt(gSurfaceCount++);
  int n = vertexCount(polygon);
  setArena(piece, float(n));
  for (int i = 0; i < n; ++i) {
    vec2 x = vertexAt(polygon, i);
    setArena3(piece + kPieceVertices + 3 * i, vec3(x, planeHeight(plane, x)));
  }
  vec3 normal = normalize(vec3(-plane.y, -plane.z, 1.0));
  setArena3(piece + kPieceNormal, normal);
  setArena(piece + kPieceOffset, dot(normal, arena3(piece + kPieceVertices)));
  setArena(piece + kPieceMaterial, float(material));
}

int materialOfOwner(int owner) { return owner < 0 ? baseMaterial() : straightMaterial(owner); }

// A cell's two layers: the heights add; the material is the one of the larger |h| (the earlier
// primitive on a tie).
void emitCell(int cell, float minArea) {
  vec3 sum = cellPlane(cell, true) + cellPlane(cell, false);
  int cutOwner = cellOwner(cell, true), ridgeOwner = cellOwner(cell, false);
  if (cutOwner < 0 || ridgeOwner < 0) {
    emitPiece(cell, sum, materialOfOwner(cutOwner >= 0 ? cutOwner : ridgeOwner));
    return;
  }
  vec3 cutDeeper = whereLower(sum, vec3(0.0));  // |cut| >= ridge where the sum is <= 0
  bool cutFirst = cutOwner < ridgeOwner;
  clipInto(kFirst, cell, cutFirst ? cutDeeper : -cutDeeper);
  makeCounterClockwise(kFirst);
  int holeEdges = edgeHalfPlanes(kFirst, kEdgesOther);
  int n = subtractEdges(cell, kEdgesOther, holeEdges, minArea, kSubtracted, kInBand, kSpare);
  if (!negligible(kFirst, minArea))
    emitPiece(kFirst, sum, materialOfOwner(cutFirst ? cutOwner : ridgeOwner));
  for (int i = 0; i < n; ++i)
    emitPiece(kSubtracted + AREA_POLY * i, sum, materialOfOwner(cutFirst ? ridgeOwner : cutOwner));
}

// H over the region as pieces: the layers built, then every cell emitted.
void buildHeightPieces(float minArea) {
  buildLayers(minArea);
  if (gAreaStopAtCap && gAreaOverflows > 0) return;
  for (int c = 0; c < gCellCount; ++c) emitCell(cellAt(gCellBank, c), minArea);
}

// --- Walls (area_walls.cpp) -----------------------------------------------------------------------

// The height of straight groove g at x from the facet holding the nudged point `probe` (a side
// limit); .x is 1 when x lies in the region on a facet with h != 0.
vec2 straightHeightAt(int g, vec2 x, vec2 probe) {
  if (planeDistance(straightJoint(g, 0), probe) < 0.0 || planeDistance(straightJoint(g, 1), probe) < 0.0)
    return vec2(0.0);
  float bProbe = acrossGroove(g, probe);
  if (bProbe < straightFirstB(g) || bProbe > straightLastB(g)) return vec2(0.0);
  int count = straightProfileCount(g);
  for (int k = 0; k + 1 < count; ++k) {
    vec2 a = straightPoint(g, k), b = straightPoint(g, k + 1);
    if (b.x <= a.x || bProbe < a.x || bProbe > b.x) continue;
    float h = a.y + (b.y - a.y) * (acrossGroove(g, x) - a.x) / (b.x - a.x);
    return vec2(h != 0.0 ? 1.0 : 0.0, h);
  }
  return vec2(0.0);
}

// H and its material at x, the limit from the side `side`.
float surfaceLimit(vec2 x, vec2 side, float tolerance, out int material) {
  vec2 probe = x + tolerance * side;
  float deepest = 0.0, highest = 0.0;
  int cutOwner = -1, ridgeOwner = -1;
  for (int g = 0; g < gStraightCount; ++g) {
    vec2 h = straightHeightAt(g, x, probe);
    if (h.x == 0.0) continue;
    if (h.y < deepest) {
      deepest = h.y;
      cutOwner = g;
    }
    if (h.y > highest) {
      highest = h.y;
      ridgeOwner = g;
    }
  }
  int owner = cutOwner >= 0 ? cutOwner : ridgeOwner;
  if (cutOwner >= 0 && ridgeOwner >= 0) {
    float cut = -deepest, ridge = highest;
    owner = cut > ridge || (cut == ridge && cutOwner < ridgeOwner) ? cutOwner : ridgeOwner;
  }
  material = materialOfOwner(owner);
  return deepest + highest;
}

// A candidate line where H may jump: x(t) = origin + t direction for t in [t0, t1], sides +-normal.
struct WallLine {
  vec2 origin, direction, normal;
  float t0, t1;
};

vec2 wallPoint(WallLine line, float t) { return line.origin + t * line.direction; }

bool clipRange(inout WallLine line, vec3 h) {
  float d0 = planeDistance(h, line.origin);
  float rate = dot(h.xy, line.direction);
  if (abs(rate) < 1e-12) return d0 >= 0.0;
  float t = -d0 / rate;
  if (rate > 0.0) line.t0 = max(line.t0, t);
  else line.t1 = min(line.t1, t);
  return line.t1 > line.t0;
}

bool clipToRegion(inout WallLine line) {
  int n = vertexCount(kRegion);
  for (int i = 0; i < n; ++i)
    if (!clipRange(line, leftOf(vertexAt(kRegion, i), vertexAt(kRegion, i + 1 == n ? 0 : i + 1)))) return false;
  return true;
}

int gWallBreakCount;
float wallBreak(int i) { return arenaAt(kBreaks + i); }

void addWallBreak(float t) {
  if (gWallBreakCount == AREA_MAX_BREAKS) {
    ++gAreaOverflows;
    return;
  }
  setArena(kBreaks + gWallBreakCount++, t);
}

void sortWallBreaks() {
  for (int i = 1; i < gWallBreakCount; ++i) {
    float t = wallBreak(i);
    int j = i;
    for (; j > 0 && wallBreak(j - 1) > t; --j) setArena(kBreaks + j, wallBreak(j - 1));
    setArena(kBreaks + j, t);
  }
}

// A linear function of t, (value at 0, slope), from two samples.
vec2 linearThrough(float ta, float va, float tb, float vb) {
  float slope = (vb - va) / (tb - ta);
  return vec2(va - slope * ta, slope);
}
float linearAt(vec2 f, float t) { return f.x + f.y * t; }
bool linearCrossing(vec2 a, vec2 b, float lo, float hi, out float t) {
  float ds = a.y - b.y;
  t = 0.0;
  if (ds == 0.0) return false;
  t = (b.x - a.x) / ds;
  return t > lo && t < hi;
}

// Joint lines and profile-vertex lines of every groove (where H's pieces change), then, within each
// interval between them, where two grooves' side limits (or one and the slab's 0) cross: the min /
// max switches. One loop over (groove, line) serves both.
void wallBreaks(WallLine line, float nudge) {
  gWallBreakCount = 0;
  addWallBreak(line.t0);
  addWallBreak(line.t1);
  for (int g = 0; g < gStraightCount; ++g) {
    int count = straightProfileCount(g);
    for (int k = -2; k < count; ++k) {
      vec3 h = k < 0 ? straightJoint(g, k + 2) : atLeastB(g, straightPoint(g, k).x);
      float rate = dot(h.xy, line.direction);
      if (abs(rate) < 1e-12) continue;
      float t = -planeDistance(h, line.origin) / rate;
      if (t > line.t0 && t < line.t1) addWallBreak(t);
    }
  }
  sortWallBreaks();
  int structural = gWallBreakCount;
  for (int i = 0; i + 1 < structural; ++i) {
    float lo = wallBreak(i), hi = wallBreak(i + 1);
    if (hi - lo <= nudge) continue;
    float ta = lo + (hi - lo) / 3.0, tb = lo + 2.0 * (hi - lo) / 3.0;
    vec2 xa = wallPoint(line, ta), xb = wallPoint(line, tb);
    for (int side = -1; side <= 1; side += 2) {
      vec2 shift = float(side) * nudge * line.normal;
      for (int g = -1; g < gStraightCount; ++g) {  // -1: the slab's own 0
        vec2 ga = g < 0 ? vec2(1.0, 0.0) : straightHeightAt(g, xa, xa + shift);
        vec2 gb = g < 0 ? vec2(1.0, 0.0) : straightHeightAt(g, xb, xb + shift);
        if (ga.x == 0.0 && gb.x == 0.0) continue;
        for (int o = g + 1; o < gStraightCount; ++o) {
          vec2 oa = straightHeightAt(o, xa, xa + shift), ob = straightHeightAt(o, xb, xb + shift);
          if (oa.x == 0.0 && ob.x == 0.0) continue;
          if (g >= 0 && (ga.y + gb.y < 0.0) != (oa.y + ob.y < 0.0)) continue;  // a cut and a ridge
          float t;
          vec2 fg = g < 0 ? vec2(0.0) : linearThrough(ta, ga.y, tb, gb.y);
          if (linearCrossing(linearThrough(ta, oa.y, tb, ob.y), fg, lo, hi, t)) addWallBreak(t);
        }
      }
    }
  }
  sortWallBreaks();
}

void emitWall(WallLine line, float p0, float p1, vec2 low, vec2 high, vec2 facing, int material,
              float heightTolerance) {
  if (gSurfaceCount == AREA_MAX_PIECES) {
    ++gAreaOverflows;
    return;
  }
  vec2 a = wallPoint(line, p0), b = wallPoint(line, p1);
  vec3 corners[4] = vec3[4](vec3(a, linearAt(low, p0)), vec3(b, linearAt(low, p1)), vec3(b, linearAt(high, p1)),
                            vec3(a, linearAt(high, p0)));
  bool keep[4] = bool[4](true, true, linearAt(high, p1) - linearAt(low, p1) > heightTolerance,
                         linearAt(high, p0) - linearAt(low, p0) > heightTolerance);
  int piece = pieceAt(gSurfaceCount);
  int n = 0;
  for (int k = 0; k < 4; ++k)
    if (keep[k]) setArena3(piece + kPieceVertices + 3 * n++, corners[k]);
  if (n < 3) return;
  setArena(piece, float(n));
  setArena3(piece + kPieceNormal, vec3(facing, 0.0));
  setArena(piece + kPieceOffset, dot(facing, a));
  setArena(piece + kPieceMaterial, float(material));
  ++gSurfaceCount;
  ++gWallCount;
}

// The walls along one candidate line.
void wallsAlong(WallLine line, float lengthScale) {
  float nudge = 1e-5 * lengthScale, heightTolerance = 1e-6 * lengthScale;
  wallBreaks(line, nudge);
  for (int i = 0; i + 1 < gWallBreakCount; ++i) {
    float lo = wallBreak(i), hi = wallBreak(i + 1);
    if (hi - lo <= nudge) continue;
    float ta = lo + (hi - lo) / 3.0, tb = lo + 2.0 * (hi - lo) / 3.0;
    // The limits of H on the + side (above) and the - side (below), linear over the interval.
    float limits[4];
    int materials[4];
    for (int k = 0; k < 4; ++k)
      limits[k] = surfaceLimit(wallPoint(line, k % 2 == 0 ? ta : tb), k < 2 ? line.normal : -line.normal, nudge,
                               materials[k]);
    vec2 above = linearThrough(ta, limits[0], tb, limits[1]);
    vec2 below = linearThrough(ta, limits[2], tb, limits[3]);
    // Split where the two limits cross (the wall changes side) or where |H+| = |H-| (its material changes).
    vec2 difference = above - below, sum = above + below;
    float cuts[4] = float[4](lo, hi, hi, hi);
    int cutCount = 2;
    float t;
    if (linearCrossing(difference, vec2(0.0), lo, hi, t)) cuts[cutCount++] = t;
    if (linearCrossing(sum, vec2(0.0), lo, hi, t)) cuts[cutCount++] = t;
    if (cutCount == 4 && cuts[3] < cuts[2]) cuts = float[4](cuts[0], cuts[1], cuts[3], cuts[2]);
    float sorted[4] = float[4](lo, cutCount > 2 ? cuts[2] : hi, cutCount > 3 ? cuts[3] : hi, hi);
    for (int k = 0; k + 1 < cutCount; ++k) {
      float p0 = sorted[k], p1 = sorted[k + 1], mid = 0.5 * (p0 + p1);
      if (p1 - p0 <= nudge) continue;
      if (max(abs(linearAt(difference, p0)), abs(linearAt(difference, p1))) <= heightTolerance) continue;
      bool plusHigher = linearAt(difference, mid) > 0.0;
      vec2 x = wallPoint(line, mid);
      int plusMaterial, minusMaterial;
      float onPlus = surfaceLimit(x, line.normal, nudge, plusMaterial);
      float onMinus = surfaceLimit(x, -line.normal, nudge, minusMaterial);
      int material = abs(onPlus) >= abs(onMinus) ? plusMaterial : minusMaterial;
      emitWall(line, p0, p1, plusHigher ? below : above, plusHigher ? above : below,
               plusHigher ? -line.normal : line.normal, material, heightTolerance);
    }
  }
}

// Candidate lines: each open-end cut across its band, and each vertical profile segment along its
// primitive between the joints; one loop over (groove, line).
void buildWalls(float lengthScale) {
  for (int g = 0; g < gStraightCount; ++g) {
    int count = straightProfileCount(g);
    for (int k = -2; k + 1 < count; ++k) {
      if (gAreaStopAtCap && gAreaOverflows > 0) return;
      WallLine line;
      if (k < 0) {
        int e = k + 2;
        if (!straightOpenEnd(g, e)) continue;
        vec2 n = straightJoint(g, e).xy;
        line = WallLine(straightJointPoint(g, e), vec2(-n.y, n.x), n, -kInfinity, kInfinity);
        if (!clipRange(line, atLeastB(g, straightFirstB(g))) || !clipRange(line, atMostB(g, straightLastB(g))))
          continue;
      } else {
        if (straightPoint(g, k + 1).x != straightPoint(g, k).x) continue;
        float b = straightPoint(g, k).x;
        line = WallLine(straightFoot(g) + b * straightBinormal(g), straightTangent(g), straightBinormal(g),
                        -kInfinity, kInfinity);
        if (!clipRange(line, straightJoint(g, 0)) || !clipRange(line, straightJoint(g, 1))) continue;
      }
      if (!clipToRegion(line)) continue;
      wallsAlong(line, lengthScale);
    }
  }
}

#endif
