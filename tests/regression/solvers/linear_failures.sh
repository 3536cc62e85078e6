#!/usr/bin/env bash
# A linear solve that stops short of its tolerance is never silent: the elastic cube on 4^3
# cells with CG limited to 2 iterations (it needs about 10) still converges in Newton (each
# step is a rough one; the Newton test on ||F|| decides), and the step line counts the short
# solves ("Newton N (M linear, K short of tolerance)"), the summary says "linear solves short
# of their tolerance: K" with K > 0, and NOX warns of each. With the deck's own limit (500) the
# count is 0 and the step line has no such part.
# usage: linear_failures.sh KILN ELASTIC-CUBE.xml
set -u
kiln=$(realpath "$1") input=$(realpath "$2")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "linear_failures.sh: $*"; exit 1; }
sed -e 's/value="{60, 60, 60}"/value="{4, 4, 4}"/' "$input" > cube.xml
sed -e 's/<Parameter name="Maximum Iterations" type="int" value="500"\/>/<Parameter name="Maximum Iterations" type="int" value="2"\/>/' \
  cube.xml > short.xml
grep -q '{4, 4, 4}' cube.xml && grep -q 'value="2"' short.xml || fail "could not derive the decks from $input"
"$kiln" cube.xml > cube.log 2>&1 || { cat cube.log; fail "the cube failed"; }
grep -qx "linear solves short of their tolerance: 0" cube.log || { cat cube.log; fail "the cube's count is not 0"; }
grep -q "short of tolerance" cube.log && fail "the cube's step line names short solves"
"$kiln" short.xml > short.log 2>&1 || { cat short.log; fail "the short-CG cube failed"; }
count=$(sed -n 's/^linear solves short of their tolerance: \([0-9][0-9]*\)$/\1/p' short.log)
[ -n "$count" ] && [ "$count" -gt 0 ] || { cat short.log; fail "no short solves counted"; }
grep -q "^steady solve 1: .*, $count short of tolerance)" short.log ||
  { cat short.log; fail "the step line does not count the $count short solves"; }
warnings=$(grep -c "WARNING: NOX::Direction::Newton::compute() - Linear solve failed" short.log)
[ "$warnings" -eq "$count" ] || fail "$warnings NOX warnings for $count short solves"
echo "linear_failures.sh: $count short solves counted and warned of; none with the deck's limit"
