#!/usr/bin/env bash
# Installs the built railmodal into a scratch prefix, then configures, builds and runs an
# out-of-tree consumer that finds it with find_package(railmodal).
set -euo pipefail
build_dir=$1 consumer_dir=$2 data_dir=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" > "$work/install.log"
# toml11 and nlohmann-json are compiled into the library: the package must not ask a consumer for them.
if grep -rqE '^[^#]*(toml11|nlohmann)' "$work/prefix"/lib*/cmake/railmodal/; then
  echo "the installed package names a private header-only dependency:"
  grep -rnE '^[^#]*(toml11|nlohmann)' "$work/prefix"/lib*/cmake/railmodal/
  exit 1
fi
cmake -S "$consumer_dir/consumer" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log"
cmake --build "$work/build" > "$work/build.log"
"$work/build/consumer" "$data_dir/vehicles/fette_car.toml" | tee "$work/run.log"
grep -q "body bounce" "$work/run.log"
"$work/build/spectrum_consumer" | tee "$work/spectrum.log"
grep -q "spectral peak 1.058" "$work/spectrum.log"
