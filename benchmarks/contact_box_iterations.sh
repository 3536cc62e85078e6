#!/usr/bin/env bash
# Benchmark: Belos iterations per linear solve (MueLu preconditioner) and wall time of
# the contact box (inputs/contact-box-close.xml, thermo-elastic) on refined meshes, the
# first three steps (t = 0..11 s: dt 1, 5, 5 s).
# usage: benchmarks/contact_box_iterations.sh [NP] [CELLS...]     (default: 2  8 16 32 64)
# KILN_PHYSICS="Heat Conduction" runs the heat conduction alone (the Mechanics block is
# dropped). KILN_DECK=open runs inputs/contact-box-open.xml instead, whose gap is closed
# (every pair in contact) over these steps; the close deck's gap is open then.
# Prints one line per mesh: cells, unknowns, Newton and linear iterations, linear per
# solve, wall time. Extra Solver options: KILN_SOLVER_XML=file.xml (a <ParameterList
# name="Solver"> block that replaces the deck's).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
kiln=${KILN:-$here/build/src/app/kiln}
np=${1:-2}
shift || true
cells=("${@:-8 16 32 64}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
printf "%8s %10s %7s %7s %12s %8s\n" cells unknowns newton linear linear/solve wall_s
for n in ${cells[@]}; do
  deck=$work/box$n.xml
  sed -e "s/value=\"{4, 4, 4}\"/value=\"{$n, $n, $n}\"/" \
      -e "s#<Parameter name=\"Times\" type=\"Array(double)\" value=\"{0, 50, 53, 150}\"/>#<Parameter name=\"Times\" type=\"Array(double)\" value=\"{11}\"/><Parameter name=\"File Base\" type=\"string\" value=\"$work/out$n\"/>#" \
      "$here/inputs/contact-box-${KILN_DECK:-close}.xml" > "$deck"
  if [ "${KILN_PHYSICS:-}" = "Heat Conduction" ]; then
    sed -i -e 's/value="Thermo-Elasticity"/value="Heat Conduction"/' \
        -e '/<ParameterList name="Mechanics">/,/^  <\/ParameterList>/d' "$deck"
  fi
  if [ -n "${KILN_SOLVER_XML:-}" ]; then
    sed -i "s#<ParameterList name=\"Time Stepping\">#$(tr -d '\n' < "$KILN_SOLVER_XML" | sed 's/[&#]/\\&/g')&#" "$deck"
  fi
  start=$(date +%s.%N)
  log=$(mpirun --oversubscribe -np "$np" "$kiln" "$deck")
  end=$(date +%s.%N)
  unknowns=$(grep -o 'unknowns: [0-9]*' <<< "$log" | grep -o '[0-9]*')
  newton=$(grep -o '^Newton iterations: [0-9]*' <<< "$log" | grep -o '[0-9]*')
  linear=$(grep -o '^linear iterations: [0-9]*' <<< "$log" | grep -o '[0-9]*')
  printf "%8s %10s %7s %7s %12.2f %8.2f\n" "$n^3" "$unknowns" "$newton" "$linear" \
    "$(echo "$linear / $newton" | bc -l)" "$(echo "$end - $start" | bc -l)"
done
