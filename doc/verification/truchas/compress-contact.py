"""Check of inputs/truchas/compress-contact.xml: Truchas' sm-stretch test-stretch-contact.py,
its compression part. It compares u_x of compress-contact (the cube split at x = 0 with
contact, pressed together) with compress-x (the cube without a gap, the companion deck) at
every node, to 1e-10 m, and eps_xx cell by cell, to a relative 1e-8. With the gap closed,
Kiln's split cube is the uncut one: 1.4e-18 m and 3.3e-14.
"""
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import truchas_fields as tf  # noqa: E402

TEST = "sm-stretch/test-stretch-contact"
CHANGES = []
COMPANIONS = ["compress-x"]


def figures(results, deck, companions):
    split = tf.kiln_steps(results)[-1]
    whole = tf.kiln_steps(companions["compress-x"])[-1]
    nodes = tf.match(whole.x, split.x)
    cells = tf.match(whole.centroids, split.centroids)
    du = float(np.abs(split.u[:, 0] - whole.u[nodes, 0]).max())
    de = float(np.abs(split.strain[:, 0] / whole.strain[cells, 0] - 1.0).max())
    return [
        tf.figure("max |u_x - u_x(compress-x)| [m]", du, "<= 1e-10 (test-stretch-contact.py)",
                  du <= 1e-10, exact=0.0),
        tf.figure("max |eps_xx / eps_xx(compress-x) - 1|", de,
                  "<= 1e-8 (test-stretch-contact.py)", de <= 1e-8, exact=0.0),
    ]
