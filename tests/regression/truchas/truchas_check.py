#!/usr/bin/env python3
"""Runs a deck of inputs/truchas/ and applies its check module (the Truchas test's own check,
doc/verification/truchas/NAME.py: the same module the verification report uses).

Usage: truchas_check.py KILN DECK SIDECARS WORK_DIR NP MPIEXEC

Passes if every figure of the module is within the Truchas test's tolerance.
"""
import importlib.util
import os
import subprocess
import sys
from pathlib import Path


def main():
    kiln, deck, sidecars, work, n_ranks, mpiexec = sys.argv[1:7]
    deck = Path(deck)
    spec = importlib.util.spec_from_file_location("check", Path(sidecars) / f"{deck.stem}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    os.makedirs(work, exist_ok=True)
    command = [kiln, str(deck)]
    if int(n_ranks) > 1:
        command = [mpiexec, "-np", n_ranks] + command
    subprocess.run(command, check=True, cwd=work, stdout=subprocess.DEVNULL)
    results = Path(work) / "results" / f"{deck.stem}.h5"
    failed = 0
    for f in module.figures(results, deck):
        print(f"{module.TEST}: {f['quantity']}: Kiln {f['kiln']:.6g}, tolerance {f['tolerance']}"
              f", exact {f.get('exact')}: {'pass' if f['passed'] else 'FAIL'}")
        failed += not f["passed"]
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
