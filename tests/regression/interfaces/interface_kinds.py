#!/usr/bin/env python3
"""The interface kinds (Mechanics/Contact/"Kind") in whole runs, against exact answers.

Usage: interface_kinds.py KILN WORK_DIR NP MPIEXEC

The box 0.04 m cube, 4 x 4 x 4 cells, rotated (phi 45, theta -30), cut at its middle plane
(side set 10, normal along the box's x), elastic (E-like aluminium).
1. "Bonded", face 1 (x-) clamped, face 2 (x+) pulled and sheared by a traction with all three
   components: the displacement at every node equals that of the uncut box (Gap Side Set 0)
   at the same position, to 1e-9 of the largest displacement (each copy of a gap node
   included): a tied gap is no gap. "Sliding" with the same conditions leaves the x+ half free
   to slide in the gap's plane and turn about its normal: refused at set-up, naming them.
2. "Sliding" and "Bonded", rollers on faces 1, 3, 5 and a tension of 1e6 Pa on face 2: the
   uniaxial state sigma_xx' = 1e6 Pa, exact for Q1; the gap carries it as a tension:
   contact_pressure = -1e6 Pa at every gap node and gap_opening 0 (to 1e-9 of the largest
   displacement). "Contact" under that load lets the gap open, which leaves the x+ half free:
   the run must stop with that error (exit 2), not give an answer.
"""
import os
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)

TRACTION = 1.0e6


def deck(base, gap, kind, conditions):
    mechanics = {"Boundary Conditions": conditions}
    if gap != 0:
        mechanics["Contact"] = {"Kind": kind}
    return {"Physics": "Elasticity",
            "Mesh": kd.box_mesh((0.04, 0.04, 0.04), (4, 4, 4), gap, phi=45, theta=-30),
            "Material": kd.lame(5.2e10, 2.6e10),
            "Mechanics": mechanics,
            "Solver": {"Absolute Tolerance": 1e-11},
            "Output": {"File Base": base, "Times": [0.0, 1.0]}}


CLAMPED_AND_SHEARED = {"clamped": kd.displacement([1], "xyz"),
                       "pulled and sheared": kd.traction([2], (1e6, 4e5, -3e5))}

ROLLERS_AND_TENSION = {"rollers": kd.normal_displacement([1, 3, 5]),
                       "tension": kd.pressure([2], -TRACTION)}


def run(kiln, work, name, text, n_ranks, mpiexec, expect=0):
    """Runs the deck text(base) as WORK/NAME.xml; (its results file, its log)."""
    base = os.path.join(work, name)
    done = kd.run_kiln(kiln, kd.write_deck(base, text(base)), n_ranks, mpiexec, expect=expect)
    return done.results, done.log


def last_step(results):
    state = kd.read_step(results)
    return state["x"], state


def main():
    kiln, work, n_ranks, mpiexec = sys.argv[1:5]
    os.makedirs(work, exist_ok=True)
    check = kd.Checks()

    # 1. Bonded = uncut; Sliding leaves the x+ half free to slide: refused.
    runs = {}
    for name, gap, kind in [("uncut", 0, "Contact"), ("bonded", 10, "Bonded")]:
        base, _ = run(kiln, work, f"sheared-{name}",
                      lambda b, g=gap, k=kind: deck(b, g, k, CLAMPED_AND_SHEARED), n_ranks,
                      mpiexec)
        runs[name] = last_step(base)
    x0, f0 = runs["uncut"]
    by_position = {tuple(np.round(p, 12)): i for i, p in enumerate(x0)}
    scale = np.abs(f0["displacement"]).max()
    x, f = runs["bonded"]
    index = np.array([by_position[tuple(np.round(p, 12))] for p in x])
    check(len(x) == len(x0) + 25, f"the bonded box has the 25 gap nodes twice ({len(x)} nodes)")
    error = np.abs(f["displacement"] - f0["displacement"][index]).max() / scale
    check(error <= 1e-9, f"bonded gap = uncut box: max |u - u_uncut| / max |u| = {error:.3g}")
    _, out = run(kiln, work, "sheared-sliding",
                 lambda b: deck(b, 10, "Sliding", CLAMPED_AND_SHEARED), n_ranks, mpiexec,
                 expect=1)
    check("translation along" in out and "rotation about the axis" in out,
          "Sliding with only x- clamped: the x+ half is free to slide (two translations and "
          "the rotation about the normal), refused at set-up (exit 1)")

    # 2. Tension carried across a sliding and a bonded gap; contact opens.
    for kind in ("Sliding", "Bonded"):
        base, _ = run(kiln, work, f"tension-{kind.lower()}",
                      lambda b, k=kind: deck(b, 10, k, ROLLERS_AND_TENSION), n_ranks, mpiexec)
        x, f = last_step(base)
        u_scale = np.abs(f["displacement"]).max()
        on_gap = ~np.isnan(f["contact_pressure"])
        p = f["contact_pressure"][on_gap]
        g = f["gap_opening"][on_gap]
        check(on_gap.sum() == 50, f"{kind}: {on_gap.sum()} gap nodes (2 x 25)")
        p_error = np.abs(p + TRACTION).max() / TRACTION
        check(p_error <= 1e-9, f"{kind}: contact_pressure = -1e6 Pa to {p_error:.3g}")
        g_error = np.abs(g).max() / u_scale
        check(g_error <= 1e-9, f"{kind}: gap_opening 0 to {g_error:.3g} of max |u|")
        s = f["stress"]
        # sigma' in the box frame: only xx' = 1e6 Pa (von Mises = 1e6 Pa everywhere).
        if "von_mises_stress" in f:
            vm = f["von_mises_stress"]
            check(np.abs(vm - TRACTION).max() / TRACTION <= 1e-9,
                  f"{kind}: von Mises stress 1e6 Pa to {np.abs(vm - TRACTION).max() / TRACTION:.3g}")
        trace = s[:, 0] + s[:, 1] + s[:, 2]
        check(np.abs(trace - TRACTION).max() / TRACTION <= 1e-9,
              f"{kind}: trace of the stress 1e6 Pa to {np.abs(trace - TRACTION).max() / TRACTION:.3g}")
    _, out = run(kiln, work, "tension-contact",
                 lambda b: deck(b, 10, "Contact", ROLLERS_AND_TENSION), n_ranks, mpiexec, expect=2)
    # Caught where it shows first: the singular factorization of the Newton step, or the
    # accepted state's check of the open gap.
    check("rigid body" in out or "the gap is open where only contact held a body" in out,
          "Contact under tension: the open gap leaves the x+ half free (exit 2)")
    return 1 if check.failed else 0


if __name__ == "__main__":
    sys.exit(main())
