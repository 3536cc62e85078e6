#!/usr/bin/env bash
# One run at a time per File Base (app/results_lock): BASE.lock.
# usage: results_lock.sh KILN MPIEXEC INPUTS_DIR ERROR_DECK
# - while a run writes results/locked.*, a second run on the same File Base (2 ranks) exits
#   with status 1 and one message naming the first run's pid and the lock file, and writes
#   nothing;
# - the lock file is gone after a run that finishes (0), is stopped by SIGTERM (3) or by an
#   error (2, ERROR_DECK);
# - a run killed with SIGKILL leaves the file, unlocked: the next run takes it.
set -u
kiln=$(realpath "$1") mpiexec=$2 inputs=$(realpath "$3") error_deck=$(realpath "$4")
expect_failure=$(dirname "$(realpath "$0")")/../../cmake/expect_failure.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
dir=$PWD/results-lock
rm -rf "$dir"
mkdir -p "$dir"
cd "$dir" || exit 1
fail() { echo "results_lock.sh: $*"; exit 1; }
base='<Parameter name="File Base" type="string" value="results/locked"/>'
sed "s#<ParameterList name=\"Output\">#&$base#" "$inputs/contact-box-close.xml" > short.xml
# slow.xml runs for about a minute (30000 steps; with 0.25 s steps it ended in 1.6 s, and under
# load before the second run was refused or the SIGTERM came); the test always stops it.
sed -e 's#name="Maximum Step" type="double" value="5"#name="Maximum Step" type="double" value="0.005"#' \
    -e 's#name="Initial Step" type="double" value="1"#name="Initial Step" type="double" value="0.005"#' \
    short.xml > slow.xml
sed "s#<ParameterList name=\"Output\">#&$base#" "$error_deck" > error.xml
grep -q 'results/locked' error.xml && grep -q 'value="0.005"' slow.xml || fail "could not make the decks"
wait_for_step() { # LOG PID: until the run has taken a step (it holds the lock)
  for _ in $(seq 600); do
    grep -q "^step 2:" "$1" && return 0
    kill -0 "$2" 2> /dev/null || { cat "$1"; fail "the first run ended early"; }
    sleep 0.1
  done
  fail "the first run took no step in 60 s"
}

# A second run while the first writes.
"$kiln" slow.xml > first.log 2>&1 &
pid=$!
wait_for_step first.log $pid
[ -f results/locked.lock ] || fail "no results/locked.lock while the run goes"
"$expect_failure" 1 "results/locked.lock: another Kiln run \(pid $pid on [^)]*\) is writing results with this File Base and holds this lock file; wait for it to end, or give this run another Kiln/Output/\"File Base\"" \
  "$mpiexec" -np 2 "$kiln" short.xml > second.log 2>&1 || { cat second.log; kill $pid; fail "the second run was not refused"; }
grep -q "^step" second.log && { kill $pid; fail "the refused run took a step"; }
# Stopped by SIGTERM: exit 3, the lock released.
kill -TERM $pid
wait $pid
status=$?
[ "$status" = 3 ] || { cat first.log; fail "the stopped run exited with $status, not 3"; }
[ -e results/locked.lock ] && fail "a run stopped by SIGTERM left results/locked.lock"

# Finished, and stopped by an error.
"$kiln" short.xml > short.log 2>&1 || { cat short.log; fail "the short run failed"; }
[ -e results/locked.lock ] && fail "a finished run left results/locked.lock"
"$kiln" error.xml > error.log 2>&1
status=$?
[ "$status" = 2 ] || { cat error.log; fail "the failing run exited with $status, not 2"; }
[ -e results/locked.lock ] && fail "a run stopped by an error left results/locked.lock"

# Killed: the file stays, unlocked; the next run goes.
"$kiln" slow.xml > killed.log 2>&1 &
pid=$!
wait_for_step killed.log $pid
kill -KILL $pid
wait $pid 2> /dev/null
[ -f results/locked.lock ] || fail "the killed run's lock file is gone (expected it to stay)"
"$mpiexec" -np 2 "$kiln" short.xml > after.log 2>&1 || { cat after.log; fail "a stale lock file stopped a run"; }
[ -e results/locked.lock ] && fail "the run after the killed one left results/locked.lock"
echo "results_lock.sh: a second run refused naming the first; the lock released after success, SIGTERM, an error and SIGKILL"
