#!/usr/bin/python3
"""The calibration of Kiln's memory estimate (src/app/memory_estimate.cpp): runs, each on 1
and 2 ranks, the contact box (inputs/contact-box-close.xml, Thermo-Elasticity with contact,
F = 4 unknowns per node) at 16^3 to 40^3 cells and its heat conduction alone (F = 1) at 24^3
to 64^3 cells to the first backward Euler step (output at t = 1 s), and the elastic cube
(inputs/elastic-cube.xml, F = 3, CG) at 20^3 to 40^3 cells; and fits the peak resident memory
of the largest rank (VmHWM, GNU time's %M) to

    peak = base + cells m_F + unknowns / ranks (k_F + 8 V)

by least squares, one (m_F, k_F) per F, V the Krylov vectors the longest solve touched
(flexible GMRES: 2 per iteration, plus 2; CG: 8, as the estimate counts). It prints every
run, the fitted constants and each run's error; copy the constants into memory_estimate.cpp
(and doc/user-guide.md, *Memory*) if they moved.

    benchmarks/memory_fit.py                 # the whole calibration, about 2 minutes
    benchmarks/memory_fit.py --kiln build/src/app/kiln
"""
import argparse
import os
import pathlib
import re
import subprocess
import sys
import tempfile

import numpy

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from scaling import deck_box, deck_cube  # noqa: E402  (the decks sized n, one home)

HERE = pathlib.Path(__file__).resolve().parent.parent
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
           "OMPI_MCA_rmaps_base_oversubscribe": "1"}
CASES = ([(4, n) for n in (16, 24, 32, 40)] + [(1, n) for n in (24, 32, 48, 64)] +
         [(3, n) for n in (20, 30, 40)])


def deck(fields, n, base):
    """The contact box sized n to t = 1 s (scaling.py's); heat conduction alone if fields == 1;
    the elastic cube (inputs/elastic-cube.xml, CG) sized n if fields == 3."""
    if fields == 3:
        return deck_cube(n, base)
    text = deck_box(n, 1.0, base)
    if fields == 1:
        text = text.replace('value="Thermo-Elasticity"', 'value="Heat Conduction"')
        text = re.sub(r'<ParameterList name="Mechanics">.*?\n  </ParameterList>\n', '', text,
                      flags=re.S)
        for key in ("Lame Lambda", "Shear Modulus", "Thermal Expansion",
                    "Reference Temperature"):
            text = re.sub(rf'\s*<Parameter name="{key}"[^>]*/>', '', text)
    return text


def run(kiln, fields, n, ranks, work):
    path = pathlib.Path(work) / f"f{fields}_n{n}.xml"
    path.write_text(deck(fields, n, str(pathlib.Path(work) / f"f{fields}_n{n}_np{ranks}")))
    command = ["mpirun", "--bind-to", "none", "-np", str(ranks), "/usr/bin/time", "-f",
               "KILN_PEAK_KB %M", kiln, str(path)]
    done = subprocess.run(command, capture_output=True, text=True,
                          env={**os.environ, **MPI_ENV})
    log = done.stdout + done.stderr
    if done.returncode != 0:
        sys.exit(f"memory_fit.py: FAILED: {' '.join(command)}\n{log[-2000:]}")
    peak = max(int(k) for k in re.findall(r"KILN_PEAK_KB (\d+)", log)) * 1024.0
    cells = int(re.search(r"mesh: (\d+) cells", log).group(1))
    unknowns = int(re.search(r"unknowns: (\d+)", log).group(1))
    longest = max(int(k) for k in re.findall(r"\((\d+) linear\)", log))
    # CG keeps a few vectors, as the estimate counts them (8); GMRES its basis as it goes.
    vectors = 8 if "Pseudo Block CG" in path.read_text() else 2 * longest + 2
    return {"fields": fields, "n": n, "ranks": ranks, "cells": cells, "unknowns": unknowns,
            "vectors": vectors, "peak": peak}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--kiln", default=str(HERE / "build/src/app/kiln"))
    args = parser.parse_args()
    runs = []
    with tempfile.TemporaryDirectory() as work:
        for fields, n in CASES:
            for ranks in (1, 2):
                r = run(args.kiln, fields, n, ranks, work)
                runs.append(r)
                print(f"F={fields} N={n} np={ranks}: {r['unknowns']} unknowns, longest solve "
                      f"touching {r['vectors']} vectors, peak {r['peak'] / 1e6:.1f} MB",
                      flush=True)
    # peak - 8 V u = base + c m_F + u k_F, u the unknowns per rank, one (m_F, k_F) per F
    fields = sorted({r["fields"] for r in runs})
    rows, rhs = [], []
    for r in runs:
        c, u = r["cells"], r["unknowns"] / r["ranks"]
        rows.append([1.0] + [c if f == r["fields"] else 0.0 for f in fields] +
                    [u if f == r["fields"] else 0.0 for f in fields])
        rhs.append(r["peak"] - 8.0 * r["vectors"] * u)
    x, *_ = numpy.linalg.lstsq(numpy.array(rows), numpy.array(rhs), rcond=None)
    print(f"\nbase_bytes = {x[0] / 1e6:.0f}e6")
    for i, f in enumerate(fields):
        print(f"F = {f}: {x[1 + i]:.0f} bytes per cell, {x[1 + len(fields) + i]:.0f} bytes per "
              "unknown")
    worst = 0.0
    for r, row, b in zip(runs, rows, rhs):
        fit = float(numpy.dot(row, x)) + (r["peak"] - b)
        error = fit / r["peak"] - 1.0
        worst = max(worst, abs(error))
        print(f"  F={r['fields']} N={r['n']} np={r['ranks']}: measured "
              f"{r['peak'] / 1e6:.1f} MB, fit {fit / 1e6:.1f} MB ({100 * error:+.1f}%)")
    print(f"largest error {100 * worst:.1f}%")


if __name__ == "__main__":
    main()
