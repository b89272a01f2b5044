#!/bin/bash
# The CTest test bazel_example (label bazel; registered only when CMake finds `bazel`): installs the
# tools from a build tree into a temporary prefix, copies bazel/ (the rules and this example) to a
# work directory and builds the example with Bazel in batch mode (no server is left running):
#   1. the first build bakes the three assets (tam.ktx2 with its threshold texture, an extra output);
#      tiles.glb is byte-identical to a direct groovebake run;
#   2. a second build re-runs nothing (both outputs keep their inode and mtime);
#   3. changing sources.json (a file declared in `data`, read through an option) re-bakes only
#      patch.glb.
# Usage: run.sh BUILD_DIR WORK_DIR
set -euo pipefail
build=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "FAIL: $*" >&2; exit 1; }
[ -d "$work" ] && chmod -R u+w "$work"  # Bazel leaves its output tree read-only
rm -rf "$work"
mkdir -p "$work"

cmake --install "$build" --prefix "$work/prefix" --component BakeTools > "$work/install.log"
mkdir "$work/rules"
cp "$here/../bake.bzl" "$here/../BUILD.bazel" "$here/../WORKSPACE" "$work/rules/"
mkdir "$work/rules/example"
cp "$here/WORKSPACE" "$here/BUILD.bazel" "$here/tiles.json" "$here/patch.obj" "$here/sources.json" "$here/hatching.json" \
   "$work/rules/example/"
cd "$work/rules/example"
export BAKE_TOOLS_PREFIX="$work/prefix"
step=0
bazel_build() {
  step=$((step + 1))
  bazel --batch --output_user_root="$work/bazel-root" build //:tiles //:patch //:tam > "$work/build$step.log" 2>&1 ||
    { cat "$work/build$step.log"; fail "bazel build $step failed"; }
}
state() { stat -c '%i %y' "bazel-bin/$1"; }

bazel_build
for output in tiles.glb patch.glb tam.ktx2 threshold.ktx2; do [ -s "bazel-bin/$output" ] || fail "bazel-bin/$output was not written"; done
"$work/prefix/bin/groovebake" tiles.json -o "$work/direct.glb" -q
cmp -s bazel-bin/tiles.glb "$work/direct.glb" || fail "tiles.glb differs from a direct groovebake run"
echo "build 1: baked tiles.glb (identical to a direct run), patch.glb, tam.ktx2 and threshold.ktx2"
tiles=$(state tiles.glb) patch=$(state patch.glb)

bazel_build
[ "$(state tiles.glb)" = "$tiles" ] && [ "$(state patch.glb)" = "$patch" ] || fail "build 2 re-baked something"
echo "build 2: nothing re-baked"

echo '{"fields": [{"name": "corner", "sources": [{"vertex": 0}]}, {"name": "far corner", "sources": [{"vertex": 15}]}]}' > sources.json
bazel_build
[ "$(state tiles.glb)" = "$tiles" ] || fail "build 3 re-baked tiles.glb"
[ "$(state patch.glb)" != "$patch" ] || fail "build 3 did not re-bake patch.glb after sources.json changed"
echo "build 3: only patch.glb re-baked"
echo "PASS"
