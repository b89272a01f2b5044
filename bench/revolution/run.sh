#!/usr/bin/env bash
# Builds bench-revolution-march and bench-revolution-edt (Release, -DBAKE_BUILD_BENCH=ON; only these two
# targets) into BUILD_DIR (default build-bench), runs both and plots revolution.png. Arguments go to
# bench-revolution-march (--quick, --profile FILE, --resolutions, --repeats, --march-resolution, --out DIR;
# default BUILD_DIR/results); --quick also shortens the EDT sizes.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh"
bench_setup "$@"
quick=0
for arg in "$@"; do if [[ "$arg" == "--quick" ]]; then quick=1; fi; done
bench_build bench-revolution-march bench-revolution-edt
"$build/bench/revolution/bench-revolution-march" "${args[@]}"
if [[ $quick == 1 ]]; then edt_args=(--sizes 512,1024,2048 --repeats 3); else edt_args=(--check-sizes 16384); fi
echo "bench-revolution-edt ${edt_args[*]}" >&2
"$build/bench/revolution/bench-revolution-edt" "${edt_args[@]}" > "$out/edt.csv"

# The headline figures: mismatch at 35 iterations (omega 1.6), bake cost at 1024, EDT ratio.
{
  echo "silhouette mismatch at 35 iterations, omega 1.6 (target 0.5 %):"
  awk -F, 'NR > 1 && $3 == 1.6 && $4 == 35 { printf "  %-8s %-9s %.3f %%\n", $1, ($2 ? "proxy" : "no proxy"), 100 * $5 }' "$out/march.csv"
  echo "bake seconds at resolution 1024 (distance + encode/decode/margin):"
  awk -F, 'NR > 1 && $2 == 1024 { printf "  %-8s %-8s %.4f + %.4f = %.4f\n", $1, $5, $6, $7, $6 + $7 }' "$out/bake.csv"
  echo "EDT ours / OpenCV:"
  awk -F, 'NR > 1 { printf "  %5d^2  %s  (wrong %d of %d checked)\n", $1, ($4 == "" ? "-" : $4), $7, $6 }' "$out/edt.csv"
} | tee "$out/summary.txt"

profiles="$(awk -F, 'NR > 1 { print $1 }' "$out/march.csv" | awk '!seen[$0]++' | tr '\n' ' ')"
bake_profile="$(awk -F, 'NR == 2 { print $1 }' "$out/bake.csv")"
bench_plot "$out/revolution.png" -e "dir='$out'; profiles='$profiles'; bake_profile='$bake_profile'" \
  "$here/bench/revolution/plot.gp"
