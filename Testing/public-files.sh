#!/usr/bin/env bash
# Remeshes every mesh file among Debian's assimp-testmodels (the Open Asset Import Library's
# public test files: OBJ, PLY, STL and OFF from many exporters, with quads, colours, several
# solids, point clouds, empty and malformed files) with `cvt surface --input`, as a user would,
# and checks what the user meets: each file is remeshed with its input's topology, or refused
# with a clear `cvt:` message and exit status 1; never a crash, a hang or a silent failure.
# Usage: public-files.sh PATH/TO/cvt [MODELS_DIR] [SITES]
set -u
CVT=${1:?usage: public-files.sh PATH/TO/cvt [MODELS_DIR] [SITES]}
CVT=$(cd "$(dirname "$CVT")" && pwd)/$(basename "$CVT") # the files are read from their folder
MODELS=${2:-/usr/share/assimp/models}
SITES=${3:-300}
if [ ! -d "$MODELS" ]; then
  echo "no test models in $MODELS: install the Debian package assimp-testmodels"
  exit 1
fi
# Files that are not surfaces or cannot be read: refused, each with its own message.
refused=(
  OBJ/box_UTF16BE.obj     # UTF-16 text
  OBJ/number_formats.obj  # a malformed number ('3.1+e2', line 11)
  OBJ/point_cloud.obj OBJ/testpoints.obj PLY/points.ply PLY/pond.0.ply # points only
  OBJ/testline.obj        # lines only
  OFF/invalid.off         # a face of no vertices
  PLY/issue623.ply        # truncated (VTK's PLY reader crashes on it: the crash is contained)
  invalid/OutOfMemory.off # claims 353535235358 vertices
  invalid/empty.obj invalid/empty.off invalid/empty.ply
  invalid/malformed.obj invalid/malformed2.obj
)
# Remeshed with a warning that the topology differs (too few sites for the thinnest parts): a
# building of 59 parts whose walls are far thinner than the cells.
too_thin=(OBJ/regr01.obj)
# Inputs whose topology is known: a ring cut open to one polygon of 66 corners that runs along the
# cut and back (ear cutting alone gave 17 of its 64 triangles; merging points first, a strip).
declare -A known=(
  [OBJ/concave_polygon.obj]="1 parts, genus 0, 2 boundary loops"
  [OBJ/space_in_material_name.obj]="1 parts, genus 0, 2 boundary loops"
)
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
remesh() { # remesh FILE SITES OUTPUT_DIR: as a user would, the report on stdout
  timeout 300 env -u DISPLAY "$CVT" surface --input "$1" --sites "$2" --report --output "$3"
}
bad=0
remeshed=0
refusals=0
cd "$MODELS" || exit 1
while IFS= read -r file; do
  file=${file#./}
  out="$T/$(echo "$file" | tr '/ ' '__')"
  remesh "$file" "$SITES" "$out" > "$out.log" 2> "$out.err"
  rc=$?
  expect=remesh
  [[ " ${refused[*]} " == *" $file "* ]] && expect=refuse
  [[ " ${too_thin[*]} " == *" $file "* ]] && expect=too_thin
  if [ $rc -ne 0 ] && [ $rc -ne 1 ]; then
    echo "$file: exit status $rc (neither 0 nor 1: a crash, a hang, no program)"; cat "$out.err"; bad=1; continue
  fi
  if [ $expect = refuse ]; then
    if [ $rc -ne 1 ] || ! head -1 "$out.err" | grep -q '^cvt: .'; then
      echo "$file: should be refused with a message; exit status $rc:"; cat "$out.err"; bad=1
    else
      refusals=$((refusals + 1))
      echo "$file: refused: $(head -1 "$out.err")"
    fi
    continue
  fi
  if [ $rc -ne 0 ] || [ ! -s "$out/remesh.vtp" ]; then
    echo "$file: not remeshed (exit status $rc):"; cat "$out.err"; bad=1; continue
  fi
  remeshed=$((remeshed + 1))
  input=$(sed -n 's/^  input topology *//p' "$out.log")
  remesh=$(sed -n 's/^  remesh topology *//p' "$out.log")
  echo "$file: $remesh; $(sed -n 's/^  valence 6 *//p' "$out.log") valence 6, angles $(sed -n 's/^  smallest \/ largest angle *//p' "$out.log")"
  if [ -n "${known[$file]:-}" ] && [ "$input" != "${known[$file]}" ]; then
    echo "  the input's topology should be ${known[$file]}"; bad=1
  fi
  if [ $expect = too_thin ]; then
    grep -q "topology differs.*use more sites" "$out.err" ||
      { echo "  no warning that the topology differs"; bad=1; }
  elif [ -z "$input" ] || [ "$input" != "$remesh" ] || grep -q "topology differs" "$out.err"; then
    echo "  the remesh's topology differs from the input's ($input)"; bad=1
  fi
done < <(find . -type f \( -iname '*.obj' -o -iname '*.ply' -o -iname '*.stl' -o -iname '*.off' \) | sort)
# The building at 1000 sites: its walls keep the topology out of reach however many sites the
# rounds add; the remesh stays near the size asked for, with corners of 23 degrees or more
# (before the bound on added sites: 21703 added, 41253 vertices, corners of 0 degrees; 25.9
# degrees before its zero-area triangles' T-junctions were joined, 23.6 after: two sheets of a
# wall far thinner than the cells meet there). L-BFGS runs on where it stalls with the gradient
# still large (it stopped after 6 of 100 iterations, and left a corner of 13.5 degrees).
if [ -f OBJ/regr01.obj ]; then
  remesh OBJ/regr01.obj 1000 "$T/regr01-1000" > "$T/regr01-1000.log" 2>&1
  added=$(sed -n 's/^  sites added for topology *\([0-9]*\).*/\1/p' "$T/regr01-1000.log")
  smallest=$(sed -n 's/^  smallest \/ largest angle *\([0-9.]*\).*/\1/p' "$T/regr01-1000.log")
  iterations=$(sed -n 's/^  iterations \/ evaluations *\([0-9]*\).*/\1/p' "$T/regr01-1000.log")
  echo "OBJ/regr01.obj at 1000 sites: ${iterations:-?} iterations, ${added:-?} sites added for topology, smallest angle ${smallest:-?}"
  if [ -z "$added" ] || [ "$added" -gt 2000 ] || [ -z "$smallest" ] || [ -z "$iterations" ] ||
    [ "$iterations" -lt 50 ] || awk -v a="$smallest" 'BEGIN { exit !(a < 23) }'; then
    echo "  more than 2000 sites added, fewer than 50 iterations or a corner under 23 degrees"
    tail -5 "$T/regr01-1000.log"; bad=1
  fi
  # No two of its vertices at one place: a point-merging reader (VTK's cleaning, the checkers)
  # would join them and make its edges non-manifold (copies split along a pinched line of the
  # walls' two sheets landed on one place again).
  coincident=$(/usr/bin/python3 -c '
import sys, vtk
reader = vtk.vtkXMLPolyDataReader(); reader.SetFileName(sys.argv[1]); reader.Update()
points = reader.GetOutput().GetPoints()
places = {points.GetPoint(i) for i in range(points.GetNumberOfPoints())}
print(points.GetNumberOfPoints() - len(places))' "$T/regr01-1000/remesh.vtp" 2>&1)
  if [ "$coincident" != 0 ]; then
    echo "  OBJ/regr01.obj at 1000 sites: vertices at a place another vertex has: $coincident"; bad=1
  fi
fi
# The same file gives the same remesh every time: VTK 9.1's threaded point merge (TBB) kept
# whichever of the building's near-coincident points its threads reached first.
if [ -f "$T/OBJ_regr01.obj/sites.csv" ]; then
  for run in 2 3; do
    remesh OBJ/regr01.obj "$SITES" "$T/regr01-run$run" > /dev/null 2>&1
    if ! cmp -s "$T/OBJ_regr01.obj/sites.csv" "$T/regr01-run$run/sites.csv" ||
      ! cmp -s "$T/OBJ_regr01.obj/remesh.vtp" "$T/regr01-run$run/remesh.vtp"; then
      echo "OBJ/regr01.obj: run $run gave other sites or another remesh than the first"; bad=1
    fi
  done
fi
# Every listed file was met (a package with other files must not pass by running none).
if [ $refusals -ne ${#refused[@]} ] || [ $remeshed -lt 30 ]; then
  echo "$refusals of ${#refused[@]} listed files refused, $remeshed remeshed (at least 30 expected)"
  bad=1
fi
[ $bad -eq 0 ] && echo "public files: ok" || { echo "public files: FAILED"; exit 1; }
