#!/usr/bin/env bash
# Kiln set-up on a fresh Debian 12 machine.
#   ./setup.sh run    install what is missing, build, run the contact box on 2 MPI ranks and
#                     print its final state against the analytic solution of the spec
#   ./setup.sh test   install what is missing, build everything (the tests too), run the whole
#                     ctest suite
# `run` builds only what it runs (kiln and kiln_contact_box_report), not the test suite.
# Environment: BUILD_DIR (default build), JOBS (default nproc).
set -euo pipefail
cd "$(dirname "$0")"
mode=${1:-run}
case "$mode" in run|test) ;; *) echo "usage: $0 run|test" >&2; exit 2 ;; esac

build=${BUILD_DIR:-build}
jobs=${JOBS:-$(nproc)}

packages/install.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release ${CI:+-DKILN_WERROR=ON}
if [ "$mode" = run ]; then
  cmake --build "$build" -j "$jobs" --target kiln kiln_contact_box_report
else
  cmake --build "$build" -j "$jobs" # ctest needs every test executable
fi

if [ "$mode" = run ]; then
  mkdir -p results
  mpirun -np 2 "$build/src/app/kiln" inputs/contact-box-close.xml
  "$build/tools/kiln_contact_box_report" inputs/contact-box-close.xml results/contact-box-close.h5
else
  ctest --test-dir "$build" --output-on-failure -j "$jobs" --timeout 600
fi
