#!/usr/bin/env bash
# The example packages of Makefile.examples (label cli): baked into the folder (incrementally: CTest
# gives it the folder examples_bake has just filled, so nothing is baked twice), every one passes
# the Khronos glTF-Validator with no errors and warnings only from tests/js/gltf_allowed_warnings.json,
# and survives glTF-Transform's copy, prune, dedup and optimize with its baked data and its picture
# (gltf_transform_round_trip.sh).
#   example_packages_test.sh TOOLS_DIR SOURCE_DIR TMP_DIR
set -euo pipefail
tools="$1" source="$2" tmp="$3"
mkdir -p "$tmp"
make -s -f "$source/Makefile.examples" -j2 BIN="$tools" OUT="$tmp" all >"$tmp/make.log" 2>&1 ||
  { cat "$tmp/make.log"; echo "FAIL: the example bakes failed" >&2; exit 1; }
mapfile -t packages < <(find "$tmp" -maxdepth 1 -name '*.glb' | sort)
((${#packages[@]} >= 10)) || { echo "FAIL: only ${#packages[@]} example packages" >&2; exit 1; }
node "$source/tests/js/validate_packages.mjs" "${packages[@]}"
# The same packages through glTF-Transform with the project's extension modules.
bash "$source/tests/pipe/gltf_transform_round_trip.sh" "$tools" "$source" "$tmp"
