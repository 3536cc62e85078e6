"""Check of inputs/truchas/thermoelastic1.xml: Truchas' sm-thermoelastic/thermoelastic1.inp.

Truchas ships no test*.py nor golden output for thermoelastic0..4; the header comment of
thermoelastic1 ("Applies a linear temperature gradient along the x-direction ...") is copied
from thermoelastic0: thermoelastic1's temperature function (1 + x + y) is commented out and
its BODY sets a uniform T = 2 K. It poses the unit cube (one cell) at T = 2 K with
T_ref = 1 K, alpha = 1/K, lambda = G = 1 Pa, insulated, with no displacement condition at
all: free expansion. The exact solution: T = 2 K for all time, eps = alpha dT I = I,
sigma = 0, u = x - x0 up to a rigid motion. Truchas solves the singular system as it comes;
Kiln refuses a body left free unless the deck asks for `Free Motions` = `Minimum Norm`, which
picks u = x - c, c the nodes' centroid (truchas_fields.free_expansion_figures).

Checked at t = 0 and 1 s to relative 1e-10 (of 2 K, 1 for eps, beta dT = 5 Pa for sigma,
1 m for u): round-off, as Q1 holds the linear displacement exactly; any real error (a wrong
beta or alpha, a rigid motion left in u) is of order 1. Truchas' cell temperature and Kiln's
nodal one are the same here (uniform T).
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import truchas_fields as tf  # noqa: E402

TEST = "sm-thermoelastic/thermoelastic1"
CHANGES = []
TOLERANCE = 1e-10
BETA = 3 * 1.0 + 2 * 1.0  # (3 lambda + 2 G) alpha


def figures(results, deck):
    return tf.free_expansion_figures(results, None, None, BETA, TOLERANCE, "thermoelastic1")
