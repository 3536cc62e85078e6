#!/usr/bin/env bash
# tests/rebaseline.sh on a copy of the contact-box-close case (np 1 only) whose gold, a copy
# of the real one with one temperature changed by 1 K, lives in a scratch folder:
#   without --yes (stdin not a terminal) it prints that difference and keeps the gold;
#   with --yes it replaces the gold by one that matches the real gold;
#   an unknown case is an error (status 2).
# usage: rebaseline_test.sh REBASELINE_SH CASES_DIR GOLD PYTHON KILN_DIFF
set -euo pipefail
rebaseline=$1 cases=$2 real_gold=$3 python=$4 kiln_diff=$5
work=$PWD/rebaseline-test
rm -rf "$work"
mkdir -p "$work/build/tests/regression-cases"
fake=$work/build/tests/regression-cases
cp "$cases/python" "$fake/python"
# the real case's arguments, with the gold and the run folder moved and np 1 only
sed -e "s#^--gold=.*#--gold=$work/gold.h5#" -e "s#^--dir=.*#--dir=$work/case#" \
    -e '/^--nps$/,$d' "$cases/contact-box-close.args" > "$fake/contact-box-close.args"
printf -- '--nps\n1\n' >> "$fake/contact-box-close.args"
cp "$real_gold" "$work/gold.h5"
"$python" -c "
import h5py, sys
with h5py.File(sys.argv[1], 'r+') as f:
    f['/steps/000003/temperature'][7] += 1.0
" "$work/gold.h5"
fail() { echo "rebaseline_test.sh: $*"; exit 1; }
before=$(md5sum < "$work/gold.h5")

status=0
"$rebaseline" --build "$work/build" contact-box-close < /dev/null > "$work/no.txt" 2>&1 || status=$?
cat "$work/no.txt"
[ $status = 1 ] || fail "without --yes: status $status, expected 1"
grep -q "temperature at t = 150 s, node 7 " "$work/no.txt" || fail "the difference is not shown"
grep -q "not replacing the gold: rerun with --yes" "$work/no.txt" || fail "no refusal"
[ "$(md5sum < "$work/gold.h5")" = "$before" ] || fail "the gold changed without --yes"

"$rebaseline" --build "$work/build" --yes gold_contact-box-close_np1 > "$work/yes.txt" 2>&1 ||
  { cat "$work/yes.txt"; fail "with --yes: failed"; }
cat "$work/yes.txt"
grep -q "replaced $work/gold.h5" "$work/yes.txt" || fail "no replacement reported"
# Within the case's own tolerances (its --tolerance lines, kiln-diff's --field).
tolerances=$(sed -n 's/^--tolerance=/--field=/p' "$cases/contact-box-close.args")
# shellcheck disable=SC2086
"$python" "$kiln_diff" $tolerances "$work/gold.h5" "$real_gold" ||
  fail "the new gold differs from the real one"

status=0
"$rebaseline" --build "$work/build" no-such-case > "$work/none.txt" 2>&1 || status=$?
[ $status = 2 ] && grep -q "no case no-such-case" "$work/none.txt" ||
  { cat "$work/none.txt"; fail "an unknown case: status $status"; }
echo "rebaseline_test.sh: passed"
