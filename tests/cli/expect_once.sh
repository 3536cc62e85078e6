#!/usr/bin/env bash
# Runs a command that must succeed and print a line matching REGEX exactly once (a warning
# printed on rank 0 only, once per run).
# usage: expect_once.sh REGEX COMMAND...
set -u
regex=$1
shift
out=$("$@" 2>&1)
rc=$?
printf '%s\n' "$out"
if [ "$rc" -ne 0 ]; then
  echo "expect_once: expected exit status 0, got $rc"
  exit 1
fi
n=$(grep -Ec -- "$regex" <<<"$out")
if [ "$n" -ne 1 ]; then
  echo "expect_once: '$regex' printed $n times, expected once"
  exit 1
fi
echo "expect_once: OK"
