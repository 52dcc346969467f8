#!/usr/bin/env bash
# cvt surface --engine opengl --input on a genus-2 test mesh: it becomes an atlas whose image
# is sized from --sites when --gi-resolution is not given (800 pixels per site, at least 512^2:
# 400 sites -> 566 x 566), and --report prints its charts, seams and distortion. The remesh is
# the restricted Delaunay triangulation of the GPU's sites on the mesh: closed, manifold, genus 2
# (checked on the written remesh.vtp, not only in the report).
# Usage: atlas-job.sh PATH/TO/cvt
set -u
CVT=${1:?usage: atlas-job.sh PATH/TO/cvt}
HERE=$(cd "$(dirname "$0")" && pwd)
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
/usr/bin/python3 "$HERE/Python/make_test_meshes.py" "$T/meshes" > /dev/null || { echo "cannot make the test meshes"; exit 1; }
env -u DISPLAY "$CVT" surface --engine opengl --input "$T/meshes/genus2.vtp" --sites 400 \
  --iterations 3 --report --output "$T/out" > "$T/log" 2>&1 || { cat "$T/log"; echo "atlas job: cvt failed"; exit 1; }
cat "$T/log"
grep -q "atlas: [0-9]* charts in a 566 x 566 image, seam length" "$T/log" || { echo "atlas job: no atlas report of a 566 x 566 image"; exit 1; }
grep -q "atlas area stretch min / max" "$T/log" || { echo "atlas job: no distortion range"; exit 1; }
grep -q "remesh topology             1 parts, genus 2, 0 boundary loops" "$T/log" || { echo "atlas job: the remesh lost the genus-2 topology"; exit 1; }
grep -q "seconds: geometry image [0-9.e-]*, optimise [0-9.e-]*, remesh [0-9.e-]*" "$T/log" || { echo "atlas job: no seconds per stage"; exit 1; }
CHECK="$HERE/../../shared/checks/mesh_topology.py" # the project's shared checks, when beside
if [ -f "$CHECK" ]; then
  /usr/bin/python3 "$CHECK" "$T/out/remesh.vtp" > "$T/topology" 2>&1
  echo "independent check: $(cat "$T/topology")"
  grep -q "components=1 boundary_loops=0 nonmanifold_edges=0 euler=-2" "$T/topology" || { echo "atlas job: remesh.vtp is not a closed manifold genus-2 surface"; exit 1; }
fi
echo "atlas job: ok"
