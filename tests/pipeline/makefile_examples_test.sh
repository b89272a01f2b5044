#!/usr/bin/env bash
# Makefile.examples end to end (CTest label pipeline):
#   makefile_examples_test.sh TOOLS_DIR SOURCE_DIR TMP_DIR
# TOOLS_DIR holds the built tools as TOOLS_DIR/<tool>/<tool>. The scene inputs are copied into TMP_DIR
# so that touching them leaves the source tree alone.
#   a. a parallel bake (make -j2) bakes and validates every example; a second run executes nothing
#      (make -q says up to date, make -n prints no command, and no file under OUT changes);
#   b. touching one input re-runs only what depends on it: ring.json re-bakes and re-validates the
#      ring alone; hatching.json runs tambake once for its three outputs (grouped targets); the
#      re-baked files are byte-identical to the first bake's (same options, a second run);
#   c. determinism: a second full bake with the same options, and a third with every baker at -j 1
#      (runs a and b have -j 2), are byte-identical to run a, file by file. Reports (*.report.json:
#      timings, absolute paths) and depfiles (*.d: absolute paths) legitimately differ and are not
#      compared; the validation stamps (empty files) are not compared either. bakeshape has no -j.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/script_support.sh"
read_test_arguments "$@"
cp -R "$src/pipelines" "$tmp/pipelines"
started=$SECONDS
step() { echo "== $* (at $((SECONDS - started)) s)"; }
mk() { make -f "$src/Makefile.examples" --no-print-directory BIN="$bin" PIPELINES="$tmp/pipelines" "$@"; }
# Every file under a directory with its modification time, one per line.
snapshot() { (cd "$1" && find . -type f -printf '%P %T@\n' | LC_ALL=C sort); }
# The names of the files whose time differs between two snapshots, or that only one has.
changed() { { diff <(echo "$1") <(echo "$2") || true; } | sed -n 's/^[<>] \(.*\) [0-9.]*$/\1/p' | LC_ALL=C sort -u | tr '\n' ' '; }

a="$tmp/a"
b="$tmp/b"
c="$tmp/c"
baked=(pretzel.glb torus.glb glaze.png bands.png hammered.png knurl.png pretzel-fields.glb vase.glb ring.glb
       plate.glb balusters.glb knobs.glb sky.exr hatching.ktx2 hatching-threshold.ktx2 torus-hatched.glb
       stippling.ktx2 pretzel-stippled.glb grooves-tiles.glb grooves-record.glb grooves-plate.glb strokes-fur.glb
       strokes-tree.glb)
# Validation renders every package headless (bakeplay validate: several views, non-empty images).
validated=(pretzel-fields vase ring plate balusters knobs torus-hatched pretzel-stippled grooves-tiles grooves-record grooves-plate
           strokes-fur strokes-tree)

# a. Everything, in parallel; then nothing to do.
step "a: make -j2 all validate into $a"
mk -j2 OUT="$a" THREADS=2 all validate
for file in "${baked[@]}"; do
  [[ -s "$a/$file" ]] || fail "a: $file was not baked"
done
for package in "${validated[@]}" example-wavy-grid; do
  [[ -f "$a/stamps/$package.validated" ]] || fail "a: $package was not validated"
done
for depfile in pretzel torus glaze bands hammered knurl pretzel-fields vase ring plate hatching stippling \
               grooves-tiles grooves-record grooves-plate strokes-fur strokes-tree; do
  [[ -s "$a/$depfile.d" ]] || fail "a: no depfile $depfile.d"
done

step "a: a second run executes no tool"
mk -q OUT="$a" THREADS=2 all validate || fail "a: make -q says something is out of date after a full run"
dry="$(mk -n OUT="$a" THREADS=2 all validate | grep -v "Nothing to be done" || true)"
[[ -z "$dry" ]] || fail "a: make -n would run: $dry"
before="$(snapshot "$a")"
rerun="$(mk -j2 OUT="$a" THREADS=2 all validate | grep -v "Nothing to be done" || true)"
[[ -z "$rerun" ]] || fail "a: the second run ran: $rerun"
after="$(snapshot "$a")"
[[ "$before" == "$after" ]] || fail "a: the second run changed: $(changed "$before" "$after")"

# b. One input touched: only its dependents run.
step "b: touch revolution/ring.json"
mkdir -p "$tmp/first"
cp -p "$a/ring.glb" "$a/hatching.ktx2" "$a/torus-hatched.glb" "$tmp/first/"
touch "$tmp/pipelines/revolution/ring.json"
before="$(snapshot "$a")"
log="$(mk -j2 OUT="$a" THREADS=2 all validate)"
after="$(snapshot "$a")"
got="$(changed "$before" "$after")"
want="ring.d ring.glb ring.report.json stamps/ring.validated "
[[ "$got" == "$want" ]] || fail "b: touching ring.json changed [$got], expected [$want]"
[[ "$(grep -c '/revolbake ' <<<"$log")" == 1 ]] || fail "b: revolbake did not run exactly once: $log"

step "b: touch hatching/hatching.json (one tambake run, three outputs)"
touch "$tmp/pipelines/hatching/hatching.json"
before="$after"
log="$(mk -j2 OUT="$a" THREADS=2 all validate)"
after="$(snapshot "$a")"
got="$(changed "$before" "$after")"
want="hatching-threshold.ktx2 hatching.d hatching.ktx2 hatching.report.json stamps/torus-hatched.validated torus-hatched.glb "
[[ "$got" == "$want" ]] || fail "b: touching hatching.json changed [$got], expected [$want]"
[[ "$(grep -c '/tambake ' <<<"$log")" == 1 ]] || fail "b: tambake did not run exactly once: $log"
mk -q OUT="$a" THREADS=2 all validate || fail "b: still out of date after the re-bake"
# The re-bakes ran with the same options as the first bakes: the same bytes.
for file in ring.glb hatching.ktx2 torus-hatched.glb; do
  cmp -s "$tmp/first/$file" "$a/$file" || fail "b: the re-baked $file differs from the first bake"
done

# c. Two more full bakes: the same options (run to run) and every baker at one thread (run a had
# two) are byte-identical to run a.
compared() { (cd "$1" && find . -type f ! -name '*.report.json' ! -name '*.d' ! -path './stamps/*' -printf '%P\n' | LC_ALL=C sort); }
compare() {  # compare DIR WHAT: every compared file of DIR equals run a's
  local files_a files_x count=0
  files_a="$(compared "$a")"
  files_x="$(compared "$1")"
  [[ "$files_a" == "$files_x" ]] ||
    fail "c: $2 wrote other files than run a: $(diff <(echo "$files_a") <(echo "$files_x") | tr '\n' ' ')"
  while read -r file; do
    [[ -n "$file" ]] || continue
    count=$((count + 1))
    cmp -s "$a/$file" "$1/$file" || fail "c: $file differs between run a and $2 ($(cmp "$a/$file" "$1/$file" 2>&1 | head -1))"
  done <<<"$files_a"
  [[ $count -ge ${#baked[@]} ]] || fail "c: compared only $count files"
  echo "$2: $count files byte-identical to run a"
}
step "c: make -j2 all into $b with THREADS=2 (run to run)"
mk -j2 OUT="$b" THREADS=2 all
compare "$b" "the second bake"
step "c: make -j2 all into $c with THREADS=1"
mk -j2 OUT="$c" THREADS=1 all
compare "$c" "the one-thread bake"

step "done"
if [[ $failures -ne 0 ]]; then
  echo "$failures failure(s)" >&2
  exit 1
fi
