// Substitution with a simplicial Cholesky factor, split over the elimination tree (see the header).
//
// The elimination tree's parent of column j is the smallest row below the diagonal in column j.
// CHOLMOD postorders its analysis, so every subtree is a contiguous range of columns ending at its
// root. Walking down from the root while a node has one child gives the top chain [top, n); the
// subtrees of the node where it branches cover [0, top) and go to two groups, heaviest first to the
// lighter group. The split is then checked against the factor itself (every entry of a group's
// column lies in its own range or in the top part); a factor that fails the check, or a tree that
// does not branch, is substituted as one part.
#include "geodesic/bake/heat_substitution.h"

#include <algorithm>

#include "core/parallel.h"

namespace bake::geodesic {
namespace {

// The most right-hand sides substituted together (the work array interleaves them).
constexpr std::size_t kMaxColumns = 8;

// True when every entry of the columns in `ranges` lies in one of those ranges or in [top, n).
bool rangesAreClosed(const SimplicialFactorView& f, const std::vector<std::pair<int, int>>& ranges,
                     std::size_t top) {
  for (const auto& [begin, end] : ranges)
    for (int j = begin; j < end; ++j)
      for (int k = f.start[j]; k < f.start[j] + f.count[j]; ++k) {
        const int i = f.rows[k];
        if (static_cast<std::size_t>(i) >= top) continue;
        if (i < begin || i >= end) return false;  // a subtree's column reaches outside its own range
      }
  return true;
}

// True when column c holds column j's entries from its r-th on (its diagonal first, at j's r-th).
bool continuesRun(const SimplicialFactorView& f, int j, int r, int c) {
  if (f.count[j] - r != f.count[c]) return false;
  return std::equal(f.rows + f.start[j] + r, f.rows + f.start[j] + f.count[j], f.rows + f.start[c]);
}

}  // namespace

// Consecutive columns whose entries below the run are the same rows (a supernode stored column by
// column) form runs of up to 4, each run inside one range so that no run crosses a group's bounds.
void SubstitutionPlan::findRuns() {
  runs_.assign(factor_.size, 0);
  runStarts_.clear();
  std::vector<std::pair<int, int>> ranges = groups_[0];
  ranges.insert(ranges.end(), groups_[1].begin(), groups_[1].end());
  ranges.push_back({static_cast<int>(top_), static_cast<int>(factor_.size)});
  for (const auto& [begin, end] : ranges)
    for (int j = begin; j < end;) {
      int r = 1;
      while (r < 4 && j + r < end && continuesRun(factor_, j, r, j + r)) ++r;
      runs_[j] = static_cast<unsigned char>(r);
      j += r;
    }
  for (std::size_t j = 0; j < factor_.size; ++j)
    if (runs_[j] > 0) runStarts_.push_back(static_cast<int>(j));
}

SubstitutionPlan::SubstitutionPlan(const SimplicialFactorView& factor) : factor_(factor) {
  const std::size_t n = factor.size;
  top_ = 0;
  // The elimination tree's parent of each column (its smallest row below the diagonal; -1 for a root),
  // found while checking the layout.
  std::vector<int> parent(n, -1);
  for (std::size_t j = 0; j < n; ++j) {
    // Every column must open with its diagonal and stay inside the matrix.
    if (factor.count[j] < 1 || factor.rows[factor.start[j]] != static_cast<int>(j)) return;
    for (int k = factor.start[j] + 1; k < factor.start[j] + factor.count[j]; ++k) {
      const int i = factor.rows[k];
      if (i <= static_cast<int>(j) || static_cast<std::size_t>(i) >= n) return;
      if (parent[j] < 0 || i < parent[j]) parent[j] = i;
    }
    nonZeros_ += static_cast<std::size_t>(factor.count[j]);
  }
  // The permutation, if any, must name every row once: solve() reads and writes through it.
  if (factor.permutation) {
    std::vector<char> seen(n, 0);
    for (std::size_t k = 0; k < n; ++k) {
      const int row = factor.permutation[k];
      if (row < 0 || static_cast<std::size_t>(row) >= n || seen[static_cast<std::size_t>(row)]) return;
      seen[static_cast<std::size_t>(row)] = 1;
    }
  }
  valid_ = true;
  splitTree(parent);
  findRuns();
}

// See the file comment: the top chain and two groups of subtrees below it.
void SubstitutionPlan::splitTree(const std::vector<int>& parent) {
  const SimplicialFactorView& factor = factor_;
  const std::size_t n = factor.size;
  if (n < 2) return;
  // Per node (n: a virtual root above the tree's roots) its number of children and its last child.
  std::vector<int> childCount(n + 1, 0), lastChild(n + 1, -1);
  std::vector<std::size_t> subtreeSize(n, 1), subtreeWork(n, 0);
  const auto parentOf = [&](std::size_t j) { return parent[j] < 0 ? n : static_cast<std::size_t>(parent[j]); };
  for (std::size_t j = 0; j < n; ++j) {
    subtreeWork[j] += static_cast<std::size_t>(factor.count[j]);
    ++childCount[parentOf(j)];
    lastChild[parentOf(j)] = static_cast<int>(j);
    if (parent[j] >= 0) {
      subtreeSize[parent[j]] += subtreeSize[j];
      subtreeWork[parent[j]] += subtreeWork[j];
    }
  }
  // Down the chain from the (virtual) root to the first node with several children.
  std::size_t node = n;
  while (childCount[node] == 1) node = static_cast<std::size_t>(lastChild[node]);
  if (childCount[node] < 2) return;
  top_ = node;
  std::vector<int> subtrees;
  for (std::size_t j = 0; j < node; ++j)
    if (parentOf(j) == node) subtrees.push_back(static_cast<int>(j));
  std::stable_sort(subtrees.begin(), subtrees.end(),
                   [&](int a, int b) { return subtreeWork[a] > subtreeWork[b]; });
  std::array<std::size_t, 2> load{0, 0};
  for (int root : subtrees) {
    const std::size_t g = load[1] < load[0] ? 1 : 0;
    load[g] += subtreeWork[root];
    groups_[g].push_back({root + 1 - static_cast<int>(subtreeSize[root]), root + 1});
  }
  for (auto& ranges : groups_) std::sort(ranges.begin(), ranges.end());
  // Postorder makes the subtrees cover [0, top) exactly; anything else falls back to one part.
  std::size_t covered = 0;
  for (const auto& ranges : groups_)
    for (const auto& [begin, end] : ranges) covered += static_cast<std::size_t>(end - begin);
  if (covered != top_ || !rangesAreClosed(factor, groups_[0], top_) || !rangesAreClosed(factor, groups_[1], top_)) {
    top_ = 0;
    groups_ = {};
  }
}

namespace {

// Forward substitution over columns [begin, end): L y = b in place. Updates of rows at or past
// `top` go to `topBuffer` (row i at (i - top) * M) when it is given.
template <std::size_t M>
void forward(const SimplicialFactorView& f, int begin, int end, double* work, std::size_t top,
             double* topBuffer) {
  for (int j = begin; j < end; ++j) {
    double* x = work + static_cast<std::size_t>(j) * M;
    if (!f.unitDiagonal) {
      const double d = f.values[f.start[j]];
      for (std::size_t c = 0; c < M; ++c) x[c] /= d;
    }
    bool zero = true;
    for (std::size_t c = 0; c < M; ++c) zero = zero && x[c] == 0.0;
    if (zero) continue;  // a sparse right-hand side: nothing to pass on
    const int last = f.start[j] + f.count[j];
    for (int k = f.start[j] + 1; k < last; ++k) {
      const auto i = static_cast<std::size_t>(f.rows[k]);
      const double l = f.values[k];
      double* y = topBuffer && i >= top ? topBuffer + (i - top) * M : work + i * M;
      for (std::size_t c = 0; c < M; ++c) y[c] -= l * x[c];
    }
  }
}

// Back substitution over columns [begin, end), last first: L' x = y in place (D y first for LDL').
template <std::size_t M>
void backward(const SimplicialFactorView& f, int begin, int end, double* work) {
  for (int j = end - 1; j >= begin; --j) {
    double sum[M];
    double* x = work + static_cast<std::size_t>(j) * M;
    const double d = f.values[f.start[j]];
    for (std::size_t c = 0; c < M; ++c) sum[c] = f.unitDiagonal ? x[c] / d : x[c];
    const int last = f.start[j] + f.count[j];
    for (int k = f.start[j] + 1; k < last; ++k) {
      const double l = f.values[k];
      const double* y = work + static_cast<std::size_t>(f.rows[k]) * M;
      for (std::size_t c = 0; c < M; ++c) sum[c] -= l * y[c];
    }
    for (std::size_t c = 0; c < M; ++c) x[c] = f.unitDiagonal ? sum[c] : sum[c] / d;
  }
}

// One right-hand side, a run of R columns j .. j+R-1 at a time (see findRuns): the run's own
// triangle first, then its shared rows, each read or updated once for the R columns.
template <int R>
void forwardRun(const SimplicialFactorView& f, int j, double* work, std::size_t top, double* topBuffer) {
  double x[R];
  bool zero = true;
  for (int t = 0; t < R; ++t) {
    const int s = f.start[j + t];
    x[t] = f.unitDiagonal ? work[j + t] : work[j + t] / f.values[s];
    for (int u = 1; u < R - t; ++u) work[j + t + u] -= f.values[s + u] * x[t];
    zero = zero && x[t] == 0.0;
  }
  for (int t = 0; t < R; ++t) work[j + t] = x[t];
  if (zero) return;  // a sparse right-hand side: nothing to pass on
  const int shared = f.count[j] - R;
  const int* rows = f.rows + f.start[j] + R;
  const double* l[R];
  for (int t = 0; t < R; ++t) l[t] = f.values + f.start[j + t] + (R - t);
  for (int k = 0; k < shared; ++k) {
    double delta = l[0][k] * x[0];
    for (int t = 1; t < R; ++t) delta += l[t][k] * x[t];
    const auto i = static_cast<std::size_t>(rows[k]);
    if (topBuffer && i >= top) topBuffer[i - top] -= delta;
    else work[i] -= delta;
  }
}

template <int R>
void backwardRun(const SimplicialFactorView& f, int j, double* work) {
  const int shared = f.count[j] - R;
  const int* rows = f.rows + f.start[j] + R;
  const double* l[R];
  for (int t = 0; t < R; ++t) l[t] = f.values + f.start[j + t] + (R - t);
  // One column alone keeps four partial sums, so that the additions do not wait on each other.
  constexpr int kPartial = R == 1 ? 4 : 1;
  double sum[R][kPartial] = {};
  int k = 0;
  for (; k + kPartial <= shared; k += kPartial)
    for (int p = 0; p < kPartial; ++p) {
      const double y = work[rows[k + p]];
      for (int t = 0; t < R; ++t) sum[t][p] += l[t][k + p] * y;
    }
  for (; k < shared; ++k)
    for (int t = 0; t < R; ++t) sum[t][0] += l[t][k] * work[rows[k]];
  for (int t = R - 1; t >= 0; --t) {
    const int s = f.start[j + t];
    double total = sum[t][0];
    for (int p = 1; p < kPartial; ++p) total += sum[t][p];
    for (int u = 1; u < R - t; ++u) total += f.values[s + u] * work[j + t + u];
    const double d = f.values[s];
    work[j + t] = f.unitDiagonal ? work[j + t] / d - total : (work[j + t] - total) / d;
  }
}

void forwardRuns(const SimplicialFactorView& f, const std::vector<unsigned char>& runs, int begin, int end,
                 double* work, std::size_t top, double* topBuffer) {
  for (int j = begin; j < end; j += runs[j]) switch (runs[j]) {
      case 1: forwardRun<1>(f, j, work, top, topBuffer); break;
      case 2: forwardRun<2>(f, j, work, top, topBuffer); break;
      case 3: forwardRun<3>(f, j, work, top, topBuffer); break;
      default: forwardRun<4>(f, j, work, top, topBuffer); break;
    }
}

// Runs start where runs[j] > 0; walking back, a run's last column is found by its start's length.
void backwardRuns(const SimplicialFactorView& f, const std::vector<int>& runStarts, int begin, int end,
                  double* work) {
  auto first = std::lower_bound(runStarts.begin(), runStarts.end(), begin);
  auto last = std::lower_bound(runStarts.begin(), runStarts.end(), end);
  for (auto it = last; it != first;) {
    --it;
    const int j = *it;
    const int length = (it + 1 != runStarts.end() ? std::min(*(it + 1), end) : end) - j;
    switch (length) {
      case 1: backwardRun<1>(f, j, work); break;
      case 2: backwardRun<2>(f, j, work); break;
      case 3: backwardRun<3>(f, j, work); break;
      default: backwardRun<4>(f, j, work); break;
    }
  }
}

}  // namespace

template <std::size_t M>
void SubstitutionPlan::solveColumns(double* work, unsigned threads) const {
  const SimplicialFactorView& f = factor_;
  const std::size_t n = f.size;
  const bool split = top_ > 0;
  const unsigned workers = split && nonZeros_ >= kThreadedFromNonZeros ? threads : 1u;
  const auto forwardRange = [&](int begin, int end, double* topBuffer) {
    if constexpr (M == 1) forwardRuns(f, runs_, begin, end, work, top_, topBuffer);
    else forward<M>(f, begin, end, work, top_, topBuffer);
  };
  const auto backwardRange = [&](int begin, int end) {
    if constexpr (M == 1) backwardRuns(f, runStarts_, begin, end, work);
    else backward<M>(f, begin, end, work);
  };
  if (split) {
    // The groups' updates of the top part, added to it in group order.
    std::array<std::vector<double>, 2> topBuffers;
    parallelForBlocks(2, 1, workers, [&](std::size_t g, std::size_t) {
      topBuffers[g].assign((n - top_) * M, 0.0);
      for (const auto& [begin, end] : groups_[g]) forwardRange(begin, end, topBuffers[g].data());
    });
    for (std::size_t g = 0; g < 2; ++g)
      for (std::size_t k = 0; k < (n - top_) * M; ++k) work[top_ * M + k] += topBuffers[g][k];
  }
  forwardRange(static_cast<int>(top_), static_cast<int>(n), nullptr);
  backwardRange(static_cast<int>(top_), static_cast<int>(n));
  if (split)
    parallelForBlocks(2, 1, workers, [&](std::size_t g, std::size_t) {
      for (auto range = groups_[g].rbegin(); range != groups_[g].rend(); ++range)
        backwardRange(range->first, range->second);
    });
}

void SubstitutionPlan::solve(std::span<const double> rhs, std::span<double> solution, std::size_t columns,
                             unsigned threads) const {
  const std::size_t n = factor_.size;
  std::vector<double> work;
  for (std::size_t first = 0; first < columns; first += kMaxColumns) {
    const std::size_t m = std::min(kMaxColumns, columns - first);
    // Interleaved (row k holds the m right-hand sides side by side) and permuted: row k is A's row
    // permutation[k].
    work.assign(n * m, 0.0);
    for (std::size_t c = 0; c < m; ++c) {
      const double* b = rhs.data() + (first + c) * n;
      for (std::size_t k = 0; k < n; ++k)
        work[k * m + c] = b[factor_.permutation ? static_cast<std::size_t>(factor_.permutation[k]) : k];
    }
    switch (m) {
      case 1: solveColumns<1>(work.data(), threads); break;
      case 2: solveColumns<2>(work.data(), threads); break;
      case 3: solveColumns<3>(work.data(), threads); break;
      case 4: solveColumns<4>(work.data(), threads); break;
      case 5: solveColumns<5>(work.data(), threads); break;
      case 6: solveColumns<6>(work.data(), threads); break;
      case 7: solveColumns<7>(work.data(), threads); break;
      default: solveColumns<8>(work.data(), threads); break;
    }
    for (std::size_t c = 0; c < m; ++c) {
      double* x = solution.data() + (first + c) * n;
      for (std::size_t k = 0; k < n; ++k)
        x[factor_.permutation ? static_cast<std::size_t>(factor_.permutation[k]) : k] = work[k * m + c];
    }
  }
}

}  // namespace bake::geodesic
