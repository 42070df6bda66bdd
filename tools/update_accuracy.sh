#!/usr/bin/env bash
# Regenerates docs/accuracy.md from one measured run (see tools/accuracy/accuracy_report.cpp).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target railmodal_accuracy
./build/tools/accuracy/railmodal_accuracy data > docs/accuracy.md.tmp
mv docs/accuracy.md.tmp docs/accuracy.md
echo "docs/accuracy.md regenerated"
