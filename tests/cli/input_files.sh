#!/usr/bin/env bash
# Inputs that are not readable regular files (issue 33), on NP ranks: a FIFO nobody writes
# is refused after Kiln's wait (5 s) instead of hanging; a FIFO that is written is read; a
# file without read permission names the system's reason (skipped as root, who reads it).
# usage: input_files.sh KILN MPIEXEC NP DECK.xml
set -u
kiln=$(realpath "$1") mpiexec=$2 np=$3 deck=$(realpath "$4")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "input_files.sh: $*"; exit 1; }
run() { timeout 60 "$mpiexec" -np "$np" "$kiln" "$@" > log.txt 2>&1; status=$?; cat log.txt; }

mkfifo pipe.xml || fail "mkfifo"
start=$(date +%s)
run --check pipe.xml
[ "$status" = 1 ] || fail "a FIFO without a writer: exit $status, expected 1"
[ "$(grep -c 'pipe.xml: is a FIFO (named pipe) and sent no end of file within 5 s (0 bytes read); give the path of the XML input file, or start the program that writes the pipe before Kiln' log.txt)" = 1 ] ||
  fail "no single message for a FIFO without a writer"
[ $(($(date +%s) - start)) -lt 50 ] || fail "the FIFO took too long"

cat "$deck" > pipe.xml &
writer=$!
run --check pipe.xml
wait "$writer"
[ "$status" = 0 ] || fail "a FIFO with a writer: exit $status"
grep -q "pipe.xml: input and mesh are valid" log.txt || fail "the deck from a FIFO was not checked"

if [ "$(id -u)" = 0 ]; then
  echo "input_files.sh: running as root, who reads any file: permission case skipped"
else
  cp "$deck" locked.xml && chmod 000 locked.xml
  run --check locked.xml
  [ "$status" = 1 ] || fail "an unreadable file: exit $status, expected 1"
  grep -q 'locked.xml: cannot open the input file (Permission denied); check that it is readable by this user' log.txt ||
    fail "no message naming the permission"
fi
echo "input_files.sh: np $np passed"
