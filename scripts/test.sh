#!/usr/bin/env bash
# The test command: installs what is missing, builds, and runs the tests with CTest.
#   scripts/test.sh              the default tier (unit, cli, stiff, gl; about 75 s of tests on
#                                2 cores): everything not labelled slow, normal build (build/)
#   scripts/test.sh --slow       the slow tier: shared-data, million-triangle, example pipelines,
#                                hostile matrix (about four minutes)
#   scripts/test.sh --all        both tiers
#   scripts/test.sh --sanitize   ASan + UBSan build with clang (build-sanitize/): the default tier, the
#                                hostile matrix and the example bakes
#   scripts/test.sh --fuzz       the libFuzzer targets (in build-sanitize/), each run briefly: ctest -L fuzz
#                                (BAKE_FUZZ_SECONDS=600 scripts/test.sh --fuzz: ten minutes each)
#   scripts/test.sh -L unit      extra arguments go to ctest (labels: unit cli gl stiff data pipeline
#                                hostile peer million web slow)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh"

export BUILD_DIR="${BUILD_DIR:-$here/build}"
# The sanitizer stage and the fuzz targets share one clang build (build-sanitize/): ASan + UBSan,
# coverage instrumentation for libFuzzer, -O1 with line tables (cmake/Fuzz.cmake), so that CI
# compiles the library twice (g++ and clang), not three times.
sanitize_build() {
  BUILD_DIR="$here/build-sanitize"
  export CC=clang CXX=clang++
  # A build folder configured earlier with another compiler is configured afresh.
  if [[ -f "$BUILD_DIR/CMakeCache.txt" ]] && ! grep -q '^CMAKE_CXX_COMPILER:.*clang++' "$BUILD_DIR/CMakeCache.txt"; then
    rm -rf "$BUILD_DIR/CMakeCache.txt" "$BUILD_DIR/CMakeFiles"
  fi
  # BAKE_FUZZ_SECONDS: how long each fuzz target runs (20 s by default; 600 for a ten-minute campaign).
  "$here/scripts/build.sh" -DBAKE_SANITIZE=ON -DBAKE_FUZZ=ON -DBAKE_FUZZ_SECONDS="${BAKE_FUZZ_SECONDS:-20}"
}
if [[ "${1:-}" == "--fuzz" ]]; then
  # Only the fuzz targets (tests/fuzz) are built, with clang, ASan, UBSan and libFuzzer.
  shift
  BUILD_TARGETS=fuzz_targets sanitize_build
  cd "$BUILD_DIR"
  exec ctest --output-on-failure --parallel "$(nproc)" -L fuzz "$@"
fi
tier=(-LE slow)
case "${1:-}" in
  --slow) shift; tier=(-L slow) ;;
  --all) shift; tier=() ;;
esac
sanitize=false
if [[ "${1:-}" == "--sanitize" ]]; then
  shift
  sanitize=true
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  sanitize_build
else
  "$here/scripts/build.sh"
fi
cd "$BUILD_DIR"

# What this run left out, so that nobody takes the default tier for the whole suite.
summary() {
  local slow data
  slow=$(ctest -N -L slow | sed -n 's/^Total Tests: //p')
  data=$(cat tests/*_suites.cmake 2>/dev/null | sed -n 's/^# .*: \([0-9]*\) tests, labels .*data.*/\1/p' |
         awk '{s+=$1} END{print s+0}')
  if [[ " ${tier[*]-} " == *" -LE slow "* ]]; then
    echo "test.sh: the slow tier (${slow} entries: shared data, million-triangle meshes, example pipelines," \
         "hostile matrix) did not run; scripts/test.sh --slow runs it."
  fi
  local data_dir="${BAKE_DATA_DIR:-$here/../shared/data}"
  if [[ ! -d "$data_dir" ]]; then
    echo "test.sh: the shared mesh set is not in $data_dir, so its ${data} data tests skip (they are in the" \
         "slow tier); set BAKE_DATA_DIR to its folder and run scripts/test.sh --slow."
  fi
}
trap summary EXIT

if ! $sanitize; then
  ctest --output-on-failure --parallel "$(nproc)" "${tier[@]}" "$@"
else
  # The sanitizer stage runs the default tier, the hostile matrix and the example bakes (the bakers on
  # every example with LeakSanitizer on); the shared-data meshes and the example pipelines only repeat,
  # many times slower, what the plain stage checks.
  # Mesa allocates for the life of the process inside its llvmpipe driver and unloads the driver at
  # eglTerminate, leaving leak reports with no symbols to suppress by; so the GL tests run with
  # AddressSanitizer and UBSan but without LeakSanitizer, and everything else with all three.
  # CGAL's own solvers (label peer: the peers we measure against, never linked into a tool) run in the
  # plain stage only: CGAL 5.5's Heat_method_3 swaps an uninitialised bool
  # (CGAL::Eigen_sparse_matrix::swap), which UBSan stops on inside CGAL's headers.
  tier=()
  ctest --output-on-failure --parallel "$(nproc)" -LE 'gl|data|peer|million|pipeline|fuzz' \
    -E 'killed_mid_write|example_packages_gltf_valid' "$@"
  ASAN_OPTIONS="detect_leaks=0:abort_on_error=1" ctest --output-on-failure --parallel "$(nproc)" -L gl -LE 'slow' "$@"
fi
