#!/usr/bin/env bash
# Quick start, step 2: install, build everything, run every test (what CI runs).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_dependencies.sh
# The test and library files compile in batches, and only the benchmark programs a test runs:
# a clean build in less time; the GoogleTest suite runs as two processes (GoogleTest shards),
# not one a test (docs/architecture.md, "Build").
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRAILMODAL_MPI=ON -DRAILMODAL_UNITY_TESTS=ON \
  -DRAILMODAL_UNITY_LIBRARY=ON -DRAILMODAL_BENCHMARKS_ALL=OFF -DRAILMODAL_TEST_SHARDS=2 >/dev/null
# Each stage's processor time (user and system, children included) and wall time.
TIMEFORMAT='%U s user, %S s system, %R s wall'
echo "CI stage: release build"
time cmake --build build -j"$(nproc)"
# The C++ suite, then the Python package's (tests/python/, the ctest "python.pytest" run directly
# so that pytest's own summary ends the log).
# Their processor times go to build/ci_stage_times.txt, not to the log, whose last lines are the
# two summaries. children_cpu sets cpu to the user + system seconds of this script's finished
# children so far (bash's times, run in this shell: in a subshell it would see none).
children_cpu() {
  times > build/ci_times.txt
  cpu=$(awk 'NR == 2 { split($1, u, /[ms]/); split($2, s, /[ms]/); print u[1] * 60 + u[2] + s[1] * 60 + s[2] }' build/ci_times.txt)
}
children_cpu; before=$cpu
ctest --test-dir build --output-on-failure --no-tests=error -j"$(nproc)" -LE python
children_cpu; after=$cpu
echo "release ctest: $(awk -v a="$after" -v b="$before" 'BEGIN { print a - b }') s CPU (user + system)" > build/ci_stage_times.txt
python=$(sed -n 's/^Python3_EXECUTABLE:[A-Z]*=//p' build/CMakeCache.txt)
PYTHONPATH=build/python RAILMODAL_SOURCE_DIR="$PWD" "$python" -m pytest -q -p no:cacheprovider tests/python
children_cpu
echo "pytest: $(awk -v a="$cpu" -v b="$after" 'BEGIN { print a - b }') s CPU (user + system)" >> build/ci_stage_times.txt
