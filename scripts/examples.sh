#!/usr/bin/env bash
# The main job: installs what is missing, builds the tools, describes the example packages in
# pipelines/example with bakeinfo, validates them and renders each (and the bundled example scene)
# headless with bakeplay into out/examples/. (As the bakers land, this bakes the example scenes first.)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh"
"$here/scripts/build.sh"
bin="${BUILD_DIR:-$here/build}/tools"
out="$here/out/examples"
mkdir -p "$out"
cd "$here/pipelines/example"
for package in *.glb *.ktx2; do
  "$bin/bakeinfo/bakeinfo" "$package"
  echo
done
"$bin/bakeplay/bakeplay" validate -q *.glb
for package in *.glb; do
  "$bin/bakeplay/bakeplay" render -q "$package" -o "$out/${package%.glb}.png"
done
"$bin/bakeplay/bakeplay" render -q -o "$out/bundled-example.png" --frames 30 --report "$out/bundled-example.report.json"
echo "rendered: $(cd "$out" && ls *.png | tr '\n' ' ')(in out/examples/)"
echo "open a window on a package: $bin/bakeplay/bakeplay view pipelines/example/wavy-grid.glb"
