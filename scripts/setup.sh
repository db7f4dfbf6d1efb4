#!/usr/bin/env bash
# Installs every Debian package wattswath needs to build, test and render its reports.
# Idempotent: installs only what is missing. Run as root (or with sudo available).
set -euo pipefail

packages=(
  cmake g++ make pkg-config ccache
  libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev
  libboost-dev libboost-graph-dev libboost-filesystem-dev libboost-serialization-dev libboost-system-dev
  libboost-program-options-dev
  libompl-dev libceres-dev libnlopt-cxx-dev libmuparser-dev libgeographiclib-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev libpng-dev
  libgdal-dev gdal-bin
  pybind11-dev python3-dev python3-numpy
)
# Tests only: headless Chromium renders the HTML reports; clang builds the fuzz targets; pytest runs
# the Python bindings' tests and matplotlib their example script (python/).
if [[ "${WATTSWATH_SETUP_TESTS:-1}" == "1" ]]; then
  packages+=(chromium clang libclang-rt-14-dev python3-pytest python3-matplotlib)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
