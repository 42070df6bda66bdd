#!/usr/bin/env bash
# Size of a critical-speed study against its number of sources (issue 18, item 5): every curve
# is swept on one grid that holds every source's critical speeds, so the curves grow as the
# square of the sources until the limit of 1e7 curve points refuses them up front (exit 3,
# with the estimate). Not a ctest.
#
# Each size runs REPEATS times (3; the machine is shared and noisy) and prints the median time
# with its range; the JSON size and the peak RSS do not depend on the load (the median is shown).
# There is no numpy side: this measures how railmodal grows, not a ratio to another code.
#
#   tools/benchmarks/critical_speed_sources.sh [build/railmodal] [REPEATS]
set -euo pipefail
exe=${1:-build/railmodal}
repeats=${2:-3}
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%8s %6s %12s %14s %10s %16s\n' sources exit "JSON (MB)" "peak RSS (MB)" "time (s)" "range (s)"
for n in 20 200 2000; do
  {
    printf '[scene]\nname = "%s sources"\nvehicle = "%s/data/vehicles/resort_car.toml"\ndofs = "vertical"\n' $n "$here"
    printf '[speed]\nmin = "10 km/h"\nmax = "180 km/h"\nstep = "0.5 km/h"\n'
    for ((i = 0; i < n; ++i)); do
      printf '[[source]]\nkind = "rail_joints"\nrail_length = "%s m"\ndip_depth = "5 mm"\n' "$(echo "10 + $i * 0.001" | bc -l)"
    done
  } > "$work/s$n.toml"
  : > "$work/runs"
  for ((r = 0; r < repeats; ++r)); do
    code=0
    /usr/bin/time -f "%M %e" -o "$work/time" "$exe" critical-speed "$work/s$n.toml" --format json -q \
      -o "$work/s$n.json" 2>/dev/null || code=$?
    tail -1 "$work/time" >> "$work/runs"
  done
  size=$([ -f "$work/s$n.json" ] && stat -c %s "$work/s$n.json" || echo 0)
  kb=$(cut -d' ' -f1 "$work/runs" | sort -n | sed -n "$(( (repeats + 1) / 2 ))p")
  seconds=$(cut -d' ' -f2 "$work/runs" | sort -g | sed -n "$(( (repeats + 1) / 2 ))p")
  range=$(cut -d' ' -f2 "$work/runs" | sort -g | sed -n '1p;$p' | paste -sd-)
  printf '%8d %6s %12.1f %14d %10s %16s\n' $n "$code" "$(echo "$size / 1000000" | bc -l)" $((kb / 1024)) "$seconds" "$range"
done
