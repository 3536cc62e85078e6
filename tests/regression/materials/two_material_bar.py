#!/usr/bin/env python3
"""Runs tests/regression/materials/two-material-bar.xml and checks the two blocks' materials:
u_x(1) = sigma (1/(lambda1 + 2 G1) + 1/(lambda2 + 2 G2)) = 1e-3 + 1/600 m at every node of
x = 1, and sigma_xx = 4e6 Pa in every cell, both to 1e-9 relative.
usage: two_material_bar.py KILN DECK WORKDIR NP MPIEXEC"""
import os
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np

kiln, deck, work, np_, mpiexec = sys.argv[1:6]
work = Path(work)
work.mkdir(parents=True, exist_ok=True)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
subprocess.run([mpiexec, "-np", np_, kiln, deck], cwd=work, env=env, check=True)
with h5py.File(work / "results" / "two-material-bar.h5", "r") as h5:
    x = h5["mesh/coordinates"][...]
    step = h5["steps"][sorted(h5["steps"].keys())[-1]]
    u = step["displacement"][...]
    stress = step["stress"][...]
end = np.isclose(x[:, 0], 1.0)
expected = 1e-3 + 1.0 / 600.0
u_error = float(np.abs(u[end, 0] / expected - 1).max())
s_error = float(np.abs(stress[:, 0] / 4e6 - 1).max())
print(f"u_x(1): relative error {u_error:.3g}; sigma_xx: relative error {s_error:.3g}")
sys.exit(0 if u_error < 1e-9 and s_error < 1e-9 and end.sum() == 4 else 1)
