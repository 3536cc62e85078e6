#!/usr/bin/env bash
# A restart of a run with a contact pair (issue 30): part 1 of inputs/contact-box-nonmatching.xml
# to 53 s (the pair closed) with a checkpoint at the end, part 2 from it to 60 s. The restart's
# line counts the pair's rows in contact as its secondary nodes ("contact-pair nodes", not "gap
# pairs"), and no warning says that the checkpoint and its state disagree (the checkpoint's
# count is of the split gaps' pairs; a pair's rows are not in it).
# usage: pair_restart.sh KILN MPIEXEC NONMATCHING_DECK.xml
set -u
kiln=$(realpath "$1") mpiexec=$2 deck=$(realpath "$3")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "pair_restart.sh: $*"; exit 1; }
python3 - "$deck" <<'PY'
import sys
text = open(sys.argv[1]).read()
part1 = text.replace('value="{0, 50, 53, 150}"', 'value="{0, 50, 53}"')
part1 = part1.replace('<ParameterList name="Output">', '<ParameterList name="Output"><Parameter '
                      'name="File Base" type="string" value="out/pair"/>', 1)
assert part1 != text
checkpoint = '<ParameterList name="Checkpoint"><Parameter name="At End" type="bool" value="true"/></ParameterList>'
open("part1.xml", "w").write(part1[: part1.rindex("</ParameterList>")] + checkpoint + "</ParameterList>\n")
part2 = part1.replace('value="{0, 50, 53}"', 'value="{0, 50, 53, 60}"')
open("part2.xml", "w").write(part2)
PY
timeout 300 "$mpiexec" -np 2 "$kiln" part1.xml > log1.txt 2>&1 || { cat log1.txt; fail "part 1 failed"; }
[ -f out/pair.checkpoint.h5 ] || { ls out; fail "no checkpoint out/pair.checkpoint.h5"; }
timeout 300 "$mpiexec" -np 2 "$kiln" --restart out/pair.checkpoint.h5 part2.xml > log2.txt 2>&1 ||
  { cat log2.txt; fail "part 2 failed"; }
cat log2.txt
grep -q "restart from out/pair.checkpoint.h5: t = 53 s" log2.txt || fail "no restart line at 53 s"
grep -Eq "; 28 of 28 contact-pair nodes in contact$" log2.txt || fail "the restart does not count the pair's 28 rows in contact"
if grep -q "warning: the checkpoint says" log2.txt; then fail "a warning that the checkpoint and its state disagree"; fi
echo "pair_restart.sh: passed"
