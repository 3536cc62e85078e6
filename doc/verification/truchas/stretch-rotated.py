"""Check of inputs/truchas/stretch-rotated.xml: Truchas' sm-stretch test-stretch-rotated.py.

The stretch-nx bar turned by Phi = 45 about y and Theta = 45 about x (Kiln's box rotation,
R = Rx(Theta) Ry(Phi), about the box's centre before its translation) gives, rotated back,
the displacement of the unrotated bar (stretch-nx, the companion) at every node: to 1e-9 m
in Truchas' test; Kiln's is round-off.
"""
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import truchas_fields as tf  # noqa: E402

TEST = "sm-stretch/test-stretch-rotated"
CHANGES = []
COMPANIONS = ["stretch-nx"]
TOLERANCE = 1e-9  # test-stretch-rotated.py: compare_max(displ0, displ, 1e-9)


def rotation(phi, theta):
    p, t = np.radians(phi), np.radians(theta)
    cp, sp, ct, st = np.cos(p), np.sin(p), np.cos(t), np.sin(t)
    return np.array([[cp, 0.0, sp], [st * sp, ct, -st * cp], [-ct * sp, st, ct * cp]])


def figures(results, deck, companions):
    turned = tf.kiln_steps(results)[-1]
    plain = tf.kiln_steps(companions["stretch-nx"])[-1]
    R = rotation(45.0, 45.0)
    centre = np.array([0.5, 0.5, 0.5])
    # The turned bar's nodes taken back to the plain bar's frame: x = R^T (y - c) + c.
    back = (turned.x - centre) @ R + centre
    index = tf.match(plain.x, back)
    difference = float(np.abs(turned.u @ R - plain.u[index]).max())
    return [tf.figure("max |R^T u_turned - u| [m], t = 1 s", difference,
                      f"<= {TOLERANCE:g} (test-stretch-rotated.py)",
                      difference <= TOLERANCE and turned.time == 1.0, exact=0.0)]
