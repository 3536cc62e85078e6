#!/usr/bin/env python3
"""Values that vary in space (Type "Expression", Initial Temperature Expression) in whole runs.

Usage: space_varying.py KILN WORK_DIR NP MPIEXEC

1. Displacement patch test: on a rotated, translated box (no gap), every face held at
   u = G x by three Displacement conditions whose values are formulas in x, y, z; the
   elastic solution is that linear field, so every node (interior ones included) must carry
   G x to rounding (the expression is evaluated at each node's own position).
2. Initial temperature field: a heat run whose initial temperature is 300 + 10x + 5yz; the
   state written at t = 0 must be that field at every node.
3. Traction formulas: a box held on its x- face and pulled on its x+ face by
   "Traction Expressions" {"1e6*(1 + 2*t)", "0", "0"} at t = 1 gives the displacements of
   "Traction" {3e6, 0, 0} (to rounding); {"3e6 + 1e7*(y - y0)", "0", "0"}, whose mean over
   the face is 3e6 Pa, gives different ones (the formula is evaluated at the Gauss points).
"""
import os
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)

G = np.array([[1e-3, 2e-4, -3e-4], [5e-4, -1e-3, 1e-4], [-2e-4, 3e-4, 2e-3]])

BOX = ((0.4, 0.3, 0.2), (4, 3, 3))
MATERIAL = kd.young(2e11, 0.3)


def displacement_deck(base):
    conditions = {}
    for d, c in enumerate("xyz"):
        formula = " + ".join(f"({G[d][k]!r})*{v}" for k, v in enumerate("xyz"))
        conditions[f"u_{c}"] = kd.displacement([1, 2, 3, 4, 5, 6], c, kd.expression(formula))
    return {"Physics": "Elasticity",
            "Mesh": kd.box_mesh(*BOX, phi=30, theta=20, translation=(0.1, -0.2, 0.3)),
            "Material": MATERIAL,
            "Mechanics": {"Boundary Conditions": conditions},
            "Output": {"File Base": base}}


def initial_deck(base):
    return {"Physics": "Heat Conduction",
            "Mesh": kd.box_mesh(*BOX, phi=30, theta=20, translation=(0.1, -0.2, 0.3)),
            "Material": MATERIAL,
            "Thermal": {"Initial Temperature Expression": "300 + 10*x + 5*y*z"},
            "Output": {"File Base": base, "Times": [0.0, 1.0]}}


def traction_deck(load):
    def deck(base):
        return {"Physics": "Elasticity",
                "Mesh": kd.box_mesh(*BOX, translation=(0.1, -0.2, 0.3)),
                "Material": MATERIAL,
                "Mechanics": {"Boundary Conditions": {
                    "clamped": kd.displacement([1], "xyz"), "pulled": load}},
                "Output": {"File Base": base, "Times": [0.0, 1.0]}}
    return deck


def run(kiln, deck_text, work, name, n_ranks, mpiexec):
    """The last and the first step of the run of deck_text(base) as WORK/NAME.xml."""
    base = os.path.join(work, name)
    results = kd.run_kiln(kiln, kd.write_deck(base, deck_text(base)), n_ranks, mpiexec).results
    return kd.read_step(results), kd.read_step(results, 0)


def main():
    kiln, work, n_ranks, mpiexec = sys.argv[1:5]
    os.makedirs(work, exist_ok=True)
    failures = 0
    last, _ = run(kiln, displacement_deck, work, "displacement", n_ranks, mpiexec)
    x, u = last["x"], last["displacement"]
    exact = x @ G.T
    err = np.abs(u - exact).max() / np.abs(exact).max()
    print(f"displacement patch test: {len(x)} nodes, max |u - G x| / max |G x| = {err:.2e}")
    if not err < 1e-10:
        print("FAIL: the displacement is not G x")
        failures += 1
    _, first = run(kiln, initial_deck, work, "initial", n_ranks, mpiexec)
    x, T0 = first["x"], first["temperature"]
    exact = 300 + 10 * x[:, 0] + 5 * x[:, 1] * x[:, 2]
    err = np.abs(T0 - exact).max()
    print(f"initial temperature field: max |T(0) - (300 + 10x + 5yz)| = {err:.2e} K")
    if not err < 1e-12:
        print("FAIL: the initial temperature is not the formula")
        failures += 1
    displacements = {}
    y0 = -0.2 - 0.15  # the translated box's y = -Ly/2 face (no rotation)
    for name, load in (
        ("vector", kd.traction([2], (3e6, 0, 0))),
        ("formula", kd.traction([2], expressions=("1e6*(1 + 2*t)", "0", "0"))),
        ("varying", kd.traction([2], expressions=(f"3e6 + 1e7*(y - ({y0 + 0.15}))", "0", "0")))):
        last, _ = run(kiln, traction_deck(load), work, "traction-" + name, n_ranks, mpiexec)
        displacements[name] = last["displacement"]
    scale = np.abs(displacements["vector"]).max()
    same = np.abs(displacements["formula"] - displacements["vector"]).max() / scale
    differ = np.abs(displacements["varying"] - displacements["vector"]).max() / scale
    print(f"traction formulas: |u(formula) - u(vector)| / |u| = {same:.2e}, "
          f"|u(varying) - u(vector)| / |u| = {differ:.2e}")
    if not same < 1e-10:
        print("FAIL: a formula of t gives another load than the same vector")
        failures += 1
    if not differ > 1e-3:
        print("FAIL: a traction varying over the face gives the uniform one's displacements")
        failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
