#!/usr/bin/env bash
# Installs the Debian 12 packages this project needs, only when one is missing.
# Idempotent: a machine that has everything returns in well under a second.
set -euo pipefail

PACKAGES=(
  # build tools
  cmake g++ clang clang-format make ninja-build pkg-config
  # ParaView 5.11 SDK (ships its own VTK 9.2) and what its CMake config asks for
  paraview paraview-dev python3-paraview
  qtbase5-dev qttools5-dev libqt5svg5-dev libqt5opengl5-dev libqt5x11extras5-dev
  qtxmlpatterns5-dev-tools libutfcpp-dev libhdf5-dev libhdf5-mpi-dev libnetcdf-dev
  libexpat1-dev libfreetype-dev libgdal-dev libgl2ps-dev libglew-dev libjpeg-dev
  liblz4-dev liblzma-dev libxml2-dev libpng-dev libtheora-dev libtiff-dev zlib1g-dev
  libx11-dev libavcodec-dev libavformat-dev libavutil-dev libswscale-dev
  libdouble-conversion-dev libopenmpi-dev openmpi-bin python3-dev python3-mpi4py
  libboost-dev libgl-dev
  # algorithm dependencies
  libcgal-dev libeigen3-dev libgmp-dev libmpfr-dev libtbb-dev
  # meshes, plots, headless GUI
  gmsh libgmsh-dev python3-gmsh python3-numpy python3-matplotlib xvfb xauth
  # tests: GoogleTest; OpenFOAM's tools and tutorials (the openfoam.* round-trip tests)
  googletest libgtest-dev openfoam openfoam-examples python3-meshio python3-netcdf4
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${#missing[@]} missing Debian packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
