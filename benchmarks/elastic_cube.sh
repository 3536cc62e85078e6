#!/usr/bin/env bash
# Benchmark: the standard elastic cube (inputs/elastic-cube.xml: unit cube, N^3 Q1 cells,
# E = 1, nu = 0.25, clamped at z = 0, body force (1, 2, 0), CG + MueLu to 1e-8).
# usage: benchmarks/elastic_cube.sh [NP] [N...]     (default: 2  20 40 60)
# Prints one line per mesh: N, unknowns, CG iterations, the largest absolute displacement
# component (reference, Q1: 5.82106, 5.83934, 5.84373 for N = 20, 40, 60), whole-run wall
# time and the peak resident memory of the largest rank.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
kiln=${KILN:-$here/build/src/app/kiln}
np=${1:-2}
shift || true
sizes=("${@:-20 40 60}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
printf "%4s %10s %6s %12s %8s %10s\n" N unknowns CG max_abs_u wall_s peak_MiB
for n in ${sizes[@]}; do
  deck=$work/cube$n.xml
  sed -e "s/value=\"{60, 60, 60}\"/value=\"{$n, $n, $n}\"/" \
      -e "s#<Parameter name=\"Times\" type=\"Array(double)\" value=\"{0}\"/>#&<Parameter name=\"File Base\" type=\"string\" value=\"$work/out$n\"/>#" \
      "$here/inputs/elastic-cube.xml" > "$deck"
  start=$(date +%s.%N)
  log=$(mpirun --oversubscribe -np "$np" /usr/bin/time -f "peak_kib %M" "$kiln" "$deck" 2>&1)
  end=$(date +%s.%N)
  unknowns=$(grep -o 'unknowns: [0-9]*' <<< "$log" | grep -o '[0-9]*')
  # The summary's count: every solve's Krylov iterations.
  linear=$(grep -o '^linear iterations: [0-9]*' <<< "$log" | grep -o '[0-9]*')
  peak=$(grep -o 'peak_kib [0-9]*' <<< "$log" | awk '{if ($2 > m) m = $2} END {printf "%.0f", m / 1024}')
  umax=$(h5dump -d /steps/000000/displacement -y -w 0 "$work/out$n.h5" | sed -n '/DATA {/,/}/p' |
         tr ', ' '\n\n' | grep -E '^-?[0-9]' |
         awk '{v = ($1 < 0) ? -$1 : $1; if (v > m) m = v} END {printf "%.5f", m}')
  printf "%4s %10s %6s %12s %8.2f %10s\n" "$n" "$unknowns" "$linear" "$umax" \
    "$(echo "$end - $start" | bc -l)" "$peak"
done
