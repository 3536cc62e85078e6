#!/usr/bin/env bash
# The default "Free Motions" = "Error" still refuses Truchas' contact-1 (inputs/truchas/
# contact-1.xml without its "Minimum Norm" line): the two quarters held only by contact are
# named with their motions (each free along the cube's z, the two together along y and about
# the cube's x axis), on 1 and 2 ranks, at --check and at a run.
# usage: truchas_contact_refused.sh KILN MPIEXEC CONTACT-1.xml MESH
set -u
kiln=$(realpath "$1") mpiexec=$2 input=$(realpath "$3") mesh=$(realpath "$4")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "truchas_contact_refused.sh: $*"; exit 1; }
grep -v '"Free Motions"' "$input" > refused.xml
grep -q 'Minimum Norm' refused.xml && fail "could not remove Free Motions from $input"
expected='refused.xml: Kiln/Mechanics: the displacement conditions leave rigid motions free, so the displacement is not determined: body 1 of 4 (element block 1, the cells between .*): translation along (0.853553, -0.146447, 0.5); and body 3 of 4 (element block 1, .*): translation along (0.853553, -0.146447, 0.5); and body 1: rotation about .*, body 3: rotation about .*, together; body 1: rotation about .*, body 3: rotation about .*, together. Add a displacement condition that holds them'
for np in 1 2; do
  for check in --check ""; do
    "$mpiexec" -np "$np" "$kiln" $check --mesh "$mesh" refused.xml > log.txt 2>&1
    status=$?
    [ "$status" -eq 1 ] || { cat log.txt; fail "np $np $check: exit $status, not 1"; }
    grep -q "$expected" log.txt || { cat log.txt; fail "np $np $check: the message"; }
  done
done
echo "truchas_contact_refused.sh: refused on 1 and 2 ranks, naming both quarters and the motions"
