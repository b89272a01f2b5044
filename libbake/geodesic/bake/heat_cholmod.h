// A sparse Cholesky factorisation held by CHOLMOD (Chen, Davis, Hager and Rajamanickam 2008),
// supernodal where the fill makes it pay. Several matrices with one sparsity pattern share one
// symbolic analysis (fill-reducing ordering and supernodes). Solving is const and thread-safe: each
// call works in its own CHOLMOD workspace and only reads the factor.
#pragma once

#include <Eigen/SparseCore>

#include <cstddef>
#include <memory>
#include <span>

#include "bake/core/status.h"
#include "geodesic/bake/heat_substitution.h"

namespace bake::geodesic {

// How a factorisation went past the BLAS it found (for the report).
struct FactoriseReport {
  bool oneAtATime = false;           // a sequential OpenBLAS: never called from two threads at once
  std::size_t redoneWithoutBlas = 0;  // factors whose check failed, computed again without the BLAS
  double worstBackwardError = 0.0;   // of the factors checked, |A x - b| / (|A| |x| + |b|), max norms
};

class CholeskyFactor {
 public:
  // Factorises each matrix (upper triangles of symmetric positive definite matrices, all with the
  // same pattern) after one shared analysis, up to `threads` at once (0: all cores); the factors do
  // not depend on `threads`. Each factor that went through the BLAS (supernodal) is checked by solving
  // a system with a known solution; one that fails (a faulty BLAS) is computed again by the simplicial
  // method, which uses no BLAS.
  static Result<std::vector<CholeskyFactor>> factoriseAll(
      std::span<const Eigen::SparseMatrix<double, Eigen::ColMajor, int>* const> uppers, unsigned threads = 0,
      FactoriseReport* report = nullptr);

  CholeskyFactor(CholeskyFactor&&) noexcept;
  CholeskyFactor& operator=(CholeskyFactor&&) noexcept;
  ~CholeskyFactor();

  std::size_t size() const;
  // Solves A X = B for `columns` right-hand sides stored as `layout` says (size() rows each), by our
  // own substitution (heat_substitution.h) on up to `threads` threads (0: all cores); the solution
  // does not depend on `threads`.
  void solve(std::span<const double> rhs, std::span<double> solution, std::size_t columns = 1,
             unsigned threads = 1, ColumnLayout layout = ColumnLayout::Consecutive) const;
  // The substitution's plan; null when solves go through CHOLMOD (a factor not laid out as expected).
  const SubstitutionPlan* substitution() const;
  // The same through CHOLMOD's own solve (an independent check of the substitution).
  void solveWithCholmod(std::span<const double> rhs, std::span<double> solution, std::size_t columns = 1) const;

 private:
  struct Impl;
  explicit CholeskyFactor(std::unique_ptr<Impl> impl);
  static Result<CholeskyFactor> factoriseSimplicial(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& upper,
                                                    int ordering);
  double backwardError(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& upper) const;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bake::geodesic
