#!/usr/bin/env bash
# Benchmark: the mortar pairing's cost against a step (issue 30: "the search and the mortar
# integrals under 20% of a step at 32^3 per body"; the figures in doc/contact.md).
# usage: benchmarks/mortar_pairing.sh [REPEAT] [SIZES...]     (default: 5  32 64 128)
# 1. build/tests/benchmarks/bench_mortar_pairing: n x n against (n-1) x (n+1) flat faces,
#    rotated: the medians of REPEAT runs of the surfaces, the search, the integrals and the
#    whole MortarPairing.
# 2. For comparison, one step of the 32^3 contact box (inputs/contact-box-close.xml with
#    {32, 32, 32} cells, output at t = 1 s: the first step, dt = 1 s), np 1, with --timers:
#    its wall time, its Newton iterations (the initial state's solve at t = 0 and step 1's)
#    and, from Kiln's timers, the time of its assemblies, preconditioner set-ups and linear
#    solves summed. KILN_NP sets the ranks.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${KILN_BUILD:-$here/build}
repeat=${1:-5}
shift || true
sizes=("${@:-32 64 128}")
"$build/tests/benchmarks/bench_mortar_pairing" --repeat "$repeat" ${sizes[@]}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
deck=$work/box32.xml
sed -e "s/value=\"{4, 4, 4}\"/value=\"{32, 32, 32}\"/" \
    -e "s#<Parameter name=\"Times\" type=\"Array(double)\" value=\"{0, 50, 53, 150}\"/>#<Parameter name=\"Times\" type=\"Array(double)\" value=\"{1}\"/><Parameter name=\"File Base\" type=\"string\" value=\"$work/out\"/>#" \
    "$here/inputs/contact-box-close.xml" > "$deck"
start=$(date +%s.%N)
mpirun --oversubscribe -np "${KILN_NP:-1}" "$build/src/app/kiln" --timers "$deck" > "$work/log"
end=$(date +%s.%N)
printf "contact box 32^3, one step (np %s): wall %.2f s (with the set-up and output)\n" \
  "${KILN_NP:-1}" "$(echo "$end - $start" | bc -l)"
grep -E '^(step 1:|Newton iterations:)' "$work/log"
# The step's work by Kiln's timers: the assemblies, the preconditioner set-up and the linear
# solves (the Krylov iterations and their preconditioner applications inside).
awk '/^Kiln: 5 assembly|^Kiln: 7 preconditioner set-up|^NOX Total Linear Solve/ {
       for (i = 1; i <= NF; ++i) if ($i ~ /^[0-9.e+-]+$/ && $(i + 1) ~ /^\(/) { t += $i; print; break } }
     END { printf "assembly + preconditioner + solve: %.2f s\n", t }' "$work/log"
