#!/usr/bin/env bash
# Peak memory (largest resident set, GNU time's %M) and wall time (%e) of every tool on its largest
# benchmark input. Builds the tools (BUILD_TYPE, default Release; -DBAKE_BUILD_BENCH=ON) into BUILD_DIR
# (default build-bench), runs each once under /usr/bin/time and writes OUT/resources.csv
# (tool, input, size, wall_s, peak_rss_mib) and OUT/resources-commands.txt (the command of each row).
#
#   bench/resources.sh [--mode quick|full] [--raw DIR] [--out DIR]
#
# --mode  which benchmark settings "largest" refers to: the revolution bench's largest resolution is
#         1024 (quick) or 4096 (full), the tam bench's 256 or 512 (default: full)
# --raw   bench/run's raw output folder: the 100,000-groove scene of groove-bake is reused from
#         RAW/groove-bake/groove-bake/ when it is there (else written again with bench-groove-scene)
# --out   where the results go (default BUILD_DIR/results/resources); scratch outputs in OUT/scratch/
#
# Inputs: geobake on the largest real mesh of ../shared/data/meshes/real (or $BAKE_DATA_DIR/meshes/real;
# else a pretzel from bakeshape), exact and heat, one source, and in full mode also on bakeshape's pretzel
# at 256 cells (about 450k triangles, the size of the full geodesic ladder's largest rungs); revolbake on pipelines/revolution/vase.json;
# groovebake on 100,000 random grooves; tambake on pipelines/hatching/hatching.json (and both shipped
# styles at their own settings, median of 5 runs); bakeshape's pretzel
# at 256 cells; bakepipe assemble on each pipelines/*/scene.json (baked first with bakepipe ninja);
# bakeplay validate and render on the largest package made here (the groove grid of 100,000 grooves).
# Every baker runs with -j THREADS (default 2).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$here/build-bench}"
mode=full
raw=""
out="$build/results/resources"
threads="${THREADS:-2}"
while (($#)); do
  case "$1" in
    --mode) mode="$2"; shift ;;
    --raw) raw="$2"; shift ;;
    --out) out="$2"; shift ;;
    *) echo "resources.sh: error: unknown argument '$1'" >&2; exit 1 ;;
  esac
  shift
done
case "$mode" in
  quick) revol_resolution=1024; tam_resolution=256 ;;
  full) revol_resolution=4096; tam_resolution=512 ;;
  *) echo "resources.sh: error: --mode quick|full" >&2; exit 1 ;;
esac

bench_build geobake revolbake groovebake tambake bakeshape bakepipe bakeplay bench-groove-scene
tools="$build/tools"
work="$out/scratch"
rm -rf "$work"
mkdir -p "$work"
csv="$out/resources.csv"
commands="$out/resources-commands.txt"
echo "tool,input,size,wall_s,peak_rss_mib" >"$csv"
: >"$commands"

# Paths on the record are relative to the checkout (or to the shared data folder).
show() { sed -e "s|$work/|SCRATCH/|g" -e "s|$here/||g" -e "s|$(cd "$here/.." && pwd)/|../|g" <<<"$*"; }

# measure_median RUNS TOOL INPUT SIZE COMMAND...: runs the command RUNS times under GNU time and appends
# a row: the median wall time and the largest peak memory (a command short enough that one run is
# mostly noise gets several). A command that fails gets a row saying so (no figures), and the script
# exits non-zero at the end. SIZE "?" is filled in afterwards by set_size (from the tool's report or
# output). measure TOOL INPUT SIZE COMMAND...: one run.
failures=0
last_ok=0
measure_median() {
  local runs="$1" tool="$2" input="$3" size="$4" rc=0 k
  shift 4
  if ((runs > 1)); then
    echo "resources: $tool ($runs runs): $(show "$*")" >&2
    input="$input (median of $runs runs)"
  else
    echo "resources: $tool: $(show "$*")" >&2
  fi
  : >"$work/times.txt"
  for ((k = 0; k < runs; k++)); do
    /usr/bin/time -f '%e %M' -o "$work/time.txt" "$@" || rc=$?
    [[ $rc == 0 ]] || break
    tail -1 "$work/time.txt" >>"$work/times.txt"
  done
  if [[ $rc != 0 ]]; then
    echo "resources: error: $tool failed (exit $rc)" >&2
    echo "$tool,$input,failed (exit $rc),," >>"$csv"
    failures=$((failures + 1))
    last_ok=0
  else
    sort -n "$work/times.txt" | awk -v t="$tool" -v i="$input" -v s="$size" \
      '{ wall[NR] = $1; if ($2 > kib) kib = $2 }
       END { gsub(",", ";", i); gsub(",", ";", s); printf "%s,%s,%s,%.2f,%.1f\n", t, i, s, wall[int((NR + 1) / 2)], kib / 1024 }' >>"$csv"
    last_ok=1
  fi
  echo "$tool: $(show "$*")" >>"$commands"
}
measure() { measure_median 1 "$@"; }
set_size() { if [[ $last_ok == 1 ]]; then sed -i "\$s/,?,/,$1,/" "$csv"; fi; }

# A number from a tool's JSON report: the first value of KEY anywhere in it.
report_value() {
  python3 -c 'import json, sys
def find(node, key):
    if isinstance(node, dict):
        if key in node: return node[key]
        node = list(node.values())
    if isinstance(node, list):
        for item in node:
            found = find(item, key)
            if found is not None: return found
    return None
print(find(json.load(open(sys.argv[1])), sys.argv[2]))' "$1" "$2"
}
bytes() { stat -c %s "$1"; }
mib() { awk -v b="$1" 'BEGIN { printf "%.1f MiB", b / 1048576 }'; }

# geobake: the largest shared real mesh (by file size), else a generated pretzel.
data="${BAKE_DATA_DIR:-$here/../shared/data}/meshes/real"
mesh=""
if [[ -d "$data" ]]; then
  mesh="$(find "$data" -maxdepth 1 -type f \( -name '*.obj' -o -name '*.off' \) -printf '%s %p\n' | sort -n | tail -1 | cut -d' ' -f2-)"
fi
if [[ -z "$mesh" ]]; then
  "$tools/bakeshape/bakeshape" pretzel --resolution 192 -o "$work/pretzel-192.glb" -q
  mesh="$work/pretzel-192.glb"
fi
mesh_name="$(basename "$mesh")"
for method in exact heat; do
  measure geobake "$mesh_name ($method; 1 source)" "?" \
    "$tools/geobake/geobake" "$mesh" -o "$work/geodesic-$method.glb" --method "$method" --auto-sources 1 \
    -j "$threads" --report "$work/geodesic-$method.json" -q
  if [[ $last_ok == 1 ]]; then set_size "$(report_value "$work/geodesic-$method.json" triangles) triangles"; fi
done

# Full mode: the geodesic ladder reaches 400k triangles, so geobake also runs on a generated mesh of
# that size (bakeshape's pretzel at 256 cells, about 450k triangles).
if [[ $mode == full ]]; then
  "$tools/bakeshape/bakeshape" pretzel --resolution 256 -o "$work/pretzel-geodesic.glb" -q
  for method in exact heat; do
    measure geobake "bakeshape pretzel at 256 cells ($method; 1 source)" "?" \
      "$tools/geobake/geobake" "$work/pretzel-geodesic.glb" -o "$work/pretzel-$method.glb" --method "$method" \
      --auto-sources 1 -j "$threads" --report "$work/pretzel-$method.json" -q
    if [[ $last_ok == 1 ]]; then set_size "$(report_value "$work/pretzel-$method.json" triangles) triangles"; fi
  done
fi

# revolbake: a profile of pipelines/revolution at the revolution bench's largest resolution.
measure revolbake "pipelines/revolution/vase.json" "${revol_resolution} texels (larger side)" \
  "$tools/revolbake/revolbake" "$here/pipelines/revolution/vase.json" -o "$work/vase.glb" \
  --resolution "$revol_resolution" -j "$threads" -q

# groovebake: the 100,000-groove scene of bench/groove-bake (same generator arguments as its run.sh).
scene="$raw/groove-bake/groove-bake/scene-100000.json"
if [[ -z "$raw" || ! -f "$scene" ]]; then
  scene="$work/scene-100000.json"
  "$build/bench/groove-bake/bench-groove-scene" -o "$scene" --grooves 100000 --long-lines 200 --domain 200.000 >/dev/null
fi
measure groovebake "groove-bake scene-100000.json" "100000 grooves" \
  "$tools/groovebake/groovebake" "$scene" -o "$work/grooves-100000.glb" -j "$threads" -q
grooves_package="$work/grooves-100000.glb"

# tambake: the pipelines/hatching style at the tam bench's largest resolution.
measure tambake "pipelines/hatching/hatching.json" "${tam_resolution}^2 finest level" \
  "$tools/tambake/tambake" "$here/pipelines/hatching/hatching.json" -o "$work/hatching.ktx2" \
  --resolution "$tam_resolution" -j "$threads" -q

# tambake's two shipped styles as a user runs them, at their own resolution (256): the default
# hatching (6 tones x 4 levels) and stippling, whole process.
for style in hatching stippling; do
  measure_median 5 tambake "pipelines/hatching/$style.json (style's own settings)" "256^2 finest level" \
    "$tools/tambake/tambake" "$here/pipelines/hatching/$style.json" -o "$work/$style-default.ktx2" -j "$threads" -q
done

# bakeshape: the pretzel (genus 3) at 256 cells along its longest side.
measure bakeshape "pretzel" "?" \
  "$tools/bakeshape/bakeshape" pretzel --resolution 256 -o "$work/pretzel-256.glb" --report "$work/pretzel-256.json" -q
if [[ $last_ok == 1 ]]; then set_size "$(report_value "$work/pretzel-256.json" triangles) triangles"; fi

# bakepipe assemble: every example scene, baked first (bakepipe ninja + ninja), then assembled again.
for scene_file in "$here"/pipelines/*/scene.json; do
  name="$(basename "$(dirname "$scene_file")")"
  scene_out="$work/scenes/$name"
  mkdir -p "$work/scenes"
  echo "bakepipe (bakes the scene first, not timed): $(show "$tools/bakepipe/bakepipe ninja $scene_file --out-dir $scene_out -o $work/scenes/$name.ninja -q && ninja -f $work/scenes/$name.ninja")" >>"$commands"
  if ! { "$tools/bakepipe/bakepipe" ninja "$scene_file" --out-dir "$scene_out" \
           -o "$work/scenes/$name.ninja" -q && ninja -f "$work/scenes/$name.ninja" --quiet >/dev/null; }; then
    echo "resources: error: baking pipelines/$name/scene.json failed" >&2
    echo "bakepipe,assemble pipelines/$name/scene.json,failed (the bake before it),," >>"$csv"
    failures=$((failures + 1))
    continue
  fi
  measure bakepipe "assemble pipelines/$name/scene.json" "?" \
    "$tools/bakepipe/bakepipe" assemble "$scene_file" --out-dir "$scene_out" \
    -o "$work/scenes/$name-assembled.glb" -q
  if [[ $last_ok == 1 ]]; then set_size "$(mib "$(bytes "$work/scenes/$name-assembled.glb")") package"; fi
done

# bakeplay: validate and render the largest package made here (headless EGL; llvmpipe without a GPU).
largest="$(find "$work" -name '*.glb' -printf '%s %p\n' | sort -n | tail -1 | cut -d' ' -f2-)"
largest_size="$(mib "$(bytes "$largest")") package"
measure bakeplay "validate $(basename "$largest")" "$largest_size" \
  "$tools/bakeplay/bakeplay" validate "$largest" -q
measure bakeplay "render $(basename "$largest") 1024x768" "$largest_size" \
  "$tools/bakeplay/bakeplay" render "$largest" --size 1024x768 -o "$work/render.png" -q

echo "resources: wrote $csv" >&2
cat "$csv" >&2
if ((failures)); then
  echo "resources: $failures run(s) failed" >&2
  exit 1
fi
