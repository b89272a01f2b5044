// Intrinsic triangulation for the robust heat method: tufted cover, mollification, Delaunay flips.
//
// Sharp and Crane 2020 ("A Laplacian for Nonmanifold Triangle Meshes") build a Laplacian that is
// positive semi-definite with non-negative weights on any triangle soup in three steps:
//  1. the tufted cover (their section 4.2): two copies of every face, one per side; around each
//     edge the sides are sorted by angle about the edge and each side is glued to the facing side of
//     the next face in that order, so every edge has exactly two sides and there is no boundary;
//  2. mollification (section 4.5): a small epsilon added to every edge length gives every triangle a
//     strict triangle inequality with margin delta, so zero-area faces get a tiny positive area;
//  3. intrinsic Delaunay flips (Fisher et al. 2007; Sharp, Soliman and Crane 2019 section 3): an edge
//     whose opposite angles sum to more than pi is replaced by the other diagonal of its two
//     triangles, whose length follows from laying them out in the plane. Every non-Delaunay edge is
//     flippable, and the result has non-negative cotangent weights.
#include "geodesic/bake/heat_intrinsic.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "bake/core/vec.h"

namespace bake::geodesic {
namespace {

// One side of a surface face: the face, which copy (0 = as given, 1 = reversed) and the halfedge slot
// of that copy lying on the edge being glued.
struct Side {
  std::uint32_t face;
  std::uint32_t copy;
  std::uint32_t slot;
};

// Copy 1 of face (c0, c1, c2) is (c0, c2, c1): its slot s leaves corner kReversedTail[s] (and lies on
// the face's edge 2 - s, edge i joining corners i and i + 1).
constexpr std::array<int, 3> kReversedTail{0, 2, 1};

using vec::cross;
using vec::dot;
using vec::sub;

// Faces around edge e ordered by the angle of their third corner about the axis a -> b.
std::vector<std::uint32_t> facesInCyclicOrder(const Surface& surface, std::uint32_t e) {
  const auto faces = surface.facesOfEdge(e);
  std::vector<std::uint32_t> order(faces.begin(), faces.end());
  if (order.size() < 3) return order;
  const Vec3d& a = surface.positions[surface.edges[e][0]];
  Vec3d axis = sub(surface.positions[surface.edges[e][1]], a);
  const double axisLength = std::sqrt(dot(axis, axis));
  if (axisLength > 0.0)
    for (double& x : axis) x /= axisLength;
  std::vector<Vec3d> spokes;
  Vec3d xAxis{0.0, 0.0, 0.0};
  for (std::uint32_t f : order) {
    std::uint32_t third = 0;
    for (std::uint32_t v : surface.triangles[f])
      if (v != surface.edges[e][0] && v != surface.edges[e][1]) third = v;
    Vec3d w = sub(surface.positions[third], a);
    const double along = dot(w, axis);
    for (int k = 0; k < 3; ++k) w[k] -= along * axis[k];
    if (dot(xAxis, xAxis) == 0.0) xAxis = w;
    spokes.push_back(w);
  }
  const Vec3d yAxis = cross(axis, xAxis);
  std::vector<double> angle(order.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    angle[i] = std::atan2(dot(spokes[i], yAxis), dot(spokes[i], xAxis));
  std::vector<std::size_t> index(order.size());
  std::iota(index.begin(), index.end(), 0);
  std::stable_sort(index.begin(), index.end(),
                   [&](std::size_t i, std::size_t j) { return angle[i] < angle[j]; });
  std::vector<std::uint32_t> sorted;
  for (std::size_t i : index) sorted.push_back(order[i]);
  return sorted;
}

// The sides of face f on edge e: `plus` runs along the edge from its smaller vertex to its larger,
// and faces towards increasing angle about that axis; `minus` is the other side.
void sidesOnEdge(const Surface& surface, std::uint32_t f, std::uint32_t e, Side& plus, Side& minus) {
  int local = 0;
  while (surface.triangleEdges[f][local] != e) ++local;
  const Side forward{f, 0, static_cast<std::uint32_t>(local)};
  const Side reversed{f, 1, static_cast<std::uint32_t>(2 - local)};
  const bool forwardIsPlus = surface.triangles[f][local] == surface.edges[e][0];
  plus = forwardIsPlus ? forward : reversed;
  minus = forwardIsPlus ? reversed : forward;
}

struct Gluing {
  Side first, second;
  std::uint32_t surfaceEdge;
};

std::vector<Gluing> glueSides(const Surface& surface, std::size_t& nonManifoldEdges) {
  std::vector<Gluing> gluings;
  gluings.reserve(surface.edgeCount() * 2);
  for (std::uint32_t e = 0; e < surface.edgeCount(); ++e) {
    const std::vector<std::uint32_t> faces = facesInCyclicOrder(surface, e);
    if (faces.size() >= 3) ++nonManifoldEdges;
    for (std::size_t i = 0; i < faces.size(); ++i) {
      Side plus{}, minus{}, nextPlus{}, nextMinus{};
      sidesOnEdge(surface, faces[i], e, plus, minus);
      sidesOnEdge(surface, faces[(i + 1) % faces.size()], e, nextPlus, nextMinus);
      gluings.push_back({plus, nextMinus, e});
    }
  }
  return gluings;
}

}  // namespace

double triangleArea(double a, double b, double c) {
  // Heron's formula in Kahan's cancellation-free arrangement (sides sorted a >= b >= c).
  if (a < b) std::swap(a, b);
  if (a < c) std::swap(a, c);
  if (b < c) std::swap(b, c);
  const double product = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
  return product > 0.0 ? 0.25 * std::sqrt(product) : 0.0;
}

double cotangentOpposite(double a, double b, double c, double area) {
  if (!(area > 0.0)) return 0.0;
  return (b * b + c * c - a * a) / (4.0 * area);
}

IntrinsicTriangulation buildTuftedCover(const Surface& surface, IntrinsicBuildStats& stats) {
  const std::vector<Gluing> gluings = glueSides(surface, stats.nonManifoldEdges);
  // Without boundary, non-manifold edges or flipped faces the reversed copies only meet each other:
  // they form a mirror image of the first copy that would double the work and change nothing.
  stats.doubled = std::any_of(gluings.begin(), gluings.end(),
                              [](const Gluing& g) { return g.first.copy != g.second.copy; });
  const std::size_t copies = stats.doubled ? 2 : 1;
  const auto halfedgeOf = [&](const Side& side) {
    const std::size_t face = stats.doubled ? 2 * side.face + side.copy : side.face;
    return static_cast<std::uint32_t>(3 * face + side.slot);
  };

  IntrinsicTriangulation mesh;
  const std::size_t halfedges = 3 * copies * surface.triangleCount();
  mesh.tail.resize(halfedges);
  mesh.twin.resize(halfedges);
  mesh.edgeOf.resize(halfedges);
  for (std::uint32_t f = 0; f < surface.triangleCount(); ++f)
    for (std::uint32_t copy = 0; copy < copies; ++copy)
      for (std::uint32_t slot = 0; slot < 3; ++slot) {
        const int corner = copy == 0 ? static_cast<int>(slot) : kReversedTail[slot];
        mesh.tail[halfedgeOf({f, copy, slot})] = surface.triangles[f][corner];
      }
  for (const Gluing& g : gluings) {
    if (!stats.doubled && g.first.copy == 1) continue;
    const std::uint32_t h = halfedgeOf(g.first), t = halfedgeOf(g.second);
    const auto edge = static_cast<std::uint32_t>(mesh.length.size());
    mesh.twin[h] = t;
    mesh.twin[t] = h;
    mesh.edgeOf[h] = mesh.edgeOf[t] = edge;
    mesh.edgeHalfedge.push_back(h);
    mesh.length.push_back(surface.edgeLengths[g.surfaceEdge]);
  }
  return mesh;
}

double mollify(IntrinsicTriangulation& mesh, double delta) {
  double epsilon = 0.0;
  for (std::uint32_t f = 0; f < mesh.faceCount(); ++f) {
    const double a = mesh.lengthOf(3 * f), b = mesh.lengthOf(3 * f + 1), c = mesh.lengthOf(3 * f + 2);
    epsilon = std::max({epsilon, delta - (b + c - a), delta - (c + a - b), delta - (a + b - c)});
  }
  if (epsilon > 0.0)
    for (double& l : mesh.length) l += epsilon;
  return epsilon;
}

namespace {

// Sum of the cotangents of the two angles facing the edge of halfedge h (non-negative iff Delaunay).
double cotanWeightSum(const IntrinsicTriangulation& mesh, std::uint32_t h) {
  double sum = 0.0;
  for (std::uint32_t side : {h, mesh.twin[h]}) {
    const double a = mesh.lengthOf(side), b = mesh.lengthOf(IntrinsicTriangulation::next(side)),
                 c = mesh.lengthOf(IntrinsicTriangulation::prev(side));
    sum += cotangentOpposite(a, b, c, triangleArea(a, b, c));
  }
  return sum;
}

// Length of the diagonal k-l of the quad i-k-j-l made of triangles (i, j, k) and (j, i, l), laid out
// with i at the origin and j on the positive x axis.
double flippedLength(double lij, double ljk, double lki, double lil, double llj) {
  const double xk = (lij * lij + lki * lki - ljk * ljk) / (2.0 * lij);
  const double yk = std::sqrt(std::max(0.0, lki * lki - xk * xk));
  const double xl = (lij * lij + lil * lil - llj * llj) / (2.0 * lij);
  const double yl = -std::sqrt(std::max(0.0, lil * lil - xl * xl));
  return std::hypot(xk - xl, yk - yl);
}

// Replaces edge e (halfedges h: i->j in face (i, j, k) and t: j->i in face (j, i, l)) by k-l. The
// faces keep their slots: face of h becomes (k, l, j) and face of t becomes (l, k, i).
void flipEdge(IntrinsicTriangulation& mesh, std::uint32_t h) {
  using T = IntrinsicTriangulation;
  const std::uint32_t t = mesh.twin[h];
  const std::uint32_t a1 = T::next(h), a2 = T::prev(h), b1 = T::next(t), b2 = T::prev(t);
  const std::uint32_t e = mesh.edgeOf[h];
  const std::uint32_t k = mesh.tail[a2], l = mesh.tail[b2];
  mesh.length[e] = flippedLength(mesh.length[e], mesh.lengthOf(a1), mesh.lengthOf(a2), mesh.lengthOf(b1),
                                 mesh.lengthOf(b2));

  const std::array<std::uint32_t, 4> from{a1, a2, b1, b2};
  const std::array<std::uint32_t, 4> to{a2, b1, b2, a1};
  const auto moved = [&](std::uint32_t x) {
    for (int i = 0; i < 4; ++i)
      if (from[i] == x) return to[i];
    return x;
  };
  std::array<std::uint32_t, 4> tails{}, twins{}, edges{};
  for (int i = 0; i < 4; ++i) {
    tails[i] = mesh.tail[from[i]];
    twins[i] = moved(mesh.twin[from[i]]);
    edges[i] = mesh.edgeOf[from[i]];
  }
  for (int i = 0; i < 4; ++i) {
    mesh.tail[to[i]] = tails[i];
    mesh.edgeOf[to[i]] = edges[i];
    mesh.twin[to[i]] = twins[i];
    mesh.twin[twins[i]] = to[i];
    mesh.edgeHalfedge[edges[i]] = to[i];
  }
  mesh.tail[h] = k;
  mesh.tail[t] = l;
  mesh.edgeHalfedge[e] = h;
}

}  // namespace

std::size_t flipToDelaunay(IntrinsicTriangulation& mesh) {
  // Rounding can make an edge and its flip both look non-Delaunay by a hair; the tolerance stops such
  // a pair from flipping back and forth, and the cap bounds the work whatever happens.
  constexpr double kTolerance = 1e-12;
  const std::size_t maxFlips = 100 * mesh.edgeCount() + 1000;
  std::vector<std::uint32_t> queue(mesh.edgeCount());
  std::iota(queue.begin(), queue.end(), 0u);
  std::vector<char> queued(mesh.edgeCount(), 1);
  std::size_t flips = 0;
  while (!queue.empty() && flips < maxFlips) {
    const std::uint32_t e = queue.back();
    queue.pop_back();
    queued[e] = 0;
    const std::uint32_t h = mesh.edgeHalfedge[e];
    if (IntrinsicTriangulation::faceOf(h) == IntrinsicTriangulation::faceOf(mesh.twin[h])) continue;
    if (cotanWeightSum(mesh, h) >= -kTolerance) continue;
    flipEdge(mesh, h);
    ++flips;
    const std::uint32_t t = mesh.twin[h];
    for (std::uint32_t x : {IntrinsicTriangulation::next(h), IntrinsicTriangulation::prev(h),
                            IntrinsicTriangulation::next(t), IntrinsicTriangulation::prev(t)}) {
      const std::uint32_t edge = mesh.edgeOf[x];
      if (!queued[edge]) {
        queued[edge] = 1;
        queue.push_back(edge);
      }
    }
  }
  return flips;
}

}  // namespace bake::geodesic
