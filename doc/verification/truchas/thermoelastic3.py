"""Check of inputs/truchas/thermoelastic3.xml: Truchas' sm-thermoelastic/thermoelastic3.inp.

thermoelastic2 on 4 x 4 x 4 cells (Truchas' and Kiln's alike): the unit cube rotated by 45
degrees about z at T = 2 K, on a roller on face 1, free expansion. The exact solution, the
Minimum Norm displacement Kiln gives and the tolerance (relative 1e-10, round-off; measured
9e-15) are thermoelastic2's (see thermoelastic2.py); this deck checks them on a mesh with
interior nodes and on 2 ranks with shared nodes.
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import thermoelastic2  # noqa: E402
import truchas_fields as tf  # noqa: E402

TEST = "sm-thermoelastic/thermoelastic3"
CHANGES = []


def figures(results, deck):
    return tf.free_expansion_figures(results, thermoelastic2.FACE_1_NORMAL, (0.0, 0.0, 0.0),
                                     thermoelastic2.BETA, thermoelastic2.TOLERANCE,
                                     "thermoelastic3")
