// Our substitution with a Cholesky factor (heat_substitution.cpp) against two references that share
// no code with it: CHOLMOD's own solve with the same factor, and, on a small factor written by hand,
// the known solution of A x = b with A multiplied out densely.
#include "geodesic/bake/heat_substitution.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "geodesic/bake/heat_cholmod.h"
#include "geodesic/bake/heat_intrinsic.h"
#include "geodesic/bake/heat_operators.h"
#include "geodesic/heat_meshes.h"

namespace bake::geodesic {
namespace {

using SparseUpper = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// The heat method's two matrices on a surface: M + tL, and L with its first vertex held.
std::array<SparseUpper, 2> heatMatrices(const Surface& s) {
  IntrinsicBuildStats stats;
  IntrinsicTriangulation mesh = buildTuftedCover(s, stats);
  flipToDelaunay(mesh);
  const HeatOperators ops = buildHeatOperators(mesh, s.vertexCount());
  const std::vector<char> free(s.vertexCount(), 0);
  std::vector<char> held(s.vertexCount(), 0);
  held[0] = 1;
  const std::vector<double> none(s.vertexCount(), 0.0);
  const double t = ops.meanEdgeLength * ops.meanEdgeLength;
  return {assembleUpper(ops, t, ops.mass, free), assembleUpper(ops, 1.0, none, held)};
}

std::vector<CholeskyFactor> factorise(const std::array<SparseUpper, 2>& matrices) {
  const std::array<const SparseUpper*, 2> pointers{&matrices[0], &matrices[1]};
  Result<std::vector<CholeskyFactor>> factors = CholeskyFactor::factoriseAll(pointers, 2);
  EXPECT_TRUE(factors.isOk()) << factors.status().describe();
  return std::move(factors).value();
}

double relativeDifference(const std::vector<double>& ours, const std::vector<double>& reference) {
  double difference = 0.0, largest = 0.0;
  for (std::size_t k = 0; k < ours.size(); ++k) {
    difference = std::max(difference, std::abs(ours[k] - reference[k]));
    largest = std::max(largest, std::abs(reference[k]));
  }
  return largest > 0.0 ? difference / largest : difference;
}

// Dense right-hand sides, a unit one (the sparse forward substitution), and batches of 3 and of 10
// (more than are substituted together): the same solution as CHOLMOD's, and the same bytes on one
// thread and on two.
void expectAgreesWithCholmod(const CholeskyFactor& factor) {
  const std::size_t n = factor.size();
  for (const std::size_t columns : {std::size_t{1}, std::size_t{3}, std::size_t{10}}) {
    for (const bool unit : {false, true}) {
      std::vector<double> rhs(n * columns, 0.0);
      for (std::size_t c = 0; c < columns; ++c)
        for (std::size_t k = 0; k < n; ++k)
          if (unit ? k == (c + 1) * n / (columns + 2) : true)
            rhs[c * n + k] = unit ? 1.0 : 1.0 + 0.5 * std::sin(0.37 * static_cast<double>(k) + c);
      std::vector<double> ours(n * columns), twoThreads(n * columns), reference(n * columns);
      factor.solve(rhs, ours, columns, 1);
      factor.solve(rhs, twoThreads, columns, 2);
      factor.solveWithCholmod(rhs, reference, columns);
      EXPECT_LE(relativeDifference(ours, reference), 1e-12) << columns << " columns, unit " << unit;
      EXPECT_EQ(std::memcmp(ours.data(), twoThreads.data(), ours.size() * sizeof(double)), 0)
          << columns << " columns, unit " << unit;
    }
  }
}

TEST(HeatSubstitution, AgreesWithCholmodOnASmallSimplicialFactor) {
  const Surface s = testing::geodesicSphere(3, 1.0);  // 642 vertices: AMD, simplicial LDL'
  for (const CholeskyFactor& factor : factorise(heatMatrices(s))) {
    ASSERT_NE(factor.substitution(), nullptr);
    expectAgreesWithCholmod(factor);
  }
}

TEST(HeatSubstitution, AgreesWithCholmodOnASupernodalFactorSplitInTwo) {
  // 68,121 vertices: METIS, a supernodal factor turned simplicial LL', large enough for two threads.
  const Surface s = testing::planarGrid(260, 1.0);
  for (const CholeskyFactor& factor : factorise(heatMatrices(s))) {
    const SubstitutionPlan* plan = factor.substitution();
    ASSERT_NE(plan, nullptr);
    // Nested dissection: a top separator over two groups of subtrees, and supernodes as runs.
    EXPECT_GT(plan->topColumns(), 0u);
    EXPECT_LT(plan->topColumns(), factor.size() / 50);
    EXPECT_FALSE(plan->groups()[0].empty());
    EXPECT_FALSE(plan->groups()[1].empty());
    EXPECT_LT(plan->runCount(), factor.size() / 2);
    EXPECT_GE(plan->nonZeros(), SubstitutionPlan::kThreadedFromNonZeros);  // the threaded path
    expectAgreesWithCholmod(factor);
  }
}

// A large grid and a small sphere beside it: a forest whose one large tree must itself be split, so
// that the small tree does not leave one thread all the work.
Surface gridAndSphere() {
  const Surface grid = testing::planarGrid(260, 1.0), sphere = testing::geodesicSphere(2, 0.1);
  std::vector<Vec3d> positions = grid.positions;
  std::vector<std::array<std::uint32_t, 3>> triangles = grid.triangles;
  const auto offset = static_cast<std::uint32_t>(positions.size());
  for (const Vec3d& p : sphere.positions) positions.push_back({p[0] + 2.0, p[1], p[2]});
  for (const auto& t : sphere.triangles) triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return makeSurface(std::move(positions), std::move(triangles));
}

// A factor written by hand: two components (rows 0-3 and 4-6 of L), so the tree is a forest that
// splits at its (virtual) root, with a permutation.
struct HandFactor {
  std::vector<int> start, count, rows, permutation;
  std::vector<double> values;
  SimplicialFactorView view(bool unitDiagonal) const {
    return {start.size(), start.data(), count.data(), rows.data(), values.data(), permutation.data(),
            unitDiagonal};
  }
};

// Columns (row: value), the diagonal first.
HandFactor handFactor(const std::vector<std::vector<std::pair<int, double>>>& columns, std::vector<int> permutation) {
  HandFactor f;
  for (const auto& column : columns) {
    f.start.push_back(static_cast<int>(f.rows.size()));
    f.count.push_back(static_cast<int>(column.size()));
    for (const auto& [row, value] : column) {
      f.rows.push_back(row);
      f.values.push_back(value);
    }
  }
  f.permutation = std::move(permutation);
  return f;
}

HandFactor handFactor() {
  return handFactor({{{0, 2.0}, {1, 0.5}, {3, -0.25}}, {{1, 1.5}, {3, 0.75}}, {{2, 3.0}, {3, -1.0}}, {{3, 1.25}},
                     {{4, 1.0}, {5, 0.5}, {6, 0.125}}, {{5, 2.5}, {6, -0.5}}, {{6, 0.75}}},
                    {3, 6, 0, 5, 1, 4, 2});
}

// A forest whose first tree (rows 0-2: leaves 0 and 1 under 2) holds 5 of the 8 entries: its root
// joins the top part, which then lies between the groups' columns (leaves 0 and 1; the tree 3-4).
HandFactor factorWithTopInTheMiddle() {
  return handFactor({{{0, 2.0}, {2, 0.5}}, {{1, 1.5}, {2, -0.75}}, {{2, 3.0}}, {{3, 1.25}, {4, 0.5}}, {{4, 2.0}}},
                    {2, 4, 0, 3, 1});
}

// A = P' L D L' P (D = I and L's stored diagonal for LL'), multiplied out densely.
std::vector<std::vector<double>> denseMatrix(const HandFactor& f, bool unitDiagonal) {
  const std::size_t n = f.start.size();
  std::vector<std::vector<double>> l(n, std::vector<double>(n, 0.0)), a(n, std::vector<double>(n, 0.0));
  std::vector<double> d(n, 1.0);
  for (std::size_t j = 0; j < n; ++j)
    for (int k = f.start[j]; k < f.start[j] + f.count[j]; ++k) l[f.rows[k]][j] = f.values[k];
  if (unitDiagonal)
    for (std::size_t j = 0; j < n; ++j) std::swap(d[j], l[j][j]);
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < n; ++c)
      for (std::size_t k = 0; k < n; ++k)
        a[f.permutation[r]][f.permutation[c]] += l[r][k] * d[k] * l[c][k];
  return a;
}

// Two right-hand sides with known solutions, one column at a time and both together.
void expectSolvesByHand(const HandFactor& f, bool unitDiagonal) {
  const std::size_t n = f.start.size();
  const SubstitutionPlan plan(f.view(unitDiagonal));
  ASSERT_TRUE(plan.valid());
  const auto a = denseMatrix(f, unitDiagonal);
  std::vector<double> truth(2 * n), rhs(2 * n, 0.0), solution(2 * n);
  for (std::size_t k = 0; k < 2 * n; ++k) truth[k] = 1.0 + 0.25 * static_cast<double>(k % 5) - 0.1 * (k / n);
  for (std::size_t c = 0; c < 2; ++c)
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t k = 0; k < n; ++k) rhs[c * n + r] += a[r][k] * truth[c * n + k];
  for (const std::size_t columns : {std::size_t{1}, std::size_t{2}}) {
    plan.solve(std::span(rhs).first(columns * n), solution, columns, 2);
    for (std::size_t k = 0; k < columns * n; ++k)
      EXPECT_NEAR(solution[k], truth[k], 1e-12) << "unit diagonal " << unitDiagonal << ", entry " << k;
  }
}

TEST(HeatSubstitution, SolvesAFactorWrittenByHand) {
  for (const bool unitDiagonal : {false, true}) {
    const HandFactor f = handFactor();
    const SubstitutionPlan plan(f.view(unitDiagonal));
    // A forest of two trees near even (8 entries against 6): a group each, no top part.
    EXPECT_EQ(plan.topColumns(), 0u);
    EXPECT_FALSE(plan.groups()[0].empty());
    EXPECT_FALSE(plan.groups()[1].empty());
    expectSolvesByHand(f, unitDiagonal);

    const HandFactor middle = factorWithTopInTheMiddle();
    const SubstitutionPlan middlePlan(middle.view(unitDiagonal));
    ASSERT_EQ(middlePlan.topRanges().size(), 1u);
    EXPECT_EQ(middlePlan.topRanges().front(), std::make_pair(2, 3));
    EXPECT_EQ(middlePlan.groups()[0], (std::vector<std::pair<int, int>>{{3, 5}}));
    EXPECT_EQ(middlePlan.groups()[1], (std::vector<std::pair<int, int>>{{0, 1}, {1, 2}}));
    expectSolvesByHand(middle, unitDiagonal);
  }
}

TEST(HeatSubstitution, RefusesAFactorNotLaidOutAsExpected) {
  HandFactor f = handFactor();
  std::swap(f.rows[0], f.rows[1]);  // column 0 no longer opens with its diagonal
  std::swap(f.values[0], f.values[1]);
  EXPECT_FALSE(SubstitutionPlan(f.view(false)).valid());
  HandFactor above = handFactor();
  above.rows[4] = 0;  // column 1 holds a row above its diagonal
  EXPECT_FALSE(SubstitutionPlan(above.view(false)).valid());
  HandFactor repeated = handFactor();
  repeated.permutation[1] = 3;  // row 3 twice, row 6 never
  EXPECT_FALSE(SubstitutionPlan(repeated.view(false)).valid());
  HandFactor outside = handFactor();
  outside.permutation[0] = 7;  // past the last row
  EXPECT_FALSE(SubstitutionPlan(outside.view(false)).valid());
}

// Every column of a batch is what it is when solved alone, to the last bit, whatever the batch's size
// (1 to 8 kernels), layout or thread count; and the in-place solve in L's row order is the same solve.
void expectBatchesEqualSingleColumns(const CholeskyFactor& factor) {
  const SubstitutionPlan& plan = *factor.substitution();
  const std::size_t n = factor.size();
  constexpr std::size_t kColumns = 11;  // a batch of 8 and one of 3
  std::vector<double> rhs(n * kColumns);
  for (std::size_t c = 0; c < kColumns; ++c)
    for (std::size_t k = 0; k < n; ++k)
      rhs[c * n + k] = c % 3 == 0 ? (k == (c * 7919) % n ? 1.0 : 0.0)  // sparse, as step I's
                                  : std::cos(0.11 * static_cast<double>(k) * (1.0 + static_cast<double>(c)));
  std::vector<double> alone(n * kColumns);
  for (std::size_t c = 0; c < kColumns; ++c)
    plan.solve(std::span(rhs).subspan(c * n, n), std::span(alone).subspan(c * n, n), 1, 1);
  const auto expectSame = [&](const std::vector<double>& x, ColumnLayout layout, std::size_t columns,
                              const char* what) {
    std::size_t differing = 0;
    for (std::size_t c = 0; c < columns; ++c)
      for (std::size_t k = 0; k < n; ++k) {
        const double value = layout == ColumnLayout::Interleaved ? x[k * columns + c] : x[c * n + k];
        differing += value != alone[c * n + k];
      }
    EXPECT_EQ(differing, 0u) << what << ", " << columns << " columns";
  };
  for (const std::size_t columns : {std::size_t{2}, std::size_t{5}, std::size_t{8}, kColumns}) {
    std::vector<double> consecutive(n * columns), interleavedRhs(n * columns), interleaved(n * columns);
    for (const unsigned threads : {1u, 2u}) {
      plan.solve(std::span(rhs).first(n * columns), consecutive, columns, threads);
      expectSame(consecutive, ColumnLayout::Consecutive, columns, "consecutive");
      for (std::size_t c = 0; c < columns; ++c)
        for (std::size_t k = 0; k < n; ++k) interleavedRhs[k * columns + c] = rhs[c * n + k];
      plan.solve(interleavedRhs, interleaved, columns, threads, ColumnLayout::Interleaved);
      expectSame(interleaved, ColumnLayout::Interleaved, columns, "interleaved");
    }
    if (columns > SubstitutionPlan::kMaxColumns) continue;
    // In L's row order: row k holds A's row permutation()[k].
    std::vector<double> work(n * columns);
    const auto rowOfL = [&](std::size_t k) { return plan.permutation() ? static_cast<std::size_t>(plan.permutation()[k]) : k; };
    for (std::size_t k = 0; k < n; ++k)
      for (std::size_t c = 0; c < columns; ++c) work[k * columns + c] = rhs[c * n + rowOfL(k)];
    plan.solveInFactorOrder(work, columns, 2);
    for (std::size_t k = 0; k < n; ++k)
      for (std::size_t c = 0; c < columns; ++c) interleaved[rowOfL(k) * columns + c] = work[k * columns + c];
    expectSame(interleaved, ColumnLayout::Interleaved, columns, "in factor order");
  }
  std::vector<double> tooMany(n * (SubstitutionPlan::kMaxColumns + 1));
  EXPECT_THROW(plan.solveInFactorOrder(tooMany, SubstitutionPlan::kMaxColumns + 1, 1), std::invalid_argument);
}

TEST(HeatSubstitution, BatchedColumnsEqualColumnsSolvedAlone) {
  for (const Surface& s : {testing::geodesicSphere(3, 1.0), testing::planarGrid(260, 1.0)})
    for (const CholeskyFactor& factor : factorise(heatMatrices(s))) {
      ASSERT_NE(factor.substitution(), nullptr);
      expectBatchesEqualSingleColumns(factor);
    }
}

// Interleaved right-hand sides: the solution CHOLMOD gives for the same columns one after another.
TEST(HeatSubstitution, InterleavedColumnsAgreeWithCholmod) {
  const Surface s = testing::geodesicSphere(3, 1.0);
  const std::vector<CholeskyFactor> factors = factorise(heatMatrices(s));
  const CholeskyFactor& factor = factors[0];
  const std::size_t n = factor.size(), columns = 3;
  std::vector<double> consecutive(n * columns), interleaved(n * columns);
  for (std::size_t c = 0; c < columns; ++c)
    for (std::size_t k = 0; k < n; ++k) {
      consecutive[c * n + k] = std::sin(0.3 * static_cast<double>(k) + static_cast<double>(c));
      interleaved[k * columns + c] = consecutive[c * n + k];
    }
  std::vector<double> reference(n * columns), ours(n * columns);
  factor.solveWithCholmod(consecutive, reference, columns);
  factor.solve(interleaved, ours, columns, 1, ColumnLayout::Interleaved);
  double worst = 0.0;
  for (std::size_t c = 0; c < columns; ++c)
    for (std::size_t k = 0; k < n; ++k) worst = std::max(worst, std::abs(ours[k * columns + c] - reference[c * n + k]));
  EXPECT_LE(worst, 1e-12);
}

TEST(HeatSubstitution, SplitsTheLargeTreeOfAForest) {
  for (const CholeskyFactor& factor : factorise(heatMatrices(gridAndSphere()))) {
    const SubstitutionPlan* plan = factor.substitution();
    ASSERT_NE(plan, nullptr);
    // Neither group holds twice the other's columns.
    std::array<std::size_t, 2> columns{0, 0};
    for (std::size_t g = 0; g < 2; ++g)
      for (const auto& [begin, end] : plan->groups()[g]) columns[g] += static_cast<std::size_t>(end - begin);
    EXPECT_GT(plan->topColumns(), 0u);
    EXPECT_LT(std::max(columns[0], columns[1]), 2 * std::min(columns[0], columns[1]))
        << columns[0] << " and " << columns[1] << " columns";
    expectAgreesWithCholmod(factor);
    expectBatchesEqualSingleColumns(factor);
  }
}

}  // namespace
}  // namespace bake::geodesic
