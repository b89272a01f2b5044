#!/usr/bin/env bash
# Builds groovebake and bench-groove-scene (BUILD_TYPE, default Release; -DBAKE_BUILD_BENCH=ON; only
# these targets) into BUILD_DIR (default build-bench), then times groovebake on random scratch scenes
# of SIZES grooves (default "1000 10000 100000"; the domain grows with the count so the density stays
# that of 10^5 grooves on 200 x 200 mm), RUNS runs each (default 5, median), THREADS threads (default 2),
# and sweeps --cell-size over 0.5 .. 8 x the automatic size on the largest scene (SWEEP_RUNS runs each,
# default 3): bake time, references per cell and the stored geometry's error. Writes groove-bake.csv, cell-size.csv, summary.txt and
# groove-bake.png under --out DIR (default BUILD_DIR/results).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh"
bench_setup "$@"
bench_build groovebake bench-groove-scene
bake="$build/tools/groovebake/groovebake"
scene_tool="$build/bench/groove-bake/bench-groove-scene"
runs="${RUNS:-5}"
size_runs="$runs"
threads="${THREADS:-2}"
sizes="${SIZES:-1000 10000 100000}"
work="$out/groove-bake"
mkdir -p "$work"

# The first number after "KEY": in a report; the seconds of stage NAME.
field() { grep -o "\"$1\": [-0-9.e+]*" "$2" | head -1 | awk '{ print $2 }'; }
stage() { awk -v name="\"$1\"," '$2 == name { getline; gsub(",", "", $2); print $2; exit }' "$2"; }
median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

# Runs one bake RUNS times; sets wall, cpu (medians, seconds) and leaves the last report in $report.
time_bake() {
  local scene="$1"
  shift
  local walls="" cpus="" r t0 t1
  for ((r = 0; r < runs; ++r)); do
    t0=$(date +%s.%N)
    /usr/bin/time -f "%U %S" -o "$work/cpu.txt" "$bake" "$scene" -o "$work/out.glb" -j "$threads" --report "$report" -q "$@"
    t1=$(date +%s.%N)
    walls="$walls $(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')"
    cpus="$cpus $(awk '{ print $1 + $2 }' "$work/cpu.txt")"
  done
  wall=$(echo "$walls" | median)
  cpu=$(echo "$cpus" | median)
}

csv="$out/groove-bake.csv"
echo "grooves,domain,wall_s,cpu_s,read_s,grid_s,records_s,pack_s,write_s,columns,cell_size,mean_refs,max_refs,intersections,ends,corners,file_bytes,max_position_error" >"$csv"
largest=""
for n in $sizes; do
  domain=$(awk -v n="$n" 'BEGIN { printf "%.3f", 200 * sqrt(n / 100000) }')
  scene="$work/scene-$n.json"
  "$scene_tool" -o "$scene" --grooves "$n" --long-lines $((n / 500)) --domain "$domain" >/dev/null
  report="$work/report-$n.json"
  time_bake "$scene"
  columns=$(grep -A1 '"cells": \[' "$report" | tail -1 | tr -d ' ,')
  echo "$n,$domain,$wall,$cpu,$(stage read "$report"),$(stage grid "$report"),$(stage records "$report"),$(stage pack "$report"),$(stage write "$report"),$columns,$(grep -A1 '"cellSize": \[' "$report" | tail -1 | tr -d ' ,'),$(field meanRefsPerCell "$report"),$(field maxRefsPerCell "$report"),$(field intersections "$report"),$(field ends "$report"),$(field corners "$report"),$(field file "$report"),$(field maxPositionError "$report")" >>"$csv"
  largest="$n"
done

# Cell size sweep on the largest scene: the grid's one knob (runtime lookups against bake time and error).
sweep="$out/cell-size.csv"
echo "factor,cell_size,wall_s,cpu_s,mean_refs,max_refs,file_bytes,max_position_error" >"$sweep"
auto=$(awk -F, -v n="$largest" '$1 == n { print $11 }' "$csv")
runs="${SWEEP_RUNS:-3}"
for factor in 0.5 1 2 4 8; do
  size=$(awk -v a="$auto" -v f="$factor" 'BEGIN { printf "%.6g", a * f }')
  report="$work/report-size.json"
  time_bake "$work/scene-$largest.json" --cell-size "$size" --max-cells 100000000
  echo "$factor,$size,$wall,$cpu,$(field meanRefsPerCell "$report"),$(field maxRefsPerCell "$report"),$(field file "$report"),$(field maxPositionError "$report")" >>"$sweep"
done

{
  echo "groovebake, -j $threads, median of $size_runs runs (wall and CPU seconds, CPU = user + system of all threads):"
  awk -F, 'NR > 1 { printf "  %7d grooves  %8.2f mm  wall %6.3f s  cpu %6.3f s  (last run: read %.3f grid %.3f records %.3f pack %.3f write %.3f)  %5d^2 cells  refs/cell mean %.2f max %d  %d intersections  %.1f MB  max error %.2g\n",
                    $1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $12, $13, $14, $17 / 1e6, $18 }' "$csv"
  echo "cell size sweep on $largest grooves (median of ${SWEEP_RUNS:-3} runs):"
  awk -F, 'NR > 1 { printf "  x%-4s %.4f mm  wall %6.3f s  cpu %6.3f s  refs/cell mean %6.2f max %4d  %.1f MB  max error %.2g\n", $1, $2, $3, $4, $5, $6, $7 / 1e6, $8 }' "$sweep"
} | tee "$out/groove-bake-summary.txt"

bench_plot "$out/groove-bake.png" -e "dir='$out'" "$here/bench/groove-bake/plot.gp"
