#!/usr/bin/env bash
# Rewrites the golden outputs (tests/golden/expected/) from build/railmodal, for a commit that
# changes an output on purpose: review `git diff tests/golden` and say why in the message.
# Usage: tools/update_golden.sh [BUILD_DIR]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
exe=${1:-build}/railmodal
[ -x "$exe" ] || { echo "update_golden: no $exe; build railmodal_cli first" >&2; exit 2; }
source tests/golden/cases.sh
rm -rf tests/golden/expected
n=0
while read -r name args; do
  out=tests/golden/expected/$name
  mkdir -p "$(dirname "$out")"
  # A case that fails is recorded too: its exit code and message, then the report it wrote if
  # any (a failed fft-check writes its whole report; check_golden.cmake).
  code=0
  # shellcheck disable=SC2086  # the arguments are words without spaces
  if [[ " $args " == *" @OUT@ "* ]]; then
    "$exe" ${args//@OUT@/$out} >/dev/null 2>"$out.stderr" || code=$?
  else
    "$exe" $args -o "$out" 2>"$out.stderr" || code=$?
  fi
  if [ "$code" != 0 ]; then
    { echo "exit code $code"; cat "$out.stderr"; if [ -f "$out" ]; then cat "$out"; fi; } > "$out.failed"
    mv "$out.failed" "$out"
  fi
  rm -f "$out.stderr"
  n=$((n + 1))
done < <(golden_cases)
echo "update_golden: $n golden outputs in tests/golden/expected ($(du -sh tests/golden/expected | cut -f1))"
