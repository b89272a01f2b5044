# Shared by the end-to-end test scripts of this folder (sourced): their arguments and failure count.
#   read_test_arguments "$@"   TOOLS_DIR SOURCE_DIR TMP_DIR -> $bin, $src and a fresh, absolute $tmp
#   fail MESSAGE               reports a failure and counts it in $failures (the script exits at the end)

read_test_arguments() {
  if [[ $# -ne 3 ]]; then
    echo "usage: $0 TOOLS_DIR SOURCE_DIR TMP_DIR" >&2
    exit 1
  fi
  bin="$(cd "$1" && pwd)"
  src="$(cd "$2" && pwd)"
  rm -rf "$3"
  mkdir -p "$3"
  tmp="$(cd "$3" && pwd)"
}

failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}
