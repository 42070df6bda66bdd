#!/usr/bin/env bash
# Regenerates the measured sections of docs/accuracy.md from one run (tools/accuracy/accuracy_report.cpp):
# the part between the file's two markers is replaced, the hand-written sections after it stay as
# they are (tools/accuracy/splice_generated.py; tests/accuracy/splice_test.py checks the markers).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target railmodal_accuracy
generated=$(mktemp)
trap 'rm -f "$generated"' EXIT
./build/tools/accuracy/railmodal_accuracy data > "$generated"
python3 tools/accuracy/splice_generated.py docs/accuracy.md "$generated"
echo "docs/accuracy.md: the generated sections regenerated, the hand-written ones kept"
