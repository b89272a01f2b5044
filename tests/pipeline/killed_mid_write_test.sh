#!/usr/bin/env bash
# A bake killed while it writes leaves no partial file (CTest label cli):
#   killed_mid_write_test.sh TOOLS_DIR SOURCE_DIR TMP_DIR
# TOOLS_DIR holds the built tools as TOOLS_DIR/<tool>/<tool>. For every baker and output kind:
#   a. the outputs are made once for reference (a full bake in ref/);
#   b. the outputs are replaced by sentinel bytes ("an earlier output"), then the same bake runs under
#      a file-size limit (ulimit -f) of half its largest output, so the kernel stops it with SIGXFSZ
#      in the middle of write(): it must die by that signal, every output must still hold the sentinel
#      byte for byte, and no temporary file (.NAME.tmp.XXXXXX) may remain;
#   c. the bake is stopped with SIGTERM at moments spread over its run time: each output then holds
#      either the sentinel or the complete reference bytes, never anything else, and no temporary
#      remains.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/script_support.sh"
read_test_arguments "$@"
mkdir -p "$tmp/inputs"
in="$tmp/inputs"

# Inputs the bakes share (generated once, outside the directories under test).
"$bin/bakeshape/bakeshape" pretzel -o "$in/pretzel.glb" -q
"$bin/bakeshape/bakeshape" torus -o "$in/torus.glb" -q
"$bin/bakeshape/bakeshape" glaze --resolution 256 -o "$in/glaze.png" -q
"$bin/bakeshape/bakeshape" hammered --resolution 256 -o "$in/hammered.png" -q

# Each case: a name, the outputs (relative to the run directory), then the command; OUT/ in the
# command stands for the run directory.
cases=(
  "shape|pretzel.glb|$bin/bakeshape/bakeshape pretzel -o OUT/pretzel.glb -q"
  "pattern|hammered.png|$bin/bakeshape/bakeshape hammered --resolution 1024 -o OUT/hammered.png -q"
  "geodesic|fields.glb|$bin/geobake/geobake $in/pretzel.glb --sources $src/pipelines/geodesic/sources.json -o OUT/fields.glb -q -j 1"
  "revolution|vase.glb|$bin/revolbake/revolbake $src/pipelines/revolution/vase.json -o OUT/vase.glb --base-color $in/glaze.png --height-map $in/hammered.png --height-scale 0.004 -q -j 1"
  "tam|hatching.ktx2 torus-hatched.glb|$bin/tambake/tambake $src/pipelines/hatching/hatching.json -o OUT/hatching.ktx2 --apply-to $in/torus.glb --package OUT/torus-hatched.glb -q -j 1"
  "grooves|tiles.glb|$bin/groovebake/groovebake $src/pipelines/grooves/tiles.json -o OUT/tiles.glb -q -j 1"
)

no_temporaries() {  # directory, context
  local left
  left="$(find "$1" -name '*.tmp.*' | head -5)"
  [[ -z "$left" ]] || fail "$2: temporaries left behind: $left"
}

write_sentinels() {  # directory, outputs...
  local dir="$1"
  shift
  for output in "$@"; do printf 'an earlier output of %s\n' "$output" > "$dir/$output"; done
}

holds_sentinel() {  # directory, output
  cmp -s "$1/$2" <(printf 'an earlier output of %s\n' "$2")
}

for entry in "${cases[@]}"; do
  IFS='|' read -r name outputs command <<< "$entry"
  read -r -a outputs <<< "$outputs"

  # a. reference bake, timed for c.
  ref="$tmp/$name/ref"
  mkdir -p "$ref"
  start=$(date +%s%N)
  ${command//OUT/$ref}
  elapsed_ms=$(( ($(date +%s%N) - start) / 1000000 ))
  largest=0
  for output in "${outputs[@]}"; do
    size=$(stat -c %s "$ref/$output")
    (( size > largest )) && largest=$size
  done

  # b. a file-size limit of half the largest output: killed by SIGXFSZ inside write().
  limited="$tmp/$name/limited"
  mkdir -p "$limited"
  write_sentinels "$limited" "${outputs[@]}"
  limit_kib=$(( largest / 2048 ))
  (( limit_kib >= 1 )) || { fail "$name: output too small ($largest bytes) for the test"; continue; }
  status=0
  # (bash's own "File size limit exceeded" notice goes to the outer redirection.)
  { ( ulimit -f "$limit_kib"; exec ${command//OUT/$limited} ) 2> "$limited.stderr"; } 2> /dev/null || status=$?
  [[ $status -eq $((128 + 25)) ]] || fail "$name: under ulimit -f $limit_kib expected death by SIGXFSZ (exit 153), got $status: $(head -3 "$limited.stderr")"
  for output in "${outputs[@]}"; do
    holds_sentinel "$limited" "$output" || fail "$name: $output changed although the bake was killed mid-write"
  done
  no_temporaries "$limited" "$name (SIGXFSZ)"

  # c. SIGTERM at moments spread over the bake (fractions of its measured time, and early on).
  for fraction in 5 20 40 60 80 95 99; do
    stopped="$tmp/$name/term-$fraction"
    mkdir -p "$stopped"
    write_sentinels "$stopped" "${outputs[@]}"
    delay_ms=$(( elapsed_ms * fraction / 100 ))
    status=0
    timeout -s TERM "$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))" ${command//OUT/$stopped} \
      2> "$stopped.stderr" || status=$?
    [[ $status -eq 0 || $status -eq 124 ]] || fail "$name: SIGTERM after ${delay_ms} ms: unexpected exit $status: $(head -3 "$stopped.stderr")"
    for output in "${outputs[@]}"; do
      if ! holds_sentinel "$stopped" "$output" && ! cmp -s "$stopped/$output" "$ref/$output"; then
        fail "$name: SIGTERM after ${delay_ms} ms left $output neither the earlier nor the complete output"
      fi
    done
    no_temporaries "$stopped" "$name (SIGTERM after ${delay_ms} ms)"
  done
  echo "$name: reference bake ${elapsed_ms} ms, largest output $largest bytes, checked"
done

if (( failures > 0 )); then
  echo "$failures failure(s)" >&2
  exit 1
fi
echo "every interrupted bake left the earlier outputs intact and no temporary file"
