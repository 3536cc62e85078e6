#!/usr/bin/env bash
# A steady elastic run (no temperature) solves once: its steady solve is the equilibrium, so
# there is no separate "initial equilibrium" solve (which made NOX warn that the steady solve
# started converged), and the summary counts the steady solve's iterations.
# usage: steady_elasticity.sh KILN ELASTIC-CUBE.xml
set -u
kiln=$(realpath "$1") input=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "steady_elasticity.sh: $*"; exit 1; }
sed -e 's/value="{60, 60, 60}"/value="{6, 6, 6}"/' "$input" > cube.xml
grep -q '{6, 6, 6}' cube.xml || fail "$input has no Cells {60, 60, 60} to coarsen"
"$kiln" cube.xml > log.txt 2>&1 || { cat log.txt; fail "kiln failed"; }
cat log.txt
grep -q "initial equilibrium" log.txt && fail "a separate initial equilibrium solve"
grep -qi "already converged" log.txt && fail "a solve that started converged"
line=$(grep -E '^steady solve 1: t = 0 s, Newton [1-9][0-9]* \([1-9][0-9]* linear\)' log.txt) ||
  fail "no steady solve with Newton and linear iterations"
linear=$(grep -oE '\([0-9]+ linear\)' <<< "$line" | grep -oE '[0-9]+')
grep -qx "linear iterations: $linear" log.txt || fail "the summary does not count the $linear linear iterations"
echo "steady_elasticity.sh: one solve, $linear linear iterations, counted"
