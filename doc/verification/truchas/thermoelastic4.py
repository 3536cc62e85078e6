"""Check of inputs/truchas/thermoelastic4.xml: Truchas' sm-thermoelastic/thermoelastic4.inp.

Truchas ships no test*.py nor golden output for thermoelastic0..4, and the header comment of
all five ("Applies a linear temperature gradient along the x-direction ...") is copied from
thermoelastic0: thermoelastic4 has no gradient. Its input poses a unit cube rotated by 45
degrees about z (4 x 4 x 4 cells) at a uniform T = 2 K with T_ref = 1 K, alpha = 1/K,
lambda = 2e10 Pa, G = 1e10 Pa, insulated, with every face on a roller (displacement-n 0).
The exact solution: T = 2 K for all time, u = 0, eps = 0, and
sigma = -(3 lambda + 2 G) alpha (T - T_ref) I = -8e10 Pa I, in any frame.

Kiln's fields (nodal T, cell-average strain and stress) are checked against it at both
output times (t = 0: the initial equilibrium; t = 1 s) to round-off: the state is uniform, so
the Q1 space holds it exactly and the only error is the solve's. Relative 1e-10 (of 1 m for
u, 1 for eps, 8e10 Pa for sigma) leaves room for the direct solve of the scaled system on a
condition number of ~1e3 while failing any real error (a wrong beta, a roller missing on one
face would give errors of order 1). Truchas' cell temperature and Kiln's nodal one are the
same here (uniform T).
"""
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import truchas_fields as tf  # noqa: E402

TEST = "sm-thermoelastic/thermoelastic4"
CHANGES = []
TOLERANCE = 1e-10
BETA = 3 * 2e10 + 2 * 1e10  # (3 lambda + 2 G) alpha, alpha = 1/K


def figures(results, deck):
    steps = tf.kiln_steps(results)
    stress = [-BETA, -BETA, -BETA, 0, 0, 0]
    return tf.uniform_state_figures(steps, 2.0, [0] * 6, stress, BETA,
                                    lambda x: np.zeros_like(x),
                                    TOLERANCE, "thermoelastic4")
