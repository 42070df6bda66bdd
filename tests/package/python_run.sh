#!/usr/bin/env bash
# Installs the build into a scratch prefix and imports the installed Python package from
# outside the build and source trees (as run.sh does for the C++ package): it must be the
# installed copy that loads, it must work, and the place it went must be one the interpreter
# searches when the prefix is the default (/usr/local) or its own.
set -euo pipefail
build_dir=$1 python=$2 install_dir=$3 data_dir=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" > "$work/install.log"
test -f "$work/prefix/$install_dir/railmodal/__init__.py"
cp "$data_dir/vehicles/resort_car.toml" "$work/car.toml"
cd "$work"
PYTHONPATH="$work/prefix/$install_dir" "$python" - "$work/prefix" "$install_dir" <<'PY'
import os, sys, sysconfig
import railmodal
prefix, install_dir = sys.argv[1], sys.argv[2]
assert railmodal.__file__.startswith(prefix), railmodal.__file__
frequencies = railmodal.modes(railmodal.assemble(railmodal.load_vehicle("car.toml"))).frequencies_hz
assert abs(frequencies[2] - 1.0586) < 1e-3, frequencies  # body bounce of the resort car
searched = {os.path.normpath(p) for p in sys.path}
places = [os.path.normpath(os.path.join(p, install_dir)) for p in ("/usr/local", sys.prefix)]
assert any(p in searched for p in places), (places, sys.path)
print("installed package:", railmodal.__file__, "body bounce %.4f Hz" % frequencies[2])
PY
