// Substitution with a simplicial Cholesky factor, split over the elimination tree (see the header).
//
// The elimination tree's parent of column j is the smallest row below the diagonal in column j.
// CHOLMOD postorders its analysis, so every subtree is a contiguous range of columns ending at its
// root. The top part starts empty, with the trees below the (virtual) root as candidates. While the
// heaviest candidate holds more than 60 % of the candidates' work (no two groups of them could be
// near even), its chain down to the first node with several children joins the top part, and that
// node's children become candidates. The candidates then go to two groups, heaviest first to the lighter
// group. On a nested-dissection tree that is the top separator's chain and its two halves; on a
// forest with one large component, that component's chain and the halves below it, with the small
// components. The top part holds every group's ancestors, so a group's columns reach only their own
// range and the top part; the split is checked against the factor itself, and a factor that fails
// the check, or a tree that does not branch, is substituted as one part.
#include "geodesic/bake/heat_substitution.h"

#include <algorithm>
#include <queue>
#include <stdexcept>

#include "core/parallel.h"
#include "core/vector_clones.h"

namespace bake::geodesic {
namespace {

// The most right-hand sides substituted together (the work array interleaves them).
constexpr std::size_t kMaxColumns = SubstitutionPlan::kMaxColumns;

// True when every entry of a column in one of `ranges` lies in that range, or past it in the top part
// (the kernels take a row past the range for a row of the top part).
bool rangesAreClosed(const SimplicialFactorView& f, const std::vector<std::pair<int, int>>& ranges,
                     const std::vector<int>& topIndex) {
  for (const auto& [begin, end] : ranges)
    for (int j = begin; j < end; ++j)
      for (int k = f.start[j]; k < f.start[j] + f.count[j]; ++k) {
        const int i = f.rows[k];
        if (i >= begin && i < end) continue;
        if (i < end || topIndex[static_cast<std::size_t>(i)] < 0) return false;
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
  ranges.insert(ranges.end(), topRanges_.begin(), topRanges_.end());
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
  if (groups_[0].empty() || groups_[1].empty()) {  // one part: all columns in the top part, in order
    groups_ = {};
    topIndex_.clear();
    topRows_.clear();
    topRanges_ = {{0, static_cast<int>(n)}};
  }
  findRuns();
}

// See the file comment: the top part and two groups of subtrees hanging from it.
void SubstitutionPlan::splitTree(const std::vector<int>& parent) {
  const SimplicialFactorView& factor = factor_;
  const std::size_t n = factor.size;
  if (n < 2) return;
  // Children lists (node n: a virtual root above the trees' roots), subtree sizes and work.
  std::vector<int> firstChild(n + 1, -1), nextSibling(n, -1), childCount(n + 1, 0);
  std::vector<std::size_t> subtreeSize(n, 1), subtreeWork(n, 0);
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t up = parent[j] < 0 ? n : static_cast<std::size_t>(parent[j]);
    nextSibling[j] = firstChild[up];
    firstChild[up] = static_cast<int>(j);
    ++childCount[up];
    subtreeWork[j] += static_cast<std::size_t>(factor.count[j]);
    if (parent[j] >= 0) {
      subtreeSize[parent[j]] += subtreeSize[j];
      subtreeWork[parent[j]] += subtreeWork[j];
    }
  }
  // Candidates in the order they arrive; the heaviest is found by a heap (ties: the earliest), so
  // that a long chain of lopsided branchings costs O(n log n), not a scan of every candidate per step.
  std::vector<char> inTop(n, 0);
  std::vector<int> arrived;
  std::vector<char> taken;
  std::priority_queue<std::pair<std::size_t, std::ptrdiff_t>> heaviestFirst;  // (work, -arrival)
  std::size_t total = 0, waiting = 0;
  const auto arrive = [&](int node) {
    heaviestFirst.push({subtreeWork[node], -static_cast<std::ptrdiff_t>(arrived.size())});
    arrived.push_back(node);
    taken.push_back(0);
    total += subtreeWork[node];
    ++waiting;
  };
  for (int c = firstChild[n]; c >= 0; c = nextSibling[c]) arrive(c);
  for (;;) {
    if (waiting == 0) return;  // the whole tree is one chain: nothing to split
    const auto [work, order] = heaviestFirst.top();
    if (waiting >= 2 && 5 * work <= 3 * total) break;
    heaviestFirst.pop();
    const auto k = static_cast<std::size_t>(-order);
    taken[k] = 1;
    total -= work;
    --waiting;
    int node = arrived[k];
    inTop[node] = 1;
    while (childCount[node] == 1) {
      node = firstChild[node];
      inTop[node] = 1;
    }
    for (int c = firstChild[node]; c >= 0; c = nextSibling[c]) arrive(c);
  }
  std::vector<int> candidates;
  for (std::size_t k = 0; k < arrived.size(); ++k)
    if (!taken[k]) candidates.push_back(arrived[k]);
  std::stable_sort(candidates.begin(), candidates.end(),
                   [&](int a, int b) { return subtreeWork[a] > subtreeWork[b]; });
  std::array<std::size_t, 2> load{0, 0};
  for (int root : candidates) {
    const std::size_t g = load[1] < load[0] ? 1 : 0;
    load[g] += subtreeWork[root];
    groups_[g].push_back({root + 1 - static_cast<int>(subtreeSize[root]), root + 1});
  }
  for (auto& ranges : groups_) std::sort(ranges.begin(), ranges.end());
  // The top part's rows in order, each with its place in a group's buffer, and as ranges of columns.
  topIndex_.assign(n, -1);
  for (std::size_t j = 0; j < n; ++j)
    if (inTop[j]) {
      topIndex_[j] = static_cast<int>(topRows_.size());
      topRows_.push_back(static_cast<int>(j));
      if (topRanges_.empty() || topRanges_.back().second != static_cast<int>(j))
        topRanges_.push_back({static_cast<int>(j), static_cast<int>(j) + 1});
      else
        ++topRanges_.back().second;
    }
  // Postorder makes the groups and the top part cover the columns exactly once; anything else falls
  // back to one part.
  std::vector<char> covered = inTop;
  bool once = true;
  for (const auto& ranges : groups_)
    for (const auto& [begin, end] : ranges)
      for (int j = begin; j < end; ++j) {
        once = once && !covered[static_cast<std::size_t>(j)];
        covered[static_cast<std::size_t>(j)] = 1;
      }
  if (!once || std::find(covered.begin(), covered.end(), 0) != covered.end() ||
      !rangesAreClosed(factor, groups_[0], topIndex_) || !rangesAreClosed(factor, groups_[1], topIndex_)) {
    groups_ = {};
    topIndex_.clear();
    topRows_.clear();
    topRanges_.clear();
  }
}

namespace {

// The kernels below are templates over a run's length R (1 to 4, see findRuns) and the number M of
// right-hand sides substituted together (1 to kMaxColumns, interleaved: row i's values are
// work[i * M .. i * M + M)). Every right-hand side goes through the same operations in the same order
// whatever M is, so a batch's solutions are those of its columns solved one at a time, bit for bit;
// the M values of a row sit side by side, so the compiler turns the loops over them into vector
// operations.

// Forward substitution of a run of R columns j .. j+R-1 (L y = b in place): the run's own triangle
// first, then its shared rows, each read or updated once for the R columns. With `topBuffer`, the run
// lies in a group's range ending at `limit`, and its updates of rows at or past `limit` (rows of the
// top part) go to the buffer, row i at topIndex[i] * M.
template <int R, std::size_t M>
BAKE_INLINE_KERNEL void forwardRun(const SimplicialFactorView& f, int j, double* work, std::size_t limit,
                                   const int* topIndex, double* topBuffer) {
  double x[R][M];
  bool zero = true;
  for (int t = 0; t < R; ++t) {
    const int s = f.start[j + t];
    const double* b = work + static_cast<std::size_t>(j + t) * M;
    for (std::size_t c = 0; c < M; ++c) x[t][c] = f.unitDiagonal ? b[c] : b[c] / f.values[s];
    for (int u = 1; u < R - t; ++u) {
      double* y = work + static_cast<std::size_t>(j + t + u) * M;
      for (std::size_t c = 0; c < M; ++c) y[c] -= f.values[s + u] * x[t][c];
    }
    for (std::size_t c = 0; c < M; ++c) zero = zero && x[t][c] == 0.0;
  }
  for (int t = 0; t < R; ++t)
    for (std::size_t c = 0; c < M; ++c) work[static_cast<std::size_t>(j + t) * M + c] = x[t][c];
  if (zero) return;  // a sparse right-hand side: nothing to pass on
  const int shared = f.count[j] - R;
  const int* rows = f.rows + f.start[j] + R;
  const double* l[R];
  for (int t = 0; t < R; ++t) l[t] = f.values + f.start[j + t] + (R - t);
  for (int k = 0; k < shared; ++k) {
    double delta[M];
    for (std::size_t c = 0; c < M; ++c) delta[c] = l[0][k] * x[0][c];
    for (int t = 1; t < R; ++t)
      for (std::size_t c = 0; c < M; ++c) delta[c] += l[t][k] * x[t][c];
    const auto i = static_cast<std::size_t>(rows[k]);
    double* y = topBuffer && i >= limit ? topBuffer + static_cast<std::size_t>(topIndex[i]) * M : work + i * M;
    for (std::size_t c = 0; c < M; ++c) y[c] -= delta[c];
  }
}

// Back substitution of a run (L' x = y in place, D y first for LDL'), its shared rows first.
template <int R, std::size_t M>
BAKE_INLINE_KERNEL void backwardRun(const SimplicialFactorView& f, int j, double* work) {
  const int shared = f.count[j] - R;
  const int* rows = f.rows + f.start[j] + R;
  const double* l[R];
  for (int t = 0; t < R; ++t) l[t] = f.values + f.start[j + t] + (R - t);
  // A column alone keeps four partial sums per right-hand side, so that the additions do not wait
  // on each other.
  constexpr int kPartial = R == 1 ? 4 : 1;
  double sum[R][kPartial][M] = {};
  int k = 0;
  for (; k + kPartial <= shared; k += kPartial)
    for (int p = 0; p < kPartial; ++p) {
      const double* y = work + static_cast<std::size_t>(rows[k + p]) * M;
      for (int t = 0; t < R; ++t)
        for (std::size_t c = 0; c < M; ++c) sum[t][p][c] += l[t][k + p] * y[c];
    }
  for (; k < shared; ++k) {
    const double* y = work + static_cast<std::size_t>(rows[k]) * M;
    for (int t = 0; t < R; ++t)
      for (std::size_t c = 0; c < M; ++c) sum[t][0][c] += l[t][k] * y[c];
  }
  for (int t = R - 1; t >= 0; --t) {
    const int s = f.start[j + t];
    double total[M];
    for (std::size_t c = 0; c < M; ++c) total[c] = sum[t][0][c];
    for (int p = 1; p < kPartial; ++p)
      for (std::size_t c = 0; c < M; ++c) total[c] += sum[t][p][c];
    for (int u = 1; u < R - t; ++u) {
      const double* y = work + static_cast<std::size_t>(j + t + u) * M;
      for (std::size_t c = 0; c < M; ++c) total[c] += f.values[s + u] * y[c];
    }
    const double d = f.values[s];
    double* x = work + static_cast<std::size_t>(j + t) * M;
    for (std::size_t c = 0; c < M; ++c) x[c] = f.unitDiagonal ? x[c] / d - total[c] : (x[c] - total[c]) / d;
  }
}

template <std::size_t M>
BAKE_INLINE_KERNEL void forwardRuns(const SimplicialFactorView& f, const unsigned char* runs, int begin, int end,
                                    double* work, const int* topIndex, double* topBuffer) {
  const auto limit = static_cast<std::size_t>(end);
  for (int j = begin; j < end; j += runs[j]) switch (runs[j]) {
      case 1: forwardRun<1, M>(f, j, work, limit, topIndex, topBuffer); break;
      case 2: forwardRun<2, M>(f, j, work, limit, topIndex, topBuffer); break;
      case 3: forwardRun<3, M>(f, j, work, limit, topIndex, topBuffer); break;
      default: forwardRun<4, M>(f, j, work, limit, topIndex, topBuffer); break;
    }
}

// The runs that start in [begin, end) are runStarts[first, last); walking back, a run's length is
// the distance to the next run's start (or to `end`).
template <std::size_t M>
BAKE_INLINE_KERNEL void backwardRuns(const SimplicialFactorView& f, const int* runStarts, std::size_t first,
                              std::size_t last, std::size_t runCount, int end, double* work) {
  for (std::size_t r = last; r > first;) {
    --r;
    const int j = runStarts[r];
    const int next = r + 1 < runCount && runStarts[r + 1] < end ? runStarts[r + 1] : end;
    switch (next - j) {
      case 1: backwardRun<1, M>(f, j, work); break;
      case 2: backwardRun<2, M>(f, j, work); break;
      case 3: backwardRun<3, M>(f, j, work); break;
      default: backwardRun<4, M>(f, j, work); break;
    }
  }
}

// One copy per vector width (core/vector_clones.h).
BAKE_VECTOR_CLONES void forwardRange(const SimplicialFactorView& f, const unsigned char* runs, int begin,
                                     int end, double* work, const int* topIndex, double* topBuffer,
                                     std::size_t m) {
  switch (m) {
    case 1: forwardRuns<1>(f, runs, begin, end, work, topIndex, topBuffer); break;
    case 2: forwardRuns<2>(f, runs, begin, end, work, topIndex, topBuffer); break;
    case 3: forwardRuns<3>(f, runs, begin, end, work, topIndex, topBuffer); break;
    case 4: forwardRuns<4>(f, runs, begin, end, work, topIndex, topBuffer); break;
    case 5: forwardRuns<5>(f, runs, begin, end, work, topIndex, topBuffer); break;
    case 6: forwardRuns<6>(f, runs, begin, end, work, topIndex, topBuffer); break;
    case 7: forwardRuns<7>(f, runs, begin, end, work, topIndex, topBuffer); break;
    default: forwardRuns<8>(f, runs, begin, end, work, topIndex, topBuffer); break;
  }
}

BAKE_VECTOR_CLONES void backwardRange(const SimplicialFactorView& f, const int* runStarts, std::size_t first,
                                      std::size_t last, std::size_t runCount, int end, double* work,
                                      std::size_t m) {
  switch (m) {
    case 1: backwardRuns<1>(f, runStarts, first, last, runCount, end, work); break;
    case 2: backwardRuns<2>(f, runStarts, first, last, runCount, end, work); break;
    case 3: backwardRuns<3>(f, runStarts, first, last, runCount, end, work); break;
    case 4: backwardRuns<4>(f, runStarts, first, last, runCount, end, work); break;
    case 5: backwardRuns<5>(f, runStarts, first, last, runCount, end, work); break;
    case 6: backwardRuns<6>(f, runStarts, first, last, runCount, end, work); break;
    case 7: backwardRuns<7>(f, runStarts, first, last, runCount, end, work); break;
    default: backwardRuns<8>(f, runStarts, first, last, runCount, end, work); break;
  }
}

static_assert(kMaxColumns == 8, "forwardRange and backwardRange instantiate 1 to 8 columns");

}  // namespace

void SubstitutionPlan::solveColumns(double* work, std::size_t m, unsigned threads) const {
  const SimplicialFactorView& f = factor_;
  const bool split = !groups_[0].empty();
  const unsigned workers = split && nonZeros_ >= kThreadedFromNonZeros ? threads : 1u;
  const auto forwardPart = [&](int begin, int end, double* topBuffer) {
    forwardRange(f, runs_.data(), begin, end, work, topIndex_.data(), topBuffer, m);
  };
  const auto backwardPart = [&](int begin, int end) {
    const auto first = std::lower_bound(runStarts_.begin(), runStarts_.end(), begin) - runStarts_.begin();
    const auto last = std::lower_bound(runStarts_.begin(), runStarts_.end(), end) - runStarts_.begin();
    backwardRange(f, runStarts_.data(), static_cast<std::size_t>(first), static_cast<std::size_t>(last),
                  runStarts_.size(), end, work, m);
  };
  if (split) {
    // The groups' updates of the top part, added to it in group order.
    std::array<std::vector<double>, 2> topBuffers;
    parallelForBlocks(2, 1, workers, [&](std::size_t g, std::size_t) {
      topBuffers[g].assign(topRows_.size() * m, 0.0);
      for (const auto& [begin, end] : groups_[g]) forwardPart(begin, end, topBuffers[g].data());
    });
    for (std::size_t g = 0; g < 2; ++g)
      for (std::size_t t = 0; t < topRows_.size(); ++t)
        for (std::size_t c = 0; c < m; ++c)
          work[static_cast<std::size_t>(topRows_[t]) * m + c] += topBuffers[g][t * m + c];
  }
  for (const auto& [begin, end] : topRanges_) forwardPart(begin, end, nullptr);
  for (auto range = topRanges_.rbegin(); range != topRanges_.rend(); ++range) backwardPart(range->first, range->second);
  if (split)
    parallelForBlocks(2, 1, workers, [&](std::size_t g, std::size_t) {
      for (auto range = groups_[g].rbegin(); range != groups_[g].rend(); ++range)
        backwardPart(range->first, range->second);
    });
}

std::size_t SubstitutionPlan::topColumns() const {
  std::size_t columns = 0;
  for (const auto& [begin, end] : topRanges_) columns += static_cast<std::size_t>(end - begin);
  return columns;
}

void SubstitutionPlan::solveInFactorOrder(std::span<double> work, std::size_t columns, unsigned threads) const {
  if (columns > kMaxColumns || work.size() != factor_.size * columns)
    throw std::invalid_argument("solveInFactorOrder: too many columns, or a work array of the wrong size");
  if (columns > 0) solveColumns(work.data(), columns, threads);
}

void SubstitutionPlan::solve(std::span<const double> rhs, std::span<double> solution, std::size_t columns,
                             unsigned threads, ColumnLayout layout) const {
  const std::size_t n = factor_.size;
  const bool interleaved = layout == ColumnLayout::Interleaved;
  const auto at = [&](std::size_t row, std::size_t column) {
    return interleaved ? row * columns + column : column * n + row;
  };
  const auto rowOf = [&](std::size_t k) {
    return factor_.permutation ? static_cast<std::size_t>(factor_.permutation[k]) : k;
  };
  std::vector<double> work;
  for (std::size_t first = 0; first < columns; first += kMaxColumns) {
    const std::size_t m = std::min(kMaxColumns, columns - first);
    // Interleaved (row k holds the m right-hand sides side by side) and permuted: row k is A's row
    // permutation[k].
    work.resize(n * m);
    for (std::size_t k = 0; k < n; ++k)
      for (std::size_t c = 0; c < m; ++c) work[k * m + c] = rhs[at(rowOf(k), first + c)];
    solveColumns(work.data(), m, threads);
    for (std::size_t k = 0; k < n; ++k)
      for (std::size_t c = 0; c < m; ++c) solution[at(rowOf(k), first + c)] = work[k * m + c];
  }
}

}  // namespace bake::geodesic
