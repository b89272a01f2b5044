#!/usr/bin/env bash
# The heat method's factor check against a faulty BLAS (label cli): a sphere large enough for the
# supernodal factorisation (81k vertices), baked once with the system BLAS and twice with a dgemm_ that
# spoils its results (faulty_blas.c, through LD_PRELOAD): grossly (the factorisation fails) and subtly
# (it succeeds with a wrong factor). Each faulty run must notice both factors, compute them again
# without the BLAS (factorsRedoneWithoutBlas = 2) and bake the same field.
# Arguments: TOOLS_DIR SOURCE_DIR TMP_DIR FAULTY_BLAS_LIBRARY. Exit 77 (skipped) when the tools load a
# sanitizer runtime as a shared library, which must come first among preloaded libraries (clang links
# its runtime statically, so the ASan + UBSan stage does run this test).
set -euo pipefail
source "$(dirname "$0")/../pipeline/script_support.sh"
faulty="$(cd "$(dirname "$4")" && pwd)/$(basename "$4")"
read_test_arguments "$1" "$2" "$3"

if ldd "$bin/geobake/geobake" | grep -q 'libasan\|libtsan'; then
  echo "skipped: a sanitizer runtime cannot share LD_PRELOAD"
  exit 77
fi

"$bin/bakeshape/bakeshape" sphere --resolution 90 -o "$tmp/sphere.glb" -q
bake() {  # OUTPUT REPORT [env...]
  local out=$1 report=$2
  shift 2
  env "$@" "$bin/geobake/geobake" "$tmp/sphere.glb" -o "$out" --method heat --auto-sources 2 -j 2 \
    --normalize none --report "$report" -q
}
bake "$tmp/system.glb" "$tmp/system.json"
bake "$tmp/gross.glb" "$tmp/gross.json" LD_PRELOAD="$faulty" FAULTY_BLAS=gross
bake "$tmp/subtle.glb" "$tmp/subtle.json" LD_PRELOAD="$faulty" FAULTY_BLAS=subtle

python3 - "$tmp" <<'PY' || fail "the faulty-BLAS bake differs (see above)"
import json, struct, sys, array
tmp = sys.argv[1]
def solver(name):
    return json.load(open(f"{tmp}/{name}.json"))["statistics"]["solver"]
def field(name):
    data = open(f"{tmp}/{name}.glb", "rb").read()
    length = struct.unpack_from("<I", data, 12)[0]
    doc = json.loads(data[20:20 + length])
    start = 20 + length + 8
    accessor = doc["accessors"][doc["meshes"][0]["primitives"][0]["attributes"]["_GEODESIC_0"]]
    view = doc["bufferViews"][accessor["bufferView"]]
    offset = start + view.get("byteOffset", 0) + accessor.get("byteOffset", 0)
    values = array.array("f")
    values.frombytes(data[offset:offset + 4 * accessor["count"]])
    return values
system = solver("system")
ok = True
if system["factorsRedoneWithoutBlas"] != 0 or system["factorBackwardError"] > 1e-12:
    print("system BLAS: unexpected check result", system); ok = False
reference = field("system")
scale = max(reference)
for name in ("gross", "subtle"):
    faulty = solver(name)
    if faulty["factorsRedoneWithoutBlas"] != 2 or faulty["factorBackwardError"] > 1e-12:
        print(f"{name} fault: both factors should have been redone", faulty); ok = False
    worst = max(abs(x - y) for x, y in zip(reference, field(name))) / scale
    print(f"{name} fault: largest difference from the system BLAS's field {worst:.3g} of the largest distance")
    if worst > 1e-5:
        ok = False
sys.exit(0 if ok else 1)
PY
exit $((failures > 0))
