// Forward and back substitution with a simplicial sparse Cholesky factor (A = P' L L' P, or
// P' L D L' P with L unit), our own instead of CHOLMOD's solve, for two reasons that the heat method's
// fields feel (Crane, Weischedel and Wardetzky 2013, Algorithm 1, steps I and III):
//   - Step I's right-hand side is zero but at the source's corners, so the forward substitution skips
//     every column whose value is still zero: only the source's path to the root of the elimination
//     tree does any work (Gilbert and Peierls' observation for sparse right-hand sides).
//   - Below a top part (the top separator's chain, and on a forest the chain of its largest tree) the
//     elimination tree splits into subtrees that share no row but the top part's, so two threads
//     substitute one group of subtrees each (their updates of the top part go to a private buffer per
//     group, added in a fixed order). The groups depend only on the factor, never on the thread
//     count, so neither does the solution.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

namespace bake::geodesic {

// A simplicial factor in CHOLMOD's layout (not owned): column j's entries are rows[start[j] ..
// start[j] + count[j]), the diagonal first. `permutation[k]` is the row of A that is row k of L (null:
// none). With `unitDiagonal`, L's diagonal is 1 and the stored diagonal is D.
struct SimplicialFactorView {
  std::size_t size = 0;
  const int* start = nullptr;
  const int* count = nullptr;
  const int* rows = nullptr;
  const double* values = nullptr;
  const int* permutation = nullptr;
  bool unitDiagonal = false;
};

// How several right-hand sides (or solutions) are stored: column after column (row r of column c at
// c * rows + r), or interleaved (row r's values side by side, at r * columns + c).
enum class ColumnLayout { Consecutive, Interleaved };

class SubstitutionPlan {
 public:
  SubstitutionPlan() = default;
  explicit SubstitutionPlan(const SimplicialFactorView& factor);

  // Solves A X = B for `columns` right-hand sides stored as `layout` says, on up to `threads`
  // threads (0: all cores). The solution depends neither on `threads` nor on which columns are solved
  // together: each is what it would be alone.
  void solve(std::span<const double> rhs, std::span<double> solution, std::size_t columns,
             unsigned threads, ColumnLayout layout = ColumnLayout::Consecutive) const;

  // The same for at most kMaxColumns right-hand sides already interleaved and in L's row order (row k
  // is A's row permutation()[k]), in place: no copies in or out.
  void solveInFactorOrder(std::span<double> work, std::size_t columns, unsigned threads) const;
  static constexpr std::size_t kMaxColumns = 8;
  // A's row of each row of L (null: the identity).
  const int* permutation() const { return factor_.permutation; }

  // False when the factor is not laid out as described, or its permutation is not one (the caller
  // then solves some other way).
  bool valid() const { return valid_; }
  // The columns substituted by one thread (ascending ranges), and the two groups of subtrees below
  // them (empty when the tree does not split: then the top part is every column).
  const std::vector<std::pair<int, int>>& topRanges() const { return topRanges_; }
  std::size_t topColumns() const;
  const std::array<std::vector<std::pair<int, int>>, 2>& groups() const { return groups_; }
  // Entries of L, and from how many the substitution uses more than one thread (below, a pass takes
  // under a millisecond: not worth starting a thread).
  std::size_t nonZeros() const { return nonZeros_; }
  static constexpr std::size_t kThreadedFromNonZeros = 1000000;
  // Runs of columns substituted together (at most size(); fewer where columns share their rows).
  std::size_t runCount() const { return runStarts_.size(); }

 private:
  // The m right-hand sides interleaved in `work` (row k's values side by side), in place.
  void solveColumns(double* work, std::size_t m, unsigned threads) const;
  void splitTree(const std::vector<int>& parent);
  void findRuns();

  SimplicialFactorView factor_;
  std::vector<std::pair<int, int>> topRanges_;  // [begin, end) column ranges, ascending
  std::vector<int> topRows_;                    // the top part's columns, ascending
  std::vector<int> topIndex_;                   // per column, its place in topRows_ (-1: in a group)
  std::array<std::vector<std::pair<int, int>>, 2> groups_;  // [begin, end) column ranges, ascending
  std::size_t nonZeros_ = 0;
  bool valid_ = false;
  std::vector<unsigned char> runs_;  // at a run's first column, its length (1 to 4); 0 elsewhere
  std::vector<int> runStarts_;       // the runs' first columns, ascending
};

}  // namespace bake::geodesic
