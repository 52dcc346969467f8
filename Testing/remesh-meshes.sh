#!/usr/bin/env bash
# Remeshes every test mesh made by Python/make_test_meshes.py (closed genus 0 to 3, a shape that
# is not star-shaped, a sphere with four holes, two parts, an assembly of 25 parts, a box with
# sharp edges, a cube of 12 triangles, a thin plate, an open disk, a dirty disk) with `cvt surface --input` and checks that the remesh has the input's topology.
# With the shared checks beside the project (../shared/checks), also prints the independent
# figures: energy F n / A^2 of the sites on the input, Hausdorff distances, valence, angles.
# Usage: remesh-meshes.sh PATH/TO/cvt [SITES] [MESH...]     (the benchmark mode of issue 10)
# A MESH is a test mesh's name or a mesh file (.off .obj .stl .ply .vtp .vtk: a user's or a
# public one); the independent checks measure against a file's cleaned copy (labels.vtp) where
# they cannot read its format (OFF).
set -u
CVT=${1:?usage: remesh-meshes.sh PATH/TO/cvt [SITES] [MESH...]}
SITES=${2:-1000}
shift $(( $# >= 2 ? 2 : 1 ))
HERE=$(cd "$(dirname "$0")" && pwd)
CHECKS="$HERE/../../shared/checks"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
/usr/bin/python3 "$HERE/Python/make_test_meshes.py" "$T/meshes" || { echo "cannot make the test meshes"; exit 1; }
if [ $# -gt 0 ]; then
  meshes=("$@") # file paths may hold spaces
else
  meshes=(sphere noisy genus2 genus3 dumbbell holes twoparts pieces box cube plate disk dirty)
fi
bad=0
run=0
for mesh in "${meshes[@]}"; do
  if [ -f "$mesh" ]; then
    m=$(basename "$mesh"); m=${m%.*}; source="$mesh"
  else
    m=$mesh; source="$T/meshes/$m.vtp"
  fi
  run=$((run + 1))
  out="$T/run$run" # two files may share a name
  log="$out.log"
  if ! env -u DISPLAY "$CVT" surface --input "$source" --sites "$SITES" --report \
      --output "$out" > "$log" 2>&1; then
    echo "$m: cvt failed:"; cat "$log"; bad=1; continue
  fi
  input=$(sed -n 's/^  input topology *//p' "$log")
  remesh=$(sed -n 's/^  remesh topology *//p' "$log")
  line="$m ($SITES sites): $remesh; $(sed -n 's/^  valence 6 *//p' "$log") valence 6, angles $(sed -n 's/^  smallest \/ largest angle *//p' "$log"); $(sed -n 's/^  seconds: //p' "$log")"
  if [ -d "$CHECKS" ]; then
    case $source in
      *.obj|*.stl|*.ply|*.vtp|*.vtk) checked=$source;;
      *) checked=$out/labels.vtp;; # the input as cleaned, in a format the checks read
    esac
    line="$line; $(/usr/bin/python3 "$CHECKS/mesh_energy.py" "$checked" "$out/sites.csv" "$out/remesh.vtp" --samples 400000 | sed 's/.*normalized=/F n \/ A^2 = /')"
  fi
  echo "$line"
  if [ "$input" != "$remesh" ] || grep -q "topology differs" "$log"; then
    echo "  the remesh's topology differs from the input's ($input)"; bad=1
  fi
  # The independent count, after merging coincident points: no vertex where sheets only touch
  # (not for the dirty mesh, whose input is itself non-manifold, nor for files, which may be too:
  # there the comparison with the repaired input above stands).
  if [ -d "$CHECKS" ] && [ "$m" != dirty ] && [ ! -f "$mesh" ]; then
    independent() { /usr/bin/python3 "$CHECKS/mesh_topology.py" "$1" | grep -o 'components=.*'; }
    if [ "$(independent "$source")" != "$(independent "$out/remesh.vtp")" ]; then
      echo "  independent topology: input $(independent "$source"), remesh $(independent "$out/remesh.vtp")"; bad=1
    fi
  fi
  # Closed smooth test meshes (no border, no crease) must give well-shaped triangles.
  angle=$(sed -n 's/^  smallest \/ largest angle *\([0-9.]*\) .*/\1/p' "$log")
  [ -f "$mesh" ] || case $m in sphere|noisy|genus2|genus3|dumbbell|twoparts)
    if awk -v a="$angle" 'BEGIN { exit !(a < 25) }'; then
      echo "  smallest angle $angle degrees on a smooth closed surface"; bad=1
    fi;;
  esac
done
[ $bad -eq 0 ] && echo "remesh meshes: ok" || { echo "remesh meshes: FAILED"; exit 1; }
