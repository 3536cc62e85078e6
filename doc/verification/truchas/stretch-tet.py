"""Check of inputs/truchas/stretch-tet.xml: Truchas' sm-stretch test-stretch-tet.py.

test-stretch-tet.py compares the displacement of Series 1 (t = 0) with the golden output to
1e-10 m (max abs), on brick-tet.gen (5320 tetrahedra, 1166 nodes). Kiln (P1 tetrahedra) is
within 4.8e-11 m of the golden (Truchas' node-centred finite volumes on the same mesh), the
largest difference on the moved face's edges. Beside the golden, the same stretch on Truchas'
hex mesh (stretch-hex's golden, interpolated) and the two conditions: see
truchas_fields.stretch_mesh_figures.
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import truchas_fields as tf  # noqa: E402

TEST = "sm-stretch/test-stretch-tet"
CHANGES = []
GOLDEN = "../shared/truchas-tests/sm-stretch/stretch-tet_golden/stretch-tet.h5"


def figures(results, deck):
    return tf.stretch_mesh_figures(results, Path(__file__).resolve().parents[3],
                                   "test-stretch-tet.py", golden=GOLDEN)
