#!/usr/bin/env bash
# Configures and builds the project into BUILD_DIR (default: build). Extra arguments go to CMake's
# configure step, e.g. -DBAKE_SANITIZE=ON.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$here/build}"
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-RelWithDebInfo}" "$@" >/dev/null
cmake --build "$build" --parallel "$(nproc)"
