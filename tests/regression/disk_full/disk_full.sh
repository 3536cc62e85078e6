#!/usr/bin/env bash
# Writing when the disk is full or a file may not grow (issue 33), for real: on a small tmpfs
# mounted here (CI runs as root; skipped with a message where mount is not permitted) and
# under ulimit -f. Each case runs steps.xml (six steps, an output step and a checkpoint after
# each) in ./disk_full-<case> of the build tree and checks: exit status 2 (every rank: mpirun
# passes the ranks' status on), one "kiln: error:" line naming the file and the system's
# reason, no HDF5 diagnostic stack, no crash (signal, core dump), the last checkpoint written
# before readable, and a restart from it that completes.
# usage: disk_full.sh CASE NP KILN MPIEXEC
#   checkpoint   the checkpoints' folder is a tmpfs with room for two of them
#   results      the results' folder is a tmpfs smaller than the results
#   ulimit       a file-size limit (on the ranks) smaller than the results file
#   restart_end  a restart from a checkpoint at the end time: exit 1, nothing written
#   fingerprint  a restart whose results were since written by another run: exit 1, both named
#   restart_fails  a restart that fails before it passes the earlier results keeps them (and
#                the history CSV) whole
#   exodus_restart  Exodus output only: a restart continues the .exo series, value for value
#   (the restarts that should go on cleanly, in these and other cases, print no warning)
#   history_kept  restart_fails without the earlier results: the history alone is kept
#   exodus_fingerprint  fingerprint with Exodus output only: the .exo of another run is refused
#   exodus_restart_fails  restart_fails with Exodus output only: the earlier .exo kept whole
#   exodus_results  Exodus output only, its folder a tmpfs smaller than the results
#   exodus_ulimit   Exodus output only, a file-size limit smaller than the results
#   csv_full     the gap table and the time history written to /dev/full (the kernel's ENOSPC)
#   killed       a run killed with SIGKILL mid-run: its results readable to the last complete step
#   filled_after_check  KILN is unit_parallel_hdf5_file: the room a step needs, reserved, survives
#                a disk that another program fills before the step's writes
#   ulimit_one_rank  a file-size limit on the last rank only (a write that fails on one rank
#                only inside HDF5 hung the run): ends within 30 s, as a full disk
set -uo pipefail
case=$1 np=$2 kiln=$3 mpiexec=$4
here=$(dirname "$(realpath "$0")")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
dir=$PWD/disk_full-$case
mountpoint -q "$dir/small" 2>/dev/null && umount "$dir/small"
rm -rf "$dir"
mkdir -p "$dir/small" "$dir/big"
cd "$dir" || exit 1
fail() { echo "disk_full.sh $case: $*"; exit 1; }
cleanup() { mountpoint -q "$dir/small" && umount "$dir/small"; }
trap cleanup EXIT
ulimit -c unlimited 2>/dev/null
mount_small() { # SIZE: a tmpfs of SIZE at ./small
  if ! mount -t tmpfs -o "size=$1" tmpfs small 2>mount.err; then
    echo "disk_full.sh $case: SKIPPED: cannot mount a tmpfs here ($(cat mount.err)); run as root"
    exit 0
  fi
}
deck() { # OUTPUT_BASE CHECKPOINT_BASE: steps.xml with these file bases, as run.xml
  sed "s|<ParameterList name=\"Output\">|&\n    <Parameter name=\"File Base\" type=\"string\" value=\"$1\"/>|;
       s|<Parameter name=\"Every Steps\" type=\"int\" value=\"1\"/>|&\n    <Parameter name=\"File Base\" type=\"string\" value=\"$2\"/>|" \
    "$here/steps.xml" > run.xml
}
check_failure() { # FILE REASON: the run failed as it should, naming FILE and REASON
  [ "$rc" = 2 ] || { cat run.log; fail "exit status $rc, expected 2"; }
  [ "$(grep -c 'kiln: error:' run.log)" = 1 ] || { cat run.log; fail "not one error line"; }
  grep -q "kiln: error: $1.*$2" run.log || { cat run.log; fail "no error naming $1 and '$2'"; }
  grep -Eq 'HDF5-DIAG|Segmentation|signal|MPI_ABORT|internal error' run.log &&
    { cat run.log; fail "HDF5's stack, a crash or an abort in the log"; }
  ls core* 2>/dev/null && fail "a core dump"
  true
}
folder_state() { ls -l --time-style=full-iso results | md5sum; md5sum results/*; }
check_refused() { # DECK CHECKPOINT MESSAGE WHAT: the restart is refused (exit 1, one line
  # matching MESSAGE) and the results folder is unchanged
  local before; before=$(folder_state)
  "$mpiexec" -np "$np" "$kiln" "$1" --restart "$2" > run.log 2>&1; rc=$?
  [ "$rc" = 1 ] || { cat run.log; fail "exit status $rc, expected 1"; }
  [ "$(grep -c 'kiln: error:' run.log)" = 1 ] || { cat run.log; fail "not one error line"; }
  grep -q "$3" run.log || { cat run.log; fail "no message $4"; }
  [ "$before" = "$(folder_state)" ] || fail "the results folder changed"
}
no_warning() { # LOG: a clean restart warns of nothing (an output-step count one off did)
  ! grep -q "warning" "$1" || { cat "$1"; fail "$1: a warning from a clean restart"; }
}
another_run() { # DECK RESULTS STEP N: run A of DECK keeps its checkpoint of STEP aside; run B
  # (another initial temperature, the same File Base) replaces RESULTS; A's restart from STEP
  # is refused naming both files, B's own continues its N output steps up to STEP s.
  local name; name=$(basename "$1" .xml)
  "$mpiexec" -np "$np" "$kiln" "$1" > first.log 2>&1 || { cat first.log; fail "run A"; }
  cp "results/$name.checkpoint-00000$3.h5" a.h5
  mkdir b # b/NAME.xml: the default File Base, results/NAME, as A's
  sed 's|name="Initial Temperature" type="double" value="288"|name="Initial Temperature" type="double" value="300"|' \
    "$1" > "b/$name.xml"
  cmp -s "$1" "b/$name.xml" && fail "could not change the initial temperature"
  "$mpiexec" -np "$np" "$kiln" "b/$name.xml" > other.log 2>&1 || { cat other.log; fail "run B"; }
  check_refused "$1" a.h5 \
    "kiln: error: $2: was written by another run (run fingerprint [0-9a-f]\{16\}) than the checkpoint a.h5 (run fingerprint [0-9a-f]\{16\}: its mesh, physics and initial state).*nothing was written" \
    "naming both files"
  "$mpiexec" -np "$np" "$kiln" "b/$name.xml" --restart "results/$name.checkpoint-00000$3.h5" > same.log 2>&1 ||
    { cat same.log; fail "the restart of the run that wrote the results"; }
  grep -q "results: the $4 output steps up to t = $3 s of $2 continue" same.log ||
    { cat same.log; fail "B's restart did not continue B's results"; }
  no_warning same.log
  echo "disk_full.sh $case: refused with exit 1 naming both files, nothing written; the same run continues"
  exit 0
}
failing_restart() { # DECK STEP FAULT_TIME FILES...: after the complete run of DECK, a restart
  # from its checkpoint of STEP with a fault injected at FAULT_TIME (its last good state is
  # written): exit 2, log run.log; FILES (of the complete run) unchanged by it
  local name before; name=$(basename "$1" .xml)
  before=$(cd results && md5sum "${@:4}")
  sed "s|<ParameterList name=\"Checkpoint\">|<ParameterList name=\"Debug\">\n    <Parameter name=\"Fault\" type=\"string\" value=\"Exception In Assembly\"/>\n    <Parameter name=\"Time\" type=\"double\" value=\"$3\"/>\n  </ParameterList>\n  &|" \
    "$1" > "$name.xml"
  grep -q "Exception In Assembly" "$name.xml" || fail "could not inject the fault"
  "$mpiexec" -np "$np" "$kiln" "$name.xml" --restart "results/$name.checkpoint-00000$2.h5" > run.log 2>&1; rc=$?
  [ "$rc" = 2 ] || { cat run.log; fail "exit status $rc, expected 2"; }
  [ "$before" = "$(cd results && md5sum "${@:4}")" ] || fail "the earlier results or history changed"
}
exo_steps() { # FILE.exo: its number of output steps
  "${PYTHON:-/usr/bin/python3}" -c "import sys; from scipy.io import netcdf_file; print(len(netcdf_file(sys.argv[1], 'r', mmap=False).variables['time_whole'][:]))" "$1"
}
restart_from() { # CHECKPOINT STEP: it is readable, and a restart from it completes
  "$mpiexec" -np "$np" "$kiln" "$here/steps.xml" --restart "$1" > restart.log 2>&1 ||
    { cat restart.log; fail "the restart from $1 failed"; }
  grep -q "restart from $1: t = $2 s after step $2" restart.log || { cat restart.log; fail "restart log"; }
}

case $case in
checkpoint)
  # A checkpoint takes 49 kB: room for two (a hard link for the latest takes none).
  mount_small 124k
  deck big/steps small/steps
  "$mpiexec" -np "$np" "$kiln" run.xml > run.log 2>&1; rc=$?
  check_failure "small/steps-000003.h5: cannot write the checkpoint" "No space left on device"
  grep -q "the last good checkpoint is small/steps-000002.h5" run.log || fail "no last good checkpoint"
  [ ! -e small/steps-000003.h5 ] && [ ! -e small/steps-000003.h5.tmp ] || fail "a partial checkpoint left"
  [ small/steps.h5 -ef small/steps-000002.h5 ] || fail "the latest link does not name step 2"
  restart_from small/steps.h5 2
  ;;
results)
  # The results take 230 kB; the mesh and the first steps fit.
  mount_small 256k
  deck small/steps big/steps
  "$mpiexec" -np "$np" "$kiln" run.xml > run.log 2>&1; rc=$?
  check_failure "small/steps.running.h5" "No space left on device"
  restart_from "$(ls big/steps-*.h5 | tail -1)" "$(ls big/steps-*.h5 | tail -1 | sed 's/.*-0*\([0-9]\+\)\.h5/\1/')"
  ;;
exodus_results)
  # The .exo takes 133 kB, its mesh 50 kB, a step 12 kB; each step wants room for twice the
  # largest step (the first: a quarter of the mesh's bytes) and 16 KiB: the mesh and the
  # first steps fit, not all.
  mount_small 100k
  deck small/steps big/steps
  sed -i 's|<ParameterList name="Output">|&\n    <Parameter name="Format" type="string" value="Exodus"/>|' run.xml
  "$mpiexec" -np "$np" "$kiln" run.xml > run.log 2>&1; rc=$?
  check_failure "small/steps.running.exo: the next step cannot be written" "No space left on device"
  restart_from "$(ls big/steps-*.h5 | tail -1)" "$(ls big/steps-*.h5 | tail -1 | sed 's/.*-0*\([0-9]\+\)\.h5/\1/')"
  ;;
ulimit_one_rank)
  deck big/steps big/ckpt
  # 120 KiB on the last rank only (MPMD): the mesh fits; a step's writes failed on that rank
  # alone, inside HDF5's collective flush, and the ranks hung in different collectives.
  # The room check on every rank now ends it before the first step (no checkpoint yet).
  timeout 30 "$mpiexec" -np $((np - 1)) "$kiln" run.xml : -np 1 bash -c "ulimit -f 120 && exec $kiln run.xml" > run.log 2>&1; rc=$?
  [ "$rc" = 124 ] && { cat run.log; fail "the run hung (killed after 30 s)"; }
  check_failure "big/steps.running.h5: the next step cannot be written" "File too large"
  echo "disk_full.sh $case: exit 2 on every rank, one message, no hang"
  exit 0
  ;;
killed)
  # Many steps (an output after each), killed with SIGKILL after step 20 on every rank: the
  # index BASE.running.xmf and BASE.running.h5 hold complete steps (complete_steps.py).
  sed -e 's|value="{0, 1, 2, 3, 4, 5, 6}"|value="{0, 1000}"/><Parameter name="Every Steps" type="int" value="1"|' \
      "$here/steps.xml" > long.xml
  grep -q 'value="{0, 1000}"' long.xml || fail "could not make the long deck"
  "$mpiexec" -np "$np" "$kiln" long.xml > run.log 2>&1 &
  pid=$!
  for _ in $(seq 600); do
    grep -q "^step 20:" run.log && break
    sleep 0.1
  done
  grep -q "^step 20:" run.log || { kill -KILL $pid; cat run.log; fail "the run did not reach step 20"; }
  ranks=$(pgrep -P $pid) # the ranks, mpiexec's children: killed, no clean stop
  [ -n "$ranks" ] || { kill -KILL $pid; fail "no ranks under mpiexec $pid"; }
  kill -KILL $ranks
  wait $pid 2>/dev/null
  grep -q "^complete" run.log && fail "the run was not killed"
  "${PYTHON:-/usr/bin/python3}" "$here/complete_steps.py" results/long.running.xmf ||
    fail "the killed run's results are not complete up to their last step"
  echo "disk_full.sh $case: the results of the killed run readable and complete to their last step"
  exit 0
  ;;
csv_full)
  # The CSV writers on a full device: /dev/full (every write fails with ENOSPC) in place of the
  # temporary file of the gap table of output step 2, then of the time history.
  mkdir results
  ln -s /dev/full results/exodus_only.gap-000002.csv.tmp
  "$mpiexec" -np "$np" "$kiln" "$here/exodus_only.xml" > run.log 2>&1; rc=$?
  check_failure "results/exodus_only.gap-000002.csv: cannot write the gap table" "No space left on device"
  [ -s results/exodus_only.gap-000001.csv ] && [ ! -e results/exodus_only.gap-000002.csv ] ||
    fail "the gap tables before are not kept, or a partial one is left"
  rm -rf results && mkdir results
  ln -s /dev/full results/exodus_only.history.csv.tmp
  "$mpiexec" -np "$np" "$kiln" "$here/exodus_only.xml" > run.log 2>&1; rc=$?
  check_failure "results/exodus_only.history.csv: cannot write the time history" "No space left on device"
  echo "disk_full.sh $case: exit 2 on every rank, one message naming the table and the system's reason"
  exit 0
  ;;
exodus_ulimit)
  deck big/steps big/ckpt
  sed -i 's|<ParameterList name="Output">|&\n    <Parameter name="Format" type="string" value="Exodus"/>|' run.xml
  # 100 KiB: room for the mesh and the first steps (as above), not for all.
  "$mpiexec" -np "$np" bash -c "ulimit -f 100 && exec $kiln run.xml" > run.log 2>&1; rc=$?
  check_failure "big/steps.running.exo: the next step cannot be written" "File too large"
  restart_from big/ckpt.h5 "$(ls big/ckpt-*.h5 | tail -1 | sed 's/.*-0*\([0-9]\+\)\.h5/\1/')"
  ;;
ulimit)
  # The checkpoints' base differs from the results' (the same base is refused at --check).
  deck big/steps big/ckpt
  # The limit on Kiln's processes only (mpiexec's own files are not limited): 250 KiB, more
  # than a checkpoint, less than the results.
  "$mpiexec" -np "$np" bash -c "ulimit -f 250 && exec $kiln run.xml" > run.log 2>&1; rc=$?
  check_failure "big/steps.running.h5" "File too large"
  restart_from big/ckpt.h5 "$(ls big/ckpt-*.h5 | tail -1 | sed 's/.*-0*\([0-9]\+\)\.h5/\1/')"
  ;;
restart_end)
  # A restart from the checkpoint at the end time (6 s): nothing to compute, nothing written.
  "$mpiexec" -np "$np" "$kiln" "$here/steps.xml" > first.log 2>&1 || { cat first.log; fail "first run"; }
  check_refused "$here/steps.xml" results/steps.checkpoint.h5 \
    "kiln: error: results/steps.checkpoint.h5: the checkpoint's time, t = 6 s, is at or past the end of this run, the last output time 6 s: there is nothing left to compute, and nothing was written" \
    "saying the checkpoint is at the end"
  echo "disk_full.sh $case: refused with exit 1, nothing written"
  exit 0
  ;;
fingerprint)
  # Run A keeps its checkpoint of step 3 aside; run B (another initial temperature, the same
  # File Base) replaces results/steps.h5; A's restart must not append to B's results.
  another_run "$here/steps.xml" results/steps.h5 3 4
  ;;
restart_fails)
  # The complete run (outputs at 0..6 s), then a restart from step 3 that fails at 5 s (an
  # injected fault; its last good state, 4 s, is written): results/steps.h5 must stay whole,
  # the restart's results go beside it, and a restart from its checkpoint completes the series.
  "$mpiexec" -np "$np" "$kiln" "$here/steps.xml" > first.log 2>&1 || { cat first.log; fail "first run"; }
  failing_restart "$here/steps.xml" 3 5 steps.h5 steps.xmf steps.history.csv
  grep -q "results: results/steps.h5 and results/steps.history.csv of the run continued (to t = 6 s) are kept whole, as this run stopped at t = 4 s, before it passed them; this run's results are in results/steps.restarted.h5 and results/steps.restarted.xmf, its history in results/steps.restarted.history.csv" run.log ||
    { cat run.log; fail "no message keeping the earlier results"; }
  [ "$(h5ls results/steps.restarted.h5/steps | wc -l)" = 5 ] || { h5ls results/steps.restarted.h5/steps; fail "the restart's results do not hold 0..4 s"; }
  grep -q 'steps.restarted.h5:/steps' results/steps.restarted.xmf || fail "the restart's index does not name its file"
  [ "$(cut -d, -f1 results/steps.restarted.history.csv | tail -n +2 | tr '\n' ' ')" = "0 1 2 3 4 " ] ||
    { cat results/steps.restarted.history.csv; fail "the restart's history does not hold steps 0..4"; }
  grep -q "history: results/steps.restarted.history.csv" run.log || { cat run.log; fail "the summary does not name the restart's history"; }
  "$mpiexec" -np "$np" "$kiln" "$here/steps.xml" --restart results/steps.checkpoint.h5 > again.log 2>&1 ||
    { cat again.log; fail "the restart from the failed run's checkpoint"; }
  no_warning again.log
  [ "$(h5ls results/steps.h5/steps | wc -l)" = 7 ] || { h5ls results/steps.h5/steps; fail "the completed results do not hold 0..6 s"; }
  [ "$(cut -d, -f1 results/steps.history.csv | tail -n +2 | tr '\n' ' ')" = "0 1 2 3 4 5 6 " ] ||
    { cat results/steps.history.csv; fail "the completed history does not hold steps 0..6"; }
  [ ! -e results/steps.running.history.csv ] || fail "the completed restart left its running history"
  echo "disk_full.sh $case: the earlier results and history kept whole; the restart's beside them; the series completed"
  exit 0
  ;;
history_kept)
  # restart_fails without the earlier results (moved away): the history alone is kept whole,
  # and the log names it alone.
  "$mpiexec" -np "$np" "$kiln" "$here/steps.xml" > first.log 2>&1 || { cat first.log; fail "first run"; }
  rm results/steps.h5 results/steps.xmf
  failing_restart "$here/steps.xml" 3 5 steps.history.csv
  grep -q "results: results/steps.history.csv of the run continued (to t = 6 s) are kept whole, as this run stopped at t = 4 s, before it passed them; this run's results are in results/steps.restarted.h5 and results/steps.restarted.xmf, its history in results/steps.restarted.history.csv" run.log ||
    { cat run.log; fail "no message keeping the earlier history alone"; }
  echo "disk_full.sh $case: the earlier history kept whole, named alone"
  exit 0
  ;;
exodus_restart)
  # A thermo-elastic run (vectors, tensors, cell fields) to 3 s, then a restart from 1 s: the
  # .exo holds 0..3 s, equal to the uninterrupted run's (but the wall time).
  deck=$here/exodus_only.xml
  "$mpiexec" -np "$np" "$kiln" "$deck" > first.log 2>&1 || { cat first.log; fail "first run"; }
  cp results/exodus_only.exo whole.exo
  "$mpiexec" -np "$np" "$kiln" "$deck" --restart results/exodus_only.checkpoint-000001.h5 > run.log 2>&1 ||
    { cat run.log; fail "the restart"; }
  grep -q "results: the 2 output steps up to t = 1 s of results/exodus_only.exo continue in results/exodus_only.exo" run.log ||
    { cat run.log; fail "the restart did not continue the .exo"; }
  no_warning run.log
  "${PYTHON:-/usr/bin/python3}" "$here/same_exodus.py" whole.exo results/exodus_only.exo || fail "the continued .exo differs from the whole run's"
  echo "disk_full.sh $case: the restart continued the .exo series, equal to the whole run's"
  exit 0
  ;;
exodus_fingerprint)
  # fingerprint with Exodus output only: A's restart must not continue B's .exo.
  another_run "$here/exodus_only.xml" results/exodus_only.exo 1 2
  ;;
exodus_restart_fails)
  # restart_fails with Exodus output only: the complete run (0..3 s), then a restart from step 1
  # that fails at 3 s (its last good state, 2 s, is written): results/exodus_only.exo stays
  # whole, the restart's results go beside it, and a restart from its checkpoint completes.
  deck=$here/exodus_only.xml
  "$mpiexec" -np "$np" "$kiln" "$deck" > first.log 2>&1 || { cat first.log; fail "first run"; }
  failing_restart "$deck" 1 3 exodus_only.exo exodus_only.history.csv
  grep -q "results: results/exodus_only.exo.* of the run continued (to t = 3 s) are kept whole, as this run stopped at t = 2 s, before it passed them; this run's results are in results/exodus_only.restarted.exo" run.log ||
    { cat run.log; fail "no message keeping the earlier results"; }
  [ "$(exo_steps results/exodus_only.restarted.exo)" = 3 ] || fail "the restart's results do not hold 0..2 s"
  "$mpiexec" -np "$np" "$kiln" "$deck" --restart results/exodus_only.checkpoint.h5 > again.log 2>&1 ||
    { cat again.log; fail "the restart from the failed run's checkpoint"; }
  [ "$(exo_steps results/exodus_only.exo)" = 4 ] || fail "the completed results do not hold 0..3 s"
  echo "disk_full.sh $case: the earlier .exo kept whole; the restart's beside it; the series completed"
  exit 0
  ;;
filled_after_check)
  # KILN is the unit test of ParallelHdf5File: on a 2 MB tmpfs it reserves a step's room,
  # fills the disk from another file, then writes the step: it must not fail.
  mount_small 2M
  KILN_TEST_SMALL_DISK=$dir/small "$mpiexec" -np "$np" "$kiln" \
    --gtest_color=no --gtest_filter='ParallelHdf5File.TheRoomReservedSurvivesADiskFilledByAnotherProgram' \
    > run.log 2>&1; rc=$?
  [ "$rc" = 0 ] || { cat run.log; fail "exit status $rc: the step's writes failed on the full disk"; }
  grep -q "\[  PASSED  \] 1 test" run.log || { cat run.log; fail "the test did not run"; }
  echo "disk_full.sh $case: the room reserved before the writes kept them from the full disk"
  exit 0
  ;;
*) fail "unknown case" ;;
esac
echo "disk_full.sh $case: exit 2 on every rank, one message, the previous checkpoint kept and continued"
