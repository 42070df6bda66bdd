#!/usr/bin/env bash
# railmodal as a subproject (add_subdirectory): it configures with the parent's settings and
# brings the library only: no tests, benchmarks or tools of its own, and no -Werror imposed.
# Configure only: building the library again would double the suite's time.
set -euo pipefail
source_dir=$1 consumer_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake -S "$consumer_dir/subproject" -B "$work/build" -DRAILMODAL_SOURCE_DIR="$source_dir" > "$work/configure.log"
targets=$(cmake --build "$work/build" --target help)
grep -q '\.\.\. consumer$' <<<"$targets" || { echo "no consumer target"; exit 1; }
grep -q '\.\.\. railmodal$' <<<"$targets" || { echo "no railmodal library target"; exit 1; }
for t in railmodal_tests railmodal_cli modal_benchmark railmodal_accuracy; do
  if grep -q "\.\.\. $t\$" <<<"$targets"; then echo "a subproject builds $t"; exit 1; fi
done
grep -q -- '-Werror' "$work/build/railmodal/CMakeFiles/railmodal.dir/flags.make" && { echo "-Werror imposed on a consumer"; exit 1; }
echo "subproject: the library alone, without -Werror"
