#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer build of Kiln and its unit, input-error and
# small regression tests (doc/fuzzing.md).
#   scripts/sanitize.sh [ctest args...]   default: the labels unit and input_error, and the
#                                         --check of each example input
# Uses the "sanitize" preset (clang, -O1 -g) in build-sanitize; slow: nice, -j 2.
# Leaks in Open MPI, hwloc and Trilinos' start-up are suppressed (scripts/lsan.supp).
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang++ >/dev/null || { apt-get update -q && apt-get install -y -q clang libclang-rt-14-dev; }
[ -f build-sanitize/CMakeCache.txt ] || nice cmake --preset sanitize
nice cmake --build build-sanitize -j 2
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
# fast_unwind_on_malloc=0: Open MPI is built without frame pointers; the fast unwinder
# loses the frames, and the suppressions below cannot match "<unknown module>".
export ASAN_OPTIONS=detect_leaks=1:detect_odr_violation=0:abort_on_error=0:fast_unwind_on_malloc=0
export LSAN_OPTIONS=suppressions=$PWD/scripts/lsan.supp:print_suppressions=0:fast_unwind_on_malloc=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
if [ $# -eq 0 ]; then
  # The unit tests, the bad decks on one rank, the command-line tests and the fuzz corpus.
  # Left out (slow under ASan, minutes each; run them by name): the contact-box and
  # convergence studies of tests/unit/app and the MueLu refinement study.
  set -- -L 'unit|input_error' -R '^(unit_|input_error_|cli_|fuzz_replay|doc_)' \
    -E 'unit_contact_box|unit_thermal_rank_independence|unit_heat_convergence|unit_muelu_refinement|input_error_.*_np[23]$'
fi
nice ctest --test-dir build-sanitize -j 2 --timeout 1200 --output-on-failure "$@"
