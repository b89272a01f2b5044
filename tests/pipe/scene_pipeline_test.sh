#!/usr/bin/env bash
# End to end over the example scenes (label pipeline): bakepipe writes a Ninja file, Ninja bakes,
# assembles and validates; a second run does nothing; touching one input re-runs only its dependents;
# the pruned scene package renders the same image as the full one (--keep-unused) and is smaller.
#   scene_pipeline_test.sh TOOLS_DIR SOURCE_DIR TMP_DIR SCENE...
set -euo pipefail
tools="$1" source="$2" tmp="$3"
shift 3
bakepipe="$tools/bakepipe/bakepipe" bakeplay="$tools/bakeplay/bakeplay"
fail() { echo "FAIL: $*" >&2; exit 1; }

# The commands a Ninja run executed, one description per line ("[n/m] desc" -> "desc").
ran() { sed -n 's/^\[[0-9]*\/[0-9]*\] //p'; }

# The scene's first camera as bakeplay's --camera and --size.
camera_of() {
  "$bakepipe" plan "$1" --json >/dev/null  # the scene must plan
  local scene="$1"
  local eye target size
  eye=$(sed -n 's/.*"eye": *\[\([^]]*\)\].*/\1/p' "$scene" | head -1 | tr -d ' ')
  target=$(sed -n 's/.*"target": *\[\([^]]*\)\].*/\1/p' "$scene" | head -1 | tr -d ' ')
  size=$(sed -n 's/.*"width": *\([0-9]*\), *"height": *\([0-9]*\).*/\1x\2/p' "$scene" | head -1)
  echo "--camera $eye:$target --size $size"
}

# Each scene runs from a copy of its folder, so touching an input never disturbs the source tree.
for name in "$@"; do
  work="$tmp/$name"
  rm -rf "$work"
  mkdir -p "$work"
  cp -r "$source/pipelines/$name" "$work/src"
  scene="$work/src/scene.json"
  for variant in pruned full; do
    keep=()
    [[ $variant == full ]] && keep=(--keep-unused)
    "$bakepipe" ninja "$scene" --out-dir "$work/$variant" --tools "$tools/bakepipe" "${keep[@]}" -o "$work/$variant.ninja" -q
    ninja -f "$work/$variant.ninja" >"$work/$variant.log" || { cat "$work/$variant.log"; fail "$name $variant: ninja failed"; }
    [[ -f "$work/$variant/$name.glb.validated" ]] || fail "$name $variant: not validated"
  done
  # Assembling again gives the same bytes.
  "$bakepipe" assemble "$scene" --out-dir "$work/pruned" --tools "$tools/bakepipe" -q -o "$work/again.glb"
  cmp -s "$work/again.glb" "$work/pruned/$name.glb" || fail "$name: a second assembly differs from the first"
  # A second run executes nothing.
  again=$(ninja -f "$work/pruned.ninja" | ran)
  [[ -z "$again" ]] || fail "$name: a second run executed: $again"

  # The same image from the pruned and the full package, and fewer bytes.
  read -r -a view <<<"$(camera_of "$scene")"
  for variant in pruned full; do
    "$bakeplay" render -q "$work/$variant/$name.glb" "${view[@]}" -o "$work/$variant.png" --report "$work/$variant.render.json"
  done
  cmp -s "$work/pruned.png" "$work/full.png" || fail "$name: the pruned package renders differently from the full one"
  pruned=$(stat -c %s "$work/pruned/$name.glb") full=$(stat -c %s "$work/full/$name.glb")
  ((pruned < full)) || fail "$name: the pruned package ($pruned bytes) is not smaller than the full one ($full bytes)"
  # The runtime uploads and compiles no more for the pruned package: GPU bytes, and shader variants
  # a subset of the full package's.
  node -e '
    const [a, b] = process.argv.slice(1).map(f => JSON.parse(require("fs").readFileSync(f)).statistics);
    const extra = a.shaderVariants.filter(v => !b.shaderVariants.includes(v));
    if (a.gpuBytes > b.gpuBytes || extra.length) {
      console.error(`FAIL: pruned ${a.gpuBytes} GPU bytes vs ${b.gpuBytes}; variants only in pruned: ${extra}`);
      process.exit(1);
    }
    console.log(`GPU bytes ${a.gpuBytes} pruned vs ${b.gpuBytes} full; ${a.shaderVariants.length} vs ${b.shaderVariants.length} shader variants`);
  ' "$work/pruned.render.json" "$work/full.render.json" || fail "$name: the pruned package costs the runtime more"
  # Every package of the scene, per object and assembled, pruned and full, passes the Khronos
  # glTF-Validator: no errors, warnings only from tests/js/gltf_allowed_warnings.json.
  mapfile -t packages < <(find "$work/pruned" "$work/full" -name '*.glb' | sort)
  node "$source/tests/js/validate_packages.mjs" -q "${packages[@]}" >"$work/validator.log" ||
    { cat "$work/validator.log"; fail "$name: a package fails the glTF-Validator"; }
  echo "$name: same image, $pruned bytes pruned vs $full full; ${#packages[@]} packages pass the glTF-Validator"
done

# Touching one input re-runs only its dependents: the ring's profile re-bakes the ring, re-assembles
# and re-validates; nothing generated, no other object.
if [[ " $* " == *" revolution "* ]]; then
  touch "$tmp/revolution/src/ring.json"
  rerun=$(ninja -f "$tmp/revolution/pruned.ninja" | ran | sort | tr '\n' ' ')
  expected="ASSEMBLE $tmp/revolution/pruned/revolution.glb VALIDATE $tmp/revolution/pruned/revolution.glb revolbake:ring "
  [[ "$rerun" == "$expected" ]] || fail "touching ring.json re-ran: $rerun (expected: $expected)"
fi
echo "ok"
