#!/usr/bin/env bash
# Installs the Debian 12 packages railmodal builds with (run as root), and any packages named as
# arguments (tools/sanitize.sh: clang), in one apt run: on a fresh machine a second run repeats
# apt-get update and the package triggers. Quick when they are already there: apt is only
# consulted for what is missing.
set -euo pipefail
packages=(cmake g++ make pkg-config libeigen3-dev libtoml11-dev nlohmann-json3-dev libcli11-dev
          libfftw3-dev libarpack2-dev libgtest-dev libbenchmark-dev libopenmpi-dev openmpi-bin
          python3-dev pybind11-dev python3-numpy python3-scipy python3-pandas python3-pytest "$@")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
