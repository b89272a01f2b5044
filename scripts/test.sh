#!/usr/bin/env bash
# The test command: installs what is missing, builds, and runs the whole test suite with CTest.
#   scripts/test.sh              normal build (build/)
#   scripts/test.sh --sanitize   ASan + UBSan build with clang (build-sanitize/)
#   scripts/test.sh --fuzz       clang libFuzzer targets (build-fuzz/), each run briefly: ctest -L fuzz
#                                (BAKE_FUZZ_SECONDS=600 scripts/test.sh --fuzz: ten minutes each)
#   scripts/test.sh -L unit      extra arguments go to ctest (labels: unit cli cli-gl gl stiff data pipeline hostile)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh"

export BUILD_DIR="${BUILD_DIR:-$here/build}"
if [[ "${1:-}" == "--fuzz" ]]; then
  # Only the fuzz targets (tests/fuzz) are built, with clang, ASan, UBSan and libFuzzer.
  shift
  BUILD_DIR="$here/build-fuzz"
  # BAKE_FUZZ_SECONDS: how long each target runs (20 s by default; 600 for a ten-minute campaign).
  CC=clang CXX=clang++ BUILD_TARGETS=fuzz_targets "$here/scripts/build.sh" -DBAKE_FUZZ=ON \
    -DBAKE_FUZZ_SECONDS="${BAKE_FUZZ_SECONDS:-20}"
  cd "$BUILD_DIR"
  exec ctest --output-on-failure --parallel "$(nproc)" -L fuzz "$@"
fi
cmake_args=()
if [[ "${1:-}" == "--sanitize" ]]; then
  shift
  BUILD_DIR="$here/build-sanitize"
  cmake_args+=(-DBAKE_SANITIZE=ON)
  # clang, not the default g++: with ASan and UBSan it compiles this code base about three times
  # faster (hatching_test.cpp: 24 s against 71 s), and the plain stage already covers g++.
  export CC=clang CXX=clang++
  # A build folder configured earlier with another compiler is configured afresh.
  if [[ -f "$BUILD_DIR/CMakeCache.txt" ]] && ! grep -q '^CMAKE_CXX_COMPILER:.*clang++' "$BUILD_DIR/CMakeCache.txt"; then
    rm -rf "$BUILD_DIR/CMakeCache.txt" "$BUILD_DIR/CMakeFiles"
  fi
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
fi
"$here/scripts/build.sh" "${cmake_args[@]}"
cd "$BUILD_DIR"
if [[ ${#cmake_args[@]} -eq 0 ]]; then
  ctest --output-on-failure --parallel "$(nproc)" "$@"
else
  # Mesa allocates for the life of the process inside its llvmpipe driver and unloads the driver at
  # eglTerminate, leaving leak reports with no symbols to suppress by; so the GL tests run with
  # AddressSanitizer and UBSan but without LeakSanitizer, and everything else with all three.
  # The million-triangle accuracy tests only repeat, ten times slower, what the plain run checks, as
  # does example_packages_gltf_valid (the example bakes again, for the glTF-Validator).
  # CgalPeer and AgreesWithCgal tests run CGAL's own solvers (the peers we measure against, never
  # linked into a tool; the exact geodesics on the real meshes take minutes under ASan);
  # CGAL 5.5's Heat_method_3 swaps an uninitialised bool (CGAL::Eigen_sparse_matrix::swap), which
  # UBSan stops on inside CGAL's headers, so they run in the plain stage only.
  # makefile_examples (plain stage only) validates the 9,000-stroke fur example: llvmpipe's tessellation
  # grows its vertex arrays by realloc, which ASan always copies, and one headless view takes minutes
  # there instead of a second. The bakers run under ASan in examples_bake, bakeplay's paintstrokes in the
  # GL tests.
  ctest --output-on-failure --parallel "$(nproc)" -LE gl -E 'MillionTriangle|CgalPeer|AgreesWithCgal|example_packages_gltf_valid' "$@"
  ASAN_OPTIONS="detect_leaks=0:abort_on_error=1" ctest --output-on-failure --parallel "$(nproc)" -L gl \
    -E makefile_examples "$@"
fi
