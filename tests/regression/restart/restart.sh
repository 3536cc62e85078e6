#!/usr/bin/env bash
# Restart tests of the closing contact box (issue 13; doc/user-guide.md "Checkpoints and
# restart"). Each case runs in ./restart-<case>-np<NP> of the build tree.
# usage: restart.sh CASE NP KILN KILN_DIFF REPORT MPIEXEC INPUTS_DIR
#   exact      0 -> 150 s in one run, against 0 -> 53 s (contact active at the checkpoint)
#              then restarted to 150 s with the same step control, both on NP ranks: the
#              results files (the restarted one holds the whole series) agree to 1e-12, and
#              the time history and gap tables continue (same_history.py).
#   exact_block_triangular
#              the same with `Preconditioner Type` Block Triangular (the default from 50,000
#              unknowns), whose hierarchies a run keeps while their blocks' values are
#              unchanged: the restarted run builds them anew and must go on exactly.
#   larger     part 1 of the restart example on 2 ranks, part 2 (steps up to 25 s, another
#              output interval) on 1 rank: the analytic closed state at 150 s.
#   signal     a stop request during a run (SIGTERM to kiln on 1 rank, SIGUSR1 to mpirun on
#              2): exit 3 with a checkpoint; the restarted run ends with the results, time
#              history and gap tables of an uninterrupted one (1e-12; the history rows written
#              after the checkpoint are dropped, none is written twice).
#   bad        checkpoints that cannot continue the run: a truncated file, a results file, a
#              missing one, another mesh, another physics, another material: one clear
#              error each (exit 1, printed once).
#   crash      a run killed with SIGKILL: the results of the earlier run (BASE.h5) stay as
#              they were, and BASE.running.h5 holds the steps written before the crash.
set -uo pipefail
case=$1 np=$2 kiln=$3 diff=$4 report=$5 mpiexec=$6 inputs=$7
here=$(dirname "$(realpath "$0")")
expect_failure=$here/../../cmake/expect_failure.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
dir=$PWD/restart-$case-np$np
rm -rf "$dir"
mkdir -p "$dir"
cd "$dir" || exit 1
fail() { echo "restart.sh $case: $*"; exit 1; }
run() { # NP LOG ARGS...: kiln on NP ranks, log in LOG; returns kiln's status
  local n=$1 log=$2
  shift 2
  "$mpiexec" -np "$n" "$kiln" "$@" > "$log" 2>&1
}
deck() { # NAME TIMES [MAX_STEP]: the closing box with these output times into results/NAME;
  # with MAX_STEP, steps of at most (and starting at) MAX_STEP seconds
  sed -e "s#<Parameter name=\"Times\" type=\"Array(double)\" value=\"{0, 50, 53, 150}\"/>#<Parameter name=\"File Base\" type=\"string\" value=\"results/$1\"/><Parameter name=\"Times\" type=\"Array(double)\" value=\"$2\"/>#" \
      "$inputs/contact-box-close.xml" > "$1.xml"
  if [ -n "${3:-}" ]; then
    sed -i -e "s#<Parameter name=\"Maximum Step\" type=\"double\" value=\"5\"/>#<Parameter name=\"Maximum Step\" type=\"double\" value=\"$3\"/>#" \
        -e "s#<Parameter name=\"Initial Step\" type=\"double\" value=\"1\"/>#<Parameter name=\"Initial Step\" type=\"double\" value=\"$3\"/>#" "$1.xml"
  fi
  grep -q "results/$1" "$1.xml" || fail "could not make deck $1"
}
same() { # A.h5 B.h5: the same series, every value to 1e-12 relative; the same history and
  # gap tables
  "$diff" --abs 0 --rel 1e-12 "$1" "$2" > diff.txt 2>&1 || { cat diff.txt; fail "$1 and $2 differ"; }
  "$here/same_history.py" "${1%.h5}" "${2%.h5}" || fail "the histories of $1 and $2 differ"
}

case $case in
exact | exact_block_triangular)
  deck full "{0, 50, 53, 150}"
  deck close "{0, 50, 53, 150}"
  if [ "$case" = exact_block_triangular ]; then
    for d in full close; do
      sed -i -e 's#<ParameterList name="Time Stepping">#<ParameterList name="Solver"><ParameterList name="Linear Solver"><Parameter name="Preconditioner Type" type="string" value="Block Triangular"/></ParameterList></ParameterList><ParameterList name="Time Stepping">#' "$d.xml"
      grep -q '"Block Triangular"' "$d.xml" || fail "could not name the preconditioner in $d.xml"
    done
  fi
  sed "s#{0, 50, 53, 150}#{0, 50, 53}#" close.xml > part1.xml
  run "$np" full.log full.xml || { cat full.log; fail "the whole run failed"; }
  run "$np" part1.log part1.xml || { cat part1.log; fail "part 1 failed"; }
  grep -q "25 of 25 gap pairs in contact" part1.log || fail "the gap is not closed at 53 s"
  grep -q "checkpoint: t = 53 s" part1.log || fail "no checkpoint at 53 s"
  run "$np" part2.log close.xml --restart results/close.checkpoint.h5 ||
    { cat part2.log; fail "the restart failed"; }
  grep -q "restart from results/close.checkpoint.h5: t = 53 s.*25 of 25 gap pairs" part2.log ||
    fail "the restart did not start from the closed state at 53 s"
  grep -q "the 3 output steps up to t = 53 s" part2.log || fail "the results did not continue"
  ! grep -q "warning" part2.log || { cat part2.log; fail "a warning from a clean restart"; }
  if [ "$case" = exact_block_triangular ]; then
    for log in full.log part1.log part2.log; do
      grep -q "preconditioner: Block Triangular" "$log" || fail "$log: not Block Triangular"
    done
  fi
  same results/full.h5 results/close.h5
  echo "restart.sh: 0 -> 150 s equals 0 -> 53 s + restart to 150 s on $np rank(s), to 1e-12"
  ;;
larger)
  run 2 part1.log "$inputs/contact-box-close-restart-1.xml" || { cat part1.log; fail "part 1"; }
  run 1 part2.log "$inputs/contact-box-close-restart-2.xml" \
      --restart results/contact-box-close-restart.checkpoint.h5 || { cat part2.log; fail "part 2"; }
  grep -q "dt = 2[0-9.]* s" part2.log || fail "part 2 took no large step"
  "$report" "$inputs/contact-box-close-restart-2.xml" results/contact-box-close-restart.h5 \
      > report.txt || { cat report.txt; fail "the report failed"; }
  cat report.txt
  grep -q "gap closed (25 of 25 pairs in contact)" report.txt || fail "the gap is not closed"
  # Every relative error of the table below 1e-4 (the temperature is within 1e-3 K of
  # uniform at 150 s after the large steps).
  awk '/\[Pa\]|\[-\]/ { e = $NF + 0; if (e > 1e-4) bad = 1 } END { exit bad }' report.txt ||
    fail "an error of the report is above 1e-4"
  # The whole series is in one file: 0, 50, 53 (part 1) and 100, 150 (part 2).
  n=$(h5ls results/contact-box-close-restart.h5/steps | wc -l)
  [ "$n" = 5 ] || fail "results/contact-box-close-restart.h5 holds $n steps, not 5"
  ;;
signal)
  deck full "{0, 150}" 0.25
  deck stopped "{0, 150}" 0.25
  run "$np" full.log full.xml || { cat full.log; fail "the whole run failed"; }
  # One rank: kiln itself gets the signal (its exit status is kiln's); two: mpirun passes
  # SIGUSR1 on to every rank.
  if [ "$np" = 1 ]; then
    "$kiln" stopped.xml > stopped.log 2>&1 &
  else
    "$mpiexec" -np "$np" "$kiln" stopped.xml > stopped.log 2>&1 &
  fi
  pid=$!
  for _ in $(seq 600); do
    grep -q "^step 100:" stopped.log && break
    sleep 0.1
  done
  if [ "$np" = 1 ]; then kill -TERM $pid; else kill -USR1 $pid; fi
  wait $pid
  status=$?
  grep -E "stopped|checkpoint|error" stopped.log
  [ "$status" != 0 ] || fail "a run stopped by a signal exited with status 0"
  [ "$np" != 1 ] || [ "$status" = 3 ] || fail "exit status $status, not 3"
  grep -q "^step 600:" stopped.log && fail "the run was not stopped"
  grep -q "stopped by SIG\(TERM\|USR1\) at t = .* continue with: kiln stopped.xml --restart" \
      stopped.log || fail "no message for the stop"
  [ -f results/stopped.checkpoint.h5 ] || fail "no checkpoint"
  [ -f results/stopped.h5 ] && [ ! -f results/stopped.running.h5 ] || fail "results not finished"
  run "$np" restarted.log stopped.xml --restart results/stopped.checkpoint.h5 ||
    { cat restarted.log; fail "the restart failed"; }
  same results/full.h5 results/stopped.h5
  echo "restart.sh: stopped by a signal on $np rank(s) and restarted: the same results, to 1e-12"
  ;;
bad)
  deck close "{0, 10}"
  run 1 close.log close.xml || { cat close.log; fail "the run failed"; }
  head -c 3000 results/close.checkpoint.h5 > truncated.h5
  sed 's#{4, 4, 4}#{2, 4, 4}#' close.xml > coarse.xml
  sed 's#value="Thermo-Elasticity"#value="Heat Conduction"#' close.xml |
    sed '/<ParameterList name="Mechanics">/,/^  <\/ParameterList>/d' > heat.xml
  sed 's#<Parameter name="Density" type="double" value="2.7e3"/>#<Parameter name="Density" type="double" value="2.8e3"/>#' close.xml > denser.xml
  check() { # NAME DECK CHECKPOINT REGEX
    "$expect_failure" 1 "$4" "$mpiexec" -np "$np" "$kiln" "$2" --restart "$3" > "$1.txt" 2>&1 ||
      { cat "$1.txt"; fail "$1"; }
  }
  check truncated close.xml truncated.h5 \
    "truncated.h5: cannot read the checkpoint: not an HDF5 file, or a damaged \(truncated\) one"
  check results close.xml results/close.h5 "close.h5: cannot read the checkpoint: not a Kiln checkpoint"
  check missing close.xml no-such.h5 "no-such.h5: cannot read the checkpoint: no such file"
  check mesh coarse.xml results/close.checkpoint.h5 \
    "cannot continue this run from the checkpoint: the mesh differs: the checkpoint's has 64 cells, 150 nodes and 25 gap pairs .*this input's has 32 cells"
  check physics heat.xml results/close.checkpoint.h5 \
    "the unknowns differ: the checkpoint has temperature displacement contact, this input temperature"
  check material denser.xml results/close.checkpoint.h5 \
    "Kiln/Material differs from the checkpoint's; a restart may change the time stepping, the solver, the output and the checkpoints, not the problem"
  grep -q "^step" mesh.txt physics.txt material.txt && fail "a refused restart took a step"
  echo "restart.sh: six checkpoints refused with one clear message each"
  ;;
crash)
  deck crash "{0, 50, 100, 150}" 0.25
  run 1 first.log crash.xml || fail "the first run failed"
  cp results/crash.h5 good.h5
  "$kiln" crash.xml > crashed.log 2>&1 &
  pid=$!
  for _ in $(seq 600); do
    grep -q "^step 300:" crashed.log && break
    sleep 0.1
  done
  kill -KILL $pid
  wait $pid 2> /dev/null
  [ -f results/crash.running.h5 ] || fail "no results/crash.running.h5 after the crash"
  "$diff" --abs 0 --rel 0 good.h5 results/crash.h5 > diff.txt 2>&1 ||
    { cat diff.txt; fail "the crash changed results/crash.h5"; }
  h5ls results/crash.running.h5/steps > steps.txt || fail "crash.running.h5 is not readable"
  [ "$(wc -l < steps.txt)" -ge 2 ] || fail "crash.running.h5 lacks the steps before the crash"
  echo "restart.sh: a killed run leaves the earlier results as they were and readable partial ones"
  ;;
*)
  fail "unknown case"
  ;;
esac
