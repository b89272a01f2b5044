#!/usr/bin/env bash
# Builds bench-groove (BUILD_TYPE, default Release; -DBAKE_BUILD_BENCH=ON; only this target) into
# BUILD_DIR (default build-bench), runs it on bench/groove/cases.json and plots groove.png: the seed's
# method against the ray-traced reference, error against time per frame, view angle and
# footprint/width. Arguments go to bench-groove (--quick, --only NAME, --spp, --repeats, --threads
# (default 1), --images DIR, --out DIR; default BUILD_DIR/results).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh"
bench_setup "$@"
bench_build bench-groove
# --runtime: every view is also drawn by bakeplay's grooves renderer (headless GL) and measured.
"$build/bench/groove/bench-groove" --cases "$here/bench/groove/cases.json" --runtime "${args[@]}"

# The headline figures per case: the worst error relative to the reference's noise floor, and the
# smallest cost ratio (reference at --spp samples per pixel over the method).
{
  echo "case: views, worst RMSE / noise floor (criterion <= 3; the seed's published variant, then the runtime's, in brackets),"
  echo "      smallest cost ratio against the reference (criterion >= 50), method CPU ns/px (fastest and slowest view):"
  awk -F, 'NR > 1 { n[$1]++; if ($22 > worst[$1]) worst[$1] = $22; if ($24 > seed[$1]) seed[$1] = $24;
                    if ($26 > runtime[$1]) runtime[$1] = $26;
                    if (!($1 in ratio) || $16 < ratio[$1]) ratio[$1] = $16;
                    if (!($1 in fast) || $13 < fast[$1]) fast[$1] = $13; if ($13 > slow[$1]) slow[$1] = $13 }
           END { for (c in n)
                   printf "  %-20s %3d views  rmse/floor %7.2f (%7.2f, runtime %7.2f)  cost ratio %8.1f  %9.0f .. %.0f ns/px\n",
                          c, n[c], worst[c], seed[c], runtime[c], ratio[c], fast[c], slow[c] }' "$out/groove.csv" | sort
} | tee "$out/groove-summary.txt"

bench_plot "$out/groove.png" -e "dir='$out'" "$here/bench/groove/plot.gp"
