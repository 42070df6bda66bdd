#!/usr/bin/env bash
# Peak memory of `railmodal simulate` against the length of the run (issue 18, item 4): a csv
# history is streamed as the simulation goes, so the peak RSS stays flat from T to 10T, while
# a json history and --spectra hold the record of the outputs and grow with it (up to the
# memory limit, docs/input.md "Resource limits"). Not a ctest: it takes about a minute.
#
#   tools/benchmarks/simulate_memory.sh [build/railmodal]
#
# Prints one line per run: the output, the duration, the samples and the peak RSS (GNU time -v).
# One run each: the peak RSS is set by the allocations, not by the load on the machine (repeat
# runs differ by a few hundred kB), and no time or ratio is reported. There is no numpy side.
set -euo pipefail
exe=${1:-build/railmodal}
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The resort car released (6 vertical DOFs, the linear path) at 5 ms, for T = 800 s and 10T.
scene() {
  cat > "$work/run_$1.toml" <<TOML
[scene]
name = "resort car released, $1 s"
vehicle = "$here/data/vehicles/resort_car.toml"
dofs = "vertical"
[simulation]
duration = "$1 s"
time_step = "5 ms"
[[simulation.initial]]
dof = "body.bounce"
displacement = "20 mm"
TOML
}
peak_kb() {
  /usr/bin/time -v -o "$work/time" "$@" >/dev/null
  sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/time"
}
printf '%-22s %10s %10s %14s\n' output duration samples "peak RSS (MB)"
for duration in 800 8000; do
  scene $duration
  samples=$((duration * 200 + 1))
  for mode in csv json spectra; do
    case $mode in
      csv) args=(-o "$work/h.csv") ;;
      json) args=(--format json -o "$work/h.json") ;;
      spectra) args=(-o "$work/h.csv" --spectra "$work/s.csv") ;;
    esac
    kb=$(peak_kb "$exe" simulate "$work/run_$duration.toml" "${args[@]}")
    printf '%-22s %9ss %10d %14d\n' "$mode" "$duration" "$samples" "$((kb / 1024))"
  done
done
