#!/bin/sh
# Installs every Debian 12 package landsim needs to build, test and cross-check.
# Idempotent: packages already present are skipped by apt. Runs as root or through sudo.
set -eu

PACKAGES="build-essential cmake ninja-build pkg-config ccache git \
  libembree-dev libopenexr-dev libopenimageio-dev libopencolorio-dev \
  libgdal-dev gdal-bin libtomlplusplus-dev libcli11-dev libspdlog-dev libfmt-dev \
  libtbb-dev libassimp-dev libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev libpugixml-dev libkissfft-dev libzstd-dev libnetcdf-dev \
  povray povray-includes embree-tools bc clang-format openmpi-bin libopenmpi-dev \
  fonts-dejavu-core python3 clang libclang-rt-14-dev \
  python3-dev pybind11-dev python3-numpy python3-pytest python3-matplotlib python3-openimageio python3-xarray python3-netcdf4"

missing=""
for p in $PACKAGES; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing="$missing $p"
  fi
done

if [ -z "$missing" ]; then
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  SUDO="sudo"
fi

echo "landsim: installing$missing" >&2
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing
