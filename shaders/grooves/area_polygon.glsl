// Convex polygons for the area sampling of seed 000 §6, as libbake/grooves/oracle/polygon.cpp: clipping by a
// half-plane (Sutherland-Hodgman on one edge), convex-convex intersection, and convex minus convex as
// disjoint convex pieces (the part outside each edge of the hole in turn). A half-plane is
// vec3(normal, offset): normal . x >= offset.
//
// Storage: every polygon, cell and piece of one area sample lives in a per-invocation slot of a
// storage buffer (the arena) and is named by its offset there. Large private arrays would do, but
// some drivers (Mesa's llvmpipe among them) compile every dynamic index into one as code proportional
// to the array's size, and unroll the loops over small ones: minutes per shader. A slot is taken by a
// compare-and-swap on its flag, trying the next ones when taken (no invocation ever waits for
// another), and freed after the sample; when every slot tried is taken, the footprint is line
// sampled instead and gAreaNoSlot says so. The slots' size is this variant's own, so the renderer
// binds an arena per slot layout: slots of two sizes cut from one arena would overlap.
// Tolerances are the CPU's scaled to fp32 rounding: edges shorter than 1e-4 of a polygon's size have
// no reliable direction here (1e-12 there), vertices within 1e-6 of their magnitude are one, and
// slivers count as empty (negligible() below).
#ifndef BAKE_GROOVES_AREA_POLYGON_GLSL
#define BAKE_GROOVES_AREA_POLYGON_GLSL

#ifndef AREA_MAX_VERTICES
#define AREA_MAX_VERTICES 16
#endif
#ifndef AREA_MAX_FRAGMENTS
#define AREA_MAX_FRAGMENTS 16
#endif
#ifndef AREA_SLOTS
#error "AREA_SLOTS comes from the renderer (runtime/render/grooves.cpp kAreaSlots)"
#endif
#define AREA_POLY (1 + 2 * AREA_MAX_VERTICES)  // count, then the vertices
#define AREA_EDGES (3 * AREA_MAX_VERTICES)     // the half-planes of a polygon's edges

layout(std430, binding = 12) coherent buffer AreaScratch {
  uint areaBusy[AREA_SLOTS];
  // Fragments of the frame over special cases: sampled by area, line sampled for want of a free slot,
  // line sampled because a driver's loop cap cut the area sample short, and cut short in the first
  // pass and shaded again in a retry pass (area_retry.glsl; counted again there). The renderer zeroes
  // them before each frame and reports them.
  uint areaCounts[4];
  float areaArena[];
};

const float kShortEdge = 1e-4;
const float kSameVertex = 1e-6;

int gSlotBase;
int gSlot;
bool gAreaNoSlot;    // no free slot: the footprint was line sampled
int gAreaOverflows;  // cells, pieces, breaks, fragments or vertices dropped for lack of room

float arenaAt(int i) { return areaArena[gSlotBase + i]; }
void setArena(int i, float x) { areaArena[gSlotBase + i] = x; }
vec2 arena2(int i) { return vec2(arenaAt(i), arenaAt(i + 1)); }
void setArena2(int i, vec2 x) {
  setArena(i, x.x);
  setArena(i + 1, x.y);
}
vec3 arena3(int i) { return vec3(arenaAt(i), arenaAt(i + 1), arenaAt(i + 2)); }
void setArena3(int i, vec3 x) {
  setArena(i, x.x);
  setArena(i + 1, x.y);
  setArena(i + 2, x.z);
}
vec4 arena4(int i) { return vec4(arenaAt(i), arenaAt(i + 1), arenaAt(i + 2), arenaAt(i + 3)); }
void setArena4(int i, vec4 x) {
  setArena2(i, x.xy);
  setArena2(i + 2, x.zw);
}

// A slot of `size` floats for this invocation; false when none was free among those tried.
bool acquireSlot(int size) {
  int slots = min(AREA_SLOTS, areaArena.length() / max(size, 1));
  int start = slots > 0 ? int(uint(gl_FragCoord.y) * 977u + uint(gl_FragCoord.x)) % slots : 0;
  bool found = false;
  for (int k = 0; k < slots && !found; ++k) {
    int s = (start + k) % slots;
    found = atomicCompSwap(areaBusy[s], 0u, 1u) == 0u;
    gSlot = s;
  }
  gSlotBase = gSlot * size;
  return found;
}

void releaseSlot() {
  memoryBarrierBuffer();
  atomicExchange(areaBusy[gSlot], 0u);
}

// --- Polygons: offsets into the slot ------------------------------------------------------------

float planeDistance(vec3 h, vec2 x) { return dot(h.xy, x) - h.z; }

// The half-plane left of the directed line a -> b (inside of a counter-clockwise polygon's edge).
vec3 leftOf(vec2 a, vec2 b) {
  vec2 n = vec2(-(b.y - a.y), b.x - a.x);
  return vec3(n, dot(n, a));
}

int vertexCount(int p) { return int(arenaAt(p)); }
void setVertexCount(int p, int n) { setArena(p, float(n)); }
vec2 vertexAt(int p, int k) { return arena2(p + 1 + 2 * k); }
void setVertex(int p, int k, vec2 x) { setArena2(p + 1 + 2 * k, x); }
bool isEmpty(int p) { return vertexCount(p) < 3; }

void addVertex(int p, vec2 x) {
  int n = vertexCount(p);
  if (n == AREA_MAX_VERTICES) {
    ++gAreaOverflows;
    return;
  }
  setVertex(p, n, x);
  setVertexCount(p, n + 1);
}

// Within rounding of each other (fp32: a crossing computed from two edges that rounds next to an
// end): their edge would have no reliable direction.
bool sameVertex(vec2 a, vec2 b) { return all(lessThanEqual(abs(a - b), kSameVertex * (abs(a) + abs(b)))); }

// Consecutive equal vertices are kept once.
void addDistinct(int p, vec2 x) {
  int n = vertexCount(p);
  if (n > 0 && sameVertex(vertexAt(p, n - 1), x)) return;
  addVertex(p, x);
}

void copyPolygon(int to, int from) {
  int n = vertexCount(from);
  for (int k = 0; k < n; ++k) setVertex(to, k, vertexAt(from, k));
  setVertexCount(to, n);
}

float signedArea(int p) {
  int n = vertexCount(p);
  if (n < 3) return 0.0;
  vec2 o = vertexAt(p, 0);  // relative to the first vertex: far-off polygons keep their precision
  float twice = 0.0;
  vec2 a = vertexAt(p, 1) - o;
  for (int i = 1; i + 1 < n; ++i) {
    vec2 b = vertexAt(p, i + 1) - o;
    twice += a.x * b.y - a.y * b.x;
    a = b;
  }
  return 0.5 * twice;
}

float polygonArea(int p) { return abs(signedArea(p)); }

vec2 polygonCentroid(int p) {
  int n = vertexCount(p);
  if (n == 0) return vec2(0.0);
  vec2 o = vertexAt(p, 0);
  float twice = 0.0;
  vec2 c = vec2(0.0);
  for (int i = 1; i + 1 < n; ++i) {
    vec2 a = vertexAt(p, i) - o, b = vertexAt(p, i + 1) - o;
    float cross = a.x * b.y - a.y * b.x;
    twice += cross;
    c += cross * (a + b);
  }
  if (twice == 0.0) {  // degenerate: the vertex mean
    vec2 s = vec2(0.0);
    for (int i = 0; i < n; ++i) s += vertexAt(p, i);
    return s / float(n);
  }
  return o + c / (3.0 * twice);
}

void makeCounterClockwise(int p) {
  if (signedArea(p) >= 0.0) return;
  for (int i = 0, j = vertexCount(p) - 1; i < j; ++i, --j) {
    vec2 t = vertexAt(p, i);
    setVertex(p, i, vertexAt(p, j));
    setVertex(p, j, t);
  }
}

// (lower, upper) as vec4; an empty polygon gives an inverted box that overlaps nothing.
vec4 polygonBox(int p) {
  vec4 b = vec4(vec2(kInfinity), vec2(-kInfinity));
  int n = vertexCount(p);
  for (int i = 0; i < n; ++i) {
    vec2 x = vertexAt(p, i);
    b = vec4(min(b.xy, x), max(b.zw, x));
  }
  return b;
}

bool boxesOverlap(vec4 a, vec4 b) { return all(lessThanEqual(a.xy, b.zw)) && all(lessThanEqual(b.xy, a.zw)); }
vec4 boxUnion(vec4 a, vec4 b) { return vec4(min(a.xy, b.xy), max(a.zw, b.zw)); }

// fp32 clipping leaves slivers where a clip line passes within rounding of a vertex (width ~1e-7 of
// their length; double precision leaves none): kept, their nearly collinear edges can come out in
// the wrong order and, subtracted as a hole, remove what lies outside them. So a polygon whose area
// is below kSliver of its box's squared diagonal counts as empty, like one below minArea (its area is
// at most kSliver of that box: below rounding of the result).
const float kSliver = 1e-5;
// Area and box in one loop, as signedArea and polygonBox compute them.
bool negligible(int p, float minArea) {
  int n = vertexCount(p);
  if (n < 3) return true;
  vec2 o = vertexAt(p, 0);
  vec4 box = vec4(o, o);
  float twice = 0.0;
  vec2 a = vertexAt(p, 1) - o;
  for (int i = 1; i < n; ++i) {
    vec2 x = vertexAt(p, i);
    box = vec4(min(box.xy, x), max(box.zw, x));
    if (i + 1 < n) {
      vec2 b = vertexAt(p, i + 1) - o;
      twice += a.x * b.y - a.y * b.x;
      a = b;
    }
  }
  float area = abs(0.5 * twice);
  vec2 size = box.zw - box.xy;
  return area <= minArea || area <= kSliver * dot(size, size);
}

// Ends a clipped polygon: a last vertex equal to the first is dropped, fewer than 3 leave it empty.
void closeClipped(int p) {
  int m = vertexCount(p);
  if (m > 1 && sameVertex(vertexAt(p, 0), vertexAt(p, m - 1))) setVertexCount(p, --m);
  if (m < 3) setVertexCount(p, 0);
}

// One Sutherland-Hodgman pass over `from` against h: the part inside into `inside`, and unless
// `outside` is negative the part outside into `outside` (neither the same as `from`). Returns where
// `from` lies, found in the same loop: 1 wholly inside, -1 wholly outside, 0 across, 2 on the line
// (each side includes the boundary). A polygon wholly on one side is kept as it is, as on the CPU:
// the pass's output is then not used. The side and both parts in one loop: loop iterations are what
// some drivers cap (see visibleLitPart in area_sampling.glsl).
int clipPass(int from, vec3 h, int inside, int outside) {
  setVertexCount(inside, 0);
  if (outside >= 0) setVertexCount(outside, 0);
  int n = vertexCount(from);
  bool allInside = true, allOutside = true;
  vec2 first = vertexAt(from, 0);
  float firstDistance = planeDistance(h, first);
  vec2 a = first;
  float da = firstDistance;
  for (int i = 0; i < n; ++i) {
    bool closing = i + 1 == n;
    vec2 b = closing ? first : vertexAt(from, i + 1);
    float db = closing ? firstDistance : planeDistance(h, b);
    allInside = allInside && da >= 0.0;
    allOutside = allOutside && da <= 0.0;
    if (da >= 0.0) addDistinct(inside, a);
    if (outside >= 0 && da <= 0.0) addDistinct(outside, a);
    if ((da > 0.0 && db < 0.0) || (da < 0.0 && db > 0.0)) {
      vec2 crossing = a + (da / (da - db)) * (b - a);  // the same point for either side
      addDistinct(inside, crossing);
      if (outside >= 0) addDistinct(outside, crossing);
    }
    a = b;
    da = db;
  }
  closeClipped(inside);
  if (outside >= 0) closeClipped(outside);
  return allInside ? (allOutside ? 2 : 1) : (allOutside ? -1 : 0);
}

// 1: p inside h (boundary included), -1: outside, 0: crossed.
int sideOfPlane(int p, vec3 h) {
  bool allInside = true, allOutside = true;
  int n = vertexCount(p);
  for (int i = 0; i < n; ++i) {
    float d = planeDistance(h, vertexAt(p, i));
    allInside = allInside && d >= 0.0;
    allOutside = allOutside && d <= 0.0;
  }
  return allInside ? 1 : (allOutside ? -1 : 0);
}

// to = from clipped by h (to != from).
void clipInto(int to, int from, vec3 h) {
  int side = clipPass(from, h, to, -1);
  if (side > 0) copyPolygon(to, from);
  else if (side < 0) setVertexCount(to, 0);
}

// p = p clipped by h, through the scratch polygon `spare`.
void clipInPlace(int p, vec3 h, int spare) {
  int side = clipPass(p, h, spare, -1);
  if (side < 0) setVertexCount(p, 0);
  else if (side == 0) copyPolygon(p, spare);
}

bool cutsPolygon(vec3 h, int p) { return sideOfPlane(p, h) <= 0 && vertexCount(p) > 0; }

// The half-planes of a counter-clockwise polygon's edges into `edges`, edges too short for a
// direction left out; returns their number.
int edgeHalfPlanes(int p, int edges) {
  vec4 b = polygonBox(p);
  float shortest = kShortEdge * max(b.z - b.x, b.w - b.y);
  int n = 0, count = vertexCount(p);
  for (int i = 0; i < count; ++i) {
    vec2 a = vertexAt(p, i), c = vertexAt(p, i + 1 == count ? 0 : i + 1);
    if (max(abs(c.x - a.x), abs(c.y - a.y)) <= shortest) continue;
    setArena3(edges + 3 * n++, leftOf(a, c));
  }
  return n;
}

vec3 edgeAt(int edges, int k) { return arena3(edges + 3 * k); }

// to = from clipped by every half-plane of `edges`.
void intersectEdgesInto(int to, int from, int edges, int n, int spare) {
  copyPolygon(to, from);
  for (int i = 0; i < n && !isEmpty(to); ++i) clipInPlace(to, edgeAt(edges, i), spare);
  if (isEmpty(to)) setVertexCount(to, 0);
}

// p minus the hole given by its edges: the pieces outside it go to the polygons at `pieces`
// (returns their number; an empty hole leaves p whole), what is left of p inside it to `rest`.
int subtractEdges(int p, int edges, int count, float minArea, int pieces, int rest, int spare) {
  int n = 0;
  if (count == 0) {
    if (!negligible(p, minArea)) copyPolygon(pieces + AREA_POLY * n++, p);
    setVertexCount(rest, 0);
    return n;
  }
  copyPolygon(rest, p);
  for (int i = 0; i < count && !isEmpty(rest); ++i) {
    // rest's parts outside and inside edge i, in one pass (as clipInto by -edge, then clipInPlace).
    int piece = pieces + AREA_POLY * n;
    int side = clipPass(rest, edgeAt(edges, i), spare, piece);
    if (side == -1 || side == 2) copyPolygon(piece, rest);
    else if (side == 1) setVertexCount(piece, 0);
    if (!negligible(piece, minArea)) ++n;
    if (side == -1) setVertexCount(rest, 0);
    else if (side == 0) copyPolygon(rest, spare);
  }
  if (isEmpty(rest)) setVertexCount(rest, 0);
  return n;
}

#endif
