#!/usr/bin/env bash
# Checks that bench/accuracy_page.py cannot write an empty record without saying so: on a copy of a
# complete record (default docs/) it must succeed; with a section's CSV emptied down to its header, a
# CSV removed, a plot removed or a section's run record removed it must exit non-zero and name the
# problem on the page.
#   bench/test_accuracy_page.sh [RECORD_DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
record="${1:-$here/docs}"
page="$here/bench/accuracy_page.py"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
failures=0

fresh() { rm -rf "$tmp/r"; mkdir -p "$tmp/r"; cp -r "$record/accuracy" "$tmp/r/"; }

# expect_failure WHAT TEXT: the generator must exit non-zero and the page must contain TEXT.
expect_failure() {
  local what="$1" text="$2" rc=0
  python3 "$page" --dir "$tmp/r" 2>"$tmp/err" || rc=$?
  if [[ $rc == 0 ]]; then
    echo "FAIL: $what: the generator succeeded" >&2
    failures=$((failures + 1))
  elif ! grep -qF "$text" "$tmp/r/accuracy.md"; then
    echo "FAIL: $what: the page does not say '$text'" >&2
    failures=$((failures + 1))
  else
    echo "ok: $what: exit $rc, the page says '$text'"
  fi
}

fresh
if python3 "$page" --dir "$tmp/r" 2>"$tmp/err"; then
  echo "ok: the complete record gives a page"
else
  echo "FAIL: the complete record in $record: $(cat "$tmp/err")" >&2
  failures=$((failures + 1))
fi

fresh
head -1 "$tmp/r/accuracy/tam/tam.csv" >"$tmp/tam.csv" && mv "$tmp/tam.csv" "$tmp/r/accuracy/tam/tam.csv"
expect_failure "tam.csv without data rows" "tam.csv has no data rows"

fresh
rm "$tmp/r/accuracy/geodesic/geodesic.csv"
expect_failure "geodesic.csv missing" "geodesic.csv is missing"

fresh
rm "$tmp/r/accuracy/stroke/stroke.png"
expect_failure "stroke.png missing" "the plot stroke.png is missing"

fresh
rm "$tmp/r/accuracy/resources/run.txt"
expect_failure "resources not run" "resources: not run"

fresh
sed -i 's/^exit=0$/exit=1/' "$tmp/r/accuracy/groove/run.txt"
expect_failure "groove failed" "This benchmark failed"

if ((failures)); then
  echo "$failures check(s) failed" >&2
  exit 1
fi
echo "all checks passed"
