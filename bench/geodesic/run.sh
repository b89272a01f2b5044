#!/usr/bin/env bash
# Builds bench-geodesic (Release, -DBAKE_BUILD_BENCH=ON) into BUILD_DIR (default build-bench), runs it
# and plots error against time. Arguments go to bench-geodesic, e.g. --quick, --max-triangles N,
# --mesh FILE, --out DIR (default BUILD_DIR/results).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${BUILD_DIR:-$here/build-bench}"
out="$build/results"
args=("$@")
out_given=0
for ((i = 0; i < ${#args[@]}; ++i)); do
  if [[ "${args[i]}" == "--out" && $((i + 1)) -lt ${#args[@]} ]]; then out="${args[i + 1]}"; out_given=1; fi
  if [[ "${args[i]}" == --out=* ]]; then out="${args[i]#--out=}"; out_given=1; fi
done
[[ $out_given == 1 ]] || args=(--out "$out" "${args[@]}")
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBAKE_BUILD_BENCH=ON >/dev/null
cmake --build "$build" --target bench-geodesic --parallel "$(nproc)"
"$build/bench/bench-geodesic" "${args[@]}"
if command -v gnuplot >/dev/null; then
  # Methods with a time and an error for each source count (gnuplot refuses a series without points).
  present() { awk -F, -v s="$1" 'NR > 1 && $5 == s && $12 == "ok" && $8 != "" { print $4 }' "$out/geodesic.csv" |
                sort -u | tr '\n' ' '; }
  gnuplot -e "csv='$out/geodesic.csv'; png='$out/geodesic.png'; methods1='$(present 1)'; methods8='$(present 8)'" \
          "$here/bench/geodesic/plot.gp"
  echo "plot: $out/geodesic.png"
else
  echo "gnuplot not found (apt-get install gnuplot-nox): no plot" >&2
fi
