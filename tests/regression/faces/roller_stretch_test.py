#!/usr/bin/env python3
"""Rollers (Normal Displacement) on every element type: a uniaxial stretch, exact.

usage: roller_stretch_test.py KILN MPIEXEC CELL_TYPE

The unit cube [0, 1]^3 on 2^3 cells of CELL_TYPE, held by rollers on x = 0, y = 0, z = 0 and
moved by d = 1e-3 along the normal of x = 1 (a Normal Displacement, not a component): the
uniaxial stress state u = (d x, -nu d y, -nu d z) is linear, so every type must give it to
round-off. A roller's direction at a node is the node's normal on its faces; on the faces
of TETRA10 (TRI6) and HEX20 (QUAD8) the corners' shape functions integrate to zero or to a
negative share of the area, so a normal weighted by them is none (TETRA10: NaN) or the
inward one (HEX20: the corners moved by -d). Exit status 0 when the field is exact.
"""
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)

D = 1e-3
LAMBDA, MU = 1.0, 1.0
NU = LAMBDA / (2 * (LAMBDA + MU))


def deck(cell_type, base):
    return {"Physics": "Elasticity",
            "Mesh": kd.box_mesh((1, 1, 1), (2, 2, 2), translation=(0.5, 0.5, 0.5),
                                cell_type=cell_type),
            "Material": kd.lame(LAMBDA, MU),
            "Mechanics": {"Boundary Conditions": {
                "rollers": kd.normal_displacement([1, 3, 5]),
                "pulled": kd.normal_displacement([2], D)}},
            "Solver": {"Relative Tolerance": 1e-12},
            "Output": {"File Base": base}}


def main():
    kiln, mpiexec, cell_type = sys.argv[1:4]
    with tempfile.TemporaryDirectory() as folder:
        base = str(Path(folder) / "stretch")
        run = kd.run_kiln(kiln, kd.write_deck(base, deck(cell_type, base)), 1, mpiexec)
        state = kd.read_step(run.results)
        x, u = state["x"], state["displacement"]
    exact = np.column_stack([D * x[:, 0], -NU * D * x[:, 1], -NU * D * x[:, 2]])
    error = np.abs(u - exact).max() / D if np.all(np.isfinite(u)) else np.inf
    worst = int(np.argmax(np.abs(u - exact).max(axis=1))) if np.isfinite(error) else -1
    print(f"{cell_type}: {len(x)} nodes, largest error {error:.3g} of d"
          + (f" (node {worst + 1} at {x[worst]}: {u[worst]} vs {exact[worst]})" if error > 1e-10
             else ""))
    return 0 if error <= 1e-10 else 1


sys.exit(main())
