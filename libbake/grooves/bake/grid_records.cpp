// Special-case records (seed 000 §4.2, Figure 5): the places where a footprint cannot be shaded from
// one cross-section and needs area sampling (§6).
//
// - End: every open end; the box is the end point ± wmax, which holds the flat cut and its walls.
// - Corner: every joint flagged cornerAtStart (never the G1 joints of a flattened curve); the box is
//   the joint point ± the mitre's reach, wmax / cos(turn / 2) (twice that when an arc is involved,
//   see grid_region.cpp), capped for near-reversals.
// - Intersection: every pair of primitives whose region polygons overlap, of different grooves or
//   non-adjacent in one groove, unless they are parallel (straight bands within kParallelSine, or
//   concentric arcs: those share one cross-section plane and are shaded as one combined section).
//   Pieces of one groove joined by G1 joints over less than a quarter turn are not paired either:
//   their regions meet only where the curve's normals cross, at the centre of curvature, which the
//   radius check keeps at the band's edge. Candidate pairs come from shared cells (each primitive
//   pairs with the later primitives of its cells), never from all pairs. The point is where the paths
//   cross inside the overlap, else the overlap's centre (the nearest approach); the box is the
//   bounding box of the two region polygons' intersection (exact for segments, conservative for arcs;
//   arcs whose annuli cannot meet are never paired).
// In a repeating scene the second primitive is moved by whole domain periods next to the first.
// Primitives are visited in the order of their first cell's row (neighbouring cell lists stay in
// cache) in parallel blocks, and their records gathered in primitive order: the same bytes for any
// thread count.
#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "grooves/bake/grid_stages.h"

namespace bake::grooves::grid_detail {
namespace {

constexpr double kParallelSine = 1e-3;      // |sin| of the crossing angle below which bands are parallel
constexpr double kConcentric = 1e-9;        // centre distance, relative to the radii, of concentric arcs
constexpr double kMinOverlap = 1e-5;        // overlap area, relative to wmax^2, that counts as overlap
constexpr double kQuarterTurn = 1.5707963267948966;
constexpr std::size_t kBlock = 256;

double grooveWidth(const GrooveScene& scene, std::size_t primitive) {
  return scene.grooves[scene.primitives[primitive].groove].wmax;
}

SpecialRecord boxRecord(SpecialRecord::Kind kind, Vec2 point, double reach, std::uint32_t first, std::uint32_t second) {
  SpecialRecord record;
  record.kind = kind;
  record.point = point;
  record.lower = {point.u - reach, point.v - reach};
  record.upper = {point.u + reach, point.v + reach};
  record.primitive[0] = first;
  record.primitive[1] = second;
  return record;
}

SpecialRecord endRecord(const GrooveScene& scene, std::size_t index, bool atStart) {
  const Primitive& p = scene.primitives[index];
  const double reach = grooveWidth(scene, index) * (1 + 1e-7);
  const auto i = static_cast<std::uint32_t>(index);
  return boxRecord(SpecialRecord::Kind::End, atStart ? p.a : p.b, reach, i, i);
}

std::size_t previousInGroove(const GrooveScene& scene, std::size_t index) {
  const Groove& g = scene.grooves[scene.primitives[index].groove];
  return index > g.firstPrimitive ? index - 1 : g.firstPrimitive + g.primitiveCount - 1;
}

SpecialRecord cornerRecord(const GrooveScene& scene, std::size_t index, double cap) {
  const Primitive& p = scene.primitives[index];
  const std::size_t before = previousInGroove(scene, index);
  const JointLine joint = jointsOf(scene, index).start;
  const double halfTurnCos = std::abs(dot(joint.normal, p.tangentAt(0)));
  const bool arc = p.kind == Primitive::Kind::Arc || scene.primitives[before].kind == Primitive::Kind::Arc;
  const double w = grooveWidth(scene, index) * (arc ? 2 : 1);
  const double reach = std::min(w / std::max(halfTurnCos, 1e-12), cap) * (1 + 1e-7);
  return boxRecord(SpecialRecord::Kind::Corner, p.a, reach, static_cast<std::uint32_t>(before),
                   static_cast<std::uint32_t>(index));
}

double turnOf(const Primitive& p) { return p.kind == Primitive::Kind::Arc ? std::abs(p.sweep) : 0.0; }

// Walks from `from` forward (wrapping in a closed groove) to `to` over G1 joints; true when it gets
// there turning less than a quarter turn in between.
bool smoothWalk(const GrooveScene& scene, const Groove& g, std::size_t from, std::size_t to) {
  const std::size_t first = g.firstPrimitive, last = first + g.primitiveCount - 1;
  double turn = 0;
  std::size_t k = from;
  while (k != to) {
    const std::size_t next = k == last ? first : k + 1;
    if ((k == last && !g.closed) || scene.primitives[next].cornerAtStart) return false;
    if (next != to) turn += turnOf(scene.primitives[next]);
    if (turn >= kQuarterTurn) return false;
    k = next;
  }
  return true;
}

// Pieces of one groove that meet at a joint, or along a gently turning G1 chain, do not cross.
bool sameGrooveNeighbours(const GrooveScene& scene, std::size_t i, std::size_t j) {
  const Primitive& a = scene.primitives[i];
  if (a.groove != scene.primitives[j].groove) return false;
  const Groove& g = scene.grooves[a.groove];
  const std::size_t first = g.firstPrimitive, last = first + g.primitiveCount - 1;
  if (j == i + 1 || (g.closed && i == first && j == last)) return true;
  return smoothWalk(scene, g, i, j) || (g.closed && smoothWalk(scene, g, j, i));
}

bool parallel(const Primitive& a, const Primitive& b) {
  if (a.kind == Primitive::Kind::Segment && b.kind == Primitive::Kind::Segment) {
    // |sin| of the angle between the directions, without square roots.
    const Vec2 da = sub(a.b, a.a), db = sub(b.b, b.a);
    const double c = cross(da, db);
    return c * c <= kParallelSine * kParallelSine * dot(da, da) * dot(db, db);
  }
  if (a.kind == Primitive::Kind::Arc && b.kind == Primitive::Kind::Arc) {
    const Vec2 d = sub(a.centre, b.centre);
    const double limit = kConcentric * (a.radius + b.radius);
    return dot(d, d) <= limit * limit;
  }
  return false;
}

// Where the lines or circles carrying two primitives cross (`shift` moves the second).
std::vector<Vec2> pathCrossings(const Primitive& a, const Primitive& b, Vec2 shift) {
  std::vector<Vec2> points;
  auto lineLine = [&](Vec2 p, Vec2 t, Vec2 q, Vec2 s) {
    const double d = cross(t, s);
    if (std::abs(d) > 1e-15) points.push_back(add(p, scaled(cross(sub(q, p), s) / d, t)));
  };
  auto lineCircle = [&](Vec2 p, Vec2 t, Vec2 c, double r) {
    const Vec2 f = sub(p, c);
    const double half = dot(f, t), disc = half * half - (dot(f, f) - r * r);
    if (disc < 0) return;
    for (const double sign : {-1.0, 1.0}) points.push_back(add(p, scaled(-half + sign * std::sqrt(disc), t)));
  };
  auto circleCircle = [&](Vec2 c0, double r0, Vec2 c1, double r1) {
    const Vec2 d = sub(c1, c0);
    const double dist = std::hypot(d.u, d.v);
    if (dist == 0 || dist > r0 + r1 || dist < std::abs(r0 - r1)) return;
    const double along = (dist * dist + r0 * r0 - r1 * r1) / (2 * dist), across = std::sqrt(std::max(0.0, r0 * r0 - along * along));
    const Vec2 e = scaled(1 / dist, d), mid = add(c0, scaled(along, e));
    for (const double sign : {-1.0, 1.0}) points.push_back(add(mid, scaled(sign * across, leftNormal(e))));
  };
  const bool aLine = a.kind == Primitive::Kind::Segment, bLine = b.kind == Primitive::Kind::Segment;
  const Vec2 bStart = add(b.a, shift), bCentre = add(b.centre, shift);
  if (aLine && bLine) lineLine(a.a, a.tangentAt(0), bStart, b.tangentAt(0));
  if (aLine && !bLine) lineCircle(a.a, a.tangentAt(0), bCentre, b.radius);
  if (!aLine && bLine) lineCircle(bStart, b.tangentAt(0), a.centre, a.radius);
  if (!aLine && !bLine) circleCircle(a.centre, a.radius, bCentre, b.radius);
  return points;
}

// The crossing point nearest the overlap's centre among those inside it, else that centre.
Vec2 crossingPoint(const Primitive& a, const Primitive& b, Vec2 shift, const Overlap& overlap) {
  const Vec2 centre = overlap.centre();
  Vec2 best = centre;
  double bestDistance = INFINITY;
  for (const Vec2& x : pathCrossings(a, b, shift)) {
    const Vec2 d = sub(x, centre);
    if (dot(d, d) < bestDistance && overlap.contains(x)) {
      best = x;
      bestDistance = dot(d, d);
    }
  }
  return best;
}

// The domain period nearest to moving the second box next to the first (none without wrap).
Vec2 nearestPeriod(const Lattice& lattice, const Polygon& a, const Polygon& b) {
  if (!lattice.wrap) return {0, 0};
  const double U = lattice.domain.u, V = lattice.domain.v;
  return {U * std::round(((a.lower.u + a.upper.u) - (b.lower.u + b.upper.u)) / (2 * U)),
          V * std::round(((a.lower.v + a.upper.v) - (b.lower.v + b.upper.v)) / (2 * V))};
}

bool boxesMeet(const Polygon& a, const Polygon& b, Vec2 shift) {
  return a.lower.u <= b.upper.u + shift.u && b.lower.u + shift.u <= a.upper.u && a.lower.v <= b.upper.v + shift.v &&
         b.lower.v + shift.v <= a.upper.v;
}

// An arc's region lies in its annulus |distance to the centre - radius| <= wmax. Two annuli that
// cannot meet rule out an overlap that the arcs' hull polygons (wider than the band by the chord's
// bulge) would report: adjacent turns of a record's spiral are the common case.
bool annuliApart(const GrooveScene& scene, std::size_t i, std::size_t j, Vec2 shift) {
  const Primitive& a = scene.primitives[i];
  const Primitive& b = scene.primitives[j];
  if (a.kind != Primitive::Kind::Arc || b.kind != Primitive::Kind::Arc) return false;
  const double reach = grooveWidth(scene, i) + grooveWidth(scene, j);
  const Vec2 d = sub(add(b.centre, shift), a.centre);
  const double distance = std::sqrt(dot(d, d));
  return std::abs(a.radius - b.radius) - distance > reach || distance - (a.radius + b.radius) > reach;
}

void addIntersection(const RecordInputs& in, std::size_t i, std::size_t j, Vec2 shift, Overlap& overlap,
                     std::vector<SpecialRecord>& out) {
  const GrooveScene& scene = *in.scene;
  const Polygon& regionA = (*in.regions)[i];
  const Polygon& regionB = (*in.regions)[j];
  if (!boxesMeet(regionA, regionB, shift) || annuliApart(scene, i, j, shift)) return;
  intersect(regionA, regionB, shift, overlap);
  const double w = std::min(grooveWidth(scene, i), grooveWidth(scene, j));
  if (overlap.count < 3 || std::abs(overlap.area()) <= kMinOverlap * w * w) return;
  SpecialRecord record;
  record.kind = SpecialRecord::Kind::Intersection;
  record.point = crossingPoint(scene.primitives[i], scene.primitives[j], shift, overlap);
  record.lower = overlap.lower;
  record.upper = overlap.upper;
  record.primitive[0] = static_cast<std::uint32_t>(i);
  record.primitive[1] = static_cast<std::uint32_t>(j);
  out.push_back(record);
}

// In a repeating scene the second primitive is tried at the nearest period and its eight neighbours.
void addIntersections(const RecordInputs& in, std::size_t i, std::size_t j, Overlap& overlap,
                      std::vector<SpecialRecord>& out) {
  const GrooveScene& scene = *in.scene;
  if (!in.lattice->wrap && !(*in.boxes)[i].meets((*in.boxes)[j])) return;
  if (sameGrooveNeighbours(scene, i, j) || parallel(scene.primitives[i], scene.primitives[j])) return;
  const Vec2 nearest = nearestPeriod(*in.lattice, (*in.regions)[i], (*in.regions)[j]);
  if (!in.lattice->wrap) return addIntersection(in, i, j, nearest, overlap, out);
  for (int dv = -1; dv <= 1; ++dv)
    for (int du = -1; du <= 1; ++du)
      addIntersection(in, i, j, add(nearest, {du * in.lattice->domain.u, dv * in.lattice->domain.v}), overlap, out);
}

// The later primitives sharing a cell with primitive i, ascending, each once.
void laterNeighbours(const RecordInputs& in, std::size_t i, std::vector<std::uint32_t>& out) {
  out.clear();
  const auto& cellStart = *in.cellStart;
  const auto& refs = *in.primitiveRefs;
  for (std::uint32_t k = (*in.primitiveCellStart)[i]; k < (*in.primitiveCellStart)[i + 1]; ++k) {
    const std::uint32_t cell = (*in.primitiveCells)[k];
    // Cells hold a few references: a branch-free filter beats a binary search that mispredicts.
    const std::uint32_t* ref = refs.data() + cellStart[cell];
    const std::uint32_t n = cellStart[cell + 1] - cellStart[cell];
    std::size_t at = out.size();
    out.resize(at + n);
    for (std::uint32_t k = 0; k < n; ++k) {
      out[at] = ref[k];
      at += ref[k] > i ? 1 : 0;
    }
    out.resize(at);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

void recordsOfPrimitive(const RecordInputs& in, std::size_t i, std::vector<std::uint32_t>& scratch, Overlap& overlap,
                        std::vector<SpecialRecord>& out) {
  const GrooveScene& scene = *in.scene;
  const Primitive& p = scene.primitives[i];
  if (p.endAtStart) out.push_back(endRecord(scene, i, true));
  if (p.cornerAtStart) out.push_back(cornerRecord(scene, i, in.cap));
  laterNeighbours(in, i, scratch);
  for (const std::uint32_t j : scratch) addIntersections(in, i, j, overlap, out);
  if (p.endAtEnd) out.push_back(endRecord(scene, i, false));
}

// Primitives in the order of the row of their first cell (a counting sort, stable by index), so that
// consecutive work reads neighbouring cells: the cell lists are then mostly read from cache.
std::vector<std::uint32_t> spatialOrder(const RecordInputs& in, std::size_t count) {
  const std::uint32_t columns = in.lattice->cells[0], rows = in.lattice->cells[1];
  const auto& start = *in.primitiveCellStart;
  auto firstRow = [&](std::size_t i) { return start[i] < start[i + 1] ? (*in.primitiveCells)[start[i]] / columns : rows; };
  std::vector<std::uint32_t> bucketStart(std::size_t(rows) + 2, 0);
  for (std::size_t i = 0; i < count; ++i) ++bucketStart[firstRow(i) + 1];
  for (std::size_t r = 0; r <= rows; ++r) bucketStart[r + 1] += bucketStart[r];
  std::vector<std::uint32_t> order(count);
  for (std::size_t i = 0; i < count; ++i) order[bucketStart[firstRow(i)]++] = static_cast<std::uint32_t>(i);
  return order;
}

struct Slot {
  std::uint32_t block = 0, begin = 0, end = 0;
};

}  // namespace

std::vector<SpecialRecord> findRecords(const RecordInputs& inputs) {
  const std::size_t count = inputs.scene->primitives.size();
  const std::vector<std::uint32_t> order = spatialOrder(inputs, count);
  const std::size_t blocks = (count + kBlock - 1) / kBlock;
  std::vector<std::vector<SpecialRecord>> perBlock(blocks);
  std::vector<Slot> slots(count);
  parallelForBlocks(blocks, 1, inputs.threads, [&](std::size_t b, std::size_t) {
    std::vector<std::uint32_t> scratch;
    Overlap overlap;
    const std::size_t end = std::min(count, (b + 1) * kBlock);
    for (std::size_t k = b * kBlock; k < end; ++k) {
      const std::uint32_t i = order[k];
      slots[i].block = static_cast<std::uint32_t>(b);
      slots[i].begin = static_cast<std::uint32_t>(perBlock[b].size());
      recordsOfPrimitive(inputs, i, scratch, overlap, perBlock[b]);
      slots[i].end = static_cast<std::uint32_t>(perBlock[b].size());
    }
  });
  // Each primitive's records were made independently: gathered in primitive order, the result does
  // not depend on the visiting order or the thread count.
  std::size_t total = 0;
  for (const auto& block : perBlock) total += block.size();
  std::vector<SpecialRecord> records;
  records.reserve(total);
  for (const Slot& slot : slots)
    records.insert(records.end(), perBlock[slot.block].begin() + slot.begin, perBlock[slot.block].begin() + slot.end);
  return records;
}

}  // namespace bake::grooves::grid_detail
