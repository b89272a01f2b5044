// Continuous Dijkstra over windows (Surazhsky et al. 2005, sections 3.3-3.4 and 4): a binary heap with
// lazy deletion orders windows by their nearest point and vertices by their distance. A window entering
// a face is unfolded onto the face's two other edges; on every edge a new window is intersected with
// the windows already there and each point keeps the smaller distance. A vertex whose distance becomes
// final relaxes its edges (a valid path, so distances stay upper bounds even on broken input) and, when
// geodesics can bend around it (saddle, boundary, non-manifold, a source), emits windows on the far
// edge of every face around it. Windows that cannot beat a path through an edge's endpoint are dropped
// before insertion (the filter of Surazhsky et al. section 4.2). An edge is closed, and its windows'
// slots reused, once the front has passed the farthest point of the edge's distance: every later
// window is farther everywhere, so the lists only matter inside the front's band.
#include "geodesic/bake/exact_propagate.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>

#include "bake/core/vec.h"

namespace bake::geodesic::exact {
namespace {

constexpr double kRelativeTolerance = 1e-10;

using vec::cross;
using vec::dot;
using vec::sub;

}  // namespace

Propagator::Propagator(const Surface& surface, const ExactOptions& options)
    : surface_(surface), options_(options) {
  const std::size_t n = surface.vertexCount();
  distance_.assign(n, kUnreachable);
  emittedAt_.assign(n, kUnreachable);
  emits_.assign(n, 0);
  edges_.resize(surface.edgeCount());
  for (std::uint32_t e = 0; e < surface.edgeCount(); ++e) {
    edges_[e].length = surface.edgeLengths[e];
    edges_[e].ends = surface.edges[e];
  }
  windowCap_ = options.maxWindows > 0 ? options.maxWindows : 400 * surface.edgeCount() + 1000000;
  buildFaceSides();
  markEmittingVertices();
}

void Propagator::buildFaceSides() {
  sides_.resize(3 * surface_.triangleCount());
  for (std::uint32_t f = 0; f < surface_.triangleCount(); ++f) {
    const auto& tri = surface_.triangles[f];
    const auto& te = surface_.triangleEdges[f];
    for (int j = 0; j < 3; ++j) {
      const std::uint32_t e = te[j];
      const std::uint32_t a = surface_.edges[e][0], b = surface_.edges[e][1];
      FaceSide& s = sides_[3 * f + j];
      s.face = f;
      s.vertex = tri[(j + 2) % 3];
      // Slot j+1 joins corners j+1 and j+2, slot j+2 joins corners j+2 and j.
      const bool firstIsCornerJ = tri[j] == a;
      s.edgeToFirst = firstIsCornerJ ? te[(j + 2) % 3] : te[(j + 1) % 3];
      s.edgeToSecond = firstIsCornerJ ? te[(j + 1) % 3] : te[(j + 2) % 3];
      const Vec3d ab = sub(surface_.positions[b], surface_.positions[a]);
      const Vec3d ac = sub(surface_.positions[s.vertex], surface_.positions[a]);
      const double length = vec::length(ab);
      if (length > 0.0) {
        s.third = {dot(ac, ab) / length, vec::length(cross(ab, ac)) / length};
      } else {
        s.third = {0.0, vec::length(ac)};
      }
    }
  }
  for (std::uint32_t e = 0; e < surface_.edgeCount(); ++e) {
    const auto faces = surface_.facesOfEdge(e);
    edges_[e].faceCount = static_cast<std::uint8_t>(std::min<std::size_t>(faces.size(), 3));
    for (std::size_t k = 0; k < faces.size() && k < 2; ++k) edges_[e].sides[k] = side(faces[k], e);
  }
}

void Propagator::markEmittingVertices() {
  std::vector<double> angle(surface_.vertexCount(), 0.0);
  for (std::uint32_t f = 0; f < surface_.triangleCount(); ++f) {
    for (int i = 0; i < 3; ++i) {
      const Vec3d& p = surface_.positions[surface_.triangles[f][i]];
      const Vec3d u = sub(surface_.positions[surface_.triangles[f][(i + 1) % 3]], p);
      const Vec3d v = sub(surface_.positions[surface_.triangles[f][(i + 2) % 3]], p);
      angle[surface_.triangles[f][i]] += std::atan2(vec::length(cross(u, v)), dot(u, v));
    }
  }
  const double zeroLength = kRelativeTolerance * surface_.diagonal;
  for (std::uint32_t v = 0; v < surface_.vertexCount(); ++v) {
    bool emits = angle[v] > 2.0 * std::numbers::pi + 1e-9;
    for (std::uint32_t e : surface_.edgesOfVertex(v))
      if (surface_.neighbourCountOfEdge(e) != 1 || surface_.edgeLengths[e] <= zeroLength) emits = true;
    // A closed fan that does not reach every face around v means several fans (a bow-tie vertex).
    const auto faces = surface_.facesOfVertex(v);
    if (!emits && !faces.empty()) {
      std::size_t visited = 0;
      std::uint32_t face = faces[0], cameThrough = kNone;
      do {
        const int corner = surface_.cornerOf(face, v);
        const std::uint32_t e1 = surface_.triangleEdges[face][corner];
        const std::uint32_t e2 = surface_.triangleEdges[face][(corner + 2) % 3];
        const std::uint32_t leave = e1 != cameThrough ? e1 : e2;
        const auto across = surface_.facesOfEdge(leave);
        face = across[0] == face ? across[1] : across[0];
        cameThrough = leave;
        ++visited;
      } while (face != faces[0] && visited <= faces.size());
      if (visited != faces.size()) emits = true;
    }
    emits_[v] = emits ? 1 : 0;
  }
}

const Propagator::FaceSide& Propagator::side(std::uint32_t face, std::uint32_t edge) const {
  const auto& te = surface_.triangleEdges[face];
  const int j = te[0] == edge ? 0 : (te[1] == edge ? 1 : 2);
  return sides_[3 * face + j];
}

void Propagator::Queue::push(Entry entry) {
  std::size_t i = entries_.size();
  entries_.push_back(entry);
  while (i > 0) {
    const std::size_t parent = (i - 1) / 4;
    if (entries_[parent].key <= entry.key) break;
    entries_[i] = entries_[parent];
    i = parent;
  }
  entries_[i] = entry;
}

Propagator::Entry Propagator::Queue::pop() {
  const Entry top = entries_.front();
  const Entry last = entries_.back();
  entries_.pop_back();
  const std::size_t n = entries_.size();
  if (n == 0) return top;
  std::size_t i = 0;
  for (;;) {
    const std::size_t first = 4 * i + 1;
    if (first >= n) break;
    std::size_t best = first;
    const std::size_t end = std::min(first + 4, n);
    for (std::size_t c = first + 1; c < end; ++c)
      if (entries_[c].key < entries_[best].key) best = c;
    if (entries_[best].key >= last.key) break;
    entries_[i] = entries_[best];
    i = best;
  }
  entries_[i] = last;
  return top;
}

std::uint64_t Propagator::RadixQueue::bitsOf(double key) {
  return key > 0.0 ? std::bit_cast<std::uint64_t>(key) : 0;
}

std::size_t Propagator::RadixQueue::bucketOf(std::uint64_t bits) const {
  return bits <= last_ ? 0 : 64 - static_cast<std::size_t>(std::countl_zero(bits ^ last_));
}

void Propagator::RadixQueue::push(const Entry& entry) {
  buckets_[bucketOf(bitsOf(entry.key))].push_back(entry);
  ++size_;
}

Propagator::Entry Propagator::RadixQueue::pop() {
  if (buckets_[0].empty()) {
    std::size_t i = 1;
    while (buckets_[i].empty()) ++i;
    std::vector<Entry>& bucket = buckets_[i];
    double smallest = bucket.front().key;
    for (const Entry& entry : bucket) smallest = std::min(smallest, entry.key);
    last_ = bitsOf(smallest);
    for (const Entry& entry : bucket) buckets_[bucketOf(bitsOf(entry.key))].push_back(entry);
    bucket.clear();
  }
  const Entry top = buckets_[0].back();
  buckets_[0].pop_back();
  --size_;
  return top;
}

void Propagator::RadixQueue::clear() {
  for (std::vector<Entry>& bucket : buckets_) bucket.clear();
  last_ = 0;
  size_ = 0;
}

void Propagator::pushWindow(std::uint32_t id) {
  queue_.push({windows_[id].minDistance(), id, windows_[id].generation});
}

std::uint32_t Propagator::allocateWindow(const Window& w) {
  ++liveWindows_;
  stats_.windowsPeak = std::max(stats_.windowsPeak, liveWindows_);
  if (freeSlots_.empty()) {
    windows_.push_back(w);
    return static_cast<std::uint32_t>(windows_.size() - 1);
  }
  const std::uint32_t id = freeSlots_.back();
  freeSlots_.pop_back();
  const std::uint32_t generation = windows_[id].generation;
  windows_[id] = w;
  windows_[id].generation = generation;
  return id;
}

// The window must already be off its edge's list.
void Propagator::releaseWindow(std::uint32_t id) {
  Window& w = windows_[id];
  w.generation = w.generation + 1;
  freeSlots_.push_back(id);
  --liveWindows_;
}

void Propagator::relaxVertex(std::uint32_t v, double distance) {
  if (!(distance < distance_[v])) return;
  if (distance_[v] == kUnreachable) ++reached_;
  distance_[v] = distance;
  // Only vertices that re-emit need their turn in the queue; the edge paths of the others are
  // relaxed once at the end (closeOverEdges), which keeps the heap small.
  if (emits_[v]) queue_.push({distance, v | kVertexBit});
}

void Propagator::closeOverEdges() {
  // Edge paths are valid paths: a Dijkstra over them from every distance found bounds each vertex from
  // above, so even a vertex no window reached (broken input) gets a finite distance when connected.
  queue_.clear();
  for (std::uint32_t v = 0; v < surface_.vertexCount(); ++v)
    if (distance_[v] < kUnreachable) queue_.push({distance_[v], v});
  while (!queue_.empty()) {
    const Entry top = queue_.pop();
    if (top.key > distance_[top.item] || top.key > options_.maxDistance) continue;
    for (std::uint32_t e : surface_.edgesOfVertex(top.item)) {
      const auto& ends = surface_.edges[e];
      const std::uint32_t other = ends[0] == top.item ? ends[1] : ends[0];
      const double candidate = top.key + surface_.edgeLengths[e];
      if (candidate < distance_[other]) {
        distance_[other] = candidate;
        queue_.push({candidate, other});
      }
    }
  }
}

void Propagator::addSource(const SurfacePoint& point) {
  const std::int64_t vertex = point.vertex(surface_);
  if (vertex >= 0) {
    emits_[vertex] = 1;
    relaxVertex(static_cast<std::uint32_t>(vertex), 0.0);
    return;
  }
  const std::uint32_t f = point.face;
  const Vec3d p = point.position(surface_);
  for (int i = 0; i < 3; ++i) {
    const std::uint32_t corner = surface_.triangles[f][i];
    relaxVertex(corner, vec::length(sub(surface_.positions[corner], p)));
  }
  // One window per edge of the face, the source unfolded into that edge's frame from its weights.
  for (int j = 0; j < 3; ++j) {
    const std::uint32_t e = surface_.triangleEdges[f][j];
    const FaceSide& s = sides_[3 * f + j];
    const double wb = point.barycentric[surface_.cornerOf(f, surface_.edges[e][1])];
    const double wc = point.barycentric[(j + 2) % 3];
    Window w;
    w.b0 = 0.0;
    w.b1 = surface_.edgeLengths[e];
    w.sx = wb * w.b1 + wc * s.third.x;
    w.sy = wc * s.third.y;
    w.sigma = 0.0;
    w.edge = e;
    w.fromFace = f;
    insertWindow(w);
  }
}

void Propagator::run() {
  constexpr std::size_t kReportEvery = 16384;
  std::size_t events = 0;
  while (!queue_.empty()) {
    if (options_.onReached && ++events % kReportEvery == 0) options_.onReached(reached_);
    const Entry top = queue_.pop();
    if (top.key > options_.maxDistance) break;
    closeEdgesBefore(top.key);
    if (top.item & kVertexBit) {
      processVertex(top.item & ~kVertexBit, top.key);
    } else {
      processWindow(top.item, top.key, top.generation);
    }
  }
  closeOverEdges();
  if (options_.onReached) options_.onReached(reached_);
}

std::vector<double> Propagator::takeDistances() {
  for (double& d : distance_)
    if (d > options_.maxDistance) d = kUnreachable;
  return std::move(distance_);
}

void Propagator::processVertex(std::uint32_t v, double key) {
  if (key > distance_[v]) return;  // superseded by a shorter path
  const double d = distance_[v];
  for (std::uint32_t e : surface_.edgesOfVertex(v)) {
    const std::uint32_t other = surface_.edges[e][0] == v ? surface_.edges[e][1] : surface_.edges[e][0];
    relaxVertex(other, d + surface_.edgeLengths[e]);
  }
  if (emits_[v] && d < emittedAt_[v] - kRelativeTolerance * surface_.meanEdgeLength) {
    emittedAt_[v] = d;
    ++stats_.pseudoSources;
    emitFromVertex(v);
  }
}

void Propagator::emitFromVertex(std::uint32_t v) {
  for (std::uint32_t f : surface_.facesOfVertex(v)) {
    const int corner = surface_.cornerOf(f, v);
    const int slot = (corner + 1) % 3;  // the edge facing v
    const std::uint32_t e = surface_.triangleEdges[f][slot];
    const FaceSide& s = sides_[3 * f + slot];
    Window w;
    w.b0 = 0.0;
    w.b1 = surface_.edgeLengths[e];
    w.sx = s.third.x;
    w.sy = s.third.y;
    w.sigma = distance_[v];
    w.edge = e;
    w.fromFace = f;
    insertWindow(w);
  }
}

void Propagator::processWindow(std::uint32_t id, double key, std::uint32_t generation) {
  const Window w = windows_[id];
  if (w.generation != generation || w.propagated) return;
  const EdgeState& edge = edges_[w.edge];
  const double length = edge.length;
  const double tolerance = kRelativeTolerance * length;
  const double nearest = w.minDistance();
  if (nearest > key + tolerance) {  // trimmed since it was queued: wait for its real turn
    pushWindow(id);
    return;
  }
  windows_[id].propagated = 1;
  // Vertex distances may have dropped since it was queued: the endpoint filter may now reject it.
  if (dominatedByEndpoints(w, length)) return;
  ++stats_.windowsPropagated;
  const Point2 source{w.sx, -w.sy};
  const Point2 first{0.0, 0.0}, second{length, 0.0};
  auto crossInto = [&](const FaceSide& s) {
    const FaceCrossing crossing = crossFace(w, length, s.third, tolerance);
    if (crossing.reachesC)
      relaxVertex(s.vertex, w.sigma + length2d(s.third.x - source.x, s.third.y - source.y));
    if (crossing.onAC.valid)
      emitChild(w, s.face, source, first, edge.ends[0], s.third, s.edgeToFirst, crossing.onAC);
    if (crossing.onBC.valid)
      emitChild(w, s.face, source, second, edge.ends[1], s.third, s.edgeToSecond, crossing.onBC);
  };
  if (edge.faceCount <= 2) {
    const FaceSide* into = nullptr;
    for (int k = 0; k < edge.faceCount; ++k)
      if (edge.sides[k].face != w.fromFace) into = &edge.sides[k];
    if (!into) return;
    // The children land on these edges and are checked against these ends: fetch them while the
    // unfolding is computed (the propagation waits on memory more than on arithmetic).
    __builtin_prefetch(&edges_[into->edgeToFirst]);
    __builtin_prefetch(&edges_[into->edgeToSecond]);
    __builtin_prefetch(&distance_[into->vertex]);
    crossInto(*into);
    return;
  }
  for (std::uint32_t g : surface_.facesOfEdge(w.edge))  // a non-manifold edge: into every other face
    if (g != w.fromFace) crossInto(side(g, w.edge));
}

void Propagator::emitChild(const Window& parent, std::uint32_t face, Point2 source, Point2 from,
                           std::uint32_t fromVertex, Point2 to, std::uint32_t edge, const ChildRange& range) {
  const double length = edges_[edge].length;
  const bool forward = edges_[edge].ends[0] == fromVertex;
  const Point2 origin = forward ? from : to;
  const Point2 end = forward ? to : from;
  const Point2 s = sourceInFrame(source, origin, end);
  Window child;
  child.b0 = forward ? range.t0 * length : (1.0 - range.t1) * length;
  child.b1 = forward ? range.t1 * length : (1.0 - range.t0) * length;
  child.sx = s.x;
  child.sy = s.y;
  child.sigma = parent.sigma;
  child.edge = edge;
  child.fromFace = face;
  insertWindow(child);
}

bool Propagator::dominatedByEndpoints(const Window& w, double length) const {
  // sigma + |S - p| - x never increases along the edge, so checking the far end suffices.
  const double tolerance = kRelativeTolerance * length;
  const double viaFirst = distance_[edges_[w.edge].ends[0]];
  const double viaSecond = distance_[edges_[w.edge].ends[1]];
  return w.distanceAt(w.b1) - w.b1 > viaFirst + tolerance ||
         w.distanceAt(w.b0) - (length - w.b0) > viaSecond + tolerance;
}

void Propagator::insertWindow(Window w) {
  EdgeState& edge = edges_[w.edge];
  const double length = edge.length;
  if (!(length > kRelativeTolerance * surface_.diagonal)) return;  // zero-length edge: vertices carry it
  if (edge.closed) return;  // every point there is nearer than any window still to come
  const double tolerance = kRelativeTolerance * length;
  w.b0 = std::clamp(w.b0, 0.0, length);
  w.b1 = std::clamp(w.b1, w.b0, length);
  if (!std::isfinite(w.sx) || !std::isfinite(w.sy) || !std::isfinite(w.sigma)) return;
  if (w.b0 <= tolerance) relaxVertex(edge.ends[0], w.distanceAt(0.0));
  if (w.b1 >= length - tolerance) relaxVertex(edge.ends[1], w.distanceAt(length));
  if (w.b1 - w.b0 <= tolerance) return;
  if (stats_.windowsCreated + stats_.windowsSplit >= windowCap_) {
    stats_.windowLimitReached = true;
    return;
  }
  if (w.minDistance() > options_.maxDistance || dominatedByEndpoints(w, length)) return;

  // The windows it overlaps: from the last one starting at or before it (which may reach into it).
  const std::vector<EdgeSlot>& slots = edge.slots;
  std::size_t i = std::upper_bound(slots.begin(), slots.end(), w.b0,
                                   [](double x, const EdgeSlot& slot) { return x < slot.b0; }) -
                  slots.begin();
  if (i > 0) --i;
  overlapped_.clear();
  for (; i < slots.size() && slots[i].b0 < w.b1 - tolerance; ++i)
    if (windows_[slots[i].id].b1 > w.b0 + tolerance) overlapped_.push_back(slots[i].id);
  lost_.clear();
  for (std::uint32_t id : overlapped_) trimAgainst(w, id);
  // What the existing windows did not keep becomes new windows.
  double cursor = w.b0;
  auto emitPiece = [&](double lo, double hi) {
    if (hi - lo <= tolerance) return;
    Window piece = w;
    piece.b0 = lo;
    piece.b1 = hi;
    const std::uint32_t newId = allocateWindow(piece);
    linkSorted(newId);
    pushWindow(newId);
    ++stats_.windowsCreated;
    edge.farthestPlaced = std::max({edge.farthestPlaced, piece.distanceAt(lo), piece.distanceAt(hi)});
    scheduleClose(piece.edge, edge.farthestPlaced);
  };
  for (const Span& s : lost_) {
    emitPiece(cursor, std::min(s.lo, w.b1));
    cursor = std::max(cursor, s.hi);
  }
  emitPiece(cursor, w.b1);
}

// Adds [a, b] to spans kept in order, merged with the last one where they touch.
void Propagator::appendSpan(std::vector<Span>& spans, double a, double b) {
  if (!spans.empty() && spans.back().hi >= a) {
    spans.back().hi = std::max(spans.back().hi, b);
  } else {
    spans.push_back({a, b});
  }
}

void Propagator::trimAgainst(const Window& incoming, std::uint32_t existing) {
  const Window old = windows_[existing];
  const double length = edges_[old.edge].length;
  const double tolerance = kRelativeTolerance * length;
  const double lo = std::max(incoming.b0, old.b0), hi = std::min(incoming.b1, old.b1);
  // Most overlaps are settled by bounds alone (each distance is convex along the edge: its smallest
  // value is at the source's foot, its largest at an end), without solving for crossings.
  auto nearestOn = [lo, hi](const Window& w) { return w.distanceAt(std::clamp(w.sx, lo, hi)); };
  auto farthestOn = [lo, hi](const Window& w) { return std::max(w.distanceAt(lo), w.distanceAt(hi)); };
  if (nearestOn(incoming) >= farthestOn(old) - tolerance) {
    appendSpan(lost_, lo, hi);
    return;
  }
  std::array<double, 2> roots{};
  const int rootCount = crossingPoints(incoming, old, lo, hi, roots);
  std::array<double, 4> cuts{lo, 0.0, 0.0, 0.0};
  int cutCount = 1;
  for (int i = 0; i < rootCount; ++i) cuts[cutCount++] = roots[i];
  cuts[cutCount++] = hi;

  won_.clear();
  for (int i = 0; i + 1 < cutCount; ++i) {
    const double a = cuts[i], b = cuts[i + 1];
    if (b <= a) continue;
    const double mid = 0.5 * (a + b);
    if (incoming.distanceAt(mid) < old.distanceAt(mid) - tolerance) {
      appendSpan(won_, a, b);
    } else {
      appendSpan(lost_, a, b);
    }
  }
  if (won_.empty()) return;

  // The existing window keeps its range minus what the incoming one won (possibly two pieces).
  pieces_.clear();
  double cursor = old.b0;
  for (const Span& s : won_) {
    if (s.lo - cursor > tolerance) pieces_.push_back({cursor, s.lo});
    cursor = std::max(cursor, s.hi);
  }
  if (old.b1 - cursor > tolerance) pieces_.push_back({cursor, old.b1});
  if (pieces_.empty()) {
    unlink(existing);
    releaseWindow(existing);
    return;
  }
  // The first piece stays in place: it starts at or after the old start and before the next window.
  edges_[old.edge].slots[slotOf(existing)].b0 = pieces_[0].lo;
  windows_[existing].b0 = pieces_[0].lo;
  windows_[existing].b1 = pieces_[0].hi;
  for (std::size_t i = 1; i < pieces_.size(); ++i) {
    Window split = old;
    split.b0 = pieces_[i].lo;
    split.b1 = pieces_[i].hi;
    const std::uint32_t newId = allocateWindow(split);
    ++stats_.windowsSplit;
    linkSorted(newId);
    if (!split.propagated) pushWindow(newId);
  }
}

std::size_t Propagator::slotOf(std::uint32_t id) const {
  const Window& w = windows_[id];
  const std::vector<EdgeSlot>& slots = edges_[w.edge].slots;
  std::size_t i = std::lower_bound(slots.begin(), slots.end(), w.b0,
                                   [](const EdgeSlot& slot, double x) { return slot.b0 < x; }) -
                  slots.begin();
  while (i < slots.size() && slots[i].id != id) ++i;  // equal starts: a few at most
  return i;
}

void Propagator::linkSorted(std::uint32_t id) {
  const Window& w = windows_[id];
  std::vector<EdgeSlot>& slots = edges_[w.edge].slots;
  const auto at = std::upper_bound(slots.begin(), slots.end(), w.b0,
                                   [](double x, const EdgeSlot& slot) { return x < slot.b0; });
  slots.insert(at, EdgeSlot{w.b0, id});
}

void Propagator::unlink(std::uint32_t id) {
  std::vector<EdgeSlot>& slots = edges_[windows_[id].edge].slots;
  const std::size_t i = slotOf(id);
  if (i < slots.size()) slots.erase(slots.begin() + static_cast<std::ptrdiff_t>(i));
}

}  // namespace bake::geodesic::exact

namespace bake::geodesic::exact {

// A bound on the largest distance of any point of the edge, kept without looking at its windows:
// the largest any window placed there ever had (trimming only lowers them), and for the points no
// window covers, the larger of the two paths through the edge's ends at their worst.
double Propagator::farthestBoundOnEdge(std::uint32_t edge) const {
  const EdgeState& state = edges_[edge];
  const double length = state.length;
  const double viaFirst = distance_[state.ends[0]];
  const double viaSecond = distance_[state.ends[1]];
  double throughEnds = kUnreachable;  // min(viaFirst + x, viaSecond + length - x) at its peak
  if (viaFirst < kUnreachable && viaSecond < kUnreachable) {
    throughEnds = 0.5 * (viaFirst + viaSecond + length);
  } else if (viaFirst < kUnreachable || viaSecond < kUnreachable) {
    throughEnds = std::min(viaFirst, viaSecond) + length;
  }
  return std::max(state.farthestPlaced, throughEnds);
}

void Propagator::scheduleClose(std::uint32_t edge, double when) {
  if (edges_[edge].closeScheduled) return;
  edges_[edge].closeScheduled = 1;
  checks_.push({when, edge});
}

// Closes the edges the front has passed: a window still to come starts at `key` or beyond (children
// are no nearer than their parent), so it cannot beat a point already nearer than that. The margin
// keeps ties, which the trimming tolerance could resolve either way, on the open side.
void Propagator::closeEdgesBefore(double key) {
  const double margin = kRelativeTolerance * surface_.diagonal;
  while (!checks_.empty() && checks_.top().key < key - margin) {
    const std::uint32_t edge = checks_.pop().item;
    const double farthest = farthestBoundOnEdge(edge);
    // Every window there was queued at its nearest point, below `key`, so all have been propagated.
    EdgeState& state = edges_[edge];
    const auto& slots = state.slots;
    if (farthest < key - margin &&
        std::all_of(slots.begin(), slots.end(), [&](const EdgeSlot& slot) { return windows_[slot.id].propagated; })) {
      for (const EdgeSlot& slot : slots) releaseWindow(slot.id);
      std::vector<EdgeSlot>().swap(state.slots);
      state.closed = 1;
      state.closeScheduled = 0;
    } else if (farthest < kUnreachable) {
      checks_.push({std::max(farthest, key), edge});  // not yet: look again when the front gets there
    } else {
      state.closeScheduled = 0;  // an end not reached yet: the next window on the edge reschedules
    }
  }
}

}  // namespace bake::geodesic::exact
