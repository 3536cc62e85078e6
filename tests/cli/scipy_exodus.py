#!/usr/bin/env python3
"""Writes a 2 x 1 x 1 HEX8 Exodus II mesh of two 1 m cells (side sets 1 and 2 on x = 0 and
x = 2) with tests/support/exodus_mesh.py (scipy.io.netcdf), storing "coordx" as netCDF
variable 0 (the case the Exodus library misreads as all zeros).

usage: scipy_exodus.py OUT.exo [--duplicate-face | --flat | --unmerged]
--duplicate-face: side set 1 lists its face twice.
--flat: every y is 0 (a mesh with no extent in y).
--unmerged: the two cells touch at x = 1 without sharing nodes (two bodies whose coincident
nodes are not merged), and side set 10 is cell 1's face at x = 1."""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "support"))
import exodus_mesh  # noqa: E402  (tests/support/exodus_mesh.py)

out = sys.argv[1]
duplicate = "--duplicate-face" in sys.argv[2:]
flat = "--flat" in sys.argv[2:]
unmerged = "--unmerged" in sys.argv[2:]
nodes = []
index = {}


def node(p, body):
    key = (p, body if unmerged else 0)
    if key not in index:
        nodes.append(p)
        index[key] = len(nodes)
    return index[key]


def hexa(x0):
    x1 = x0 + 1.0
    corners = [(x0, 0, 0), (x1, 0, 0), (x1, 1, 0), (x0, 1, 0),
               (x0, 0, 1), (x1, 0, 1), (x1, 1, 1), (x0, 1, 1)]
    return [node((float(a), float(b), float(c)), x0) for a, b, c in corners]


connect = [hexa(0.0), hexa(1.0)]
side_sets = [(1, [1, 1] if duplicate else [1], [4, 4] if duplicate else [4]), (2, [2], [2])]
if unmerged:
    side_sets.append((10, [1], [2]))

exodus_mesh.write(out, [(p[0], 0.0 if flat else p[1], p[2]) for p in nodes],
                  [(1, "HEX8", connect)], side_sets, title="scipy mesh", coordinates_first=True)
