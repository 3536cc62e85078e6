#!/usr/bin/env bash
# Benchmark: start-up of the kiln executable, `kiln --version` run by hand (not under
# mpirun: it then answers before MPI starts). Prints the median and the range of N runs
# of the whole process's wall time [s] and the number of shared libraries it loads.
# usage: benchmarks/startup.sh [N]     (default 21). Target (issue 12): median <= 0.1 s.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
kiln=${KILN:-$here/build/src/app/kiln}
n=${1:-21}
python3 - "$kiln" "$n" <<'PY'
import statistics, subprocess, sys, time
kiln, n = sys.argv[1], int(sys.argv[2])
walls = []
for _ in range(n):
    start = time.perf_counter()
    subprocess.run([kiln, "--version"], check=True, stdout=subprocess.DEVNULL)
    walls.append(time.perf_counter() - start)
libraries = subprocess.run(["ldd", kiln], check=True, capture_output=True, text=True).stdout
print(f"kiln --version: median {statistics.median(walls):.3f} s, "
      f"min {min(walls):.3f} s, max {max(walls):.3f} s over {n} runs; "
      f"{len(libraries.splitlines())} shared libraries")
PY
