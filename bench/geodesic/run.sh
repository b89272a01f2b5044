#!/usr/bin/env bash
# Builds bench-geodesic (Release, -DBAKE_BUILD_BENCH=ON) into BUILD_DIR (default build-bench), runs it
# and plots error against time. Arguments go to bench-geodesic, e.g. --quick, --max-triangles N,
# --mesh FILE, --out DIR (default BUILD_DIR/results).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${BUILD_DIR:-$here/build-bench}"
out="$build/results"
args=("$@")
for ((i = 0; i < ${#args[@]}; ++i)); do
  [[ "${args[i]}" == "--out" && $((i + 1)) -lt ${#args[@]} ]] && out="${args[i + 1]}"
  [[ "${args[i]}" == --out=* ]] && out="${args[i]#--out=}"
done
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBAKE_BUILD_BENCH=ON >/dev/null
cmake --build "$build" --target bench-geodesic --parallel "$(nproc)"
"$build/bench/bench-geodesic" --out "$out" "$@"
if command -v gnuplot >/dev/null; then
  gnuplot -e "csv='$out/geodesic.csv'; png='$out/geodesic.png'" "$here/bench/geodesic/plot.gp"
  echo "plot: $out/geodesic.png"
else
  echo "gnuplot not found (apt-get install gnuplot-nox): no plot" >&2
fi
