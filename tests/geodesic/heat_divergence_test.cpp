// Step II of the heat method (heat_divergence.cpp) against a plain implementation of its formula
// written here: per face, X = -grad u / |grad u| from the hat gradients, and area * (grad phi_i . X)
// added at each corner, with hypot for the norm. Several fields interleaved must give, each, the bytes
// of that field alone, including fields so flat or so small that some faces take the careful path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "geodesic/bake/heat_intrinsic.h"
#include "geodesic/bake/heat_operators.h"
#include "geodesic/heat_meshes.h"

namespace bake::geodesic {
namespace {

std::vector<double> plainDivergence(const HeatOperators& ops, const std::vector<double>& u) {
  std::vector<double> rhs(u.size(), 0.0);
  for (const HeatFace& face : ops.faces) {
    double gx = 0.0, gy = 0.0;
    for (int i = 0; i < 3; ++i) {
      gx += u[face.vertices[i]] * face.hatGradient[i][0];
      gy += u[face.vertices[i]] * face.hatGradient[i][1];
    }
    const double norm = std::hypot(gx, gy);
    if (!(norm > 0.0) || !std::isfinite(norm)) continue;
    for (int i = 0; i < 3; ++i)
      rhs[face.vertices[i]] += face.area * (face.hatGradient[i][0] * -gx + face.hatGradient[i][1] * -gy) / norm;
  }
  return rhs;
}

// Fields on the sphere: smooth ones of several scales, one as small as 1e-300 (squares underflow),
// one as large as 1e200 (squares overflow) and one flat on half the sphere.
std::vector<std::vector<double>> testFields(const Surface& s) {
  std::vector<std::vector<double>> fields;
  for (const double scale : {1.0, 1e-300, 1e200, 3.5, 1e-5, 1.0, 0.25, 40.0, 2.0}) {
    std::vector<double> u(s.vertexCount());
    for (std::size_t v = 0; v < u.size(); ++v) {
      const Vec3d& p = s.positions[v];
      u[v] = scale * std::exp(-2.0 * (p[0] + 1.0) * (p[0] + 1.0) - 0.5 * p[1] * static_cast<double>(fields.size()));
    }
    fields.push_back(std::move(u));
  }
  std::vector<double> halfFlat(s.vertexCount());
  for (std::size_t v = 0; v < halfFlat.size(); ++v) halfFlat[v] = std::max(0.0, s.positions[v][2]);
  fields.push_back(std::move(halfFlat));
  return fields;
}

TEST(HeatDivergence, EveryInterleavedFieldIsItsFieldAloneAndMatchesThePlainFormula) {
  const Surface s = testing::geodesicSphere(3, 1.0);
  IntrinsicBuildStats stats;
  IntrinsicTriangulation mesh = buildTuftedCover(s, stats);
  flipToDelaunay(mesh);
  const HeatOperators ops = buildHeatOperators(mesh, s.vertexCount());
  const std::vector<std::vector<double>> fields = testFields(s);
  const std::size_t n = s.vertexCount(), columns = fields.size();  // 10: a group of 8 and one of 2

  std::vector<std::vector<double>> alone;
  for (const auto& u : fields) {
    std::vector<double> rhs(n, 0.0);
    divergenceOfNormalizedGradient(ops.faces, u, rhs);
    const std::vector<double> plain = plainDivergence(ops, u);
    double largest = 0.0;
    for (std::size_t v = 0; v < n; ++v) largest = std::max(largest, std::abs(plain[v]));
    ASSERT_GT(largest, 0.0) << "field " << alone.size();
    std::size_t outside = 0;  // written so that a NaN counts
    for (std::size_t v = 0; v < n; ++v) outside += !(std::abs(rhs[v] - plain[v]) <= 1e-12 * largest);
    EXPECT_EQ(outside, 0u) << "field " << alone.size();
    alone.push_back(std::move(rhs));
  }

  for (const std::size_t together : {std::size_t{3}, std::size_t{8}, columns}) {
    std::vector<double> u(n * together), rhs(n * together, 0.0);
    for (std::size_t c = 0; c < together; ++c)
      for (std::size_t v = 0; v < n; ++v) u[v * together + c] = fields[c][v];
    divergenceOfNormalizedGradient(ops.faces, u, rhs, together);
    std::size_t differing = 0;
    for (std::size_t c = 0; c < together; ++c)
      for (std::size_t v = 0; v < n; ++v) differing += rhs[v * together + c] != alone[c][v];
    EXPECT_EQ(differing, 0u) << together << " fields together";
  }
}

}  // namespace
}  // namespace bake::geodesic
