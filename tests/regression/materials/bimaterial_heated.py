#!/usr/bin/env python3
"""Two materials (aluminium, steel) heated by 100 K between walls, in series and in parallel
(issue 31): the closed-form bimaterial states, to 1e-9.

usage: bimaterial_heated.py KILN MPIEXEC NP series|parallel

The box [-0.1, 0.1] x [-0.5, 0.5] x [-0.05, 0.05] m (the generator's blocks: 1 for x < 0,
aluminium; 2 for x > 0, steel), Thermo-Elasticity, steady, T = 398 K everywhere (T_ref 298 K,
dT = 100 K). With M = lambda + 2G and beta = (3 lambda + 2G) alpha of each material:
- series: walls at x = -0.1 and x = 0.1 (u_x = 0), rollers on the y and z faces. Both blocks
  are in uniaxial strain along x with one sigma_xx: eps_i = (sigma_xx + beta_i dT) / M_i and
  eps_1 + eps_2 = 0 (equal lengths) give sigma_xx = -dT (beta_1/M_1 + beta_2/M_2) /
  (1/M_1 + 1/M_2); sigma_yy = sigma_zz = lambda_i eps_i - beta_i dT; u_x piecewise linear,
  0 at the walls.
- parallel: walls at y = -0.5 and y = 0.5 (u_y = 0), rollers on the z faces and on x = -0.1,
  x = 0.1 free: each block expands along x alone, eps_i = beta_i dT / M_i, sigma_xx = 0,
  sigma_yy = sigma_zz = lambda_i eps_i - beta_i dT (each bar carries its own wall force);
  u_x = eps_1 (x + 0.1) in block 1, eps_1 0.1 + eps_2 x in block 2.
The fields are piecewise linear, so every cell type is exact: errors to 1e-9 of the largest.
"""
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)

MATERIALS = {  # E [Pa], nu, alpha [1/K]
    "aluminium": (70e9, 0.33, 23e-6),
    "steel": (200e9, 0.30, 12e-6),
}
DT = 100.0


def lame(E, nu):
    return E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))


def deck(base, walls, rollers):
    materials = {name: {"Blocks": [block], **kd.young(E, nu), "Thermal Expansion": alpha,
                        "Reference Temperature": 298.0, "Density": 3000.0,
                        "Specific Heat": 700.0, "Conductivity": 100.0}
                 for block, (name, (E, nu, alpha)) in enumerate(MATERIALS.items(), start=1)}
    conditions = {name: kd.displacement(sets, component)
                  for name, (sets, component) in {**walls, **rollers}.items()}
    return {"Physics": "Thermo-Elasticity",
            "Mesh": kd.box_mesh((0.2, 1, 0.1), (4, 5, 2)),
            "Materials": materials,
            "Thermal": {"Initial Temperature": 298 + DT, "Boundary Conditions": {
                "held": kd.temperature([1, 2, 3, 4, 5, 6], 298 + DT)}},
            "Mechanics": {"Boundary Conditions": conditions},
            "Time Stepping": {"Method": "Steady"},
            "Solver": {"Relative Tolerance": 1e-12},
            "Output": {"File Base": base}}


def exact(case, x):
    """(displacement at the points x, stress per block) of the closed-form state."""
    M, lam, beta = [], [], []
    for E, nu, alpha in MATERIALS.values():
        l, g = lame(E, nu)
        lam.append(l)
        M.append(l + 2 * g)
        beta.append((3 * l + 2 * g) * alpha)
    if case == "series":
        sxx = -DT * (beta[0] / M[0] + beta[1] / M[1]) / (1 / M[0] + 1 / M[1])
        eps = [(sxx + beta[i] * DT) / M[i] for i in range(2)]
        ux = np.where(x[:, 0] < 0, eps[0] * (x[:, 0] + 0.1), eps[1] * (x[:, 0] - 0.1))
    else:
        sxx = 0.0
        eps = [beta[i] * DT / M[i] for i in range(2)]
        ux = np.where(x[:, 0] < 0, eps[0] * (x[:, 0] + 0.1), eps[0] * 0.1 + eps[1] * x[:, 0])
    u = np.column_stack([ux, np.zeros(len(x)), np.zeros(len(x))])
    stress = [np.array([sxx, lam[i] * eps[i] - beta[i] * DT, lam[i] * eps[i] - beta[i] * DT,
                        0, 0, 0]) for i in range(2)]
    return u, stress


def main():
    kiln, mpiexec, n_ranks, case = sys.argv[1:5]
    # Side sets of the box: 1, 2 at x = -0.1, 0.1; 3, 4 at y = -0.5, 0.5; 5, 6 at z.
    if case == "series":
        walls = {"walls": ((1, 2), "x")}
        rollers = {"rollers y": ((3, 4), "y"), "rollers z": ((5, 6), "z")}
    else:
        walls = {"walls": ((3, 4), "y")}
        rollers = {"rollers z": ((5, 6), "z"), "roller x": ((1,), "x")}
    with tempfile.TemporaryDirectory() as folder:
        base = str(Path(folder) / case)
        run = kd.run_kiln(kiln, kd.write_deck(base, deck(base, walls, rollers)), n_ranks, mpiexec)
        state = kd.read_step(run.results)
    x, block, u, stress = state["x"], state["block"], state["displacement"], state["stress"]
    u_exact, stress_exact = exact(case, x)
    u_error = np.abs(u - u_exact).max() / np.abs(u_exact).max()
    # The results' tensor order is xx yy zz xy yz xz (doc/output-format.md).
    wanted = np.array([stress_exact[b - 1] for b in block])
    s_error = np.abs(stress - wanted).max() / np.abs(wanted).max()
    print(f"{case}, np {n_ranks}: displacement error {u_error:.3g}, stress error {s_error:.3g} "
          f"(sigma_yy {wanted[0, 1]:.6g} / {wanted[-1, 1]:.6g} Pa, sigma_xx {wanted[0, 0]:.6g} Pa)")
    return 0 if u_error <= 1e-9 and s_error <= 1e-9 else 1


sys.exit(main())
