#!/usr/bin/env bash
# Moertel (Debian's Trilinos 13.2) against the hand-written clipping on the same surfaces: the
# figures of doc/contact.md, "Separately meshed bodies (issue 30): design".
#
#   benchmarks/moertel_probe/run.sh            # every case (about a minute: Moertel's 64x64)
#   benchmarks/moertel_probe/run.sh --quick    # without the 64x64 timing
#
# Builds into ${BUILD:-/tmp/moertel_probe-build} (CMake, Debian's Trilinos 13.2 with Moertel and
# Epetra: trilinos-all-dev, as packages/install.sh installs). Each line: rows of D (secondary nodes),
# off-diagonal entries of D (a dual basis: 0), sum D (the secondary area: 1 on the unit
# square), max |row sum M - row sum D| (partition of unity), max |weighted gap / D_ii - offset|
# and the time of the integration.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${BUILD:-/tmp/moertel_probe-build}
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release > "$build.cmake.log"
cmake --build "$build" -j 2 > "$build.build.log"
export OMPI_MCA_rmaps_base_oversubscribe=1
cases=(
  "4 4 5 3 --offset -0.01 --flat-frame"  # closed by 0.01, faces in the xy plane
  "4 4 5 3 --offset 0.01 --flat-frame"   # open by 0.01
  "4 4 5 3 --offset -0.01"               # the same, rotated
  "4 4 5 3 --offset 0.01"
  "4 4 4 4 --offset 0.01"                # matching faces
  "16 16 17 15 --offset 0.003"
  "4 4 5 3 --curve 2"                    # both on a cylinder of radius 2
  "32 32 31 33 --offset -0.001"
)
for c in "${cases[@]}"; do
  # shellcheck disable=SC2086
  "$build/moertel_probe" $c
  # shellcheck disable=SC2086
  "$build/clip_probe" $c
done
# A column of secondary faces half covered (shifted by 0.1 along x) and nearly uncovered (0.199):
# the dual basis of the whole face against that of the covered part (--consistent).
for c in "--shift 0.1" "--shift 0.1 --consistent" "--shift 0.199" "--shift 0.199 --consistent"; do
  # shellcheck disable=SC2086
  "$build/clip_probe" 4 4 5 3 --offset 0.01 $c
done
"$build/clip_probe" 4 4 5 3 --curve 2 --offset 0.01
"$build/clip_probe" 4 4 5 3 --curve 2 --offset 0.01 --consistent
for g in 3 6 12 27; do "$build/moertel_probe" 4 4 5 3 --offset -0.01 --flat-frame --gauss $g; done
"$build/moertel_probe" 4 4 5 3 --offset -0.01 --flat-frame --tri
# MoertelT, the Tpetra port: D and M come back empty (doc/contact.md says why).
"$build/moertelt_probe" 4 4 5 3 --offset -0.01 --flat-frame
"$build/moertel_probe" 4 4 5 3 --flat-frame --boundary
mpirun -np 2 "$build/moertel_probe" 4 4 5 3 --offset -0.01
mpirun -np 2 "$build/moertel_probe" 32 32 31 33 --offset -0.001
if [ "${1:-}" != "--quick" ]; then
  "$build/moertel_probe" 64 64 63 65 --offset -0.001
  "$build/clip_probe" 64 64 63 65 --offset -0.001
fi
