// The continuous Dijkstra of the exact geodesic method (Mitchell, Mount and Papadimitriou 1987;
// Surazhsky et al. 2005, section 3.4): one priority queue, keyed by the smallest distance a window
// reaches, holds windows to unfold into the next faces and vertices whose distance has just become
// final. Saddle, boundary and non-manifold vertices then re-emit as pseudo-sources. Each edge keeps its
// windows in one sorted list without overlaps; a new window is trimmed against them point by point.
#pragma once

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
    std::uint32_t vertex = kNone;          // the third corner
    std::uint32_t edgeToFirst = kNone;     // edge between the edge's first vertex and the third corner
    std::uint32_t edgeToSecond = kNone;    // edge between the edge's second vertex and the third corner
  };
  struct Entry {
    double key;
    std::uint32_t item;  // window index, or vertex index | kVertexBit
  };
  static constexpr std::uint32_t kVertexBit = 0x80000000u;

  void buildFaceSides();
  void markEmittingVertices();
  const FaceSide& side(std::uint32_t face, std::uint32_t edge) const;

  void push(double key, std::uint32_t item);
  Entry popMin();
  void relaxVertex(std::uint32_t v, double distance);
  void closeOverEdges();
  void processVertex(std::uint32_t v, double key);
  void emitFromVertex(std::uint32_t v);
  void processWindow(std::uint32_t id, double key);
  void emitChild(const Window& parent, std::uint32_t face, Point2 source, Point2 from, std::uint32_t fromVertex,
                 Point2 to, std::uint32_t edge, const ChildRange& range);

  void insertWindow(Window w);
  bool dominatedByEndpoints(const Window& w, double length) const;
  void trimAgainst(const Window& incoming, std::uint32_t existing);
  void linkSorted(std::uint32_t id);
  void unlink(std::uint32_t id);

  const Surface& surface_;
  ExactOptions options_;
  std::vector<FaceSide> sides_;  // 3 per face, in triangleEdges order
  std::vector<double> distance_;
  std::vector<double> emittedAt_;
  std::vector<std::uint8_t> emits_;
  std::vector<Window> windows_;
  std::vector<std::uint32_t> edgeHead_;
  std::vector<Entry> heap_;
  std::size_t windowCap_ = 0;
  std::size_t reached_ = 0;  // vertices with a finite distance, for ExactOptions::onReached
  ExactStats stats_;

  // Scratch for trimming, reused so that no window costs an allocation.
  struct Span {
    double lo, hi;
  };
  std::vector<Span> lost_;      // parts of the incoming window an existing one keeps
  std::vector<Span> pieces_;    // what is left of a window after subtraction
  std::vector<Span> won_;       // parts of an existing window the incoming one takes
};

}  // namespace bake::geodesic::exact
