#!/usr/bin/env python3
"""A column under its own weight with a density of temperature, and two blocks of two densities
(issue 31: the body force rho(T) g, doc/materials.md "Gravity with a density of T"): the exact
uniaxial-strain state, to 1e-9.

usage: gravity_column.py KILN MPIEXEC NP rho-of-T|two-densities

The box [-0.5, 0.5] x [-0.05, 0.05]^2 m, 8 x 2 x 2 HEX8 cells (the generator's blocks: 1 for
x < 0, 2 for x > 0), Thermo-Elasticity, steady; gravity g = 9.81 m/s^2 along -x. Held
temperatures T = 300 K on x = -0.5 and 500 K on x = 0.5 (the other faces insulated): the
steady T is linear along the column, s = x + 0.5, T(s) = 300 + 200 s. The foot x = -0.5 is held
(u_x = 0), rollers on the four long faces (u_y = 0, u_z = 0), the top x = 0.5 free. No thermal
expansion (alpha = 0: the stress is the weight's alone). Each block is in uniaxial strain:
  sigma_xx(s) = -g int_s^1 rho(T(s')) ds',  eps_xx = sigma_xx / M,  sigma_yy = sigma_zz =
  lambda eps_xx,  u_x(s) = int_0^s eps_xx ds',  M = lambda + 2G,
with rho(T) at the point's temperature.
- rho-of-T: one material, rho(T) = 8000 - 10 (T - 300) kg/m^3 (an Expression): rho is linear in
  s, sigma_xx quadratic, u_x cubic.
- two-densities: aluminium (block 1, rho 2700, E 70 GPa, nu 0.33) below steel (block 2, rho
  7900, E 200 GPa, nu 0.30), each density a number.
Why exact with Q1: the problem is one-dimensional (u_x(x) alone), where the Galerkin solution
with linear elements is exact at the nodes for any load computed exactly (the load rho phi_i is
quadratic in s on a cell: the 2-point Gauss rule integrates it exactly, with rho at the point's
T, which is exact for a linear T); the strain of a cell is then the mean of the exact strain over
it, so each cell's stress is the exact cell average. Nodal displacements and cell stresses are
compared with the exact values to 1e-9 of their largest.
"""
import os
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
from kiln_deck import (box_mesh, displacement, read_step, run_kiln, temperature,  # noqa: E402
                       write_deck, young)

G0 = 9.81
T_FOOT, T_TOP = 300.0, 500.0
CASES = {  # per block (1, 2): name, E [Pa], nu, rho as (rho at 300 K, d rho/dT)
    "rho-of-T": [("steel", 200e9, 0.30, (8000.0, -10.0))] * 2,
    "two-densities": [("aluminium", 70e9, 0.33, (2700.0, 0.0)),
                      ("steel", 200e9, 0.30, (7900.0, 0.0))],
}


def lame(E, nu):
    return E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))


def density(rho0, slope):
    if slope == 0.0:
        return rho0
    return {"Type": "Expression", "Expression": f"{rho0} + ({slope})*(T - 300)",
            "Temperatures": [300.0, 400.0, 500.0]}


def deck(base, case):
    materials = {}
    for block, (name, E, nu, (rho0, slope)) in enumerate(CASES[case], start=1):
        material = materials.setdefault(name, {
            "Blocks": [], **young(E, nu), "Thermal Expansion": 0.0,
            "Reference Temperature": 300.0, "Density": density(rho0, slope),
            "Specific Heat": 500.0, "Conductivity": 40.0})
        material["Blocks"].append(block)
    return {
        "Physics": "Thermo-Elasticity",
        "Mesh": box_mesh((1, 0.1, 0.1), (8, 2, 2)),
        "Materials": materials,
        "Thermal": {"Initial Temperature": 400.0,
                    "Boundary Conditions": {"foot": temperature([1], T_FOOT),
                                            "top": temperature([2], T_TOP)}},
        "Mechanics": {"Gravity": [-G0, 0.0, 0.0],
                      "Boundary Conditions": {"foot": displacement([1], ["x"]),
                                              "rollers y": displacement([3, 4], ["y"]),
                                              "rollers z": displacement([5, 6], ["z"])}},
        "Time Stepping": {"Method": "Steady"},
        "Solver": {"Relative Tolerance": 1e-13},
        "Output": {"File Base": base},
    }


def integral(f, a, b, n=4):
    """int_a^b f by Gauss-Legendre with n points on each side of the block boundary s = 0.5
    (exact for the piecewise polynomials here)."""
    points, weights = np.polynomial.legendre.leggauss(n)
    total = 0.0
    for lo, hi in ((a, min(b, 0.5)), (max(a, 0.5), b)):
        if hi > lo:
            s = 0.5 * (hi - lo) * points + 0.5 * (hi + lo)
            total += 0.5 * (hi - lo) * np.sum(weights * np.array([f(x) for x in s]))
    return total


def exact(case):
    """Functions of s: rho, sigma_xx, eps_xx, lambda/M, u_x."""
    props = CASES[case]

    def block(s):
        return props[0] if s < 0.5 else props[1]

    def rho(s):
        rho0, slope = block(s)[3]
        return rho0 + slope * (T_FOOT + (T_TOP - T_FOOT) * s - 300.0)

    def moduli(s):
        lam, g = lame(block(s)[1], block(s)[2])
        return lam, lam + 2 * g

    def sigma_xx(s):
        return -G0 * integral(rho, s, 1.0)

    def eps_xx(s):
        return sigma_xx(s) / moduli(s)[1]

    def u_x(s):
        return integral(eps_xx, 0.0, s)

    return sigma_xx, moduli, u_x


def main():
    kiln, mpiexec, n_ranks, case = sys.argv[1:5]
    with tempfile.TemporaryDirectory() as folder:
        base = os.path.join(folder, case)
        state = read_step(run_kiln(kiln, write_deck(base, deck(base, case)), n_ranks,
                                   mpiexec).results)
    x, connectivity = state["x"], state["cells"]
    T, u, stress = state["temperature"], state["displacement"], state["stress"]
    sigma_xx, moduli, u_x = exact(case)
    s_nodes = x[:, 0] + 0.5
    T_exact = T_FOOT + (T_TOP - T_FOOT) * s_nodes
    T_error = np.abs(T - T_exact).max() / T_exact.max()
    u_exact = np.array([u_x(s) for s in s_nodes])
    u_error = max(np.abs(u[:, 0] - u_exact).max(), np.abs(u[:, 1:]).max()) / np.abs(u_exact).max()
    # Cell averages of the exact stress (the results' tensor order: xx yy zz xy yz xz).
    wanted = np.zeros((len(connectivity), 6))
    for c, nodes in enumerate(connectivity):
        s = s_nodes[nodes[nodes >= 0]]
        lo, hi = s.min(), s.max()
        mean = integral(sigma_xx, lo, hi) / (hi - lo)
        lam, M = moduli(0.5 * (lo + hi))
        wanted[c, :3] = [mean, lam / M * mean, lam / M * mean]
    s_error = np.abs(stress - wanted).max() / np.abs(wanted).max()
    foot = sigma_xx(0.0)
    print(f"{case}, np {n_ranks}: temperature error {T_error:.3g}, displacement error "
          f"{u_error:.3g}, stress error {s_error:.3g} (sigma_xx at the foot {foot:.8g} Pa, top "
          f"displacement {u_x(1.0):.8g} m)")
    return 0 if max(T_error, u_error, s_error) <= 1e-9 else 1


sys.exit(main())
