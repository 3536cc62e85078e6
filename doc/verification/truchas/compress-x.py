"""Check of inputs/truchas/compress-x.xml, the box without a gap that Truchas'
test-stretch-contact.py compares compress-contact with (there: inputs/truchas/
compress-contact.xml's module). Its own figures: u_x = -1e-4 (x + 0.5) m exactly (the rollers
and the end displacement give a uniform strain, which Q1 reproduces), and the free z
translation taken out ("Free Motions" = "Minimum Norm": the z displacements sum to zero).
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
    ux = float(np.abs(step.u[:, 0] + 1e-4 * (step.x[:, 0] + 0.5)).max())
    uz = float(abs(step.u[:, 2].mean()))
    return [
        tf.figure("max |u_x + 1e-4 (x + 0.5)| [m]", ux, "<= 1e-15 (round-off; exact for Q1)",
                  ux <= 1e-15, exact=0.0),
        tf.figure("mean u_z [m] (the free translation)", uz, "<= 1e-15 (Minimum Norm)",
                  uz <= 1e-15, exact=0.0),
    ]
