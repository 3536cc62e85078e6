"""The one-gap closing box (inputs/contact-box-close.xml) at 150 s: the spec's closed state,
sigma'xx = sigma'zz = -2.288e7 Pa, sigma'yy = 0 (von Mises 2.288e7 Pa, trace -4.576e7 Pa), and
a contact pressure of 2.288e7 Pa at every gap node, to the temperature's floor (1e-6).
The companion of the crossing decks.
"""
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "truchas"))
import truchas_fields as tf  # noqa: E402

SIGMA = 2.08e11 * 2.2e-5 * 10.0  # (3 lambda + 2G) alpha dT [Pa], dT = 10 K
FLOOR = 1e-6  # the temperature at 150 s is 1.2e-6 K from 308 K (BDF2's last steps)

TEST = "contact box, one gap"
CHANGES = []


def last(results):
    import h5py
    with h5py.File(results, "r") as h5:
        step = h5["steps"][sorted(h5["steps"].keys())[-1]]
        return {k: step[k][...] for k in step.keys()}, float(step.attrs["time"])


def closed_state(results, name):
    f, time = last(results)
    vm = float(np.abs(f["von_mises_stress"] / (0.5 * SIGMA) - 1).max())
    s = f["stress"]
    trace = float(np.abs((s[:, 0] + s[:, 1] + s[:, 2]) / -SIGMA - 1).max())
    p = f["contact_pressure"][~np.isnan(f["contact_pressure"])]
    dp = float(np.abs(p / (0.5 * SIGMA) - 1).max())
    at_end = time == 150.0
    return [
        tf.figure(f"{name}: max |von Mises / 2.288e7 Pa - 1|, t = 150 s", vm,
                  f"<= {FLOOR:g} (the temperature's floor)", vm <= FLOOR and at_end, exact=0.0),
        tf.figure(f"{name}: max |trace / -4.576e7 Pa - 1|", trace, f"<= {FLOOR:g}",
                  trace <= FLOOR, exact=0.0),
        tf.figure(f"{name}: max |contact_pressure / 2.288e7 Pa - 1|", dp, f"<= {FLOOR:g}",
                  dp <= FLOOR, exact=0.0),
    ]


def figures(results, deck):
    return closed_state(results, "one gap")
