# Shared by the bench run.sh scripts (sourced after `set -euo pipefail`).
#   bench_setup "$@"       sets here (the checkout), build (BUILD_DIR, default build-bench), out (the
#                          value of --out DIR / --out=DIR, else BUILD_DIR/results) and args (the
#                          arguments, with --out added when they had none); creates out.
#   bench_build TARGET...  configures build (BUILD_TYPE, default Release, -DBAKE_BUILD_BENCH=ON) and
#                          builds only these targets.
#   bench_plot PNG GNUPLOT_ARGS...  runs gnuplot when it is there, else says how to get it.
bench_setup() {
  here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  build="${BUILD_DIR:-$here/build-bench}"
  out="$build/results"
  args=("$@")
  local out_given=0 i
  for ((i = 0; i < ${#args[@]}; ++i)); do
    if [[ "${args[i]}" == "--out" && $((i + 1)) -lt ${#args[@]} ]]; then out="${args[i + 1]}"; out_given=1; fi
    if [[ "${args[i]}" == --out=* ]]; then out="${args[i]#--out=}"; out_given=1; fi
  done
  [[ $out_given == 1 ]] || args=(--out "$out" "${args[@]}")
  mkdir -p "$out"
}

bench_build() {
  cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-Release}" -DBAKE_BUILD_BENCH=ON >/dev/null
  cmake --build "$build" --target "$@" --parallel "$(nproc)"
}

bench_plot() {
  local png="$1"
  shift
  if command -v gnuplot >/dev/null; then
    gnuplot "$@"
    echo "plot: $png"
  else
    echo "gnuplot not found (apt-get install gnuplot-nox): no plot" >&2
  fi
}
