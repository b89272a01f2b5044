// Discrete operators of the heat method on an intrinsic triangulation (Crane, Weischedel and
// Wardetzky 2013, section 3.2): the cotangent Laplacian, the lumped (barycentric) mass and, per face,
// the gradients of the three hat functions in a planar layout of the face built from its edge lengths.
// The integrated divergence of a per-face vector field X at vertex i is sum over faces of
// area * (grad phi_i . X), the transpose of the gradient; with X = grad u it gives back L u, so the
// Poisson step L phi = div X is consistent by construction.
#pragma once

#include <Eigen/SparseCore>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "geodesic/bake/heat_intrinsic.h"

namespace bake::geodesic {

struct HeatFace {
  std::array<std::uint32_t, 3> vertices;
  // Gradient of the hat function of each corner, in the face's own planar frame.
  std::array<std::array<double, 2>, 3> hatGradient;
  double area;  // of the face, times the number of mirrored copies merged into it
};

struct HeatOperators {
  std::vector<HeatFace> faces;
  // Off-diagonal cotangent weights, one entry per intrinsic edge joining two distinct vertices
  // (L_ij = -weight); the diagonal of L is the sum of the weights at a vertex.
  std::vector<std::array<std::uint32_t, 2>> edgeVertices;
  std::vector<double> edgeWeights;
  std::vector<double> laplacianDiagonal;
  std::vector<double> mass;  // lumped: a third of the area of each face at each corner
  double meanEdgeLength = 0.0;
};

HeatOperators buildHeatOperators(const IntrinsicTriangulation& mesh, std::size_t vertexCount);

// The upper triangle of scale * L + diag(diagonal) (L positive semi-definite), in compressed column
// form. Rows and columns flagged in `identityRows` hold a lone 1 on the diagonal instead; their
// off-diagonal entries are kept as explicit zeros so that every matrix made from the same operators
// has the same sparsity pattern (one symbolic analysis serves them all).
Eigen::SparseMatrix<double, Eigen::ColMajor, int> assembleUpper(const HeatOperators& ops, double scale,
                                                                std::span<const double> diagonal,
                                                                std::span<const char> identityRows);

// rhs_i = sum over faces of area * (grad phi_i . X) with X = -grad u / |grad u| (the unit vector
// pointing away from the heat source); faces where u is flat contribute nothing. With `columns` > 1,
// u and rhs hold that many fields interleaved (vertex v's values at v * columns .. v * columns +
// columns), done in one pass over the faces; each field's values are those of a pass of its own.
// `faces` are HeatOperators::faces, or the same with their corners renumbered as u's rows are. Up to
// `threads` threads (0: all cores) take groups of fields; the values do not depend on `threads`.
void divergenceOfNormalizedGradient(std::span<const HeatFace> faces, std::span<const double> u,
                                    std::span<double> rhs, std::size_t columns = 1, unsigned threads = 1);

}  // namespace bake::geodesic
