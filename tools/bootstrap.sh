#!/usr/bin/env bash
# Installs every dependency of the project on Debian 12 (apt) and builds it into ./build.
# Used by both README commands; safe to run again (apt and CMake skip what is done).
set -euo pipefail
cd "$(dirname "$0")/.."

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

# ParaView 5.11's development package (its bundled VTK 9.2) and the packages its exported
# CMake configuration looks for, EGL for the headless OpenGL context, the numerical core's
# libraries (Eigen, LBFGS++, nanoflann, oneTBB for its threads), and the test tools
# (assimp-testmodels: public mesh files, BSD-licensed, for Testing/public-files.sh).
packages=(
  build-essential cmake
  paraview-dev python3-paraview
  qtbase5-dev qttools5-dev libqt5svg5-dev qtxmlpatterns5-dev-tools libqt5opengl5-dev
  libx11-dev libglew-dev mpi-default-dev openmpi-bin
  libhdf5-dev libnetcdf-dev libgdal-dev libavcodec-dev libavformat-dev libswscale-dev
  libavutil-dev libtheora-dev libogg-dev libtiff-dev libpng-dev libjpeg-dev liblz4-dev
  liblzma-dev libfreetype-dev libgl2ps-dev libdouble-conversion-dev libutfcpp-dev zlib1g-dev
  libxml2-dev libexpat1-dev libjsoncpp-dev libpugixml-dev libcgns-dev libproj-dev libfmt-dev
  libprotobuf-dev protobuf-compiler
  libegl-dev libegl1 libegl-mesa0 libgl1-mesa-dri
  libeigen3-dev liblbfgspp-dev libnanoflann-dev libtbb-dev
  libgtest-dev googletest python3-matplotlib xvfb xauth xdotool assimp-testmodels
  libvtk9.1 libvtk9.1-qt
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi

# Debian's standalone VTK 9.1, for the test of the VTK-only build (Testing/standalone-vtk.sh).
# Its libraries install beside ParaView (above); its development and Python packages conflict
# with ParaView's (python3-vtk9 against python3-paraview), so they are unpacked, not installed,
# into a private prefix.
standalone=build/standalone-vtk
if [ ! -e "$standalone/prefix/usr/lib/x86_64-linux-gnu/cmake/vtk-9.1/vtk-config.cmake" ]; then
  rm -rf "$standalone/debs" && mkdir -p "$standalone/debs"
  (cd "$standalone/debs" && apt-get download libvtk9-dev libvtk9.1 libvtk9.1-qt python3-vtk9 vtk9)
  for deb in "$standalone"/debs/*.deb; do dpkg-deb -x "$deb" "$standalone/prefix"; done
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
