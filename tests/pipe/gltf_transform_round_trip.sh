#!/usr/bin/env bash
# Baked data survive glTF-Transform (npm @gltf-transform/cli, pinned in tests/js/package.json) with our
# extension modules (integrations/gltf-transform): every package in FOLDER goes through `copy`,
# `prune`, `dedup` and `optimize` (without the steps that rewrite what the extensions index: geometry
# simplification, welding, vertex-attribute pruning, mesh and texture compression; see
# integrations/gltf-transform/README.md), and the result must pass `bakeplay
# validate` and show the first reference view of the original package (the same tolerances as a
# golden image).
#   gltf_transform_round_trip.sh TOOLS_DIR SOURCE_DIR FOLDER
set -euo pipefail
tools="$(cd "$1" && pwd)" source="$(cd "$2" && pwd)" folder="$(cd "$3" && pwd)"
cli="$source/tests/js/node_modules/.bin/gltf-transform"
config="$source/tests/js/gltf_transform_config.mjs"
[[ -x "$cli" ]] || { echo "FAIL: $cli is missing (scripts/setup.sh installs it)" >&2; exit 1; }
work="$folder/gltf-transform"
rm -rf "$work"
mkdir -p "$work/views"
failures=0
checked=0
mapfile -t packages < <(find "$folder" -maxdepth 1 -name '*.glb' | sort)
for package in "${packages[@]}"; do
  name="$(basename "$package" .glb)"
  # Only packages that carry a BAKE_* extension (the generated meshes are plain glTF).
  grep -aq '"BAKE_' "$package" || continue
  "$tools/bakeplay/bakeplay" validate -q "$package" --views "$work/views/$name" --size 96
  golden="$work/views/$name/$name.view0.png"
  for step in copy prune dedup optimize; do
    # Vertex-attribute pruning keeps TEXCOORD_n only for materials with standard textures, and the
    # grooves' TEXCOORD_0 is the groove domain: prune and optimize run without it.
    options=()
    [[ $step == prune ]] && options=(--keep-attributes true)
    [[ $step == optimize ]] && options=(--compress false --texture-compress false --simplify false --weld false
                                        --prune-attributes false)
    out="$work/$name.$step.glb"
    if ! (cd "$source/tests/js" && "$cli" "$step" "$package" "$out" "${options[@]}" --config "$config") \
        >"$work/$name.$step.log" 2>&1; then
      echo "FAIL: gltf-transform $step $name:"; cat "$work/$name.$step.log"; failures=$((failures + 1)); continue
    fi
    if grep -q "Missing" "$work/$name.$step.log"; then
      echo "FAIL: gltf-transform $step $name did not know an extension:"; cat "$work/$name.$step.log"
      failures=$((failures + 1)); continue
    fi
    if ! "$tools/bakeplay/bakeplay" validate -q "$out" --golden "$golden" --size 96; then
      echo "FAIL: $name after gltf-transform $step"; failures=$((failures + 1)); continue
    fi
    checked=$((checked + 1))
  done
done
echo "gltf-transform round trip: $checked package/step pairs kept their baked data and picture, $failures failed"
((checked >= 40)) || { echo "FAIL: only $checked pairs checked" >&2; exit 1; }
((failures == 0))
