#!/usr/bin/env python3
"""Writes the mixed-type Exodus II meshes of the input-error tests (with
tests/support/exodus_mesh.py; run once, the files are committed beside this script):

  shell-block.exo    a HEX8 block (the unit cube, block 1) and a SHELL4 block (block 2: one
                     shell on the cube's x = 1 face): Kiln supports volume elements only.
  nonconforming.exo  the unit cube as a HEX8 (block 1) and the cube [1,2] x [0,1]^2 as six
                     TETRA4 (block 2, Kuhn's split along its main diagonal) on the same nodes:
                     the hex's face at x = 1 meets two tet faces, a non-conforming mesh.

  tets.exo           the cubes [0,1]^3 and [1,2] x [0,1]^2 as six TETRA4 each (Kuhn's split,
                     conforming), one block; side set 1 on x = 0 and side set 10 on the
                     first cube's tets' faces at x = 1, inside the body.

shell-block.exo and nonconforming.exo have side set 1 = the hex's x = 0 face (cell 1, Exodus
side 4).

usage: make_mixed_exodus.py FOLDER"""
import itertools
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
import exodus_mesh  # noqa: E402  (tests/support/exodus_mesh.py)


def cube(x0):
    x1 = x0 + 1.0
    return [(x0, 0, 0), (x1, 0, 0), (x1, 1, 0), (x0, 1, 0),
            (x0, 0, 1), (x1, 0, 1), (x1, 1, 1), (x0, 1, 1)]


def write(path, nodes, blocks, side_sets):
    """blocks: (id, Exodus type, connectivity 1-based); side_sets: (id, elems, sides)."""
    exodus_mesh.write(path, nodes, blocks, side_sets, title="kiln input-error mesh")


def main():
    folder = Path(sys.argv[1])
    nodes = cube(0.0) + [p for p in cube(1.0) if p[0] == 2.0]
    index = {p: i + 1 for i, p in enumerate(nodes)}
    hexa = [index[p] for p in cube(0.0)]
    x_minus = [(1, [1], [4])]
    write(folder / "shell-block.exo", nodes[:8],
          [(1, "HEX8", [hexa]), (2, "SHELL4", [[2, 3, 7, 6]])], x_minus)
    tets = kuhn_tets(1.0, index)
    write(folder / "nonconforming.exo", nodes, [(1, "HEX8", [hexa]), (2, "TETRA4", tets)],
          x_minus)
    nodes = cube(0.0) + [p for p in cube(1.0) if p[0] == 2.0]
    index = {p: i + 1 for i, p in enumerate(nodes)}
    tets = kuhn_tets(0.0, index) + kuhn_tets(1.0, index)
    write(folder / "tets.exo", nodes, [(1, "TETRA4", tets)],
          [(1,) + sides_at(tets[:6], nodes, 0.0), (10,) + sides_at(tets[:6], nodes, 1.0)])


TET_SIDES = [(0, 1, 3), (1, 2, 3), (0, 3, 2), (0, 2, 1)]  # Exodus TETRA4 sides 1..4


def sides_at(tets, nodes, x):
    """(elements, sides), 1-based, of the faces of `tets` (the first tets of the file) on the
    plane at x."""
    elems, sides = [], []
    for e, tet in enumerate(tets, start=1):
        for s, local in enumerate(TET_SIDES, start=1):
            if all(nodes[tet[i] - 1][0] == x for i in local):
                elems.append(e)
                sides.append(s)
    return elems, sides


def kuhn_tets(x0, index):
    """The cube [x0, x0 + 1] x [0, 1]^2 as six positive tetrahedra along its main diagonal."""
    tets = []
    for order in itertools.permutations(range(3)):
        corner = np.array([x0, 0.0, 0.0])
        path = [tuple(corner)]
        for axis in order:
            corner[axis] += 1.0
            path.append(tuple(corner))
        x = np.array(path)
        if np.linalg.det(np.array([x[1] - x[0], x[2] - x[0], x[3] - x[0]])) < 0:
            path[1], path[2] = path[2], path[1]
        tets.append([index[p] for p in path])
    return tets


if __name__ == "__main__":
    main()
