#!/usr/bin/env bash
# Start-up time of every tool, whole process: the median wall time of RUNS runs (default 21) of
#   TOOL --version       what a build system pays per call before any work;
#   TOOL --help          the option parser set up as well;
# and of a small image job, which loads the image codec module (OpenImageIO, io/image_codec.h):
#   bakeshape glaze --resolution 16 -o x.png    writes a 16x16 PNG.
# Peers in the same run: `oiiotool --version` (OpenImageIO's own tool) and, when installed, Debian's
# `gltfpack -h`. The goal is ≤ 50 ms for every `--version`. Writes OUT/startup.csv
# (command, group, runs, median_ms, min_ms, max_ms).
#
#   bench/startup.sh [--runs N] [--out DIR]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$here/build-bench}"
runs=21
out="$build/results/startup"
while (($#)); do
  case "$1" in
    --runs) runs="$2"; shift ;;
    --out) out="$2"; shift ;;
    *) echo "startup.sh: error: unknown argument '$1'" >&2; exit 1 ;;
  esac
  shift
done
tool_names=(geobake revolbake tambake groovebake strokebake bakeshape bakepipe bakeinfo bakeplay)
bench_build "${tool_names[@]}"
mkdir -p "$out/scratch"
csv="$out/startup.csv"

# Each line: GROUP<TAB>COMMAND (run through no shell: words split on spaces). The list run stays in
# scratch/; commands.txt, which the record keeps, names paths relative to the checkout.
commands="$out/scratch/commands.tsv"
: >"$commands"
for tool in "${tool_names[@]}"; do
  printf 'ours\t%s --version\n' "$build/tools/$tool/$tool" >>"$commands"
  printf 'ours (help)\t%s --help\n' "$build/tools/$tool/$tool" >>"$commands"
done
printf 'ours (image)\t%s glaze --resolution 16 -o %s/glaze.png -q\n' "$build/tools/bakeshape/bakeshape" "$out/scratch" >>"$commands"
printf 'peer\t%s --version\n' "$(command -v oiiotool || echo oiiotool)" >>"$commands"
if command -v gltfpack >/dev/null; then printf 'peer\t%s -h\n' "$(command -v gltfpack)" >>"$commands"; fi

# The timing loop runs in one Python process, so only the measured program starts each time; its
# output goes to /dev/null and its exit status is not judged (gltfpack -h exits 1).
python3 - "$commands" "$runs" "$csv" "$here" <<'EOF'
import statistics, subprocess, sys, time
commands, runs, csv, here = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
rows = []
for line in open(commands):
    group, command = line.rstrip("\n").split("\t")
    words = command.split(" ")
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        subprocess.run(words, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        times.append((time.perf_counter() - start) * 1000)
    shown = command.replace(here + "/", "")
    rows.append((shown, group, runs, statistics.median(times), min(times), max(times)))
    print(f"startup: {statistics.median(times):8.1f} ms  {shown}", file=sys.stderr)
with open(csv, "w") as f:
    f.write("command,group,runs,median_ms,min_ms,max_ms\n")
    for r in rows:
        f.write(f"{r[0]},{r[1]},{r[2]},{r[3]:.2f},{r[4]:.2f},{r[5]:.2f}\n")
EOF
sed -e "s|$here/||g" "$commands" >"$out/commands.txt"
echo "startup: wrote $csv" >&2
