#!/usr/bin/env bash
# l1 Gauss-Seidel, Kiln's default smoother setting ("relaxation: use l1"), against plain
# Gauss-Seidel on the closing contact box (tests/cli/reuse_summary.xml at 8^3 cells, to 60 s,
# the gap closing at 50-55 s): on one rank the runs are the same to the bit (the l1 term only
# touches the couplings to other ranks); on more they take the same steps, at least 5% fewer
# Krylov iterations (2 ranks: 238 against 276 when written) and end with the same temperature
# (1e-7 K) and displacement (1e-12 m, of up to 1e-5 m) at every output time.
# usage: l1_gauss_seidel.sh KILN DECK KILN_DIFF NP [LAUNCHER...] (LAUNCHER: mpiexec -n NP ...)
set -uo pipefail
kiln=$1 deck=$2 diff=$3 np=$4
shift 4
fail() { echo "l1_gauss_seidel.sh: $*"; exit 1; }
mkdir -p l1
make_deck() {
  sed -e "s#reuse-summary/on#l1/$1#" -e 's#value="{4, 4, 4}"#value="{8, 8, 8}"#' \
      -e 's#value="{0, 30}"#value="{0, 50, 60}"#' \
      -e "s#<ParameterList name=\"Time Stepping\">#$2&#" "$deck" > l1/$1.xml
}
make_deck l1 ""
make_deck plain '<ParameterList name="Solver"><ParameterList name="Linear Solver"><ParameterList name="Preconditioner Types"><ParameterList name="MueLu"><ParameterList name="smoother: params"><Parameter name="relaxation: use l1" type="bool" value="false"/></ParameterList></ParameterList></ParameterList></ParameterList></ParameterList>'
grep -q '"relaxation: use l1" type="bool" value="false"' l1/plain.xml &&
  grep -q '{8, 8, 8}' l1/l1.xml && grep -q '{0, 50, 60}' l1/l1.xml || fail "could not make the decks"
for v in l1 plain; do
  rm -f l1/$v.lock
  "$@" "$kiln" l1/$v.xml > l1/$v.log 2>&1 || { cat l1/$v.log; fail "the run with $v failed"; }
done
grep -q "the gap has closed" l1/l1.log || fail "the gap did not close"
count() { grep -o "^$2: [0-9]*" "l1/$1.log" | grep -o '[0-9]*$'; }
il=$(count l1 "linear iterations") ip=$(count plain "linear iterations")
sl=$(grep -c "^step " l1/l1.log) sp=$(grep -c "^step " l1/plain.log)
echo "np $np: l1 Gauss-Seidel $il Krylov iterations, $sl steps; plain Gauss-Seidel $ip, $sp"
[ -n "$il" ] && [ -n "$ip" ] && [ "$sl" = "$sp" ] || fail "the steps differ: $sl and $sp"
if [ "$np" = 1 ]; then
  [ "$il" = "$ip" ] || fail "on one rank l1 changed the iterations: $il against $ip"
  "$diff" --fields temperature,displacement --field temperature:0:0 --field displacement:0:0 \
      l1/l1.h5 l1/plain.h5 || fail "on one rank the results differ"
else
  [ $((il * 100)) -le $((ip * 95)) ] || fail "l1 took $il Krylov iterations, plain Gauss-Seidel $ip"
  "$diff" --fields temperature,displacement --field temperature:1e-7:0 \
      --field displacement:1e-12:0 l1/l1.h5 l1/plain.h5 || fail "the results differ"
fi
