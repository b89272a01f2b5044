// Cotangent Laplacian, lumped mass and per-face hat gradients on an intrinsic triangulation (Crane,
// Weischedel and Wardetzky 2013, section 3.2); the divergence of step II is in heat_divergence.cpp.
//
// Everything is computed from edge lengths alone (Sharp, Soliman and Crane 2019): each face is laid
// out in its own plane, corner 0 at the origin and corner 1 on the x axis, and hat gradients are the
// rotated opposite edges divided by twice the area. On an intrinsic Delaunay triangulation every
// cotangent weight sum is non-negative, so L is an M-matrix and M + tL has a positive inverse: heat
// is positive everywhere it has not underflowed.
#include "geodesic/bake/heat_operators.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace bake::geodesic {
namespace {

HeatFace layoutFace(const IntrinsicTriangulation& mesh, std::uint32_t f) {
  // Halfedge 3f + i runs from corner i to corner i + 1, so its length is the side opposite corner i + 2.
  const double l01 = mesh.lengthOf(3 * f), l12 = mesh.lengthOf(3 * f + 1), l20 = mesh.lengthOf(3 * f + 2);
  HeatFace face{};
  for (int i = 0; i < 3; ++i) face.vertices[i] = mesh.tail[3 * f + i];
  face.area = triangleArea(l01, l12, l20);
  if (!(face.area > 0.0) || !(l01 > 0.0)) return face;  // hat gradients stay zero
  const std::array<double, 2> p0{0.0, 0.0}, p1{l01, 0.0};
  const std::array<double, 2> p2{(l01 * l01 + l20 * l20 - l12 * l12) / (2.0 * l01), 2.0 * face.area / l01};
  const std::array<std::array<double, 2>, 3> p{p0, p1, p2};
  for (int i = 0; i < 3; ++i) {
    // The edge opposite corner i, counter-clockwise, turned a quarter towards corner i.
    const auto& from = p[(i + 1) % 3];
    const auto& to = p[(i + 2) % 3];
    face.hatGradient[i] = {-(to[1] - from[1]) / (2.0 * face.area), (to[0] - from[0]) / (2.0 * face.area)};
  }
  return face;
}

// Both sides of a face that no flip touched are the same triangle, mirrored; they contribute the same
// divergence, so the doubled cover's faces are merged into one of double area where they coincide
// (same corner vertices facing the same side lengths), halving the per-field work.
std::vector<HeatFace> mergeMirroredFaces(const IntrinsicTriangulation& mesh, std::vector<HeatFace> faces) {
  using Key = std::array<std::pair<std::uint32_t, double>, 3>;
  std::vector<Key> keys(faces.size());
  for (std::uint32_t f = 0; f < faces.size(); ++f) {
    for (int i = 0; i < 3; ++i) keys[f][i] = {mesh.tail[3 * f + i], mesh.lengthOf(3 * f + (i + 1) % 3)};
    std::sort(keys[f].begin(), keys[f].end());
  }
  // Faces in key order (ties by index), so that each face finds the first face with its key.
  std::vector<std::uint32_t> order(faces.size());
  for (std::uint32_t f = 0; f < order.size(); ++f) order[f] = f;
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return keys[a] != keys[b] ? keys[a] < keys[b] : a < b; });
  std::vector<std::uint32_t> firstWithKey(faces.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    firstWithKey[order[k]] = k > 0 && keys[order[k]] == keys[order[k - 1]] ? firstWithKey[order[k - 1]] : order[k];
  std::vector<HeatFace> merged;
  std::vector<std::size_t> mergedIndex(faces.size());
  merged.reserve(faces.size());
  for (std::uint32_t f = 0; f < faces.size(); ++f) {
    if (firstWithKey[f] == f) {
      mergedIndex[f] = merged.size();
      merged.push_back(faces[f]);
    } else {
      merged[mergedIndex[firstWithKey[f]]].area += faces[f].area;
    }
  }
  return merged;
}

}  // namespace

HeatOperators buildHeatOperators(const IntrinsicTriangulation& mesh, std::size_t vertexCount) {
  HeatOperators ops;
  ops.mass.assign(vertexCount, 0.0);
  ops.laplacianDiagonal.assign(vertexCount, 0.0);
  ops.faces.reserve(mesh.faceCount());
  for (std::uint32_t f = 0; f < mesh.faceCount(); ++f) {
    ops.faces.push_back(layoutFace(mesh, f));
    for (std::uint32_t v : ops.faces.back().vertices) ops.mass[v] += ops.faces.back().area / 3.0;
  }
  double lengthSum = 0.0;
  for (std::uint32_t e = 0; e < mesh.edgeCount(); ++e) {
    lengthSum += mesh.length[e];
    const std::uint32_t h = mesh.edgeHalfedge[e];
    const std::uint32_t i = mesh.tail[h], j = mesh.tail[IntrinsicTriangulation::next(h)];
    if (i == j) continue;  // a loop edge adds to and takes from the same vertex
    double weight = 0.0;
    for (std::uint32_t side : {h, mesh.twin[h]}) {
      const double a = mesh.lengthOf(side), b = mesh.lengthOf(IntrinsicTriangulation::next(side)),
                   c = mesh.lengthOf(IntrinsicTriangulation::prev(side));
      weight += 0.5 * cotangentOpposite(a, b, c, triangleArea(a, b, c));
    }
    ops.edgeVertices.push_back({i, j});
    ops.edgeWeights.push_back(weight);
    ops.laplacianDiagonal[i] += weight;
    ops.laplacianDiagonal[j] += weight;
  }
  ops.faces = mergeMirroredFaces(mesh, std::move(ops.faces));
  if (mesh.edgeCount() > 0) ops.meanEdgeLength = lengthSum / static_cast<double>(mesh.edgeCount());
  return ops;
}

Eigen::SparseMatrix<double, Eigen::ColMajor, int> assembleUpper(const HeatOperators& ops, double scale,
                                                                std::span<const double> diagonal,
                                                                std::span<const char> identityRows) {
  const auto n = static_cast<int>(ops.laplacianDiagonal.size());
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(ops.edgeWeights.size() + ops.laplacianDiagonal.size());
  for (std::size_t e = 0; e < ops.edgeWeights.size(); ++e) {
    const auto [i, j] = ops.edgeVertices[e];
    const bool cut = identityRows[i] || identityRows[j];
    entries.emplace_back(std::min(i, j), std::max(i, j), cut ? 0.0 : -scale * ops.edgeWeights[e]);
  }
  for (int v = 0; v < n; ++v)
    entries.emplace_back(v, v, identityRows[v] ? 1.0 : scale * ops.laplacianDiagonal[v] + diagonal[v]);
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> matrix(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  matrix.makeCompressed();
  return matrix;
}

}  // namespace bake::geodesic
