#!/usr/bin/env bash
# The VTK-only build (no ParaView): configures a second build directory with
# CVT_USE_STANDALONE_VTK against Debian's VTK 9.1 unpacked in PREFIX (tools/bootstrap.sh does
# that), builds it without warnings, and runs its whole suite there: C++ tests, the CLI,
# Python with that VTK's own vtkmodules, the install test. ParaView's tests are not defined in
# such a build.
# Usage: standalone-vtk.sh SOURCE_DIR PREFIX BUILD_DIR
set -eu
SOURCE=${1:?usage: standalone-vtk.sh SOURCE_DIR PREFIX BUILD_DIR}
PREFIX=${2:?usage: standalone-vtk.sh SOURCE_DIR PREFIX BUILD_DIR}
BUILD=${3:?usage: standalone-vtk.sh SOURCE_DIR PREFIX BUILD_DIR}
VTK_DIR="$PREFIX/usr/lib/x86_64-linux-gnu/cmake/vtk-9.1"
[ -e "$VTK_DIR/vtk-config.cmake" ] ||
  { echo "no VTK 9.1 in $PREFIX: run tools/bootstrap.sh (it unpacks Debian's packages there)"; exit 1; }
# The unpacked libraries come first (the programs find them by RUNPATH, their own
# dependencies by this path).
export LD_LIBRARY_PATH="$PREFIX/usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"

cmake -S "$SOURCE" -B "$BUILD" -DCVT_USE_STANDALONE_VTK=ON -DVTK_DIR="$VTK_DIR" \
  -DCMAKE_BUILD_TYPE=Release > "$BUILD.configure.log" 2>&1 ||
  { cat "$BUILD.configure.log"; exit 1; }
cmake --build "$BUILD" -j"$(nproc)" > "$BUILD.build.log" 2>&1 || { tail -50 "$BUILD.build.log"; exit 1; }
if grep -E "warning:|CMake Warning" "$BUILD.configure.log" "$BUILD.build.log"; then
  echo "the standalone build has warnings (above)"; exit 1
fi
[ ! -e "$BUILD/lib/paraview-plugins" ] || { echo "a plugin was built without ParaView"; exit 1; }
ldd "$BUILD/bin/cvt" | grep -q "libvtkCommonCore-9.1.so.1 => $PREFIX" ||
  { echo "cvt does not run on the unpacked VTK 9.1:"; ldd "$BUILD/bin/cvt" | grep CommonCore; exit 1; }
ctest --test-dir "$BUILD" -j"$(nproc)" --output-on-failure --timeout 600
echo "standalone vtk: ok"
