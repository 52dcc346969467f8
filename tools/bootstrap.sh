#!/usr/bin/env bash
# Installs every dependency of the project on Debian 12 (apt) and builds it into ./build.
# Used by both README commands; safe to run again (apt and CMake skip what is done).
set -euo pipefail
cd "$(dirname "$0")/.."

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

# ParaView 5.11's development package (its bundled VTK 9.2) and the packages its exported
# CMake configuration looks for, EGL for the headless OpenGL context, and the test tools.
packages=(
  build-essential cmake
  paraview-dev python3-paraview
  qtbase5-dev qttools5-dev libqt5svg5-dev qtxmlpatterns5-dev-tools libqt5opengl5-dev
  libx11-dev libglew-dev mpi-default-dev
  libhdf5-dev libnetcdf-dev libgdal-dev libavcodec-dev libavformat-dev libswscale-dev
  libavutil-dev libtheora-dev libogg-dev libtiff-dev libpng-dev libjpeg-dev liblz4-dev
  liblzma-dev libfreetype-dev libgl2ps-dev libdouble-conversion-dev libutfcpp-dev zlib1g-dev
  libxml2-dev libexpat1-dev libjsoncpp-dev libpugixml-dev libcgns-dev libproj-dev libfmt-dev
  libprotobuf-dev protobuf-compiler
  libegl-dev libegl1 libegl-mesa0 libgl1-mesa-dri
  libeigen3-dev liblbfgspp-dev libnanoflann-dev
  libgtest-dev googletest python3-matplotlib xvfb xauth
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
