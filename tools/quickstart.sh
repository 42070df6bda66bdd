#!/usr/bin/env bash
# Quick start, step 1: install, build, and compute the natural modes of a bundled wagon.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target railmodal_cli
./build/railmodal modes data/vehicles/resort_car.toml
