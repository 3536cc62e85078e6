"""inputs/contact-box-crossing.xml (gaps at x = 0 and z = 0) at 150 s: with both gaps closed
the box is the uncut one, and its temperature does not depend on z, so every node's
displacement and every cell's stress equal the one-gap box's (contact-box-close, the
companion) to 1e-9 of the largest: 8.9e-16 and 2.8e-15 measured; and the spec's closed state
to the temperature's floor.
"""
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "truchas"))
import truchas_fields as tf  # noqa: E402

SIGMA = 2.08e11 * 2.2e-5 * 10.0  # (3 lambda + 2G) alpha dT [Pa], dT = 10 K
FLOOR = 1e-6  # the temperature at 150 s is 1.2e-6 K from 308 K (BDF2's last steps)

import importlib.util  # noqa: E402

TEST = "contact box, gaps at x = 0 and z = 0"
CHANGES = []
COMPANIONS = ["contact-box-close"]

_spec = importlib.util.spec_from_file_location("one_gap", Path(__file__).resolve().parent /
                                               "contact-box-close.py")
one_gap = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(one_gap)


def figures(results, deck, companions):
    two = tf.kiln_steps(results)[-1]
    one = tf.kiln_steps(companions["contact-box-close"])[-1]
    index = tf.match(one.x, two.x)
    du = float(np.abs(two.u - one.u[index]).max() / np.abs(one.u).max())
    ds = float(np.abs(two.stress - one.stress).max() / np.abs(one.stress).max())
    return [
        tf.figure("max |u - u(one gap)| / max |u|, t = 150 s", du, "<= 1e-9", du <= 1e-9,
                  exact=0.0),
        tf.figure("max |sigma - sigma(one gap)| / max |sigma|", ds, "<= 1e-9", ds <= 1e-9,
                  exact=0.0),
    ] + one_gap.closed_state(results, "two gaps")
