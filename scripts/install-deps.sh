#!/bin/sh
# Installs the Debian 12 packages arksph needs to build and test.
# Idempotent: when every package is already present it does nothing and touches no network.
set -eu
PKGS="build-essential cmake pkg-config
libsundials-dev libeigen3-dev libsuitesparse-dev libvtk9-dev libhdf5-dev
doctest-dev libtomlplusplus-dev libmuparser-dev libbenchmark-dev
libopenmpi-dev openmpi-bin libhypre-dev
python3 python3-numpy python3-h5py python3-matplotlib python3-scipy python3-vtk9 pybind11-dev python3-dev"
missing=""
for p in $PKGS; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing="$missing $p"
  fi
done
if [ -z "$missing" ]; then
  echo "install-deps: all packages present"
  exit 0
fi
echo "install-deps: installing$missing"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
# shellcheck disable=SC2086
$SUDO apt-get install -y -qq --no-install-recommends $missing
