#!/usr/bin/env bash
# Semismooth Newton on contact converges once the active set is right (the problem is linear
# within an active set), so every solve of a contact run takes at most (active-set changes + 2)
# Newton iterations. Runs kiln on an input and checks that from its log: for every "step S:",
# "steady solve S:" and "initial equilibrium:" line, Newton I <= C + 2, C the number of
# "  contact, Newton iteration K: ..." lines since the previous such line (lines of an attempt
# that was retried with a smaller step are not counted). Fails also if kiln fails, if the log
# has no step line, or if the active set never changed (no contact line at all: the run must
# exercise contact).
# usage: newton_iterations.sh INPUT.xml [NP [KILN [MPIEXEC]]]
#   NP default 2; KILN default build/src/app/kiln of this checkout; MPIEXEC default mpirun.
#   The run happens in ./newton-<input>-np<NP> (its log is log.txt there).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
input=$(realpath "$1")
np=${2:-2}
kiln=${3:-$here/../../../build/src/app/kiln}
mpiexec=${4:-mpirun}
name=$(basename "$input" .xml)
dir=$PWD/newton-$name-np$np
rm -rf "$dir"
mkdir -p "$dir"
cd "$dir"
if ! "$mpiexec" -np "$np" --oversubscribe --allow-run-as-root "$kiln" "$input" > log.txt 2>&1; then
  cat log.txt
  echo "newton_iterations.sh: kiln failed on $input (np $np)"
  exit 1
fi
awk -v input="$name" -v np="$np" '
  /^  contact, Newton iteration [0-9]+:/ { ++changes; ++contact_lines; next }
  /retrying with dt = / { changes = 0; next }
  /^(step [0-9]+|steady solve [0-9]+|initial equilibrium): / {
    if (!match($0, /Newton [0-9]+ \(/)) {
      print "newton_iterations.sh: no Newton count in: " $0; ++bad; next
    }
    newton = substr($0, RSTART + 7, RLENGTH - 9) + 0
    ++solves
    total_changes += changes
    if (newton - changes > worst) worst = newton - changes
    if (newton > changes + 2) {
      printf "newton_iterations.sh: %d Newton iterations > %d active-set changes + 2: %s\n",
             newton, changes, $0
      ++bad
    }
    changes = 0
  }
  END {
    if (solves == 0) { print "newton_iterations.sh: no step line in the log"; exit 1 }
    if (contact_lines == 0) {
      print "newton_iterations.sh: no \"contact, Newton iteration\" line: the active set never changed"
      exit 1
    }
    printf "newton_iterations.sh: %s on %d rank(s): %d solves, %d active-set changes, " \
           "max Newton - changes = %d (allowed 2)\n", input, np, solves, total_changes, worst
    exit bad > 0
  }' log.txt || { echo "newton_iterations.sh: failed; the log is $dir/log.txt"; exit 1; }
