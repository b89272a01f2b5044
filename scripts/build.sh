#!/usr/bin/env bash
# Configures and builds the project into BUILD_DIR (default: build). Extra arguments go to CMake's
# configure step, e.g. -DBAKE_SANITIZE=ON; BUILD_TARGETS (space-separated) builds only those targets.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$here/build}"
# ccache (when installed) hashes paths relative to the checkout and ignores the build folder's own
# path, so clones in other folders reuse each other's objects; a clean clone then compiles only what
# differs. Debug information of a reused object names the folder that compiled it first.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$here}"
export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-true}"
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-RelWithDebInfo}" "$@" >/dev/null
targets=()
for t in ${BUILD_TARGETS:-}; do targets+=(--target "$t"); done
cmake --build "$build" --parallel "$(nproc)" "${targets[@]}"
