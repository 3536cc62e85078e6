#!/usr/bin/env bash
# Inputs that were silently wrong (issue 33), on NP ranks:
# - an Exodus file whose "coordx" is netCDF variable 0 (scipy's writer), which the Exodus
#   library reads as zeros: Kiln warns and reads it right (T(0) = 302 K below);
# - a side set that lists a face twice: a warning, and the flux counted once (302 K, not 304);
# - a condition that names a side set twice: an error on every rank (exit 1);
# - a mesh with no extent in y: an error naming the direction;
# - two bodies whose coincident nodes are not merged, named as the gap: an error saying so.
# usage: silent_inputs.sh KILN MPIEXEC NP TWO_CELL_FLUX.xml SCIPY_EXODUS.py
set -u
kiln=$(realpath "$1") mpiexec=$2 np=$3 deck=$(realpath "$4") generator=$(realpath "$5")
python=${PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "silent_inputs.sh: $*"; exit 1; }
run() { "$mpiexec" -np "$np" "$kiln" "$@" > log.txt 2>&1; status=$?; cat log.txt; }
T0() { awk -F, 'NR > 1 { t = $7 } END { print t }' flux.history.csv; }

"$python" "$generator" mesh.exo || fail "cannot write the mesh with scipy (python3-scipy)"
run "$deck"
[ "$status" = 0 ] || fail "the scipy mesh: exit $status"
grep -q 'warning: mesh.exo: the Exodus library read "coordx" as all zeros, because the file stores it as netCDF variable 0' log.txt ||
  fail "no warning naming the library's misread"
[ "$(T0)" = 302 ] || fail "T_max $(T0), expected 302"

"$python" "$generator" mesh.exo --duplicate-face || fail "cannot write the mesh"
rm -f flux.*
run "$deck"
[ "$status" = 0 ] || fail "the doubled face: exit $status"
[ "$(grep -c 'side set 1 lists 1 face more than once (the first: element 1, side 4); Kiln counts each face once' log.txt)" = 1 ] ||
  fail "no single warning for the doubled face"
[ "$(T0)" = 302 ] || fail "T_max $(T0) with a face listed twice: the flux is not counted once"

sed 's/value="{1}"/value="{1, 1}"/' "$deck" > twice.xml
run twice.xml
[ "$status" = 1 ] || fail "a side set named twice: exit $status, expected 1"
[ "$(grep -c 'twice.xml: Kiln/Thermal/Boundary Conditions/flux/"Side Sets": side set 1 is listed twice; its faces would take the condition twice' log.txt)" = 1 ] ||
  fail "no single message for a side set named twice"

"$python" "$generator" mesh.exo --flat || fail "cannot write the mesh"
run --check "$deck"
[ "$status" = 1 ] || fail "a flat mesh: exit $status, expected 1"
grep -q 'mesh.exo: all 12 nodes have y = 0, so the mesh has no extent in y and holds no 3D cell' log.txt ||
  fail "no message for a flat mesh"
"$python" "$generator" mesh.exo --unmerged || fail "cannot write the mesh"
sed 's/"Gap Side Set" type="int" value="0"/"Gap Side Set" type="int" value="10"/' "$deck" > gap.xml
run gap.xml
[ "$status" = 1 ] || fail "unmerged bodies: exit $status, expected 1"
[ "$(grep -c 'gap.xml: Kiln/Mesh/"Gap Side Set": side set 10 has no interior face: its faces touch other cells, but through nodes that are not merged (node 2 of side set 10 and node 9 are both at (1, 0, 0)).*Merge the coincident nodes' log.txt)" = 1 ] ||
  fail "no single message for unmerged bodies"
echo "silent_inputs.sh: np $np passed"
