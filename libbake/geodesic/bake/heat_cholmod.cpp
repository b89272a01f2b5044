// CHOLMOD wrapper for the heat method's two systems. One analysis is copied into one factor per matrix: AMD
// below kMetisFromRows unknowns, METIS nested dissection above (and AMD if METIS fails). METIS fills less on
// surface meshes, so its factor and solves are cheaper, but its analysis costs more, which small meshes feel:
// set-up (analysis + both numeric factorisations) and one field, with the reference BLAS, AMD against METIS:
// camelhead (11k vertices) 0.037 s / 0.0016 s against 0.070 s / 0.0017 s; a 35k-vertex bunny 0.19 s /
// 0.0080 s against 0.28 s / 0.0061 s; a 41k-vertex sphere 0.44 s / 0.0119 s against 0.35 s / 0.0092 s; 163k
// vertices 1.42 s / 0.065 s against 1.67 s / 0.053 s (METIS is kept there for the field: CGAL's heat method
// takes 0.114 s); 687k vertices 11.7 s / 0.27 s against 9.96 s / 0.23 s. From kSupernodalFromRows unknowns
// the numeric factorisation is supernodal LL^T, whose dense blocks make it fast (the more so with an
// optimised BLAS: scripts/setup.sh installs OpenBLAS, which Debian's alternatives then use in place of
// the reference one; the 687k-vertex set-up falls to 7.2 s); the
// factor is then turned into a simplicial LL^T, because a single right-hand side solves faster column by
// column than through the small dense triangular solves of the supernodes (measured: about 1.5x on a
// 41k-vertex sphere). Below it, the supernodes are too small to pay for themselves and the factorisation is
// simplicial LDL^T from the start: set-up 0.045 s against 0.072 s on camelhead (11k vertices), 0.23 s against
// 0.24 s on an 83k-triangle sphere, but 1.9 s against 1.4 s on a 326k-triangle one. The matrices factorise in
// parallel, each in its own CHOLMOD workspace, with the BLAS held to one thread: each factor is then computed
// by one sequential code path, so it does not depend on the thread count (a threaded BLAS splits its sums by
// its thread count). Solves are our own substitution (heat_substitution.h), which only reads the factor, so
// several threads share it; CHOLMOD's solve remains for a factor not laid out as that expects.
// A BLAS is trusted only so far: Debian's sequential OpenBLAS (libopenblas0-serial 0.3.21) is not safe to
// call from two threads at once: factorising both matrices of 0.8M- and 2M-triangle spheres concurrently
// through it failed as "not positive definite" (one at a time they succeed). So a sequential OpenBLAS is
// called from one thread at a time, and every factor is checked by its backward error on a system with a
// known solution; a factor that fails the check is computed again simplicially, without the BLAS.
#include "geodesic/bake/heat_cholmod.h"

#include <cholmod.h>
#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/parallel.h"
#include "geodesic/bake/heat_substitution.h"

namespace bake::geodesic {
namespace {

using Common = std::shared_ptr<cholmod_common>;

// Unknowns (vertices) from which the analysis orders by METIS rather than AMD, and from which the
// factor is supernodal (see above).
constexpr std::size_t kMetisFromRows = 40000;
constexpr std::size_t kSupernodalFromRows = 60000;

Common startCommon() {
  Common common(new cholmod_common, [](cholmod_common* c) {
    cholmod_finish(c);
    delete c;
  });
  cholmod_start(common.get());
  common->print = 0;
  common->error_handler = nullptr;
  return common;
}

// A view of an Eigen matrix's upper triangle as a symmetric CHOLMOD matrix (no copy).
cholmod_sparse viewUpper(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& m) {
  cholmod_sparse a{};
  a.nrow = static_cast<std::size_t>(m.rows());
  a.ncol = static_cast<std::size_t>(m.cols());
  a.nzmax = static_cast<std::size_t>(m.nonZeros());
  a.p = const_cast<int*>(m.outerIndexPtr());
  a.i = const_cast<int*>(m.innerIndexPtr());
  a.x = const_cast<double*>(m.valuePtr());
  a.stype = 1;
  a.itype = CHOLMOD_INT;
  a.xtype = CHOLMOD_REAL;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = 1;
  a.packed = 1;
  return a;
}

// OpenBLAS threads its own kernels; held to one thread, a factor's sums never depend on how many
// cores the machine has. Other BLAS libraries (the reference one) have no threads to hold.
void holdBlasToOneThread() {
  using SetThreads = void (*)(int);
  if (auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set(1);
}

// A sequential OpenBLAS keeps unlocked buffers of its own: calls from two threads at once corrupt each
// other. OpenBLAS says how it was built; other BLAS libraries keep no such state.
bool blasIsSequentialOpenBlas() {
  using GetParallel = int (*)();
  auto get = reinterpret_cast<GetParallel>(dlsym(RTLD_DEFAULT, "openblas_get_parallel"));
  return get && get() == 0;
}

using SparseUpper = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// y = A x for the symmetric matrix whose upper triangle is stored.
std::vector<double> multiplySymmetric(const SparseUpper& upper, const std::vector<double>& x) {
  std::vector<double> y(x.size(), 0.0);
  for (int j = 0; j < upper.outerSize(); ++j)
    for (SparseUpper::InnerIterator it(upper, j); it; ++it) {
      const auto i = static_cast<std::size_t>(it.row());
      y[i] += it.value() * x[static_cast<std::size_t>(j)];
      if (i != static_cast<std::size_t>(j)) y[static_cast<std::size_t>(j)] += it.value() * x[i];
    }
  return y;
}

// Largest absolute row sum of the symmetric matrix (its infinity norm).
double normInfinity(const SparseUpper& upper) {
  std::vector<double> rows(static_cast<std::size_t>(upper.rows()), 0.0);
  for (int j = 0; j < upper.outerSize(); ++j)
    for (SparseUpper::InnerIterator it(upper, j); it; ++it) {
      rows[static_cast<std::size_t>(it.row())] += std::fabs(it.value());
      if (it.row() != j) rows[static_cast<std::size_t>(j)] += std::fabs(it.value());
    }
  return rows.empty() ? 0.0 : *std::max_element(rows.begin(), rows.end());
}

double normInfinity(const std::vector<double>& v) {
  double largest = 0.0;
  for (double x : v) largest = std::max(largest, std::fabs(x));
  return largest;
}

}  // namespace

// Normwise backward error of the factor on A x = b with b = A t for a fixed t: Cholesky is backward
// stable, so a sound factor gives a few units of rounding whatever A's conditioning; a corrupted one
// gives orders of magnitude more. A plain check, independent of how the factor was computed.
double CholeskyFactor::backwardError(const SparseUpper& upper) const {
  const std::size_t n = size();
  std::vector<double> truth(n);
  for (std::size_t k = 0; k < n; ++k) truth[k] = 1.0 + 0.5 * std::sin(static_cast<double>(k));
  const std::vector<double> rhs = multiplySymmetric(upper, truth);
  std::vector<double> x(n);
  solve(rhs, x);
  std::vector<double> residual = multiplySymmetric(upper, x);
  for (std::size_t k = 0; k < n; ++k) residual[k] -= rhs[k];
  const double scale = normInfinity(upper) * normInfinity(x) + normInfinity(rhs);
  const double error = normInfinity(residual);
  if (!std::isfinite(error)) return std::numeric_limits<double>::infinity();
  return scale > 0.0 ? error / scale : error;
}

struct CholeskyFactor::Impl {
  Common common;  // owns the factor's memory
  cholmod_factor* factor = nullptr;
  SubstitutionPlan substitution;  // our own solves, once the factor is simplicial
  bool planned = false;
  // Plans the substitution of a simplicial factor (a supernodal one keeps CHOLMOD's solve).
  void plan() {
    if (!factor || factor->is_super || factor->xtype != CHOLMOD_REAL || factor->itype != CHOLMOD_INT) return;
    SimplicialFactorView view;
    view.size = factor->n;
    view.start = static_cast<const int*>(factor->p);
    view.count = static_cast<const int*>(factor->nz);
    view.rows = static_cast<const int*>(factor->i);
    view.values = static_cast<const double*>(factor->x);
    view.permutation = static_cast<const int*>(factor->Perm);
    view.unitDiagonal = !factor->is_ll;
    substitution = SubstitutionPlan(view);
    planned = substitution.valid();
  }
  ~Impl() {
    if (factor) cholmod_free_factor(&factor, common.get());
  }
};

CholeskyFactor::CholeskyFactor(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
CholeskyFactor::CholeskyFactor(CholeskyFactor&&) noexcept = default;
CholeskyFactor& CholeskyFactor::operator=(CholeskyFactor&&) noexcept = default;
CholeskyFactor::~CholeskyFactor() = default;

std::size_t CholeskyFactor::size() const { return impl_->factor->n; }

const SubstitutionPlan* CholeskyFactor::substitution() const {
  return impl_->planned ? &impl_->substitution : nullptr;
}

Result<std::vector<CholeskyFactor>> CholeskyFactor::factoriseAll(
    std::span<const Eigen::SparseMatrix<double, Eigen::ColMajor, int>* const> uppers, unsigned threads,
    FactoriseReport* report) {
  FactoriseReport local;
  FactoriseReport& out = report ? *report : local;
  std::vector<CholeskyFactor> factors;
  if (uppers.empty()) return factors;
  Common common = startCommon();
  cholmod_sparse first = viewUpper(*uppers[0]);
  const int supernodal = first.nrow < kSupernodalFromRows ? CHOLMOD_SIMPLICIAL : CHOLMOD_SUPERNODAL;
  common->supernodal = supernodal;
  common->nmethods = 1;
  const int ordering = first.nrow < kMetisFromRows ? CHOLMOD_AMD : CHOLMOD_METIS;
  common->method[0].ordering = ordering;
  cholmod_factor* symbolic = cholmod_analyze(&first, common.get());
  if (!symbolic) {
    common->method[0].ordering = CHOLMOD_AMD;
    symbolic = cholmod_analyze(&first, common.get());
  }
  if (!symbolic)
    return internalError("sparse Cholesky analysis failed (status " + std::to_string(common->status) + ")");
  // One factor per matrix, each with its own workspace (a cholmod_common is not shared between
  // threads), copied from the analysis.
  std::vector<std::unique_ptr<Impl>> impls;
  for (std::size_t k = 0; k < uppers.size(); ++k) {
    auto impl = std::make_unique<Impl>();
    impl->common = startCommon();
    impl->common->supernodal = supernodal;
    impl->factor = cholmod_copy_factor(symbolic, impl->common.get());
    impls.push_back(std::move(impl));
  }
  cholmod_free_factor(&symbolic, common.get());
  // Only a supernodal factor calls the BLAS (the simplicial method and its solves make no BLAS call).
  if (supernodal == CHOLMOD_SUPERNODAL) holdBlasToOneThread();
  out.oneAtATime = supernodal == CHOLMOD_SUPERNODAL && blasIsSequentialOpenBlas();
  std::vector<int> status(uppers.size(), CHOLMOD_OK);
  parallelForBlocks(uppers.size(), 1, out.oneAtATime ? 1u : threads, [&](std::size_t k, std::size_t) {
    Impl& impl = *impls[k];
    cholmod_common* c = impl.common.get();
    cholmod_sparse a = viewUpper(*uppers[k]);
    int ok = impl.factor ? cholmod_factorize(&a, impl.factor, c) : 0;
    if (ok && c->status == CHOLMOD_OK && impl.factor->is_super)
      ok = cholmod_change_factor(CHOLMOD_REAL, /*to_ll=*/1, /*to_super=*/0, /*to_packed=*/1,
                                 /*to_monotonic=*/1, impl.factor, c);
    if (ok && c->status == CHOLMOD_OK) impl.plan();
    status[k] = ok && c->status == CHOLMOD_OK ? CHOLMOD_OK : (c->status != CHOLMOD_OK ? c->status : CHOLMOD_INVALID);
  });
  // Backward errors of a sound factor are about 1e-16; this bound leaves room for rounding on large
  // meshes and still catches corruption, which shows as 1e-6 and worse.
  constexpr double kBackwardErrorBound = 1e-10;
  // Only the supernodal factorisation calls the BLAS; a simplicial one is CHOLMOD's own code.
  const bool check = supernodal == CHOLMOD_SUPERNODAL;
  for (std::size_t k = 0; k < uppers.size(); ++k) {
    double error = std::numeric_limits<double>::infinity();
    if (status[k] == CHOLMOD_OK && !check) {
      factors.push_back(CholeskyFactor(std::move(impls[k])));
      continue;
    }
    if (status[k] == CHOLMOD_OK) {
      CholeskyFactor factor(std::move(impls[k]));
      error = factor.backwardError(*uppers[k]);
      if (error <= kBackwardErrorBound) {
        out.worstBackwardError = std::max(out.worstBackwardError, error);
        factors.push_back(std::move(factor));
        continue;
      }
    }
    BAKE_ASSIGN_OR_RETURN(CholeskyFactor redone, factoriseSimplicial(*uppers[k], ordering));
    ++out.redoneWithoutBlas;
    error = redone.backwardError(*uppers[k]);
    if (!(error <= kBackwardErrorBound))
      return internalError("sparse Cholesky factorisation failed: backward error " + std::to_string(error) +
                           " even without the BLAS (is the matrix positive definite?)");
    out.worstBackwardError = std::max(out.worstBackwardError, error);
    factors.push_back(std::move(redone));
  }
  return factors;
}

// One matrix alone, simplicial from its own analysis: no dense blocks, so no BLAS call.
Result<CholeskyFactor> CholeskyFactor::factoriseSimplicial(const SparseUpper& upper, int ordering) {
  auto impl = std::make_unique<Impl>();
  impl->common = startCommon();
  cholmod_common* c = impl->common.get();
  c->supernodal = CHOLMOD_SIMPLICIAL;
  c->nmethods = 1;
  c->method[0].ordering = ordering;
  cholmod_sparse a = viewUpper(upper);
  impl->factor = cholmod_analyze(&a, c);
  if (!impl->factor) {
    c->method[0].ordering = CHOLMOD_AMD;
    impl->factor = cholmod_analyze(&a, c);
  }
  if (!impl->factor || !cholmod_factorize(&a, impl->factor, c) || c->status != CHOLMOD_OK)
    return internalError("sparse Cholesky factorisation failed (status " + std::to_string(c->status) + ")");
  impl->plan();
  return CholeskyFactor(std::move(impl));
}

void CholeskyFactor::solve(std::span<const double> rhs, std::span<double> solution, std::size_t columns,
                           unsigned threads, ColumnLayout layout) const {
  if (impl_->planned) {
    impl_->substitution.solve(rhs, solution, columns, threads, layout);
    return;
  }
  if (layout == ColumnLayout::Consecutive || columns == 1) {
    solveWithCholmod(rhs, solution, columns);
    return;
  }
  // CHOLMOD reads and writes columns one after another.
  const std::size_t n = size();
  std::vector<double> consecutive(n * columns), solved(n * columns);
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < columns; ++c) consecutive[c * n + r] = rhs[r * columns + c];
  solveWithCholmod(consecutive, solved, columns);
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < columns; ++c) solution[r * columns + c] = solved[c * n + r];
}

void CholeskyFactor::solveWithCholmod(std::span<const double> rhs, std::span<double> solution,
                                      std::size_t columns) const {
  const std::size_t n = size();
  cholmod_common local;
  cholmod_start(&local);
  local.print = 0;
  local.error_handler = nullptr;
  cholmod_dense b{};
  b.nrow = n;
  b.ncol = columns;
  b.nzmax = n * columns;
  b.d = n;
  b.x = const_cast<double*>(rhs.data());
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, impl_->factor, &b, &local);
  if (x) {
    const auto* values = static_cast<const double*>(x->x);
    std::copy(values, values + n * columns, solution.begin());
    cholmod_free_dense(&x, &local);
  } else {
    std::fill(solution.begin(), solution.begin() + static_cast<std::ptrdiff_t>(n * columns), 0.0);
  }
  cholmod_finish(&local);
}

}  // namespace bake::geodesic
