#!/usr/bin/env python3
"""Truchas' sm-viscoplastic/test-restart.py posed to Kiln: inputs/truchas/viscoplastic-1d.xml
run from 0 to 0.5 s in one run, against a run to 0.3 s (its checkpoint at its end, a
mid-run state of the whole run: plastic strain at every quadrature point) restarted to 0.5 s
from that checkpoint, on NP ranks both.

Passes if the restart continues bit-identically (kiln-diff with no tolerance: every field,
among them plastic_strain and plastic_strain_rate, at every output; Truchas compares sigma,
epsilon, epsdot and e_plastic at the final time to 1e-9), and the restarted results (the
whole series, 0 to 0.5 s, in one file) pass the deck's own checks
(doc/verification/truchas/viscoplastic-1d.py, test.py's quantities).

Usage: viscoplastic_restart.py KILN KILN_DIFF DECK SIDECARS WORK_DIR NP MPIEXEC
"""
import importlib.util
import re
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)

TIMES = '<Parameter name="Times" type="Array(double)" value="{0, 0.1, 0.2, 0.3, 0.4, 0.5}"/>'


def main():
    kiln, kiln_diff, deck, sidecars, work, n_ranks, mpiexec = sys.argv[1:8]
    deck = Path(deck)
    work = Path(work)
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    text = deck.read_text()
    if TIMES not in text:
        print(f"{deck}: its Output Times are not {TIMES}")
        return 1

    def write(name, times):
        body = text.replace(TIMES, f'<Parameter name="File Base" type="string" '
                                  f'value="results/{name}"/>{times}')
        (work / f"{name}.xml").write_text(body)

    write("complete", TIMES)
    write("restarted", TIMES)
    (work / "part1.xml").write_text((work / "restarted.xml").read_text().replace(
        "{0, 0.1, 0.2, 0.3, 0.4, 0.5}", "{0, 0.1, 0.2, 0.3}"))

    def run(name, *extra):
        return kd.run_kiln(kiln, f"{name}.xml", n_ranks, mpiexec, extra, cwd=work,
                           log=work / f"{name}.log").log

    run("complete")
    run("part1")
    log = run("restarted", "--restart", "results/restarted.checkpoint.h5")
    if not re.search(r"restart from results/restarted.checkpoint.h5: t = 0.3 s", log):
        print(log)
        print("the restart did not start from the checkpoint at 0.3 s")
        return 1
    diff = subprocess.run([kiln_diff, "--abs", "0", "--rel", "0", "results/complete.h5",
                           "results/restarted.h5"], cwd=work, capture_output=True, text=True)
    print(diff.stdout + diff.stderr, end="")
    if diff.returncode != 0:
        print("the restarted run is not bit-identical to the complete one")
        return 1

    spec = importlib.util.spec_from_file_location("check", Path(sidecars) / f"{deck.stem}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    failed = 0
    for f in module.figures(work / "results" / "restarted.h5", deck):
        print(f"{module.TEST} (restarted): {f['quantity']}: Kiln {f['kiln']:.6g}, tolerance "
              f"{f['tolerance']}: {'pass' if f['passed'] else 'FAIL'}")
        failed += not f["passed"]
    if failed:
        return 1
    print(f"viscoplastic-1d: 0 -> 0.5 s equals 0 -> 0.3 s + restart to 0.5 s on {n_ranks} "
          "rank(s), bit for bit")
    return 0


if __name__ == "__main__":
    sys.exit(main())
