"""Check of inputs/truchas/stretch-ny.xml: Truchas' sm-stretch test-stretch-y.py, which runs
stretch-y.inp (the moved face displaced along y by Displacement components) and
stretch-ny.inp (by displacement-n) and requires the same displacement from both, to 0.0. In
Kiln (this deck and its companion inputs/truchas/stretch-y.xml) they agree to round-off:
truchas_fields.stretch_pair_figures says why not to 0.0.
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import truchas_fields as tf  # noqa: E402

TEST = "sm-stretch/test-stretch-y"
CHANGES = []
COMPANIONS = ["stretch-y"]


def figures(results, deck, companions):
    return tf.stretch_pair_figures(results, companions["stretch-y"], "y",
                                   "test-stretch-y.py")
