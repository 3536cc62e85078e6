#!/usr/bin/env bash
# The progress of a run (app/progress_report), on a terminal and not.
# usage: progress.sh KILN INPUT.xml
# - Not on a terminal (a pipe): one line per step, "step N: t = T s, dt = H s (BDF2), Newton
#   ..." with the share done, the pairs in contact, the wall time and the time left; no
#   carriage return.
# - On a terminal (a pseudo-terminal made by script(1)): the step lines are one status line
#   rewritten in place ("\r...ESC[K"), none is a line of its own, and the log's other lines
#   (outputs, the summary) still are.
# Both end with the summary's "key: value" lines, whose Newton and linear iterations are the
# sums over the solves (the initial equilibrium and the steps).
set -u
kiln=$(realpath "$1") input=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "progress.sh: $*"; exit 1; }
"$kiln" "$input" > pipe.log 2>&1 || { cat pipe.log; fail "kiln failed"; }
cat pipe.log
grep -q $'\r' pipe.log && fail "carriage returns in a log that is not a terminal"
grep -Eq '^step 12: t = 53 s, dt = 3 s \(BDF2\), Newton [0-9]+ \([0-9]+ linear\), \|F\| .*; 35% of 150 s, 25/25 pairs in contact, wall [0-9.]+ s, [0-9.]+ s left$' pipe.log ||
  fail "no step line with its progress figures"
for key in "status: complete" "wall time: " "steps: " "Newton iterations: " \
           "linear iterations: " "gap closed at: 53 s" "gap opened at: never" \
           "peak RSS per rank: " "peak RSS summed: " "results: " "history: " "gap tables: "; do
  grep -q "^$key" pipe.log || fail "no summary line \"$key\""
done
# The summary's iterations are those of every solve, the initial equilibrium's included.
sums=$(awk '/^(initial equilibrium|step [0-9]+):/ {
              match($0, /Newton [0-9]+ \([0-9]+ linear/)
              split(substr($0, RSTART, RLENGTH), n, /[ (]+/); newton += n[2]; linear += n[3]; solves++ }
            END { print solves, newton, linear }' pipe.log)
read -r solves newton linear <<< "$sums"
grep -q "^initial equilibrium: Newton [1-9]" pipe.log || fail "no initial equilibrium line"
grep -qx "Newton iterations: $newton" pipe.log ||
  fail "the summary's Newton iterations are not the $newton of the $solves solves"
grep -qx "linear iterations: $linear" pipe.log ||
  fail "the summary's linear iterations are not the $linear of the $solves solves"
command -v script > /dev/null || { echo "progress.sh: no script(1): the terminal is not tested"; exit 0; }
rm -rf results
script -qec "\"$kiln\" \"$input\"" /dev/null > tty.log 2>&1 || { cat -v tty.log; fail "kiln failed on a terminal"; }
[ "$(grep -o $'\rstep [0-9]*: t = ' tty.log | wc -l)" -ge 30 ] || { cat -v tty.log; fail "no status lines"; }
grep -Eq '^step [0-9]+: t = .*\|F\|' tty.log && { cat -v tty.log; fail "step lines of their own on a terminal"; }
# What is left on the screen of each line: the text after its last erase (ESC [K).
grep -q "^output: t = 53 s written" <(sed $'s/.*\x1b\\[K//' tty.log) ||
  { cat -v tty.log; fail "the output lines are lost"; }
grep -q "^status: complete" <(tr -d '\r' < tty.log) || { cat -v tty.log; fail "no summary on a terminal"; }
echo "progress.sh: one line per step in a pipe, one status line on a terminal"
