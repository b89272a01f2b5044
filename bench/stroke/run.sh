#!/usr/bin/env bash
# Builds bench-stroke (only that target; a new BUILD_DIR, default build-bench, is configured Release
# with -DBAKE_BUILD_BENCH=ON), runs it and writes OUT (default BUILD_DIR/results): stroke.csv (one row
# per method, radius and knob: CPU microseconds per stroke, largest per-pixel coverage error, relative
# ink error), summary.txt, and stroke.png (error against time) when gnuplot is there. Extra arguments go
# to the benchmark (e.g. --benchmark_min_time=0.05 for a quick run).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${BUILD_DIR:-$here/build-bench}"
out="${OUT:-$build/results}"
if [[ ! -f "$build/build.ninja" ]]; then
  cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBAKE_BUILD_BENCH=ON >/dev/null
fi
cmake --build "$build" --target bench-stroke --parallel "$(nproc)"
mkdir -p "$out"
"$build/bench/stroke/bench-stroke" --benchmark_format=csv "$@" > "$out/raw.csv"

# Google Benchmark's CSV: name,iterations,real_time,cpu_time,time_unit,...,ink_error,max_pixel_error,pixels.
# name = BM_<Method>/<radius x 10>/<piece length x 10 | samples per side>.
awk -F, '
  NR == 1 { for (i = 1; i <= NF; ++i) { h = $i; gsub(/"/, "", h); col[h] = i } print "method,radius,knob,cpu_us,max_pixel_error,ink_error,pixels"; next }
  /^"?BM_/ {
    name = $1; gsub(/"/, "", name); split(name, part, "/")
    method = part[1] == "BM_Rasterize" ? "ours" : "supersample"
    knob = method == "ours" ? part[3] / 10 : part[3]
    printf "%s,%g,%g,%.3f,%.6g,%.6g,%d\n", method, part[2] / 10, knob, $col["cpu_time"], \
           $col["max_pixel_error"], $col["ink_error"], $col["pixels"]
  }' "$out/raw.csv" > "$out/stroke.csv"

{
  echo "per stroke (80 px, curved, 256^2 wrapping tile): CPU microseconds, largest pixel error, ink error"
  awk -F, 'NR > 1 { printf "  %-11s r %-4s %-12s %9.1f us  %.4f  %.2e\n", $1, $2, ($1 == "ours" ? "piece " : "samples ") $3, $4, $5, $6 }' "$out/stroke.csv"
  echo "supersampling 4x4 / ours (default 2 px pieces), CPU time:"
  awk -F, 'NR > 1 && $1 == "ours" && $3 == 2 { ours[$2] = $4 } NR > 1 && $1 == "supersample" && $3 == 4 { peer[$2] = $4 }
           END { for (r in ours) if (r in peer) printf "  r %-4s %.0f x\n", r, peer[r] / ours[r] }' "$out/stroke.csv"
} | tee "$out/summary.txt"

if command -v gnuplot >/dev/null; then
  gnuplot -e "dir='$out'" "$here/bench/stroke/plot.gp"
  echo "plot: $out/stroke.png"
else
  echo "gnuplot not found (apt-get install gnuplot-nox): no plot" >&2
fi
