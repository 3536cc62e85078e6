#!/usr/bin/env bash
# Checkpoint/File Base (issue 33): equal to the results' File Base, refused at --check; in a
# folder that does not exist, created at the start; in one that cannot be created, refused
# before the first step; shared by two runs at once, the second refused by the checkpoints'
# own lock (BASE.lock), on 2 ranks; shared in turn, another run is refused at --check (the
# run fingerprint of BASE.h5) while the run that wrote the checkpoints (or a rerun) goes on.
# usage: checkpoint_base.sh KILN MPIEXEC STEADY_DECK.xml CONTACT_BOX_CLOSE.xml
set -u
kiln=$(realpath "$1") mpiexec=$2 steady=$(realpath "$3") box=$(realpath "$4")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "checkpoint_base.sh: $*"; exit 1; }
# with_bases RESULTS CHECKPOINTS DECK: the deck with both File Bases set
with_bases() {
  python3 - "$@" <<'PY'
import sys
results, checkpoints, deck = sys.argv[1:]
text = open(deck).read()
output = '<Parameter name="File Base" type="string" value="%s"/>' % results
if '<ParameterList name="Output">' in text:
    text = text.replace('<ParameterList name="Output">', '<ParameterList name="Output">' + output, 1)
else:
    output = '<ParameterList name="Output">%s</ParameterList>' % output
    text = text[: text.rindex("</ParameterList>")] + output + "</ParameterList>\n"
checkpoint = ('<ParameterList name="Checkpoint"><Parameter name="File Base" type="string" '
              'value="%s"/></ParameterList>' % checkpoints)
print(text[: text.rindex("</ParameterList>")] + checkpoint + "</ParameterList>")
PY
}
run() { timeout 120 "$mpiexec" -np 2 "$kiln" "$@" > log.txt 2>&1; status=$?; cat log.txt; }

cp "$steady" steady.xml
with_bases out/run out/run steady.xml > same.xml
run --check same.xml
[ "$status" = 1 ] || fail "a checkpoint base equal to the results': exit $status, expected 1"
grep -q 'same.xml: Kiln/Checkpoint/"File Base": = "out/run" is also the results. File Base (Kiln/Output): the latest checkpoint out/run.h5 would overwrite the results out/run.h5' log.txt ||
  fail "no message for a checkpoint base equal to the results'"

with_bases out/run ck/deep/run steady.xml > deep.xml
run deep.xml
[ "$status" = 0 ] || fail "a checkpoint folder that does not exist: exit $status"
[ -s ck/deep/run.h5 ] || fail "no checkpoint ck/deep/run.h5"

with_bases out/run /proc/no-such-dir/run steady.xml > bad.xml
run bad.xml
[ "$status" = 1 ] || fail "a checkpoint folder that cannot be made: exit $status, expected 1"
grep -q 'bad.xml: Kiln/Checkpoint/"File Base": = "/proc/no-such-dir/run": cannot create its folder "/proc/no-such-dir"' log.txt ||
  fail "no message for a checkpoint folder that cannot be made"
grep -q '^step' log.txt && fail "the refused run took a step"

# Two runs at once with one checkpoint base: the first runs for about a minute (small steps).
sed -e 's#name="Maximum Step" type="double" value="5"#name="Maximum Step" type="double" value="0.005"#' \
    -e 's#name="Initial Step" type="double" value="1"#name="Initial Step" type="double" value="0.005"#' \
    "$box" > slow-box.xml
grep -q 'value="0.005"' slow-box.xml || fail "could not slow the contact box down"
with_bases first/run shared/ck slow-box.xml > first.xml
with_bases second/run shared/ck "$box" > second.xml
"$kiln" first.xml > first.log 2>&1 &
pid=$!
for _ in $(seq 600); do
  grep -q "^step 2:" first.log && break
  kill -0 $pid 2> /dev/null || { cat first.log; fail "the first run ended early"; }
  sleep 0.1
done
[ -f shared/ck.lock ] || { kill $pid; fail "no shared/ck.lock while the first run goes"; }
run second.xml
kill -TERM $pid
wait $pid
[ "$status" = 1 ] || fail "a second run on the same checkpoint base: exit $status, expected 1"
grep -q "shared/ck.lock: another Kiln run (pid $pid on [^)]*) is writing checkpoints with this Checkpoint/File Base and holds this lock file; wait for it to end, or give this run another Kiln/Checkpoint/\"File Base\"" log.txt ||
  fail "no message naming the checkpoints' lock"
[ -e second/run.h5 ] && fail "the refused run wrote results"

# In turn: the first run's checkpoints (shared/ck.h5, written when SIGTERM stopped it) are not
# overwritten by another run (the steady deck); a run of the same problem goes on.
[ -s shared/ck.h5 ] || fail "the stopped run wrote no checkpoint shared/ck.h5"
with_bases third/run shared/ck steady.xml > third.xml
run --check third.xml
[ "$status" = 1 ] || fail "another run on a checkpoint base used before: exit $status, expected 1"
grep -q 'third.xml: Kiln/Checkpoint/"File Base": = "shared/ck": shared/ck.h5 holds the checkpoints of another run (run fingerprint [0-9a-f]\{16\}, this run.s [0-9a-f]\{16\}: another mesh, physics or initial state), which this run would overwrite' log.txt ||
  fail "no message naming the other run's checkpoints"
run --check second.xml
[ "$status" = 0 ] || fail "the same problem on its own checkpoint base refused: exit $status"
echo "checkpoint_base.sh: passed"
