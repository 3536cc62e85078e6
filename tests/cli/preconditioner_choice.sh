#!/usr/bin/env bash
# The Preconditioner Type Kiln picks, as the set-up log says ("preconditioner: ..."): for
# temperature and displacement with at least 50,000 unknowns "Block Triangular" (the closing
# contact box at 24^3 cells, 65,000 unknowns), below it "MueLu" (8^3 cells, 3,240 unknowns),
# with at most 2,000 unknowns "Direct" (4^3 cells, 600 unknowns) unless the input gives a
# "MueLu" list (4^3 with "aggregation: drop tol"); a type the input names is kept (24^3 with
# "MueLu").
# usage: preconditioner_choice.sh KILN DECK (tests/cli/reuse_summary.xml)
set -uo pipefail
kiln=$1 deck=$2
fail() { echo "preconditioner_choice.sh: $*"; exit 1; }
mkdir -p preconditioner-choice
given='<ParameterList name="Solver"><ParameterList name="Linear Solver"><Parameter name="Preconditioner Type" type="string" value="MueLu"/></ParameterList></ParameterList>'
sed -e 's#reuse-summary/on#preconditioner-choice/large#' -e 's#value="{4, 4, 4}"#value="{24, 24, 24}"#' \
    "$deck" > preconditioner-choice/large.xml
sed -e 's#reuse-summary/on#preconditioner-choice/small#' "$deck" > preconditioner-choice/small.xml
sed -e 's#reuse-summary/on#preconditioner-choice/medium#' -e 's#value="{4, 4, 4}"#value="{8, 8, 8}"#' \
    "$deck" > preconditioner-choice/medium.xml
tuned='<ParameterList name="Solver"><ParameterList name="Linear Solver"><ParameterList name="Preconditioner Types"><ParameterList name="MueLu"><Parameter name="aggregation: drop tol" type="double" value="0.01"/></ParameterList></ParameterList></ParameterList></ParameterList>'
sed -e "s#<ParameterList name=\"Time Stepping\">#$tuned&#" preconditioner-choice/small.xml \
    > preconditioner-choice/tuned.xml
sed -e "s#<ParameterList name=\"Time Stepping\">#$given&#" preconditioner-choice/large.xml \
    > preconditioner-choice/given.xml
grep -q '{24, 24, 24}' preconditioner-choice/large.xml && grep -q '"MueLu"' preconditioner-choice/given.xml &&
  grep -q '{8, 8, 8}' preconditioner-choice/medium.xml && grep -q 'drop tol' preconditioner-choice/tuned.xml ||
  fail "could not make the decks"
check() {
  "$kiln" --check "preconditioner-choice/$1.xml" > "preconditioner-choice/$1.log" 2>&1 ||
    { cat "preconditioner-choice/$1.log"; fail "kiln --check $1.xml failed"; }
  grep -q "^unknowns: $2 " "preconditioner-choice/$1.log" || fail "$1.xml: not $2 unknowns"
  grep -qx "preconditioner: $3" "preconditioner-choice/$1.log" ||
    fail "$1.xml: $(grep '^preconditioner:' "preconditioner-choice/$1.log"), expected $3"
  echo "$1.xml: $2 unknowns, preconditioner $3"
}
check large 65000 "Block Triangular"
check medium 3240 MueLu
check small 600 Direct
check tuned 600 MueLu
check given 65000 MueLu
