#!/usr/bin/env bash
# Runs a command that must fail: checks its exit status, that its output matches
# a regular expression, and that the error is printed once (not once per rank).
# usage: expect_failure.sh STATUS REGEX COMMAND...
set -u
status=$1 regex=$2
shift 2
out=$("$@" 2>&1)
rc=$?
printf '%s\n' "$out"
if [ "$rc" -ne "$status" ]; then
  echo "expect_failure: expected exit status $status, got $rc"
  exit 1
fi
if ! grep -Eq -- "$regex" <<<"$out"; then
  echo "expect_failure: the output does not match: $regex"
  exit 1
fi
n=$(grep -c 'kiln: error:' <<<"$out")
if [ "$n" -ne 1 ]; then
  echo "expect_failure: 'kiln: error:' printed $n times, expected once"
  exit 1
fi
echo "expect_failure: OK"
