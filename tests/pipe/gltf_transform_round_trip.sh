#!/usr/bin/env bash
# Baked data survive glTF-Transform (npm @gltf-transform/cli, pinned in tests/js/package.json) with our
# extension modules (integrations/gltf-transform): every package in FOLDER goes through `copy`, then
# `prune`, `dedup` and `optimize`, each on the one before, without the steps that rewrite what the
# extensions index (geometry simplification, welding, vertex-attribute pruning, mesh and texture
# compression; integrations/gltf-transform/README.md). The result must pass `bakeplay validate` and
# show the original package's first reference view (the tolerances of a golden image). Without the
# modules, glTF-Transform must refuse the packages that list their extension as required.
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
refused=0
mapfile -t packages < <(find "$folder" -maxdepth 1 -name '*.glb' | sort)
# One chain per package, copy -> prune -> dedup -> optimize, each step reading the one before: every
# step must run and know every extension, and the chain's end must still be the same package (one
# validation per package keeps the test to about a minute).
for package in "${packages[@]}"; do
  name="$(basename "$package" .glb)"
  # Only packages that carry a BAKE_* extension (the generated meshes are plain glTF).
  grep -aq '"BAKE_' "$package" || continue
  "$tools/bakeplay/bakeplay" validate -q "$package" --views "$work/views/$name" --size 96
  golden="$work/views/$name/$name.view0.png"
  input="$package"
  ok=true
  for step in copy prune dedup optimize; do
    # Vertex-attribute pruning keeps TEXCOORD_n only for materials with standard textures, and the
    # grooves' TEXCOORD_0 is the groove domain: prune and optimize run without it.
    options=()
    [[ $step == prune ]] && options=(--keep-attributes true)
    [[ $step == optimize ]] && options=(--compress false --texture-compress false --simplify false --weld false
                                        --prune-attributes false)
    out="$work/$name.$step.glb"
    if ! (cd "$source/tests/js" && "$cli" "$step" "$input" "$out" "${options[@]}" --config "$config") \
        >"$work/$name.$step.log" 2>&1; then
      echo "FAIL: gltf-transform $step $name:"; cat "$work/$name.$step.log"; ok=false; break
    fi
    if grep -q "Missing" "$work/$name.$step.log"; then
      echo "FAIL: gltf-transform $step $name did not know an extension:"; cat "$work/$name.$step.log"; ok=false; break
    fi
    input="$out"
  done
  # Without the modules glTF-Transform is a tool that does not know our extensions: it must refuse a
  # package whose primitives mean nothing without theirs (extensionsRequired: BAKE_grooves, the policy
  # of docs/architecture.md) and copy the others, keeping the plain object.
  required=$(node -e '
    const b = require("fs").readFileSync(process.argv[1]), n = b.readUInt32LE(12);
    const j = JSON.parse(b.toString("utf8", 20, 20 + n));
    const used = j.extensionsUsed || [], req = j.extensionsRequired || [];
    if (used.includes("BAKE_grooves") && !req.includes("BAKE_grooves")) { console.log("unlisted"); process.exit(0); }
    console.log(req.filter((e) => e.startsWith("BAKE_")).join(" "));' "$package")
  if [[ $required == unlisted ]]; then
    echo "FAIL: $name carries BAKE_grooves without listing it in extensionsRequired"; ok=false
  elif (cd "$source/tests/js" && "$cli" copy "$package" "$work/$name.plain.glb") >"$work/$name.plain.log" 2>&1; then
    [[ -z $required ]] || { echo "FAIL: gltf-transform without our modules copied $name (requires $required)"; ok=false; }
  elif [[ -z $required ]] || ! grep -q "Missing required extension" "$work/$name.plain.log"; then
    echo "FAIL: gltf-transform without our modules refused $name:"; cat "$work/$name.plain.log"; ok=false
  else
    refused=$((refused + 1))
  fi
  if $ok && ! "$tools/bakeplay/bakeplay" validate -q "$input" --golden "$golden" --size 96; then
    echo "FAIL: $name after gltf-transform copy, prune, dedup and optimize"; ok=false
  fi
  if $ok; then checked=$((checked + 1)); else failures=$((failures + 1)); fi
done
echo "gltf-transform round trip: $checked packages kept their baked data and picture through copy, prune," \
     "dedup and optimize; $failures failed; without our modules it refused the $refused that require their extension"
((checked >= 12)) || { echo "FAIL: only $checked packages checked" >&2; exit 1; }
((refused >= 1)) || { echo "FAIL: no package required its extension" >&2; exit 1; }
((failures == 0))
