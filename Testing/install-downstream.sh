#!/usr/bin/env bash
# Installs the build into a temporary prefix, checks what lands there, imports the installed
# Python package, and builds and runs a downstream project that finds the modules with
# find_package(CVT).
# Usage: install-downstream.sh BUILD_DIR SOURCE_DIR [plugin=ON|OFF] [python=DESTINATION]
#                              [vtkpython=DIR] [vtkdir=VTK_DIR]
#   plugin     whether the build made the ParaView plugin (default ON)
#   python     where the Python package goes in the prefix (none: not wrapped)
#   vtkpython  the vtkmodules folder of a standalone VTK, put first on PYTHONPATH
#   vtkdir     a standalone VTK's CMake folder, handed to the downstream configure
set -eu
BUILD=${1:?usage: install-downstream.sh BUILD_DIR SOURCE_DIR [key=value...]}
SOURCE=${2:?usage: install-downstream.sh BUILD_DIR SOURCE_DIR [key=value...]}
shift 2
PLUGIN=ON PYDEST="" VTKPYTHON="" VTKDIR=""
for arg in "$@"; do
  case "$arg" in
    plugin=*) PLUGIN=${arg#plugin=} ;;
    python=*) PYDEST=${arg#python=} ;;
    vtkpython=*) VTKPYTHON=${arg#vtkpython=} ;;
    vtkdir=*) VTKDIR=${arg#vtkdir=} ;;
    *) echo "install-downstream.sh: unknown argument $arg"; exit 2 ;;
  esac
done
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
cmake --install "$BUILD" --prefix "$T/prefix" > "$T/install.log"
expected="bin/cvt lib/libcvtFilters.so lib/libcvtRendering.so lib/libcvtNumerics.so lib/libcvtIO.so
  lib/cmake/cvt/CVTConfig.cmake include/cvt/vtkCVTImageFilter.h"
[ "$PLUGIN" = ON ] && expected="$expected lib/paraview-plugins/CVTPlugin/CVTPlugin.so"
[ -n "$PYDEST" ] && expected="$expected $PYDEST/cvt/__init__.py $PYDEST/cvt/cvtFilters.so $PYDEST/cvt/cvtIO.so"
for f in $expected; do
  [ -e "$T/prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done
if [ "$PLUGIN" != ON ] && [ -e "$T/prefix/lib/paraview-plugins" ]; then
  echo "a plugin folder was installed without a plugin"; exit 1
fi
env -u DISPLAY "$T/prefix/bin/cvt" image --resolution 32 --sites 5 --iterations 3 --output "$T/out" --quiet

# The installed package, as the README tells users to import it.
if [ -n "$PYDEST" ]; then
  PYTHONPATH="$T/prefix/$PYDEST${VTKPYTHON:+:$VTKPYTHON}" env -u DISPLAY /usr/bin/python3 -c '
import cvt, sys
from cvt.cvtFilters import vtkCVTImageFilter
from cvt.cvtRendering import vtkCVTSceneRenderer
assert cvt.__file__.startswith(sys.argv[1]), cvt.__file__
print("installed python package: ok")' "$T/prefix"
fi

# find_package(CVT) downstream; the package configuration says where the plugin and Python
# package are, and only those that were built.
configure=(-DCMAKE_PREFIX_PATH="$T/prefix" -DCMAKE_BUILD_TYPE=Release)
[ -n "$VTKDIR" ] && configure+=(-DVTK_DIR="$VTKDIR")
cmake -S "$SOURCE/Testing/Downstream" -B "$T/downstream" "${configure[@]}" > "$T/configure.log" ||
  { cat "$T/configure.log"; exit 1; }
plugin_path="" python_path=""
[ "$PLUGIN" = ON ] && plugin_path="$T/prefix/lib/paraview-plugins/CVTPlugin/CVTPlugin.so"
[ -n "$PYDEST" ] && python_path="$T/prefix/$PYDEST"
grep -qx -- "-- CVT_PLUGIN=$plugin_path\\$" "$T/configure.log" &&
  grep -qx -- "-- CVT_PYTHONPATH=$python_path\\$" "$T/configure.log" ||
  { echo "CVTConfig.cmake does not follow the build:"; grep -- "-- CVT_" "$T/configure.log"; exit 1; }
cmake --build "$T/downstream" > "$T/build.log" || { cat "$T/build.log"; exit 1; }
env -u DISPLAY "$T/downstream/downstream"
echo "install and downstream: ok"
