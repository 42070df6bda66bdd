#!/usr/bin/env bash
# Quick start, step 2: install, build everything, run every test (what CI runs).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_dependencies.sh
# The test files compile in batches: a clean build in less time (docs/architecture.md, "Build").
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRAILMODAL_MPI=ON -DRAILMODAL_UNITY_TESTS=ON >/dev/null
cmake --build build -j"$(nproc)"
# The C++ suite, then the Python package's (tests/python/, the ctest "python.pytest" run directly
# so that pytest's own summary ends the log).
ctest --test-dir build --output-on-failure --no-tests=error -j"$(nproc)" -LE python
python=$(sed -n 's/^Python3_EXECUTABLE:[A-Z]*=//p' build/CMakeCache.txt)
PYTHONPATH=build/python RAILMODAL_SOURCE_DIR="$PWD" "$python" -m pytest -q -p no:cacheprovider tests/python
