#!/usr/bin/env bash
# Installs the build into a temporary prefix, checks what lands there, and builds and runs a
# downstream project that finds the modules with find_package(CVT).
# Usage: install-downstream.sh BUILD_DIR SOURCE_DIR
set -eu
BUILD=${1:?usage: install-downstream.sh BUILD_DIR SOURCE_DIR}
SOURCE=${2:?usage: install-downstream.sh BUILD_DIR SOURCE_DIR}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
cmake --install "$BUILD" --prefix "$T/prefix" > "$T/install.log"
for f in bin/cvt lib/libcvtFilters.so lib/libcvtRendering.so lib/libcvtCore.so \
         lib/paraview-plugins/CVTPlugin/CVTPlugin.so lib/cmake/cvt/CVTConfig.cmake \
         include/cvt/vtkCVTImageFilter.h; do
  [ -e "$T/prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done
ls "$T"/prefix/lib/python3*/site-packages/cvt/cvtFilters*.so > /dev/null
env -u DISPLAY "$T/prefix/bin/cvt" image --resolution 32 --sites 5 --iterations 3 --output "$T/out" --quiet
cmake -S "$SOURCE/Testing/Downstream" -B "$T/downstream" -DCMAKE_PREFIX_PATH="$T/prefix" \
  -DCMAKE_BUILD_TYPE=Release > "$T/configure.log" || { cat "$T/configure.log"; exit 1; }
cmake --build "$T/downstream" > "$T/build.log" || { cat "$T/build.log"; exit 1; }
env -u DISPLAY "$T/downstream/downstream"
echo "install and downstream: ok"
