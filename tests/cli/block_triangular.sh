#!/usr/bin/env bash
# Preconditioner Type "Block Triangular" (the default with temperature and displacement) against
# "MueLu" on the whole system, on the closing contact box (tests/cli/reuse_summary.xml
# at 8^3 cells, to 60 s: the initial equilibrium with the temperature held, the gap closing at
# 50-55 s, preconditioners kept for new Jacobians): the run takes the same steps as with MueLu
# on the whole system, about as many Krylov iterations (at most 10% more), and ends with the
# same temperature (1e-7 K) and displacement (1e-12 m, of up to 1e-5 m) at every output time.
# usage: block_triangular.sh KILN DECK KILN_DIFF [LAUNCHER...] (LAUNCHER: mpiexec -n 2 ...)
set -uo pipefail
kiln=$1 deck=$2 diff=$3
shift 3
fail() { echo "block_triangular.sh: $*"; exit 1; }
mkdir -p block-triangular
make_deck() {
  sed -e "s#reuse-summary/on#block-triangular/$1#" -e 's#value="{4, 4, 4}"#value="{8, 8, 8}"#' \
      -e 's#value="{0, 30}"#value="{0, 50, 60}"#' \
      -e "s#<ParameterList name=\"Time Stepping\">#$2&#" "$deck" > block-triangular/$1.xml
}
choose() {
  echo "<ParameterList name=\"Solver\"><ParameterList name=\"Linear Solver\"><Parameter name=\"Preconditioner Type\" type=\"string\" value=\"$1\"/></ParameterList></ParameterList>"
}
make_deck monolithic "$(choose MueLu)"
make_deck blocks "$(choose "Block Triangular")"
grep -q '"Block Triangular"' block-triangular/blocks.xml && grep -q '"MueLu"' block-triangular/monolithic.xml &&
  grep -q '{8, 8, 8}' block-triangular/blocks.xml &&
  grep -q '{0, 50, 60}' block-triangular/blocks.xml || fail "could not make the decks"
for v in monolithic blocks; do
  rm -f block-triangular/$v.lock
  "$@" "$kiln" block-triangular/$v.xml > block-triangular/$v.log 2>&1 ||
    { cat block-triangular/$v.log; fail "the run with $v failed"; }
done
grep -q "the gap has closed" block-triangular/blocks.log || fail "the gap did not close"
count() { grep -o "^$2: [0-9]*" "block-triangular/$1.log" | grep -o '[0-9]*$'; }
im=$(count monolithic "linear iterations") ib=$(count blocks "linear iterations")
sm=$(grep -c "^step " block-triangular/monolithic.log) sb=$(grep -c "^step " block-triangular/blocks.log)
echo "MueLu: $im Krylov iterations, $sm steps; Block Triangular: $ib, $sb"
[ -n "$im" ] && [ -n "$ib" ] && [ "$sm" = "$sb" ] || fail "the steps differ: $sm and $sb"
[ $((ib * 10)) -le $((im * 11)) ] || fail "Block Triangular took $ib Krylov iterations, MueLu $im"
"$diff" --fields temperature,displacement --field temperature:1e-7:0 \
    --field displacement:1e-12:0 block-triangular/monolithic.h5 block-triangular/blocks.h5 ||
  fail "the results differ"
