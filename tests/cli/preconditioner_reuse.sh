#!/usr/bin/env bash
# Solver/"Preconditioner Reuse Tolerance" on the closing contact box (tests/cli/reuse_summary.xml,
# 4^3 cells to 30 s): with the default 1, the run assembles the same Jacobians as with 0 but
# builds fewer preconditioners (the coupled problem's time coefficient a is a smooth
# dependency), takes the same steps, and ends with the same temperature (1e-7 K) and
# displacement (1e-13 m, of up to 5e-6 m) at every output time.
# usage: preconditioner_reuse.sh KILN DECK KILN_DIFF
set -uo pipefail
kiln=$1 deck=$2 diff=$3
fail() { echo "preconditioner_reuse.sh: $*"; exit 1; }
mkdir -p reuse-tolerance
sed -e 's#reuse-summary/on#reuse-tolerance/zero#' \
    -e 's#<ParameterList name="Time Stepping">#<ParameterList name="Solver"><Parameter name="Preconditioner Reuse Tolerance" type="double" value="0"/></ParameterList>&#' \
    "$deck" > reuse-tolerance/zero.xml
sed -e 's#reuse-summary/on#reuse-tolerance/one#' "$deck" > reuse-tolerance/one.xml
grep -q "Preconditioner Reuse Tolerance" reuse-tolerance/zero.xml || fail "could not make the deck"
for v in zero one; do
  rm -f reuse-tolerance/$v.lock
  "$kiln" reuse-tolerance/$v.xml > reuse-tolerance/$v.log 2>&1 || { cat reuse-tolerance/$v.log; fail "the run with $v failed"; }
done
count() { grep -o "^$2 in this run: [0-9]*" "reuse-tolerance/$1.log" | grep -o '[0-9]*$'; }
jz=$(count zero "Jacobians assembled") jo=$(count one "Jacobians assembled")
pz=$(count zero "preconditioners built") po=$(count one "preconditioners built")
sz=$(grep -c "^step " reuse-tolerance/zero.log) so=$(grep -c "^step " reuse-tolerance/one.log)
echo "tolerance 0: $jz Jacobians, $pz preconditioners, $sz steps; 1: $jo, $po, $so"
[ -n "$jz" ] && [ "$jz" = "$jo" ] || fail "the Jacobians assembled differ: $jz and $jo"
[ "$sz" = "$so" ] || fail "the steps differ: $sz and $so"
[ -n "$po" ] && [ "$po" -lt "$pz" ] || fail "no preconditioner kept for a new Jacobian: $pz and $po built"
# T about 300 K, u up to 5e-6 m: the Krylov solves (1e-10) leave 4e-16 m here.
"$diff" --fields temperature,displacement --field temperature:1e-7:0 \
    --field displacement:1e-13:0 reuse-tolerance/zero.h5 reuse-tolerance/one.h5 ||
  fail "the results differ"
