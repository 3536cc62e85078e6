"""inputs/contact-box-crossing3.xml (held on six faces, three gaps) at 150 s: the hydrostatic
state sigma = -3 K alpha dT = -4.576e7 Pa, no shear, a contact pressure of 4.576e7 Pa at
every gap node, u = 0, to the temperature's floor (1e-6).
"""
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "truchas"))
import truchas_fields as tf  # noqa: E402

SIGMA = 2.08e11 * 2.2e-5 * 10.0  # (3 lambda + 2G) alpha dT [Pa], dT = 10 K
FLOOR = 1e-6  # the temperature at 150 s is 1.2e-6 K from 308 K (BDF2's last steps)

TEST = "contact box, three gaps, held on six faces"
CHANGES = []


def figures(results, deck):
    step = tf.kiln_steps(results)[-1]
    import h5py
    with h5py.File(results, "r") as h5:
        last = h5["steps"][sorted(h5["steps"].keys())[-1]]
        p = last["contact_pressure"][...]
    p = p[~np.isnan(p)]
    diagonal = float(np.abs(step.stress[:, :3] / -SIGMA - 1).max())
    shear = float(np.abs(step.stress[:, 3:]).max() / SIGMA)
    dp = float(np.abs(p / SIGMA - 1).max())
    u = float(np.abs(step.u).max() / (2.2e-5 * 10.0 * 0.02))
    at_end = step.time == 150.0
    return [
        tf.figure("max |sigma_ii / -4.576e7 Pa - 1|, t = 150 s", diagonal, f"<= {FLOOR:g}",
                  diagonal <= FLOOR and at_end, exact=0.0),
        tf.figure("max |sigma_ij| / 4.576e7 Pa, i != j", shear, f"<= {FLOOR:g}",
                  shear <= FLOOR, exact=0.0),
        tf.figure("max |contact_pressure / 4.576e7 Pa - 1|", dp, f"<= {FLOOR:g}", dp <= FLOOR,
                  exact=0.0),
        tf.figure("max |u| / (alpha dT L/2)", u, f"<= {FLOOR:g}", u <= FLOOR, exact=0.0),
    ]
