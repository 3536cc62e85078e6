"""Check of inputs/truchas/stretch-nz.xml: Truchas' sm-stretch test-stretch-z.py, which runs
stretch-z.inp (the moved face displaced along z by Displacement components) and
stretch-nz.inp (by displacement-n) and requires the same displacement from both, to 0.0. In
Kiln (this deck and its companion inputs/truchas/stretch-z.xml) they agree to round-off:
truchas_fields.stretch_pair_figures says why not to 0.0.
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import truchas_fields as tf  # noqa: E402

TEST = "sm-stretch/test-stretch-z"
CHANGES = []
COMPANIONS = ["stretch-z"]


def figures(results, deck, companions):
    return tf.stretch_pair_figures(results, companions["stretch-z"], "z",
                                   "test-stretch-z.py")
