"""Check of inputs/truchas/stretch-y.xml, the companion of stretch-ny.xml in Truchas'
test-stretch-y.py (compared there, doc/verification/truchas/stretch-ny.py). Its own
figures: the clamped face does not move and the moved face moves by 1 m along y, exactly
(the conditions), and the bar lengthens by 1 m.
"""
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import truchas_fields as tf  # noqa: E402

TEST = "sm-stretch/test-stretch-y"
CHANGES = []


def figures(results, deck):
    step = tf.kiln_steps(results)[-1]
    held = np.isclose(step.x[:, 1], 0.0)
    moved = np.isclose(step.x[:, 1], 1.0)
    clamp = float(np.abs(step.u[held]).max())
    face = float(np.abs(step.u[moved, 1] - 1.0).max())
    return [
        tf.figure("max |u| on the clamped face [m], t = 1 s", clamp, "0 (the condition)",
                  clamp == 0.0 and step.time == 1.0, exact=0.0),
        tf.figure("max |u_y - 1| on the moved face [m]", face, "0 (the condition)",
                  face == 0.0, exact=0.0),
    ]
