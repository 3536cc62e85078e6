#!/usr/bin/env bash
# Remakes the gold of gold-file regression tests (doc/testing.md).
#
# usage: tests/rebaseline.sh [--build DIR] [--yes] NAME...
#        tests/rebaseline.sh [--build DIR] [--yes] --all
#        tests/rebaseline.sh [--build DIR] --list
#
# NAME is the NAME of a kiln_add_regression_test call (the test gold_NAME_np1 or
# gold_NAME_np2 may be given too). For each case it reruns kiln on every rank count of the
# case (in DIR/tests/regression-cases/NAME/), makes the new gold from the first run, checks
# that the other runs match it within the case's tolerances, prints the kiln-diff
# differences between the new gold and the current one, and only then replaces the gold in
# the source tree: after asking, or at once with --yes. Build first (DIR default: build/ of
# this checkout). Commit the new golds with the physical reason for the change.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=$here/../build
yes=()
all=0
list=0
names=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build=${2:?--build needs a folder}; shift 2 ;;
    --yes|-y) yes=(--yes); shift ;;
    --all) all=1; shift ;;
    --list) list=1; shift ;;
    -h|--help) sed -n '2,14p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "rebaseline.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) names+=("$1"); shift ;;
  esac
done
cases=$build/tests/regression-cases
if [ ! -f "$cases/python" ]; then
  echo "rebaseline.sh: no regression cases in $cases: configure and build first" \
       "(cmake -S . -B build && cmake --build build), or give --build DIR" >&2
  exit 2
fi
python=$(cat "$cases/python")
available=()
for f in "$cases"/*.args; do
  [ -e "$f" ] && available+=("$(basename "$f" .args)")
done
if [ $list = 1 ]; then
  printf '%s\n' "${available[@]}"
  exit 0
fi
if [ $all = 1 ]; then
  [ ${#names[@]} -eq 0 ] || { echo "rebaseline.sh: --all takes no NAME" >&2; exit 2; }
  names=("${available[@]}")
fi
if [ ${#names[@]} -eq 0 ]; then
  echo "rebaseline.sh: give the NAME of a case, or --all (--list lists them)" >&2
  exit 2
fi
failed=()
for i in "${!names[@]}"; do
  name=${names[$i]#gold_}
  name=$(echo "$name" | sed -E 's/_np[0-9]+$//')
  names[$i]=$name
  if [ ! -f "$cases/$name.args" ]; then
    echo "rebaseline.sh: no case $name in $cases; the cases are: ${available[*]}" >&2
    exit 2
  fi
  echo "=== $name"
  if ! "$python" "$here/cmake/kiln_regression.py" "@$cases/$name.args" --rebaseline \
       "${yes[@]}"; then
    failed+=("$name")
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "rebaseline.sh: not rebaselined: ${failed[*]}"
  exit 1
fi
echo "rebaseline.sh: rebaselined ${#names[@]} case(s): ${names[*]}"
