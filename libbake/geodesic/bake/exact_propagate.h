// The continuous Dijkstra of the exact geodesic method (Mitchell, Mount and Papadimitriou 1987;
// Surazhsky et al. 2005, section 3.4): one priority queue, keyed by the smallest distance a window
// reaches, holds windows to unfold into the next faces and vertices whose distance has just become
// final. Saddle, boundary and non-manifold vertices then re-emit as pseudo-sources. Each edge keeps its
// windows in one sorted list without overlaps; a new window is trimmed against them point by point.
// An edge whose every point is already closer than the front is closed: its windows are released
// (no later window can beat them) and their slots reused, so memory follows the front, not the mesh.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "geodesic/bake/exact.h"
#include "geodesic/bake/exact_window.h"

namespace bake::geodesic::exact {

class Propagator {
 public:
  Propagator(const Surface& surface, const ExactOptions& options);

  void addSource(const SurfacePoint& point);
  void run();
  std::vector<double> takeDistances();
  const ExactStats& stats() const { return stats_; }

 private:
  // The face seen from one of its edges: its third corner in that edge's frame and the two other edges.
  struct FaceSide {
    Point2 third;
    std::uint32_t face = kNone;
    std::uint32_t vertex = kNone;          // the third corner
    std::uint32_t edgeToFirst = kNone;     // edge between the edge's first vertex and the third corner
    std::uint32_t edgeToSecond = kNone;    // edge between the edge's second vertex and the third corner
  };
  struct Entry {
    double key;
    std::uint32_t item;            // window index, or vertex index | kVertexBit; an edge in checks_
    std::uint32_t generation = 0;  // of the window slot when queued
  };
  // A 4-ary min-heap: half the depth of a binary heap, and the four children share a cache line or
  // two. It holds the edges waiting to be closed, a small queue.
  class Queue {
   public:
    void push(Entry entry);
    Entry pop();
    const Entry& top() const { return entries_.front(); }
    bool empty() const { return entries_.empty(); }
    void clear() { entries_.clear(); }

   private:
    std::vector<Entry> entries_;
  };
  // A monotone radix heap (Ahuja, Mehlhorn, Orlin and Tarjan 1990) over the bit patterns of the
  // keys, which for non-negative doubles sort as the numbers do. The propagation never queues below
  // the distance last popped (children are no nearer than their parents), so each entry only moves
  // to lower buckets: constant work per push and a short scan per pop, where a comparison heap paid
  // a cache miss per level. A key a rounding below the last is served as if equal to it.
  class RadixQueue {
   public:
    void push(const Entry& entry);
    Entry pop();
    bool empty() const { return size_ == 0; }
    void clear();

   private:
    static std::uint64_t bitsOf(double key);
    std::size_t bucketOf(std::uint64_t bits) const;
    std::array<std::vector<Entry>, 65> buckets_;
    std::uint64_t last_ = 0;
    std::size_t size_ = 0;
  };

  static constexpr std::uint32_t kVertexBit = 0x80000000u;

  // Each edge's windows sorted by start, with the start kept beside the index so that finding where
  // a new window falls is a binary search over contiguous memory.
  struct EdgeSlot {
    double b0;
    std::uint32_t id;
  };
  // What processing and placing windows needs about an edge, together: a window costs a cache line
  // or two here rather than a miss in each of the surface's arrays. The first line is all that
  // placing a window reads; the second holds the faces on either side (of at most two).
  struct alignas(64) EdgeState {
    double length = 0.0;
    std::array<std::uint32_t, 2> ends{};
    double farthestPlaced = 0.0;  // the largest distance of any window placed here
    std::vector<EdgeSlot> slots;
    std::uint8_t closed = 0;
    std::uint8_t closeScheduled = 0;
    std::uint8_t faceCount = 0;  // 3 stands for three or more: then the surface's lists are used
    std::array<FaceSide, 2> sides;
  };

  void buildFaceSides();
  void markEmittingVertices();
  const FaceSide& side(std::uint32_t face, std::uint32_t edge) const;

  void pushWindow(std::uint32_t id);
  std::uint32_t allocateWindow(const Window& w);
  void releaseWindow(std::uint32_t id);
  void scheduleClose(std::uint32_t edge, double when);
  void closeEdgesBefore(double key);
  double farthestBoundOnEdge(std::uint32_t edge) const;
  void relaxVertex(std::uint32_t v, double distance);
  void closeOverEdges();
  void processVertex(std::uint32_t v, double key);
  void emitFromVertex(std::uint32_t v);
  void processWindow(std::uint32_t id, double key, std::uint32_t generation);
  void emitChild(const Window& parent, std::uint32_t face, Point2 source, Point2 from, std::uint32_t fromVertex,
                 Point2 to, std::uint32_t edge, const ChildRange& range);

  void insertWindow(Window w);
  bool dominatedByEndpoints(const Window& w, double length) const;
  void trimAgainst(const Window& incoming, std::uint32_t existing);
  void linkSorted(std::uint32_t id);
  void unlink(std::uint32_t id);
  std::size_t slotOf(std::uint32_t id) const;

  const Surface& surface_;
  ExactOptions options_;
  std::vector<FaceSide> sides_;  // 3 per face, in triangleEdges order
  std::vector<double> distance_;
  std::vector<double> emittedAt_;
  std::vector<std::uint8_t> emits_;
  std::vector<Window> windows_;
  std::vector<std::uint32_t> freeSlots_;
  std::vector<EdgeState> edges_;
  RadixQueue queue_;  // windows and vertices, by distance
  Queue checks_;  // edges to try closing, by the distance beyond which they may be final
  std::size_t windowCap_ = 0;
  std::size_t liveWindows_ = 0;
  std::size_t reached_ = 0;  // vertices with a finite distance, for ExactOptions::onReached
  ExactStats stats_;

  // Scratch for trimming, reused so that no window costs an allocation.
  struct Span {
    double lo, hi;
  };
  static void appendSpan(std::vector<Span>& spans, double a, double b);
  std::vector<Span> lost_;      // parts of the incoming window an existing one keeps
  std::vector<Span> pieces_;    // what is left of a window after subtraction
  std::vector<Span> won_;       // parts of an existing window the incoming one takes
  std::vector<std::uint32_t> overlapped_;  // existing windows an incoming one overlaps
};

}  // namespace bake::geodesic::exact
