#!/usr/bin/env bash
# Bad input to `cvt image`: a non-zero exit status and a message that says what to fix.
# Usage: cli-errors.sh PATH/TO/cvt
set -u
CVT=${1:?usage: cli-errors.sh PATH/TO/cvt}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
bad=0
expect_error() { # expect_error "message part" args...
  local part=$1; shift
  if env -u DISPLAY "$CVT" "$@" --output "$T/out" > "$T/log" 2>&1; then
    echo "accepted: cvt $*"; bad=1
  elif ! grep -q -- "$part" "$T/log"; then
    echo "cvt $* failed without saying '$part':"; cat "$T/log"; bad=1
  fi
}
printf '%s\n' '0,0' '2,0' > "$T/outside.csv"
printf '%s\n' '0.1,0.1' '0.1,0.1' > "$T/duplicate.csv"
printf '%s\n' '0.1,0.1' 'oops' > "$T/garbled.csv"
: > "$T/empty.csv"
expect_error "at least one site" image --resolution 16 --sites 0
expect_error "exceeds the 16 pixels" image --resolution 4 --sites 17
expect_error "outside the domain" image --resolution 16 --initial-sites "$T/outside.csv"
expect_error "duplicates" image --resolution 16 --initial-sites "$T/duplicate.csv"
expect_error "not 'x,y'" image --resolution 16 --initial-sites "$T/garbled.csv"
expect_error "no sites" image --resolution 16 --initial-sites "$T/empty.csv"
expect_error "no such file" image --input "$T/missing.png"
expect_error "unknown option" image --frobnicate
expect_error "expects a number" image --tolerance abc
expect_error "out of range" image --resolution 16 --sites 4294967297 # would wrap to 1 site
expect_error "XMIN < XMAX" image --domain 1 -1 0 1
expect_error "lloyd or lbfgs" image --method newton
expect_error "between 1 and 100" image --corrections 0
expect_error "0 < r < R" surface --torus 0.4 1
expect_error "not of 'cvt surface'" surface --invert
expect_error "no such file" surface --input "$T/missing.vtp"
: > "$T/mesh.xyz"
expect_error "unknown type" surface --input "$T/mesh.xyz"
printf '\xff\xfev\x00 \x000\x00' > "$T/utf16.obj"
expect_error "UTF-16 text" surface --input "$T/utf16.obj"
expect_error "option of 'cvt surface'" image --torus 1 0.4
expect_error "mask leaves" surface --gi-resolution 4 4 --sites 100
expect_error "between 0 and 1" image --gradient-tolerance 2
# A torus mesh's atlas does not fit in 4 x 4 pixels; points alone are not a surface for either
# engine.
env -u DISPLAY "$CVT" surface --engine opengl --gi-resolution 64 32 --sites 40 --iterations 2 --output "$T/torus" --quiet
expect_error "give a larger resolution" surface --engine opengl --input "$T/torus/remesh.vtp" --gi-resolution 4 4
expect_error "no triangles" surface --engine opengl --input "$T/torus/sites.vtp" --gi-resolution 32 32
expect_error "no polygons (only points or lines)" surface --input "$T/torus/sites.vtp"
expect_error "auto, cpu or opengl" surface --engine cuda
expect_error "names a point array of the --input mesh" surface --array Density
expect_error "option of 'cvt surface --input'" surface --keep-every-site
expect_error "option of 'cvt surface --input'" image --keep-every-site
expect_error "no one-component point array 'Density'" surface --input "$T/torus/remesh.vtp" --array Density
expect_error "at least 3" surface --input "$T/torus/remesh.vtp" --sites 2
# Three triangles on one edge: refused in one line saying where, without VTK's pipeline dump.
cat > "$T/fin.vtk" <<'MESH'
# vtk DataFile Version 3.0
fin
ASCII
DATASET POLYDATA
POINTS 5 float
0 0 0 1 0 0 0 1 0 0 -1 0 0 0 1
POLYGONS 3 12
3 0 1 2
3 1 0 3
3 0 1 4
MESH
# Repaired (the third triangle detached) with one warning line.
if ! env -u DISPLAY "$CVT" surface --input "$T/fin.vtk" --sites 12 --iterations 3 --output "$T/fin" > "$T/log" 2>&1; then
  echo "the fin mesh was refused:"; cat "$T/log"; bad=1
elif ! grep -q "^cvt: warning: The input mesh was repaired: split non-manifold edges: 1" "$T/log"; then
  echo "the fin repair was not reported in one line:"; cat "$T/log"; bad=1
fi
# Errors come as one line, without VTK's pipeline dump.
expect_error "cvt: NumberOfSites is 2; a remesh needs at least 3" surface --input "$T/fin.vtk" --sites 2
if [ "$(grep -cv '^cvt: warning' "$T/log")" -ne 1 ] || grep -q "ERROR: In\|vtkExecutive" "$T/log"; then
  echo "the error was not one clean line:"; cat "$T/log"; bad=1
fi
# OFF meshes (CGAL's and Geogram's format) are read: a tetrahedron with a comment and its counts
# on the keyword line; a truncated one is refused naming its line.
printf '%s\n' 'OFF 4 4 6' '# a tetrahedron' '0 0 0' '1 0 0' '0 1 0' '0 0 1' \
  '3 0 2 1' '3 0 1 3' '3 1 2 3' '3 0 3 2' > "$T/tetra.off"
if ! env -u DISPLAY "$CVT" surface --input "$T/tetra.off" --sites 20 --iterations 5 --report \
    --output "$T/tetra" > "$T/log" 2>&1 || ! grep -q "remesh topology *1 parts, genus 0, 0 boundary loops" "$T/log"; then
  echo "the OFF tetrahedron was not remeshed:"; cat "$T/log"; bad=1
fi
# A surface's picture is drawn on the CPU too: written without any OpenGL.
if ! CVT_OPENGL_CONTEXT=none env -u DISPLAY "$CVT" surface --input "$T/tetra.off" --sites 20 \
    --iterations 5 --output "$T/tetra-nogl" > "$T/log" 2>&1 || [ ! -s "$T/tetra-nogl/cvt.png" ] ||
    grep -q "cvt.png not written" "$T/log"; then
  echo "the surface picture was not written without OpenGL:"; cat "$T/log"; bad=1
fi
# A mesh is parsed once (the reader's crash-proof child hands it over): one from a named pipe,
# which can be read only once, is remeshed, where a second read would wait for ever.
printf '%s\n' ply 'format ascii 1.0' 'element vertex 4' 'property float x' 'property float y' \
  'property float z' 'element face 4' 'property list uchar int vertex_indices' end_header \
  '0 0 0' '1 0 0' '0 1 0' '0 0 1' '3 0 2 1' '3 0 1 3' '3 1 2 3' '3 0 3 2' > "$T/tetra.ply"
mkfifo "$T/piped.ply"
cat "$T/tetra.ply" > "$T/piped.ply" &
if ! timeout 60 env -u DISPLAY "$CVT" surface --input "$T/piped.ply" --sites 20 --iterations 5 \
    --report --output "$T/piped" > "$T/log" 2>&1 || ! grep -q "remesh topology *1 parts, genus 0, 0 boundary loops" "$T/log"; then
  echo "the PLY tetrahedron from a named pipe was not remeshed (read twice?):"; cat "$T/log"; bad=1
fi
kill %1 2> /dev/null # the writer, where the pipe was not read
head -n 5 "$T/tetra.off" > "$T/truncated.off"
expect_error "truncated.off' line 5: the file ends after 3 of its 4 vertices" surface --input "$T/truncated.off"
# An explicit engine is used and named.
if ! env -u DISPLAY "$CVT" image --engine cpu --resolution 16 --sites 3 --output "$T/out" > "$T/log" 2>&1 ||
  ! grep -q "engine: CPU (asked for the CPU)" "$T/log"; then
  echo "--engine cpu was not used or not reported:"; cat "$T/log"; bad=1
fi
# No OpenGL context at all: Auto runs on the CPU and says why; an explicit OpenGL is an error.
if ! CVT_OPENGL_CONTEXT=none env -u DISPLAY "$CVT" image --resolution 16 --sites 3 --output "$T/out" > "$T/log" 2>&1; then
  echo "Auto did not fall back to the CPU without OpenGL:"; cat "$T/log"; bad=1
elif ! grep -q "engine: CPU (Auto: no OpenGL context" "$T/log"; then
  echo "Auto's choice without OpenGL was not reported:"; cat "$T/log"; bad=1
elif [ ! -s "$T/out/cvt.png" ] || grep -q "cvt.png not written" "$T/log"; then
  echo "the 2D picture (drawn on the CPU) was not written without OpenGL:"; cat "$T/log"; bad=1
fi
if CVT_OPENGL_CONTEXT=none env -u DISPLAY "$CVT" image --engine opengl --resolution 16 --sites 3 --output "$T/out" > "$T/log" 2>&1; then
  echo "ran without an OpenGL context"; bad=1
elif ! grep -q "no OpenGL >= 4.0 context" "$T/log"; then
  echo "no-context failure without a clear message:"; cat "$T/log"; bad=1
fi
# An X server that refuses the connection (none on that display): a clear error, not VTK's abort.
if CVT_OPENGL_CONTEXT=window DISPLAY=:4242 "$CVT" image --engine opengl --resolution 16 --sites 3 --output "$T/out" > "$T/log" 2>&1; then
  echo "ran without an X server"; bad=1
elif ! grep -q "cannot connect to the X server DISPLAY=:4242" "$T/log"; then
  echo "a refused X connection without a clear message:"; cat "$T/log"; bad=1
fi
[ $bad -eq 0 ] && echo "cli errors: ok" || { echo "cli errors: FAILED"; exit 1; }
