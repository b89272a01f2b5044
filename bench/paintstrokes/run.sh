#!/usr/bin/env bash
# Builds strokebake, bakeplay and bakeshape (BUILD_TYPE, default Release; -DBAKE_BUILD_BENCH=ON; only
# these targets) into BUILD_DIR (default build-bench), bakes the benchmark's stroke sets and renders
# each view headless with bakeplay: the reference (the same strokes as fixed tubes, finely tessellated
# on the CPU), paintstrokes at quality levels 0, 1, 2 over the subdivision tolerance, and coarser fixed
# tubes (the peer). For every render: the polygons and vertices drawn (GL primitive query), the
# median frame time and the RMSE against the reference (idiff, 8-bit sRGB). Writes paintstrokes.csv,
# paintstrokes-summary.txt (analyse.py: polygons at equal image error) and paintstrokes.png.
#
#   bench/paintstrokes/run.sh [--quick] [--out DIR]
#
# --quick: 512 x 384 frames, 3 frames per timing, a reduced sweep (about 13 minutes on 2 cores).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh"
bench_setup "$@"
quick=0
for a in "$@"; do [[ "$a" == --quick ]] && quick=1; done
bench_build strokebake bakeplay bakeshape
bin="$build/tools"
work="$out/paintstrokes"
mkdir -p "$work"
command -v idiff >/dev/null || { echo "idiff not found (apt-get install openimageio-tools)" >&2; exit 2; }

if [[ $quick == 1 ]]; then
  size=512x384 frames=3 reference=48x24
  tolerances="2 1 0.5 0.25"
  tubes="3x1 3x2 4x2 4x4 6x2 6x4 8x4 8x8 12x8 16x8"
else
  size=1024x768 frames=5 reference=64x32
  tolerances="4 2 1 0.5 0.25 0.125"
  tubes="3x1 3x2 4x1 4x2 4x4 6x2 6x4 6x8 8x4 8x8 12x4 12x8 16x8 16x16 24x16"
fi

# The stroke sets: curls (helices around a sphere, made by make_curls.py), a tree and fur grown on a
# torus (strokebake's generators; bakeshape makes the torus).
"$bin/bakeshape/bakeshape" torus -o "$work/torus.obj" -q
python3 "$here/bench/paintstrokes/make_curls.py" 600 >"$work/curls.json"
cp "$here/bench/paintstrokes/scenes/"*.json "$work/"
for set in curls tree fur; do
  "$bin/strokebake/strokebake" "$work/$set.json" -o "$work/$set.glb" --report "$work/$set-bake.json" -q
done

# Views per set: NAME EYE:TARGET (a close view where curvature matters, a mid one, a far one).
views() {
  case "$1" in
    curls) echo "close 0.9,0.6,1.6:0,0,0.2 mid 2.2,1.4,3.2:0,0,0 far 5,3.2,7:0,0,0" ;;
    tree) echo "close 0.5,1.1,0.9:0,1.0,0 mid 1.6,1.2,2.4:0,0.8,0 far 3.5,2.2,5:0,0.8,0" ;;
    fur) echo "close 0.9,-1.3,1.0:0.7,0,0 mid 1.8,-2.6,2.6:0,0,0 far 4,-5.5,5.5:0,0,0" ;;
  esac
}

# A value of a bakeplay report by dotted path (frameTimeCpu.medianMs), wherever it is nested.
field() {
  python3 -c '
import json, sys
def find(node, path):
    if isinstance(node, dict):
        value = node
        for key in path:
            value = value.get(key) if isinstance(value, dict) else None
        if value is not None: return value
        for child in node.values():
            found = find(child, path)
            if found is not None: return found
    return None
print(find(json.load(open(sys.argv[2])), sys.argv[1].split(".")))' "$1" "$2"
}
# idiff exits 2 when the images differ at all: its RMS line is what counts here.
rmse() { { idiff -a "$1" "$2" 2>&1 || true; } | awk '/RMS error/ { for (i = 1; i <= NF; ++i) if ($i == "=") { print $(i + 1); exit } }'; }

csv="$out/paintstrokes.csv"
echo "set,view,method,quality,tolerance_px,sides,steps,polygons,vertices,frame_ms,rmse" >"$csv"
render() {  # set view camera method quality tolerance sides steps -- bakeplay options
  local set="$1" view="$2" camera="$3" method="$4" quality="$5" tolerance="$6" sides="$7" steps="$8"
  shift 8
  local image="$work/$set-$view-$method-q$quality-t$tolerance-$sides-$steps.png" report="$work/report.json"
  "$bin/bakeplay/bakeplay" render -q "$work/$set.glb" --size "$size" --camera "$camera" --frames "$frames" \
    -o "$image" --report "$report" "$@"
  local error=0
  [[ "$method" == reference ]] || error="$(rmse "$work/$set-$view-ref.png" "$image")"
  echo "$set,$view,$method,$quality,$tolerance,$sides,$steps,$(field strokePolygons "$report"),$(field strokeVertices "$report"),$(field frameTimeCpu.medianMs "$report"),$error" >>"$csv"
}

for set in curls tree fur; do
  read -r -a v <<<"$(views "$set")"
  for ((i = 0; i < ${#v[@]}; i += 2)); do
    view="${v[i]}" camera="${v[i + 1]}"
    echo "paintstrokes: $set $view" >&2
    "$bin/bakeplay/bakeplay" render -q "$work/$set.glb" --size "$size" --camera "$camera" \
      --stroke-tubes "$reference" -o "$work/$set-$view-ref.png"
    render "$set" "$view" "$camera" reference - - "${reference%x*}" "${reference#*x}" --stroke-tubes "$reference"
    for quality in 0 1 2; do
      for tolerance in $tolerances; do
        render "$set" "$view" "$camera" paintstrokes "$quality" "$tolerance" - - \
          --stroke-quality "$quality" --stroke-tolerance "$tolerance"
      done
    done
    for t in $tubes; do
      render "$set" "$view" "$camera" tubes - - "${t%x*}" "${t#*x}" --stroke-tubes "$t"
    done
  done
done

python3 "$here/bench/paintstrokes/analyse.py" "$csv" | tee "$out/paintstrokes-summary.txt"
bench_plot "$out/paintstrokes.png" -e "dir='$out'" "$here/bench/paintstrokes/plot.gp"
