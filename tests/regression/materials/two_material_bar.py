#!/usr/bin/env python3
"""Runs tests/regression/materials/two-material-bar.xml and checks the two blocks' materials:
u_x(1) = sigma (1/(lambda1 + 2 G1) + 1/(lambda2 + 2 G2)) = 1e-3 + 1/600 m at every node of
x = 1, and sigma_xx = 4e6 Pa in every cell, both to 1e-9 relative.
usage: two_material_bar.py KILN DECK WORKDIR NP MPIEXEC"""
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)

kiln, deck, work, np_, mpiexec = sys.argv[1:6]
work = Path(work)
work.mkdir(parents=True, exist_ok=True)
state = kd.read_step(kd.run_kiln(kiln, deck, np_, mpiexec, cwd=work).results)
x, u, stress = state["x"], state["displacement"], state["stress"]
end = np.isclose(x[:, 0], 1.0)
expected = 1e-3 + 1.0 / 600.0
u_error = float(np.abs(u[end, 0] / expected - 1).max())
s_error = float(np.abs(stress[:, 0] / 4e6 - 1).max())
print(f"u_x(1): relative error {u_error:.3g}; sigma_xx: relative error {s_error:.3g}")
sys.exit(0 if u_error < 1e-9 and s_error < 1e-9 and end.sum() == 4 else 1)
