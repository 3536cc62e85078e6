"""Check of inputs/truchas/stretch-contact.xml: Truchas' sm-stretch test-stretch-contact.py,
its stretching part: the halves of the split cube part, each a rigid body with its face; no
strain (to 1e-10), u_y = u_z = 0 (to 1e-10 m), and 275 nodes with u_x = 0 and 275 with u_x = 1
(to 1e-10 m): the 5 x 5 x 11 nodes of each half.
"""
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import truchas_fields as tf  # noqa: E402

TEST = "sm-stretch/test-stretch-contact"
CHANGES = []


def figures(results, deck):
    step = tf.kiln_steps(results)[-1]
    strain = float(np.abs(step.strain).max())
    uyz = float(np.abs(step.u[:, 1:]).max())
    at_0 = int(np.count_nonzero(np.abs(step.u[:, 0]) < 1e-10))
    at_1 = int(np.count_nonzero(np.abs(step.u[:, 0] - 1.0) < 1e-10))
    return [
        tf.figure("max |eps|", strain, "<= 1e-10 (test-stretch-contact.py)", strain <= 1e-10,
                  exact=0.0),
        tf.figure("max |u_y|, |u_z| [m]", uyz, "<= 1e-10 (test-stretch-contact.py)",
                  uyz <= 1e-10, exact=0.0),
        tf.figure("nodes with u_x = 0", at_0, "275 (test-stretch-contact.py)", at_0 == 275,
                  exact=275.0),
        tf.figure("nodes with u_x = 1 m", at_1, "275 (test-stretch-contact.py)", at_1 == 275,
                  exact=275.0),
    ]
