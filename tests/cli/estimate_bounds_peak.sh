#!/usr/bin/env bash
# The memory estimate Kiln prints before a run ("memory: about X per rank (...)", from
# src/app/memory_estimate.cpp) must be at least the peak resident memory of every rank that
# the run reports at its end ("peak RSS per rank: a, b"): a run the estimate lets through
# must not run out where it said it fits. Fails if the estimate falls below a rank's peak,
# or if either line is missing.
# usage: estimate_bounds_peak.sh INPUT.xml LAUNCH... (LAUNCH: the kiln command, e.g.
#        "mpiexec -n 2 kiln"; the input is appended)
set -u
input=$(realpath "$1")
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
"$@" "$input" >log.txt 2>&1
status=$?
cat log.txt
if [ "$status" -ne 0 ]; then
  echo "estimate_bounds_peak: FAILED: the run ended with status $status"
  exit 1
fi
/usr/bin/env python3 - log.txt <<'PY'
import re, sys
text = open(sys.argv[1]).read()
unit = {"kB": 1e3, "MB": 1e6, "GB": 1e9, "TB": 1e12}
estimate = re.search(r"memory: about ([0-9.]+) (kB|MB|GB|TB) per rank", text)
peaks = re.search(r"peak RSS per rank: (.*)", text)
if not estimate or not peaks:
    sys.exit("estimate_bounds_peak: FAILED: no estimate or no peak in the log")
bound = float(estimate.group(1)) * unit[estimate.group(2)]
ranks = [float(v) * unit[u] for v, u in re.findall(r"([0-9.]+) (kB|MB|GB|TB)", peaks.group(1))]
if not ranks:
    sys.exit("estimate_bounds_peak: FAILED: no peak per rank in the log")
worst = max(ranks)
print(f"estimate_bounds_peak: estimate {bound / 1e6:.1f} MB per rank, largest peak "
      f"{worst / 1e6:.1f} MB ({100 * worst / bound:.0f}% of it)")
if worst > bound:
    sys.exit("estimate_bounds_peak: FAILED: a rank's peak exceeds the estimate")
PY
