#!/usr/bin/env bash
# The main job: installs what is missing, builds the tools, and describes the example packages in
# pipelines/example with bakeinfo. (As the bakers land, this bakes the example scenes and renders them.)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh"
"$here/scripts/build.sh"
bin="${BUILD_DIR:-$here/build}/tools"
cd "$here/pipelines/example"
for package in *.glb *.ktx2; do
  "$bin/bakeinfo/bakeinfo" "$package"
  echo
done
