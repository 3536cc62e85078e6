"""Check of inputs/truchas/3d-ss-hc-linear-hex.xml: Truchas' 3d-ss-hc-linear-hex test.py.

test.py compares Truchas' cell temperatures Z_TEMP at the cell centroids with
Tref = 1 + x + 2y + 3z (max |T - Tref| / Tref <= 1e-6) and its cell enthalpies Z_ENTHALPY
with 2 Tref (rho c = 4 x 0.5), at the last output (t = 500 s). Kiln's temperature is nodal
(Q1): its cell value is the mean of the cell's nodes, which for a linear field is the value
at the centroid. Kiln writes no enthalpy field: the enthalpy is checked as a whole, the
history's thermal_energy (int rho c T dV) against int 2 Tref dV = 8 J, to the same relative
1e-6. Truchas ships no golden output for this test (its check is analytic).
"""
import csv

import h5py
import numpy as np

TEST = "3d-ss-hc-linear-hex"
CHANGES = []
TOLERANCE = 1e-6  # test.py: compare_max(err, 0, 1e-6, ...)


def figures(results, deck):
    with h5py.File(results, "r") as h5:
        x = h5["mesh/coordinates"][...]
        cells = h5["mesh/connectivity"][...]
        steps = h5["steps"]
        last = steps[sorted(steps.keys())[-1]]
        time = float(last.attrs["time"])
        T_nodes = last["temperature"][...]
    nodes = [row[row >= 0] for row in cells]  # rows padded with -1 on a mixed mesh
    centroids = np.array([x[n].mean(axis=0) for n in nodes])
    T_cells = np.array([T_nodes[n].mean() for n in nodes])
    T_ref = 1 + centroids[:, 0] + 2 * centroids[:, 1] + 3 * centroids[:, 2]
    err_T = float(np.max(np.abs((T_cells - T_ref) / T_ref)))
    with open(str(results)[:-len(".h5")] + ".history.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    column = next(c for c in rows[-1] if c.split(" [")[0] == "thermal_energy")
    H = float(rows[-1][column])
    err_H = abs(H / 2 - 4.0) / 4.0
    at_end = time == 500.0
    return [
        {"quantity": f"max |T - Tref| / Tref at the cell centroids, t = {time:g} s",
         "kiln": err_T, "tolerance": f"<= {TOLERANCE:g} (test.py)",
         "passed": err_T <= TOLERANCE and at_end, "golden": None, "exact": 0.0},
        {"quantity": f"int H dV [J], t = {time:g} s", "kiln": H,
         "tolerance": f"relative {TOLERANCE:g} of 8 J (test.py's per cell)",
         "passed": err_H <= TOLERANCE and at_end, "golden": None, "exact": 8.0},
    ]
