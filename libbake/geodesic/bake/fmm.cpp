// Fast marching on triangle meshes (Kimmel and Sethian 1998, "Computing geodesic paths on manifolds").
//
// Vertices are finalised in increasing distance order, as in Dijkstra's algorithm. When a vertex is
// finalised, every vertex sharing a face with it is updated from that face: if two corners of the face
// are known, the distance at the third is that of the planar wavefront through both (section 3 of the
// paper: the front is locally a plane wave, |grad T| = 1); the update is accepted only when the
// characteristic reaching the vertex crosses the opposite edge inside the triangle (causality) and
// both known values can belong to one front (where two sources' fronts meet, a plane wave through
// both would undercut them), otherwise the vertex falls back to Dijkstra edge updates. A planar update is only consistent at an
// acute corner, so each obtuse corner is split (section 4 of the paper): neighbouring triangles are
// unfolded across the opposite edge into the corner's plane until a vertex lands in the corner's acute
// section (the directions within 90 degrees of both edges); the corner is then updated from the two
// acute virtual triangles through that vertex. The search is bounded; a corner without a split keeps
// the plain update. Non-manifold edges unfold into any face across them.
//
// Sources are vertices (distance 0) or points inside a face (its corners start at their Euclidean
// distance; a point on an edge starts the corners of every face of that edge). Vertices in components
// without a source keep kUnreachable. The error is first order in the edge length.
#include "geodesic/bake/fmm.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace bake::geodesic {
namespace {

constexpr std::uint32_t kNoSplit = std::numeric_limits<std::uint32_t>::max();
// Faces unfolded per obtuse corner: a few on ordinary meshes; strongly sheared grids need tens.
constexpr int kMaxUnfoldings = 32;

struct Vec2 {
  double x = 0.0, y = 0.0;
};
Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
double length(Vec2 a) { return std::sqrt(dot(a, a)); }

double distance3(const Vec3d& a, const Vec3d& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// Corner i of a face as the origin of a plane frame: corner i+1 on the positive x axis, corner i+2 in
// the upper half plane (placed from the three edge lengths).
struct CornerFrame {
  std::uint32_t c, a, b;  // vertices of corners i, i+1, i+2
  Vec2 pa, pb;
};

CornerFrame cornerFrame(const Surface& s, std::uint32_t face, int corner) {
  const auto& t = s.triangles[face];
  CornerFrame f{t[corner], t[(corner + 1) % 3], t[(corner + 2) % 3], {}, {}};
  const double ca = distance3(s.positions[f.c], s.positions[f.a]);
  const double cb = distance3(s.positions[f.c], s.positions[f.b]);
  const double ab = distance3(s.positions[f.a], s.positions[f.b]);
  f.pa = {ca, 0.0};
  const double bx = ca > 0.0 ? (ca * ca + cb * cb - ab * ab) / (2.0 * ca) : 0.0;
  f.pb = {bx, std::sqrt(std::max(0.0, cb * cb - bx * bx))};
  return f;
}

// Places the third vertex of a triangle across the segment p-q (2D) from the point `away`, given its
// distances to p and q. Returns false for a degenerate segment.
bool unfoldAcross(Vec2 p, Vec2 q, double toP, double toQ, Vec2 away, Vec2& placed) {
  const Vec2 e = q - p;
  const double len = length(e);
  if (len <= 0.0) return false;
  const Vec2 along = (1.0 / len) * e;
  Vec2 normal{-along.y, along.x};
  if (dot(normal, away - p) > 0.0) normal = -1.0 * normal;
  const double x = (toP * toP - toQ * toQ + len * len) / (2.0 * len);
  const double h = std::sqrt(std::max(0.0, toP * toP - x * x));
  placed = p + x * along + h * normal;
  return true;
}

// An obtuse corner's split: vertex `w` unfolded to `pw` in the corner's frame, inside its acute section.
struct Split {
  std::uint32_t face;
  std::uint8_t corner;
  std::uint32_t w;
  Vec2 pw;
};

struct UnfoldStep {
  std::uint32_t face;      // the face whose edge p-q is crossed next
  std::uint32_t p, q;      // vertices of that edge
  Vec2 pp, pq, opposite;   // their places, and the place of the face's third vertex
  int depth;
};

std::uint32_t edgeBetween(const Surface& s, std::uint32_t face, std::uint32_t u, std::uint32_t v) {
  for (int i = 0; i < 3; ++i) {
    const auto& t = s.triangles[face];
    if ((t[i] == u && t[(i + 1) % 3] == v) || (t[i] == v && t[(i + 1) % 3] == u)) return s.triangleEdges[face][i];
  }
  return std::numeric_limits<std::uint32_t>::max();
}

// Unfolds faces across the edge opposite an obtuse corner until a vertex lies in the corner's acute
// section, depth first over every face across each (possibly non-manifold) edge.
bool findSplit(const Surface& s, std::uint32_t face, int corner, Split& split) {
  const CornerFrame frame = cornerFrame(s, face, corner);
  std::vector<UnfoldStep> stack{{face, frame.a, frame.b, frame.pa, frame.pb, {0.0, 0.0}, 0}};
  int unfoldings = 0;
  while (!stack.empty() && unfoldings < kMaxUnfoldings) {
    const UnfoldStep step = stack.back();
    stack.pop_back();
    const std::uint32_t edge = edgeBetween(s, step.face, step.p, step.q);
    for (std::uint32_t next : s.facesOfEdge(edge)) {
      if (next == step.face || unfoldings >= kMaxUnfoldings) continue;
      ++unfoldings;
      const auto& t = s.triangles[next];
      const std::uint32_t w = t[0] != step.p && t[0] != step.q ? t[0] : (t[1] != step.p && t[1] != step.q ? t[1] : t[2]);
      if (w == frame.c) continue;
      Vec2 pw;
      const double toP = distance3(s.positions[w], s.positions[step.p]);
      const double toQ = distance3(s.positions[w], s.positions[step.q]);
      if (!unfoldAcross(step.pp, step.pq, toP, toQ, step.opposite, pw)) continue;
      const bool pastA = dot(pw, frame.pa) > 0.0, pastB = dot(pw, frame.pb) > 0.0;
      if (pastA && pastB) {
        split = {face, static_cast<std::uint8_t>(corner), w, pw};
        return true;
      }
      if (step.depth + 1 >= kMaxUnfoldings) continue;
      // The section lies on the side of w where the failed test's edge is: keep the edge it crosses.
      if (!pastB)
        stack.push_back({next, w, step.q, pw, step.pq, step.pp, step.depth + 1});
      else
        stack.push_back({next, step.p, w, step.pp, pw, step.pq, step.depth + 1});
    }
  }
  return false;
}

// Split of every obtuse corner (face * 3 + corner -> index into splits, or kNoSplit), and for each
// split vertex the corners it splits, so that they are updated again when it is finalised.
struct SplitTable {
  std::vector<std::uint32_t> ofCorner;
  std::vector<Split> splits;
  std::vector<std::uint32_t> byVertexOffsets, byVertex;  // CSR: vertex w -> split indices
};

SplitTable findSplits(const Surface& s) {
  SplitTable table;
  table.ofCorner.assign(3 * s.triangleCount(), kNoSplit);
  for (std::uint32_t face = 0; face < s.triangleCount(); ++face)
    for (int corner = 0; corner < 3; ++corner) {
      const CornerFrame frame = cornerFrame(s, face, corner);
      // Right corners (within rounding) are split too: the extra virtual vertex, across the hypotenuse,
      // halves the error on grids. Acute and flat corners keep the plain update.
      if (dot(frame.pa, frame.pb) > 1e-9 * length(frame.pa) * length(frame.pb) || frame.pb.y <= 0.0) continue;
      Split split;
      if (!findSplit(s, face, corner, split)) continue;
      table.ofCorner[3 * face + corner] = static_cast<std::uint32_t>(table.splits.size());
      table.splits.push_back(split);
    }
  table.byVertexOffsets.assign(s.vertexCount() + 1, 0);
  for (const Split& split : table.splits) ++table.byVertexOffsets[split.w + 1];
  for (std::size_t v = 0; v < s.vertexCount(); ++v) table.byVertexOffsets[v + 1] += table.byVertexOffsets[v];
  table.byVertex.resize(table.splits.size());
  std::vector<std::uint32_t> fill(table.byVertexOffsets.begin(), table.byVertexOffsets.end() - 1);
  for (std::uint32_t i = 0; i < table.splits.size(); ++i) table.byVertex[fill[table.splits[i].w]++] = i;
  return table;
}

// The planar wavefront through p (distance dp) and q (distance dq), evaluated at the origin, or
// infinity when the characteristic reaching the origin does not cross the segment p-q.
double planarFrontUpdate(Vec2 p, double dp, Vec2 q, double dq) {
  const Vec2 e = q - p;
  const double len = length(e);
  const double rise = dq - dp;
  if (len <= 0.0 || std::abs(rise) >= len) return kUnreachable;
  // One front reaches both ends only if dp + dq >= |pq| (no surface path is shorter than the edge);
  // less means two fronts (two sources) meet inside, where a plane wave would cut the corner.
  if (dp + dq < (1.0 - 1e-9) * len) return kUnreachable;
  const Vec2 along = (1.0 / len) * e;
  Vec2 normal{-along.y, along.x};
  if (dot(normal, p) > 0.0) normal = -1.0 * normal;  // towards the origin's side
  const double slope = rise / len;
  const Vec2 direction = slope * along + std::sqrt(1.0 - slope * slope) * normal;
  const double value = dp - dot(direction, p);
  // Trace the characteristic back from the origin to the line p-q: it must hit the segment.
  const double towards = dot(direction, normal);
  if (towards <= 0.0) return kUnreachable;
  const double back = -dot(p, normal) / towards;
  const double at = dot((-back) * direction - p, along);
  if (at < 0.0 || at > len || value < std::max(dp, dq)) return kUnreachable;
  return value;
}

// Distance at the origin from known points p and q: the planar front when both are known, and the
// straight edges from each known one.
double triangleUpdate(Vec2 p, double dp, Vec2 q, double dq) {
  double best = std::min(dp + length(p), dq + length(q));
  if (dp < kUnreachable && dq < kUnreachable) best = std::min(best, planarFrontUpdate(p, dp, q, dq));
  return best;
}

class FastMarching {
 public:
  FastMarching(const Surface& surface, const SplitTable& splits)
      : s_(surface), splits_(splits), distance_(surface.vertexCount(), kUnreachable),
        known_(surface.vertexCount(), 0) {}

  void seed(const SurfacePoint& source) {
    const std::int64_t vertex = source.vertex(s_);
    if (vertex >= 0) {
      offer(static_cast<std::uint32_t>(vertex), 0.0);
      return;
    }
    const Vec3d point = source.position(s_);
    seedFace(source.face, point);
    // A point on an edge sees the corners of every face of that edge in a straight line.
    for (int i = 0; i < 3; ++i)
      if (source.barycentric[(i + 2) % 3] == 0.0)
        for (std::uint32_t face : s_.facesOfEdge(s_.triangleEdges[source.face][i])) seedFace(face, point);
  }

  std::vector<double> run() {
    while (!front_.empty()) {
      const auto [d, v] = front_.top();
      front_.pop();
      if (known_[v] || d > distance_[v]) continue;
      known_[v] = 1;
      for (std::uint32_t face : s_.facesOfVertex(v))
        for (int corner = 0; corner < 3; ++corner) update(face, corner);
      for (std::uint32_t i = splits_.byVertexOffsets[v]; i < splits_.byVertexOffsets[v + 1]; ++i) {
        const Split& split = splits_.splits[splits_.byVertex[i]];
        update(split.face, split.corner);
      }
    }
    return std::move(distance_);
  }

 private:
  void seedFace(std::uint32_t face, const Vec3d& point) {
    for (std::uint32_t v : s_.triangles[face]) offer(v, distance3(point, s_.positions[v]));
  }

  void offer(std::uint32_t v, double d) {
    if (known_[v] || !(d < distance_[v])) return;
    distance_[v] = d;
    front_.push({d, v});
  }

  double known(std::uint32_t v) const { return known_[v] ? distance_[v] : kUnreachable; }

  // Updates the corner's vertex from the known vertices of its face (and of its split).
  void update(std::uint32_t face, int corner) {
    const CornerFrame frame = cornerFrame(s_, face, corner);
    if (known_[frame.c]) return;
    const double da = known(frame.a), db = known(frame.b);
    if (da == kUnreachable && db == kUnreachable) return;
    double best = triangleUpdate(frame.pa, da, frame.pb, db);
    const std::uint32_t splitIndex = splits_.ofCorner[3 * face + corner];
    if (splitIndex != kNoSplit) {
      const Split& split = splits_.splits[splitIndex];
      const double dw = known(split.w);
      if (dw < kUnreachable) {
        best = std::min(best, triangleUpdate(frame.pa, da, split.pw, dw));
        best = std::min(best, triangleUpdate(split.pw, dw, frame.pb, db));
      }
    }
    offer(frame.c, best);
  }

  using Entry = std::pair<double, std::uint32_t>;
  const Surface& s_;
  const SplitTable& splits_;
  std::vector<double> distance_;
  std::vector<char> known_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> front_;
};

}  // namespace

std::vector<double> fastMarchingDistances(const Surface& surface, std::span<const SurfacePoint> sources) {
  const SplitTable splits = findSplits(surface);
  FastMarching marching(surface, splits);
  for (const SurfacePoint& source : sources) marching.seed(source);
  return marching.run();
}

}  // namespace bake::geodesic
