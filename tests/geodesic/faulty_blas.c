/* A faulty BLAS for the heat method's factor check (faulty_blas_test.sh), loaded with LD_PRELOAD in
 * front of the real one: dgemm_ computes the right product through the real routine, then spoils its
 * first entry, as a broken optimised kernel would. The supernodal Cholesky updates go through dgemm_.
 * FAULTY_BLAS=gross spoils it enough that the factorisation reports the matrix not positive definite;
 * FAULTY_BLAS=subtle by a part in a million, so the factor comes out quietly wrong and only the
 * backward-error check can tell. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdlib.h>
#include <string.h>

typedef void (*dgemm_fn)(const char*, const char*, const int*, const int*, const int*, const double*,
                         const double*, const int*, const double*, const int*, const double*, double*,
                         const int*);

void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
            const double* alpha, const double* a, const int* lda, const double* b, const int* ldb,
            const double* beta, double* c, const int* ldc) {
  static dgemm_fn real = 0;
  if (!real) real = (dgemm_fn)dlsym(RTLD_NEXT, "dgemm_");
  real(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
  static int subtle = -1;
  if (subtle < 0) subtle = getenv("FAULTY_BLAS") && strcmp(getenv("FAULTY_BLAS"), "subtle") == 0;
  const double size = c[0] < 0 ? -c[0] : c[0];
  if (*m > 0 && *n > 0) c[0] += subtle ? 1e-6 * size : 0.25 * size + 1e-3;
}
