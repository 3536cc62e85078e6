#!/usr/bin/env python3
"""Runs tests/regression/interfaces/ring-sliding-pressure.xml (the viscoplastic-ring mesh, a
Sliding curved gap cut by the rollers x = 0 and y = 0, the ring squeezed by 1e7 Pa at the
reference temperature) and checks it against the exact state (the plane-stress Lame solution,
exact in 3D with a sliding interface; doc/verification/truchas/viscoplastic-ring.py has the
formulas): interface pressure p = 2.920 MPa.

Bounds, from this coarse mesh (285 cells; its curved faces are chords of 15 degrees, so the
discretization error is that of the faceted geometry): the interface pressure to 2% of p at
every gap node (measured 1.27%), the same at the 16 gap nodes on the planes x = 0 and y = 0
(measured 1.26%),
whose area-weighted normal leans 7.5 degrees out of the roller's plane and is projected into
it (doc/contact.md, "Conditions at gap nodes": without it the roller would be refused or the
pressure there wrong); the cell stresses to 3% of q (measured 1.97%: cell averages against
the centroid value); no opening of the sliding gap (|g| <= 1e-12 of the largest displacement).
usage: ring_sliding.py KILN DECK MESH WORKDIR NP MPIEXEC"""
import importlib.util
import sys
from pathlib import Path

import h5py
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)

kiln, deck, mesh, work, n_ranks, mpiexec = sys.argv[1:7]
here = Path(__file__).resolve().parent
spec = importlib.util.spec_from_file_location(
    "ring", here.parents[2] / "doc" / "verification" / "truchas" / "viscoplastic-ring.py")
ring = importlib.util.module_from_spec(spec)
spec.loader.exec_module(ring)

work = Path(work)
work.mkdir(parents=True, exist_ok=True)
results = kd.run_kiln(kiln, deck, n_ranks, mpiexec, ["--mesh", mesh], cwd=work).results
Q = 1.0e7
p_exact = ring.interface_pressure(0.0, Q)
sigma_error, eps_error, p_error, step = ring.t0_errors(results, 0.0, Q)
plane_error, n_plane = ring.plane_nodes_error(results, "000000", p_exact)
with h5py.File(results, "r") as h5:
    g = h5["steps/000000/gap_opening"][...]
opening = float(np.nanmax(np.abs(g)) / np.abs(step.u).max())
print(f"exact p {p_exact:.6g} Pa; |p - exact| max {p_error:.4g} Pa ({p_error / p_exact:.3g}), at "
      f"the {n_plane} plane nodes {plane_error:.4g} Pa ({plane_error / p_exact:.3g}); "
      f"|sigma - exact| max {sigma_error:.4g} Pa ({sigma_error / Q:.3g} of q); "
      f"|eps - exact| max {eps_error:.3g}; max |g| / max |u| {opening:.3g}")
passed = (p_error <= 0.02 * p_exact and plane_error <= 0.02 * p_exact and n_plane == 16
          and sigma_error <= 0.03 * Q and opening <= 1e-12)
sys.exit(0 if passed else 1)
