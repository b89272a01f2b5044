#!/usr/bin/env bash
# Builds bench-geodesic (Release, -DBAKE_BUILD_BENCH=ON) into BUILD_DIR (default build-bench), runs it
# and plots error against time. Arguments go to bench-geodesic, e.g. --quick, --max-triangles N,
# --mesh FILE, --out DIR (default BUILD_DIR/results).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh"
bench_setup "$@"
bench_build bench-geodesic
"$build/bench/bench-geodesic" "${args[@]}"
# Methods with a time and an error for each source count (gnuplot refuses a series without points).
present() { awk -F, -v s="$1" 'NR > 1 && $5 == s && $12 == "ok" && $8 != "" { print $4 }' "$out/geodesic.csv" |
              sort -u | tr '\n' ' '; }
bench_plot "$out/geodesic.png" \
  -e "csv='$out/geodesic.csv'; png='$out/geodesic.png'; methods1='$(present 1)'; methods8='$(present 8)'" \
  "$here/bench/geodesic/plot.gp"
