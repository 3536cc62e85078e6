#!/usr/bin/env python3
"""Runs the two-material slabs of tests/regression/materials/ (doc/heat.md, "Conservative
capacity"; doc/materials.md, "Materials and blocks"):
- two-material-slab.xml, steady: T at every node against the piecewise-linear exact
  temperature (T(0) = 300 + 100/3 K at the shared nodes), to 1e-9 K;
- two-material-slab-energy.xml, transient with rho(T), c(T) and k(T) on two blocks, as given
  (BDF2, lumped capacity) and with backward Euler and the consistent capacity: at every step
  the change of the time history's thermal_energy (the integral of H(T) = ∫ rho c dT) against
  the heat in, q A t = 10 W * t, to 2e-9 of the 200 J that come in; and the rise is at least
  20 K, so that rho c(T) varies;
- the same (BDF2, lumped) stopped at 10 s with a checkpoint and restarted: the results agree
  with the run that never stopped bit for bit (kiln-diff --rel 0: the past temperatures of
  the enthalpy come back with the checkpoint's x_n, x_{n-1}).
usage: two_material_slab.py KILN STEADY_DECK ENERGY_DECK WORKDIR NP MPIEXEC KILN_DIFF"""
import subprocess
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)

kiln, steady_deck, energy_deck, work, np_, mpiexec, kiln_diff = sys.argv[1:8]
work = Path(work)
work.mkdir(parents=True, exist_ok=True)
failures = []


def run(deck, *args):
    return kd.run_kiln(kiln, deck, np_, mpiexec, args, cwd=work)


# Steady: piecewise linear, k = 100 on x < 0, 50 on x > 0.
state = kd.read_step(run(steady_deck).results)
x, T = state["x"], state["temperature"].reshape(-1)
T_interface = 300.0 + 100.0 / 3.0
exact = np.where(x[:, 0] <= 0.0, T_interface + (T_interface - 300.0) * x[:, 0],
                 T_interface + (400.0 - T_interface) * x[:, 0])
error = float(np.abs(T - exact).max())
at_interface = np.isclose(x[:, 0], 0.0)
print(f"steady slab: max |T - T_exact| = {error:.3g} K; T at x = 0: "
      f"{T[at_interface].min():.12f} .. {T[at_interface].max():.12f} K")
if error > 1e-9 or at_interface.sum() != 9:
    failures.append("steady slab")

# Transient: the energy balance, in three variants.
text = Path(energy_deck).read_text()
variants = {
    "bdf2-lumped": text,
    "euler-consistent": text.replace('value="BDF2"', 'value="Backward Euler"').replace(
        'value="Lumped"', 'value="Consistent"'),
    "bdf2-consistent": text.replace('value="Lumped"', 'value="Consistent"'),
}
heat_rate = 1e5 * 1e-4  # q A [W]
for name, deck_text in variants.items():
    deck = work / f"slab-energy-{name}.xml"
    deck.write_text(deck_text)
    run(deck)
    history = np.genfromtxt(work / "results" / f"slab-energy-{name}.history.csv", delimiter=",",
                            names=True)
    t = history["time_s"]
    E = history["thermal_energy_J"]
    imbalance = float(np.abs((E - E[0]) - heat_rate * t).max()) / (heat_rate * t[-1])
    rise = float(history["T_mean_K"][-1] - history["T_mean_K"][0])
    print(f"{name}: {len(t) - 1} steps to t = {t[-1]} s; max |ΔE - q A t| / (q A t_end) = "
          f"{imbalance:.3g}; mean T rose by {rise:.2f} K")
    # The balance holds to Newton's tolerance (Relative Tolerance 1e-8 of each step's |F|):
    # 1e-10 to 4e-10 when Newton started each step at x_n, up to 1.3e-9 (euler-consistent)
    # from the Extrapolated Newton Start (default since 2026-11-29), which stops one Newton
    # iteration earlier, just inside the tolerance.
    if abs(t[-1] - 20.0) > 1e-9 or imbalance > 2e-9 or rise < 20.0:
        failures.append(name)

# Restart at 10 s: bit for bit the run that never stopped.
for name, times in (("full", "{10, 20}"), ("restarted", "{10, 20}"), ("part1", "{10}")):
    base = "restarted" if name == "part1" else name
    (work / f"slab-{name}.xml").write_text(text.replace(
        'value="{20}"/>', f'value="{times}"/><Parameter name="File Base" type="string" '
        f'value="results/slab-{base}"/>'))
run(work / "slab-full.xml")
run(work / "slab-part1.xml")
run(work / "slab-restarted.xml", "--restart", "results/slab-restarted.checkpoint.h5")
same = subprocess.run([kiln_diff, "--abs", "0", "--rel", "0", "results/slab-full.h5",
                       "results/slab-restarted.h5"], cwd=work, capture_output=True, text=True)
print("restart at 10 s: " + same.stdout.strip().splitlines()[-1])
if same.returncode != 0:
    failures.append("restart")
print("failed: " + ", ".join(failures) if failures else "passed")
sys.exit(1 if failures else 0)
