#!/usr/bin/env python3
"""The "Contact Dependent" gap conductance between two materials, and with E(T) on one side
(issue 31; doc/contact.md "Contact Dependent between materials"): the closed-form steady state,
to 1e-9.

usage: contact_conductance_materials.py KILN MPIEXEC NP two-materials|E-of-T

The contact box's geometry (the cube [-0.02, 0.02]^3 m, not rotated, split at x = 0 into a gap
of zero width, side set 10; 4 x 2 x 2 cells; block 1 the half x < 0, block 2 the half x > 0),
Thermo-Elasticity with contact, steady. Walls u_x = 0 on x = -0.02 and u_x = -2e-5 m on x = 0.02 press the
halves together; rollers on y = -0.02 and z = -0.02 (the other faces free: the lateral
expansion is free).
Temperatures 400 K on x = -0.02 and 300 K on x = 0.02. No thermal expansion (alpha = 0 on both
sides, "the same alpha": a temperature linear in x would otherwise bend the free faces, a
quadratic displacement Q1 does not hold).
The state: uniaxial stress sigma_xx = -P, the same in both halves (in series), so the contact
pressure is P and the gap conductance h = h0 L / (L + 0) + h_p P (h0 = 1e3 W/(m^2 K), h_p =
1e-4 W/(m^2 K Pa): h_p P about 5e3); the steady temperature is linear in each half, with the flux
q = (400 - 300) / (L_a/k_a + 1/h + L_b/k_b) through the gap (jump q/h), L_a = L_b = 0.02 m.
- two-materials: aluminium (E 70 GPa, nu 0.33, k 240) and steel (E 200 GPa, nu 0.30, k 50),
  constant (the constant-model path of the kernel, one model per side): P = 2e-5 / (L_a/E_a +
  L_b/E_b) = 5.185e7 Pa; a kernel that took one material's E for both sides would see
  p = (1 + E_a/E_b) P / 2 (or its mirror), h off by a fifth.
- E-of-T: steel with E(T) a table (210 GPa at 300 K, 150 GPa at 400 K) and nu = 0 (the bar is
  then one-dimensional, and the equilibrium of each cell makes the quadrature mean of
  E(T) eps_xx exactly -P, P not in closed form: the run's contact pressure, checked against
  every cell's sigma_xx); its side's p is the model's stress at each point's T.
Checked: the temperature at every node (each cell's nodes by its half's line) and the
gap_heat_flux at the gap's nodes (q) to 1e-9, the stress (sigma_xx = -P, the rest 0) and the
contact pressure (P) to 1e-9 P.
"""
import os
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
from kiln_deck import (box_mesh, constant, displacement, normal_displacement,  # noqa: E402
                       read_step, run_kiln, temperature, write_deck)

SHORTENING = 2.0e-5
H0, WIDTH, HP = 1.0e3, 1.0e-5, 1.0e-4
T_A, T_B = 400.0, 300.0
HALF = 0.02
CASES = {  # block 1, block 2: name, E (a number or a table), nu, k
    "two-materials": [("aluminium", 70e9, 0.33, 240.0), ("steel", 200e9, 0.30, 50.0)],
    "E-of-T": [("aluminium", 70e9, 0.33, 240.0), ("steel", ((300.0, 400.0), (2.1e11, 1.5e11)),
                                                  0.0, 50.0)],
}


def youngs_modulus(E):
    if isinstance(E, float):
        return E
    (T1, T2), (E1, E2) = E
    return {"Type": "Table", "Temperatures": [T1, T2], "Values": [E1, E2]}


def deck(base, case):
    materials = {name: {"Blocks": [block], "Young's Modulus": youngs_modulus(E),
                        "Poisson's Ratio": nu, "Thermal Expansion": 0.0,
                        "Reference Temperature": 300.0, "Conductivity": k}
                 for block, (name, E, nu, k) in enumerate(CASES[case], start=1)}
    return {
        "Physics": "Thermo-Elasticity",
        "Mesh": box_mesh((0.04, 0.04, 0.04), (4, 2, 2), 10),
        "Materials": materials,
        "Thermal": {"Initial Temperature": 350.0, "Gap Conductance": H0,
                    "Gap Conductance Model": "Contact Dependent", "Gap Width Scale": WIDTH,
                    "Gap Pressure Coefficient": HP,
                    "Boundary Conditions": {"hot": temperature([1], T_A),
                                            "cold": temperature([2], T_B)}},
        "Mechanics": {"Boundary Conditions": {
            "wall": displacement([1], ["x"]), "rollers": normal_displacement([3, 5]),
            "pressed": displacement([2], ["x"], constant(-SHORTENING))}},
        "Time Stepping": {"Method": "Steady"},
        "Solver": {"Relative Tolerance": 1e-13},
        "Output": {"File Base": base},
    }


def main():
    kiln, mpiexec, n_ranks, case = sys.argv[1:5]
    with tempfile.TemporaryDirectory() as folder:
        base = os.path.join(folder, case)
        state = read_step(run_kiln(kiln, write_deck(base, deck(base, case)), n_ranks,
                                   mpiexec).results)
    x, connectivity, block = state["x"], state["cells"], state["block"]
    T, stress = state["temperature"], state["stress"]
    flux, pressure = state["gap_heat_flux"], state["contact_pressure"]
    k_a, k_b = CASES[case][0][3], CASES[case][1][3]
    pressure = pressure[~np.isnan(pressure)]
    if case == "two-materials":
        E_a, E_b = CASES[case][0][1], CASES[case][1][1]
        P = SHORTENING / (HALF / E_a + HALF / E_b)
    else:
        P = pressure.mean()
    h = H0 + HP * P
    q = (T_A - T_B) / (HALF / k_a + 1.0 / h + HALF / k_b)
    T_exact = np.full(len(x), np.nan)
    for c, nodes in enumerate(connectivity):
        nodes = nodes[nodes >= 0]
        s = x[nodes, 0]
        T_exact[nodes] = T_A - q * (s + HALF) / k_a if block[c] == 1 else T_B + q * (HALF - s) / k_b
    T_error = np.abs(T - T_exact).max() / (T_A - T_B)
    on_gap = ~np.isnan(flux)
    flux_error = np.abs(flux[on_gap] - q).max() / q
    wanted = np.zeros_like(stress)
    wanted[:, 0] = -P
    s_error = max(np.abs(stress - wanted).max(), np.abs(pressure - P).max()) / P
    print(f"{case}, np {n_ranks}: P = {P:.10g} Pa, h = {h:.6g} W/(m^2 K), q = {q:.10g} W/m^2, gap jump "
          f"{q / h:.8g} K; temperature error {T_error:.3g} (of the 100 K range), gap heat flux "
          f"error {flux_error:.3g} ({on_gap.sum()} gap nodes), stress error {s_error:.3g} (of P)")
    return 0 if on_gap.sum() > 0 and max(T_error, flux_error, s_error) <= 1e-9 else 1


sys.exit(main())
