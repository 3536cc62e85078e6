#!/usr/bin/env bash
# Kiln's hand-written least_norm_shift() against ROL (Debian's Trilinos 13.2, header-only) on
# the QPs of the minimum-norm solution with contact: the figures of doc/contact.md, "Free
# motions while pairs open".
#
#   benchmarks/least_norm_qp.sh                     (about a minute)
#   benchmarks/least_norm_qp.sh --interior-point    (ROL's interior point as well: much longer)
#
# Each ROL time is the best of 3 runs of ${REPEAT:-3} solves, the hand-written one's of 100 x
# REPEAT.
#
# Compiles benchmarks/least_norm_qp.cpp with src/physics/mechanics/least_norm_shift.cpp into
# ${BUILD:-/tmp/least_norm_qp-build} (mpicxx -O2; Teuchos, ROL and LAPACK: trilinos-all-dev, as packages/install.sh
# installs them) and runs it on the unit test's problems, the QPs that Truchas' contact-1 and
# contact-2 solve (benchmarks/least_norm_qp/*.qp: the arguments of least_norm_shift() in
# pairs_held_shut.cpp, printed by a temporary patch that is not in Kiln while kiln ran
# inputs/truchas/contact-1.xml and -2.xml on one rank; one QP per time step) and random ones
# with k up to 50.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
build=${BUILD:-/tmp/least_norm_qp-build}
mkdir -p "$build"
mpicxx -std=c++17 -O2 -DNDEBUG -I"$root/src" -isystem /usr/include/trilinos \
  "$here/least_norm_qp.cpp" "$root/src/physics/mechanics/least_norm_shift.cpp" \
  -o "$build/least_norm_qp" \
  -ltrilinos_teuchosparameterlist -ltrilinos_teuchosnumerics -ltrilinos_teuchoscore \
  -llapack -lblas
shopt -s nullglob
"$build/least_norm_qp" "$@" "${REPEAT:-3}" "$here"/least_norm_qp/*.qp
