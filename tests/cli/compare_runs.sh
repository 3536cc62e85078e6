#!/usr/bin/env bash
# Two variants of the closing contact box (tests/cli/reuse_summary.xml at 8^3 cells, to 60 s:
# the initial equilibrium with the temperature held, the gap closing at 50-55 s, kept
# Jacobians and preconditioners), each made by replacing the deck's
# <ParameterList name="Time Stepping"> with a snippet that contains it. Both runs must
# complete with the gap closed and take the same steps. CHECK says what else:
#   same     the same Krylov iterations and the same results to the bit;
#   le:P     A takes at most P% of B's Krylov iterations, and the results agree: temperature
#            to 1e-7 K, displacement to 1e-12 m (of up to 1e-5 m), at every output time.
# usage: compare_runs.sh KILN DECK KILN_DIFF NAME A SNIPPET_A B SNIPPET_B CHECK [LAUNCHER...]
# (LAUNCHER: mpiexec -n 2 ...)
set -uo pipefail
kiln=$1 deck=$2 diff=$3 name=$4 a=$5 snippet_a=$6 b=$7 snippet_b=$8 check=$9
shift 9
fail() { echo "compare_runs.sh ($name): $*"; exit 1; }
mkdir -p "$name"
make_deck() {
  local escaped
  escaped=$(printf '%s' "$2" | sed 's/[&#\\]/\\&/g')
  sed -e "s#reuse-summary/on#$name/$1#" -e 's#value="{4, 4, 4}"#value="{8, 8, 8}"#' \
      -e 's#value="{0, 30}"#value="{0, 50, 60}"#' \
      -e "s#<ParameterList name=\"Time Stepping\">#$escaped#" "$deck" > "$name/$1.xml"
  grep -qF -- "$2" "$name/$1.xml" && grep -q '{8, 8, 8}' "$name/$1.xml" &&
    grep -q '{0, 50, 60}' "$name/$1.xml" || fail "could not make the deck $1"
}
make_deck "$a" "$snippet_a"
make_deck "$b" "$snippet_b"
for v in "$a" "$b"; do
  rm -f "$name/$v.lock"
  "$@" "$kiln" "$name/$v.xml" > "$name/$v.log" 2>&1 || { cat "$name/$v.log"; fail "the run $v failed"; }
  grep -q "the gap has closed" "$name/$v.log" || fail "the gap did not close in the run $v"
done
count() { grep -o "^linear iterations: [0-9]*" "$name/$1.log" | grep -o '[0-9]*$'; }
ia=$(count "$a") ib=$(count "$b")
sa=$(grep -c "^step " "$name/$a.log") sb=$(grep -c "^step " "$name/$b.log")
echo "$a: $ia Krylov iterations, $sa steps; $b: $ib, $sb"
[ -n "$ia" ] && [ -n "$ib" ] && [ "$sa" = "$sb" ] || fail "the steps differ: $sa and $sb"
case "$check" in
  same)
    [ "$ia" = "$ib" ] || fail "the iterations differ: $ia and $ib"
    "$diff" --fields temperature,displacement --field temperature:0:0 --field displacement:0:0 \
        "$name/$a.h5" "$name/$b.h5" || fail "the results differ" ;;
  le:*)
    percent=${check#le:}
    [ $((ia * 100)) -le $((ib * percent)) ] ||
      fail "$a took $ia Krylov iterations, more than $percent% of $b's $ib"
    "$diff" --fields temperature,displacement --field temperature:1e-7:0 \
        --field displacement:1e-12:0 "$name/$a.h5" "$name/$b.h5" || fail "the results differ" ;;
  *) fail "unknown CHECK $check" ;;
esac
