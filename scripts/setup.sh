#!/usr/bin/env bash
# Installs every build, test and runtime dependency of the bake toolchain from Debian 12 packages,
# plus the npm packages the tests use as independent checkers. Idempotent: when everything is already
# present it does no network access and returns in well under a second.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

debian_packages=(
  build-essential cmake ninja-build ccache pkg-config git ca-certificates
  libopenmesh-dev libcgal-dev libgmp-dev libmpfr-dev
  libopenimageio-dev openimageio-tools libopenexr-dev libdraco-dev libxxhash-dev
  libcli11-dev nlohmann-json3-dev libxml2-dev
  libeigen3-dev libsuitesparse-dev libzstd-dev libopenblas0-pthread
  libgtest-dev libgmock-dev libbenchmark-dev
  libegl-dev libgl-dev libopengl-dev libegl-mesa0 libgl1-mesa-dri libglfw3-dev
  libopencv-dev gnuplot-nox xvfb xauth help2man
  clang libclang-rt-14-dev time python3 chromium
)

missing=()
for p in "${debian_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
command -v npm >/dev/null 2>&1 || missing+=(nodejs npm)

if ((${#missing[@]})); then
  echo "setup: installing ${#missing[@]} Debian packages: ${missing[*]}" >&2
  sudo=""; [[ $(id -u) -ne 0 ]] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# Independent checkers used by the tests (Khronos glTF-Validator, ktx-parse, Ajv for JSON Schema), and
# glTF-Transform, the tool the packages must survive (tests/pipe/gltf_transform_round_trip.sh).
js="$here/tests/js"
if [[ ! -f "$js/node_modules/.setup-stamp" || "$js/package-lock.json" -nt "$js/node_modules/.setup-stamp" ]]; then
  echo "setup: installing npm test checkers" >&2
  (cd "$js" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
  touch "$js/node_modules/.setup-stamp"
fi
# three.js for the web engine plugin (integrations/three), drawn in headless Chromium by its test.
three="$here/integrations/three"
if [[ ! -f "$three/node_modules/.setup-stamp" || "$three/package-lock.json" -nt "$three/node_modules/.setup-stamp" ]]; then
  echo "setup: installing three.js for integrations/three" >&2
  (cd "$three" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
  touch "$three/node_modules/.setup-stamp"
fi
