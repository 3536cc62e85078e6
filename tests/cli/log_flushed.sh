#!/usr/bin/env bash
# With stdout redirected to a file (a batch job), the log must reach the file line by line
# while Kiln runs: a run killed by a time limit used to leave an empty log, the C library
# holding the whole output in its block buffer until exit.
# usage: log_flushed.sh KILN INPUT.xml
# Passes when the header line ("mesh: ...") is in the file while kiln is still running, before
# 4096 bytes (the C library's block size for files) have been written; kiln is then killed
# with SIGKILL (as a batch system does after its grace period).
set -u
kiln=$(realpath "$1") input=$(realpath "$2")
# A folder of its own: the results the killed run leaves must not meet other tests' files.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
log=$work/log.txt
"$kiln" "$input" >"$log" 2>&1 &
pid=$!
for _ in $(seq 1 2400); do # up to 120 s
  if grep -q '^mesh: ' "$log"; then
    size=$(stat -c %s "$log")
    if kill -0 "$pid" 2>/dev/null && [ "$size" -lt 4096 ]; then
      kill -KILL "$pid" 2>/dev/null
      wait "$pid" 2>/dev/null
      cat "$log"
      echo "log_flushed: OK (the header was in the log while kiln ran; kiln killed)"
      exit 0
    fi
    break
  fi
  if ! kill -0 "$pid" 2>/dev/null; then
    break
  fi
  sleep 0.05
done
wait "$pid" 2>/dev/null
cat "$log"
echo "log_flushed: the log reached the file in blocks (or only when kiln ended), not line by line"
exit 1
