// Step II of the heat method (Crane, Weischedel and Wardetzky 2013, Algorithm 1): per face, the unit
// vector X = -grad u / |grad u| pointing away from the heat, and its integrated divergence at the
// face's corners, area * (grad phi_i . X), summed over faces into the Poisson step's right-hand side.
//
// Several fields are interleaved (a vertex's values side by side), so a face reads and writes one
// short row per corner for all of them, and the loops over the fields become vector operations. Each
// field goes through the same operations in the same order as when it is alone.
#include <algorithm>
#include <array>
#include <cmath>

#include "core/parallel.h"
#include "core/vector_clones.h"
#include "geodesic/bake/heat_operators.h"

namespace bake::geodesic {
namespace {

// Squared gradients inside this range are safe to square-root and invert directly.
constexpr double kSafeLow = 1e-280, kSafeHigh = 1e280;

// X for a gradient outside the safe range: far from the sources u is as small as 1e-300, where the
// squares would underflow, so the components are scaled by the larger first (hypot's care, at a
// fraction of its cost). False where the face is flat or not a number.
bool carefulDirection(double gx, double gy, double& xx, double& xy) {
  const double scale = std::max(std::abs(gx), std::abs(gy));
  if (!(scale > 0.0) || !std::isfinite(scale)) return false;
  gx /= scale;
  gy /= scale;
  const double inverseNorm = 1.0 / std::sqrt(gx * gx + gy * gy);
  xx = -gx * inverseNorm;
  xy = -gy * inverseNorm;
  return true;
}

// Columns [offset, offset + M) of fields interleaved `stride` to a vertex.
template <std::size_t M>
BAKE_INLINE_KERNEL void divergenceColumns(std::span<const HeatFace> faces, const double* u, double* rhs,
                                          std::size_t stride, std::size_t offset) {
  for (const HeatFace& face : faces) {
    // area * grad phi_i, per corner: the divergence's weights, and (area > 0) parallel to the gradient.
    double wx[3], wy[3];
    const double* in[3];
    double* out[3];
    for (int i = 0; i < 3; ++i) {
      wx[i] = face.area * face.hatGradient[i][0];
      wy[i] = face.area * face.hatGradient[i][1];
      in[i] = u + face.vertices[i] * stride + offset;
      out[i] = rhs + face.vertices[i] * stride + offset;
    }
    // One short loop per step over the M fields, so that each becomes vector operations.
    double gx[M], gy[M], squared[M];
    for (std::size_t c = 0; c < M; ++c) gx[c] = gy[c] = 0.0;
    for (int i = 0; i < 3; ++i)
      for (std::size_t c = 0; c < M; ++c) {
        gx[c] += in[i][c] * wx[i];
        gy[c] += in[i][c] * wy[i];
      }
    for (std::size_t c = 0; c < M; ++c) squared[c] = gx[c] * gx[c] + gy[c] * gy[c];
    // All fields in the safe range: the smallest and largest squares inside it, and no NaN (which
    // min and max may pass over, but which makes the sum NaN). Reductions a vector unit does well.
    double lo = squared[0], hi = squared[0], total = 0.0;
    for (std::size_t c = 0; c < M; ++c) { lo = std::min(lo, squared[c]); hi = std::max(hi, squared[c]); }
    for (std::size_t c = 0; c < M; ++c) total += squared[c];
    if (lo > kSafeLow && hi < kSafeHigh && total == total) {
      double root[M], xx[M], xy[M];
      for (std::size_t c = 0; c < M; ++c) root[c] = std::sqrt(squared[c]);
      for (std::size_t c = 0; c < M; ++c) {
        const double inverseNorm = 1.0 / root[c];
        xx[c] = -gx[c] * inverseNorm;
        xy[c] = -gy[c] * inverseNorm;
      }
      for (int i = 0; i < 3; ++i)
        for (std::size_t c = 0; c < M; ++c) out[i][c] += wx[i] * xx[c] + wy[i] * xy[c];
      continue;
    }
    for (std::size_t c = 0; c < M; ++c) {
      double xx, xy;
      if (squared[c] > kSafeLow && squared[c] < kSafeHigh) {
        const double inverseNorm = 1.0 / std::sqrt(squared[c]);
        xx = -gx[c] * inverseNorm;
        xy = -gy[c] * inverseNorm;
      } else if (!carefulDirection(gx[c], gy[c], xx, xy)) {
        continue;
      }
      for (int i = 0; i < 3; ++i) out[i][c] += wx[i] * xx + wy[i] * xy;
    }
  }
}

BAKE_VECTOR_CLONES void divergenceOfColumns(std::span<const HeatFace> faces, const double* u, double* rhs,
                                            std::size_t stride, std::size_t offset, std::size_t m) {
  switch (m) {
    case 1: divergenceColumns<1>(faces, u, rhs, stride, offset); break;
    case 2: divergenceColumns<2>(faces, u, rhs, stride, offset); break;
    case 3: divergenceColumns<3>(faces, u, rhs, stride, offset); break;
    case 4: divergenceColumns<4>(faces, u, rhs, stride, offset); break;
    case 5: divergenceColumns<5>(faces, u, rhs, stride, offset); break;
    case 6: divergenceColumns<6>(faces, u, rhs, stride, offset); break;
    case 7: divergenceColumns<7>(faces, u, rhs, stride, offset); break;
    default: divergenceColumns<8>(faces, u, rhs, stride, offset); break;
  }
}

}  // namespace

void divergenceOfNormalizedGradient(std::span<const HeatFace> faces, std::span<const double> u,
                                    std::span<double> rhs, std::size_t columns, unsigned threads) {
  // Groups of at most 8 fields; on a large mesh with threads to spare, at least two groups, one per
  // thread (each field's values do not depend on its group).
  constexpr std::size_t kMaxTogether = 8, kThreadedFromFaces = 100000;
  std::size_t groups = (columns + kMaxTogether - 1) / kMaxTogether;
  if (threads != 1 && faces.size() >= kThreadedFromFaces && columns >= 2) groups = std::max<std::size_t>(groups, 2);
  parallelForBlocks(groups, 1, threads, [&](std::size_t g, std::size_t) {
    const std::size_t first = g * columns / groups, last = (g + 1) * columns / groups;
    divergenceOfColumns(faces, u.data(), rhs.data(), columns, first, last - first);
  });
}

}  // namespace bake::geodesic
