#!/usr/bin/env bash
# Faults inside a run, injected through Kiln/Debug (issue 15, class 7; doc/user-guide.md
# "Faults"), in the step from t = 1 s to 2 s of faulty.xml. Each case runs in
# ./faults-<case>-np<NP> of the build tree.
# usage: faults.sh CASE NP KILN MPIEXEC
#   exception   an exception in the residual evaluation of the last rank only: every rank
#               stops within seconds (no hang) with one message, exit status 2; the results
#               (t = 0 and 1 s) are finished with the status "stopped by an error", and the
#               last good state (t = 1 s) is in a checkpoint.
#   nan         a NaN in the last rank's residual in every evaluation from then on: the step
#               is repeated with smaller steps down to "Minimum Step", then the run stops with
#               one message saying what happened (exit 2), its last good state kept.
#   transient   a NaN in one residual evaluation only: the step is repeated once with a
#               smaller one and the run completes.
#   step_failure
#               a StepFailure (what a constitutive model whose local solve does not converge
#               throws) on the last rank only, in one evaluation: every rank repeats the step
#               once with a smaller one and the run completes; in every evaluation: the step
#               is cut down to "Minimum Step", then the run stops with one message (exit 2).
set -uo pipefail
case=$1 np=$2 kiln=$3 mpiexec=$4
here=$(dirname "$(realpath "$0")")
expect_failure=$here/../../cmake/expect_failure.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
dir=$PWD/faults-$case-np$np
rm -rf "$dir"
mkdir -p "$dir"
cd "$dir" || exit 1
fail() { echo "faults.sh $case np $np: $*"; exit 1; }
deck() { # FAULT EVALUATIONS: faulty.xml as $case.xml with the fault on the last rank from 1.001 s
  { sed '$d' "$here/faulty.xml"
    echo "  <ParameterList name=\"Debug\">"
    echo "    <Parameter name=\"Fault\" type=\"string\" value=\"$1\"/>"
    echo "    <Parameter name=\"Rank\" type=\"int\" value=\"$((np - 1))\"/>"
    echo "    <Parameter name=\"Time\" type=\"double\" value=\"1.001\"/>"
    echo "    <Parameter name=\"Evaluations\" type=\"int\" value=\"$2\"/>"
    echo "  </ParameterList>"
    echo "</ParameterList>"; } > "$case.xml"
}
status_of() { # FILE.h5: its root attribute "status"
  h5dump -a /status "$1" | sed -n 's/.*(0): "\(.*\)".*/\1/p'
}
stopped_by_error() { # the results finished with the error's status, and a checkpoint at 1 s
  [ -f "results/$case.h5" ] && [ ! -f "results/$case.running.h5" ] || fail "results not finished"
  status_of "results/$case.h5" | grep -q "^stopped by an error at t = 1 s: $1" ||
    fail "results/$case.h5 has the status '$(status_of "results/$case.h5")'"
  [ "$(h5ls "results/$case.h5/steps" | wc -l)" = 2 ] || fail "results/$case.h5 lacks t = 0 and 1 s"
  [ -f "results/$case.checkpoint-000001.h5" ] || fail "no checkpoint of t = 1 s"
  grep -q "stopped by the error below at t = 1 s; its last good state is in results/$case.h5 and results/$case.checkpoint-000001.h5" \
    run.log || fail "the log does not say where the last good state is"
}

case $case in
exception)
  deck "Exception In Assembly" 1
  start=$SECONDS
  timeout 120 "$expect_failure" 2 \
    "kiln: error: $case.xml: Kiln/Debug/\"Fault\" = \"Exception In Assembly\": the exception injected on rank $((np - 1)) of $np in the residual evaluation at t = 2 s; every rank stopped" \
    "$mpiexec" -np "$np" "$kiln" "$case.xml" > run.log 2>&1 || { cat run.log; fail "see above"; }
  elapsed=$((SECONDS - start))
  [ "$elapsed" -le 30 ] || fail "the run took $elapsed s to stop"
  grep -q "^step 2" run.log && fail "a step after the fault was accepted"
  stopped_by_error "$case.xml: Kiln/Debug"
  echo "faults.sh: an exception on rank $((np - 1)) of $np stopped every rank in $elapsed s, last good state kept"
  ;;
nan)
  deck "NaN In Residual" -1
  timeout 120 "$expect_failure" 2 \
    "kiln: error: $case.xml: Kiln/Time Stepping: Newton did not converge in the step from t = 1 s with dt = 0.015625 s: the residual at the start of the step is not a finite number \\(NaN or Inf\\); the next step, 0.00390625 s, would be below \"Minimum Step\" = 0.01 s. The results up to t = 1 s are written. A NaN or Inf comes from" \
    "$mpiexec" -np "$np" "$kiln" "$case.xml" > run.log 2>&1 || { cat run.log; fail "see above"; }
  [ "$(grep -c "not a finite number (NaN or Inf); retrying with dt" run.log)" = 3 ] ||
    fail "not 3 retries with smaller steps"
  grep -q "boundary condition" run.log && fail "the message blames the boundary conditions"
  stopped_by_error "$case.xml: Kiln/Time Stepping: Newton did not converge"
  echo "faults.sh: a NaN that stays stopped the run at the minimum step, last good state kept"
  ;;
transient)
  deck "NaN In Residual" 1
  timeout 120 "$mpiexec" -np "$np" "$kiln" "$case.xml" > run.log 2>&1 || { cat run.log; fail "the run failed"; }
  [ "$(grep -c "retrying with dt = 0.25 s" run.log)" = 1 ] || { cat run.log; fail "not one retry"; }
  grep -q "output: t = 2 s" run.log && grep -q "^status: complete" run.log || fail "the run did not complete"
  [ "$(status_of "results/$case.h5")" = complete ] || fail "results/$case.h5 not complete"
  echo "faults.sh: one NaN cost one repeated step; the run completed"
  ;;
step_failure)
  deck "Step Failure In Assembly" 1
  timeout 120 "$mpiexec" -np "$np" "$kiln" "$case.xml" > run.log 2>&1 || { cat run.log; fail "the run failed"; }
  [ "$(grep -c "an evaluation failed after 0 Newton iterations: $case.xml: Kiln/Debug/\"Fault\" = \"Step Failure In Assembly\": the exception injected on rank $((np - 1)) of $np .*; retrying with dt = 0.25 s" run.log)" = 1 ] ||
    { cat run.log; fail "not one retry after the step failure"; }
  grep -q "output: t = 2 s" run.log && grep -q "^status: complete" run.log || fail "the run did not complete"
  [ "$(status_of "results/$case.h5")" = complete ] || fail "results/$case.h5 not complete"
  # In every evaluation: cut to the minimum step, then one error on every rank.
  case=step_failure_stays
  deck "Step Failure In Assembly" -1
  timeout 120 "$expect_failure" 2 \
    "kiln: error: $case.xml: Kiln/Time Stepping: Newton did not converge in the step from t = 1 s with dt = 0.015625 s: an evaluation failed after 0 Newton iterations: .*Step Failure In Assembly.*would be below \"Minimum Step\" = 0.01 s" \
    "$mpiexec" -np "$np" "$kiln" "$case.xml" > run.log 2>&1 || { cat run.log; fail "see above"; }
  [ "$(grep -c "Step Failure In Assembly.*retrying with dt" run.log)" = 3 ] ||
    { cat run.log; fail "not 3 retries with smaller steps"; }
  stopped_by_error "$case.xml: Kiln/Time Stepping: Newton did not converge"
  echo "faults.sh: a step failure on rank $((np - 1)) of $np cost one repeated step; one that stays stopped the run at the minimum step"
  ;;
*)
  fail "unknown case"
  ;;
esac
