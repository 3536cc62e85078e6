"""Check of inputs/truchas/stretch-nx.xml: Truchas' sm-stretch test-stretch-x.py, which runs
stretch-x.inp (the moved face displaced along x by Displacement components) and
stretch-nx.inp (by displacement-n) and requires the same displacement from both, to 0.0. In
Kiln (this deck and its companion inputs/truchas/stretch-x.xml) they agree to round-off:
truchas_fields.stretch_pair_figures says why not to 0.0.
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import truchas_fields as tf  # noqa: E402

TEST = "sm-stretch/test-stretch-x"
CHANGES = []
COMPANIONS = ["stretch-x"]


def figures(results, deck, companions):
    return tf.stretch_pair_figures(results, companions["stretch-x"], "x",
                                   "test-stretch-x.py")
