#!/usr/bin/env bash
# Quick start, step 2: install, build everything, run every test (what CI runs).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRAILMODAL_MPI=ON >/dev/null
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure --no-tests=error -j"$(nproc)"
