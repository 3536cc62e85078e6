#!/usr/bin/env bash
# Closed contact must not cost the Krylov solver more than an open gap (issue 12): runs the
# closing contact box on CELLS^3 cells to 150 s and compares the mean GMRES iterations per
# Newton iteration of the steps after the log says "the gap has closed" with those of the
# steps before. Fails if the ratio exceeds MAX (default 1.3), if kiln fails, or if the gap
# never closes. (Iteration counts, not times: the suite times nothing.)
# usage: linear_iterations.sh INPUT.xml CELLS [NP [KILN [MPIEXEC [MAX]]]]
#   The run happens in ./linear-<input>-<CELLS>-np<NP> (its log is log.txt there).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
input=$(realpath "$1")
cells=$2
np=${3:-2}
kiln=${4:-$here/../../../build/src/app/kiln}
mpiexec=${5:-mpirun}
max=${6:-1.3}
name=$(basename "$input" .xml)
dir=$PWD/linear-$name-$cells-np$np
rm -rf "$dir"
mkdir -p "$dir"
cd "$dir"
sed -e "s/value=\"{4, 4, 4}\"/value=\"{$cells, $cells, $cells}\"/" \
    -e "s#<Parameter name=\"Times\" type=\"Array(double)\" value=\"{[^}]*}\"/>#<Parameter name=\"Times\" type=\"Array(double)\" value=\"{150}\"/><Parameter name=\"File Base\" type=\"string\" value=\"out\"/>#" \
    "$input" > deck.xml
grep -q "{$cells, $cells, $cells}" deck.xml || { echo "linear_iterations.sh: $input has no Cells {4, 4, 4} to refine"; exit 1; }
if ! "$mpiexec" -np "$np" --oversubscribe --allow-run-as-root "$kiln" deck.xml > log.txt 2>&1; then
  cat log.txt
  echo "linear_iterations.sh: kiln failed on $input at $cells^3 (np $np)"
  exit 1
fi
awk -v max="$max" -v what="$name $cells^3 np $np" '
  /the gap has closed/ { closed = 1 }
  /^step [0-9]+:/ {
    match($0, /Newton [0-9]+ \([0-9]+ linear/)
    split(substr($0, RSTART, RLENGTH), n, /[ (]+/)
    if (closed) { closed_newton += n[2]; closed_linear += n[3] }
    else { open_newton += n[2]; open_linear += n[3] }
  }
  END {
    if (!closed || closed_newton == 0 || open_newton == 0) {
      print "linear_iterations.sh: " what ": the gap never closed, or no step before it"; exit 1
    }
    open = open_linear / open_newton; shut = closed_linear / closed_newton
    printf "%s: %.1f linear iterations per Newton iteration with the gap open, %.1f closed: ratio %.2f (at most %s)\n", what, open, shut, shut / open, max
    if (shut / open > max) exit 1
  }' log.txt
