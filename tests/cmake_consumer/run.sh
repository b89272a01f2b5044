#!/bin/bash
# The CTest test cmake_consumer: installs the tools and the BakeTools CMake package from a build tree
# into a temporary prefix, builds the consumer project (tests/cmake_consumer) against it with Ninja,
# checks that an installed tool loads the installed image codec module, and checks the incremental builds the depfiles make possible:
#   1. the first build bakes both assets;
#   2. a second build has nothing to do (`ninja -n` says "no work to do") and bakes nothing;
#   3. touching the groove scene (the INPUT) re-bakes only that asset;
#   4. touching the geodesic sources file (named only in ARGS, so known only from the depfile)
#      re-bakes only that asset;
#   5. afterwards there is nothing to do again.
# Usage: run.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
build=$1 source=$2 work=$3
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$work"
mkdir -p "$work"

cmake --install "$build" --prefix "$work/prefix" --component BakeTools > "$work/install.log"
for tool in groovebake geobake; do
  [ -x "$work/prefix/bin/$tool" ] || fail "cmake --install did not install bin/$tool"
done
[ -f "$work/prefix/lib/cmake/BakeTools/BakeToolsConfig.cmake" ] || fail "no BakeToolsConfig.cmake installed"
[ -f "$work/prefix/lib/cmake/BakeTools/BakeToolsConfigVersion.cmake" ] || fail "no BakeToolsConfigVersion.cmake installed"
# The man pages (made by help2man from --help) are installed with the tools.
if command -v help2man >/dev/null; then
  for tool in groovebake geobake tambake; do
    grep -qF -- '\-\-output' "$work/prefix/share/man/man1/$tool.1" 2>/dev/null || fail "no man page share/man/man1/$tool.1"
  done
fi
# The image codec module is installed with the tools, and an installed tool loads that copy (not the
# build tree's) the first time it writes an image.
codec=$(find "$work/prefix" -name libbake_image_oiio.so | head -n 1)
[ -n "$codec" ] || fail "cmake --install did not install the image codec module"
LD_DEBUG=files "$work/prefix/bin/bakeshape" glaze --resolution 16 -o "$work/pattern.png" 2> "$work/loads.log" ||
  fail "the installed bakeshape cannot write a PNG"
grep -q "file=$work/prefix/bin/../lib[^ ]*/bake/libbake_image_oiio.so .*dynamically loaded" "$work/loads.log" ||
  fail "the installed bakeshape did not load the installed image codec ($codec)"

cp -r "$source/tests/cmake_consumer" "$work/src"
cmake -S "$work/src" -B "$work/build" -G Ninja -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log" ||
  { cat "$work/configure.log"; fail "the consumer does not configure"; }
grep -q "$work/prefix/bin/groovebake" "$work/build/build.ninja" || fail "the build does not use the installed groovebake"

step=0
build_consumer() {  # build_consumer EXPECTED... : the assets that must be baked (and no others)
  step=$((step + 1))
  local log="$work/build$step.log"
  cmake --build "$work/build" > "$log" 2>&1 || { cat "$log"; fail "build $step failed"; }
  for asset in tiles patch; do
    local expected=no
    for e in "$@"; do [ "$e" = "$asset" ] && expected=yes; done
    if grep -q "Baking assets/$asset.glb" "$log"; then baked=yes; else baked=no; fi
    [ "$baked" = "$expected" ] || { cat "$log"; fail "build $step: $asset baked: $baked, expected: $expected"; }
  done
  echo "build $step: baked ${*:-nothing}"
}
no_work() {
  ninja -C "$work/build" -n > "$work/dry$step.log"
  grep -q "no work to do" "$work/dry$step.log" || { cat "$work/dry$step.log"; fail "after build $step: ninja -n has work to do"; }
  echo "after build $step: ninja -n: no work to do"
}

build_consumer tiles patch
for asset in tiles patch; do
  [ -s "$work/build/assets/$asset.glb" ] || fail "assets/$asset.glb was not written"
  grep -q "$work/src/" "$work/build/assets/$asset.glb.d" || fail "assets/$asset.glb.d names no input"
done
grep -q "sources.json" "$work/build/assets/patch.glb.d" || fail "the geobake depfile does not name the sources file"
no_work
build_consumer

touch "$work/src/tiles.json"
build_consumer tiles
no_work

touch "$work/src/sources.json"
build_consumer patch
no_work
echo "PASS"
