#!/usr/bin/env bash
# Builds bench-tam (BUILD_TYPE, default Release; -DBAKE_BUILD_BENCH=ON; only this target) into BUILD_DIR (default
# build-bench), runs it and plots tam.png: tone error and ink uniformity against construction time,
# over K (1 2 4 8 16 32) and the finest resolution (64 128 256 512). Arguments go to bench-tam
# (--quick, --candidates, --resolutions, --repeats, --threads (default 2), --seed, --detail,
# --images DIR, --out DIR; default BUILD_DIR/results).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh"
bench_setup "$@"
bench_build bench-tam
"$build/bench/tam/bench-tam" "${args[@]}"

# The headline figures: per resolution and K, the median time and the quality figures.
{
  echo "median seconds / max tone error (x tolerance) / max CV / max low-frequency power (scoped images; all images):"
  # No image of a 64^2 map is in the uniformity scope (side >= 128): "-".
  awk -F, 'NR > 1 { cv = $6 > 0 ? sprintf("%.3f", $6) : "-"; lfp = $7 > 0 ? sprintf("%.4f", $7) : "-";
                    printf "  %4d^2  K %2d  %7.3f s  %.4f (%.2f)  cv %5s  lfp %6s  (all: cv %.3f lfp %.4f)  %d strokes\n",
                    $2, $1, $3, $4, $5, cv, lfp, $8, $9, $11 }' "$out/tam.csv"
} | tee "$out/summary.txt"

resolutions="$(awk -F, 'NR > 1 { print $2 }' "$out/tam.csv" | awk '!seen[$0]++' | tr '\n' ' ')"
bench_plot "$out/tam.png" -e "dir='$out'; resolutions='$resolutions'" "$here/bench/tam/plot.gp"
