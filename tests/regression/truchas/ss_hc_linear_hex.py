#!/usr/bin/env python3
"""Truchas' 3d-ss-hc-linear-hex check (its test.py) on Kiln's run of
inputs/truchas/3d-ss-hc-linear-hex.xml.

Usage: ss_hc_linear_hex.py KILN DECK WORK_DIR NP MPIEXEC

test.py compares Truchas' cell temperatures Z_TEMP at the cell centroids with
Tref = 1 + x + 2y + 3z (max |T - Tref| / Tref <= 1e-6), and its cell enthalpies Z_ENTHALPY
with 2 Tref (rho c = 4 x 0.5). Kiln's temperature is nodal (Q1): its cell value is the mean
of the cell's nodes, which for a linear field is the value at the centroid; Kiln writes no
enthalpy field, so the enthalpy is checked as a whole, the history's thermal_energy
(int rho c T dV) against int 2 Tref dV = 8 J, to the same relative 1e-6. Same tolerance as
test.py at the last output (t = 500 s).
"""
import csv
import os
import subprocess
import sys

import h5py
import numpy as np

TOLERANCE = 1e-6  # test.py: compare_max(err, 0, 1e-6, ...)


def main():
    kiln, deck, work, n_ranks, mpiexec = sys.argv[1:6]
    os.makedirs(work, exist_ok=True)
    command = [kiln, deck]
    if int(n_ranks) > 1:
        command = [mpiexec, "-np", n_ranks] + command
    subprocess.run(command, check=True, cwd=work, stdout=subprocess.DEVNULL)
    base = os.path.join(work, "results", "3d-ss-hc-linear-hex")
    failures = 0
    with h5py.File(base + ".h5", "r") as h5:
        x = h5["mesh/coordinates"][...]
        cells = h5["mesh/connectivity"][...]
        steps = h5["steps"]
        last = steps[sorted(steps.keys())[-1]]
        time = float(last.attrs["time"])
        T_nodes = last["temperature"][...]
    centroids = x[cells].mean(axis=1)
    T_cells = T_nodes[cells].mean(axis=1)
    T_ref = 1 + centroids[:, 0] + 2 * centroids[:, 1] + 3 * centroids[:, 2]
    err = np.max(np.abs((T_cells - T_ref) / T_ref))
    print(f"t = {time} s, {len(cells)} cells: max |T - Tref| / Tref = {err:.3e} (tolerance {TOLERANCE})")
    if not err <= TOLERANCE:
        print("FAIL: temperature")
        failures += 1
    if time != 500.0:
        print(f"FAIL: the last output is at t = {time} s, not 500 s")
        failures += 1
    with open(base + ".history.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    H = float(rows[-1]["thermal_energy"])
    err_H = abs(H / 2 - 4.0) / 4.0
    print(f"int H dV = {H!r} J (exact 8): relative error {err_H:.3e}")
    if not err_H <= TOLERANCE:
        print("FAIL: enthalpy")
        failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
