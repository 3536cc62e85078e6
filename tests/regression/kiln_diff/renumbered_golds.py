"""Checks that two golds of the same problem on differently numbered meshes agree.

usage: renumbered_golds.py KILN_DIFF A.h5 B.h5 [NAME:ABS:REL ...]

Fails if the two files number their nodes or cells the same way (the test would
then not show that kiln-diff matches by coordinates), or if kiln-diff does not
find them equal within the tolerances.
"""

import subprocess
import sys

import h5py
import numpy as np


def main(kiln_diff, a, b, tolerances):
    with h5py.File(a, "r") as fa, h5py.File(b, "r") as fb:
        xa, xb = fa["/mesh/coordinates"][...], fb["/mesh/coordinates"][...]
        ca, cb = fa["/mesh/connectivity"][...], fb["/mesh/connectivity"][...]
        twins = len(xa) - len(np.unique(xa, axis=0))
    if xa.shape == xb.shape and np.allclose(xa, xb, rtol=0, atol=1e-9):
        sys.exit("renumbered_golds.py: the two meshes number their nodes alike")
    if ca.shape == cb.shape and np.array_equal(ca, cb):
        sys.exit("renumbered_golds.py: the two meshes number their cells alike")
    if twins == 0:
        sys.exit("renumbered_golds.py: the mesh has no twin nodes")
    print(f"the meshes are numbered differently; {twins} twin nodes")
    options = ["--field=" + t for t in tolerances]
    return subprocess.call([sys.executable, kiln_diff, *options, a, b])


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]))
