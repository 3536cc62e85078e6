"""Check of inputs/truchas/thermoelastic2.xml: Truchas' sm-thermoelastic/thermoelastic2.inp.

Truchas ships no test*.py nor golden output for thermoelastic0..4, and the header comment of
all five ("Applies a linear temperature gradient along the x-direction ...") is copied from
thermoelastic0: thermoelastic2 has no gradient. It poses the unit cube (one cell) rotated by 45
degrees about z, at a uniform T = 2 K (T_ref 1 K, alpha 1/K, lambda 2e10 Pa, G 1e10 Pa),
insulated, on a roller on face 1 (displacement-n 0; the plane through the origin with
normal -(cos 45, sin 45, 0)) and free elsewhere. The exact solution: T = 2 K for all time,
eps = alpha dT I = I, sigma = 0, u = x - q with q on face 1's plane, up to the rigid motions
the roller leaves free (translations in its plane, rotation about its normal). Truchas
solves that singular system as it comes; Kiln refuses it unless the deck sets
`Free Motions` = `Minimum Norm`, whose answer is u = x - q with q the nodes' centroid
projected onto face 1's plane (truchas_fields.free_expansion_figures).

Checked at t = 0 and 1 s (2 x 1 x 1 cells in Kiln) to relative 1e-10 (of 2 K, 1 for eps,
beta dT = 8e10 Pa for sigma, 1.06 m for u): round-off, as Q1 holds the linear displacement
exactly; measured 1e-14 and below. Any real error (a wrong beta, a roller on the wrong face
or along the wrong normal, a rigid motion left in u) is of order 1. Truchas' cell
temperature and Kiln's nodal one are the same here (uniform T).
"""
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import truchas_fields as tf  # noqa: E402

TEST = "sm-thermoelastic/thermoelastic2"
CHANGES = []
TOLERANCE = 1e-10
BETA = 3 * 2e10 + 2 * 1e10  # (3 lambda + 2 G) alpha, alpha = 1/K
FACE_1_NORMAL = (-math.sqrt(0.5), -math.sqrt(0.5), 0.0)  # outward, through the origin


def figures(results, deck):
    return tf.free_expansion_figures(results, FACE_1_NORMAL, (0.0, 0.0, 0.0), BETA, TOLERANCE,
                                     "thermoelastic2")
