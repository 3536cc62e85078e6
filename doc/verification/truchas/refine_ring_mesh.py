#!/usr/bin/env python3
"""Refines Truchas' viscoplastic-ring mesh (hytec_quarter_coarse.gen, no Cubit here) by
splitting every HEX8 into 8, for the convergence study of viscoplastic-ring.py (not a deck's
module: no inputs/truchas/refine_ring_mesh.xml).

Usage: refine_ring_mesh.py IN.gen OUT.gen [LEVELS]

Each level puts a node at every edge's, face's and cell's midpoint (the trilinear map of the
parent) and then moves the nodes of the faces of side sets 1 (the plug/ring interface,
r = 0.0254 m) and 4 (the outer radius, r = 0.0508 m) radially onto their cylinder, so the
refined meshes approach the true geometry (the coarse mesh's facets are chords). Moving along
the radius keeps a node of the planes x = 0 and y = 0 in its plane. Blocks and side sets are
carried to the children (a face of a side set becomes its 4 children's faces of the same side
number). Written by tests/support/exodus_mesh.py.
"""
import sys
from pathlib import Path

import numpy as np
from scipy.io import netcdf_file

sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "tests" / "support"))
import exodus_mesh  # noqa: E402  (tests/support/exodus_mesh.py)

# Exodus HEX8 sides as (axis, end) of the reference cube: side 1 eta = -1, 2 xi = +1,
# 3 eta = +1, 4 xi = -1, 5 zeta = -1, 6 zeta = +1.
SIDES = {1: (1, 0), 2: (0, 1), 3: (1, 1), 4: (0, 0), 5: (2, 0), 6: (2, 1)}
# Reference coordinates (0..2 on each axis) of the Exodus HEX8 corner nodes.
CORNERS = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2)]
RADII = {1: 0.0254, 4: 0.0508}


def trilinear(xc, a):
    """The point of the hex with corners xc at reference (a/2 in [0, 1]^3)."""
    s = np.asarray(a, dtype=float) / 2.0
    w = [(1 - s[0]) * (1 - s[1]) * (1 - s[2]), s[0] * (1 - s[1]) * (1 - s[2]),
         s[0] * s[1] * (1 - s[2]), (1 - s[0]) * s[1] * (1 - s[2]),
         (1 - s[0]) * (1 - s[1]) * s[2], s[0] * (1 - s[1]) * s[2], s[0] * s[1] * s[2],
         (1 - s[0]) * s[1] * s[2]]
    return sum(wi * xi for wi, xi in zip(w, xc))


def refine(x, blocks, side_sets):
    """x: (n, 3); blocks: {id: (m, 8) 0-based}; side_sets: {id: [(global elem, side)]} with
    the global element numbering of the blocks in increasing id. Returns the same for the
    children."""
    key_of = {}
    points = []

    def node(p):
        k = tuple(np.round(p / 1e-12).astype(np.int64))
        if k not in key_of:
            key_of[k] = len(points)
            points.append(p)
        return key_of[k]

    for i in range(len(x)):
        node(x[i])
    new_blocks = {}
    child_of = []  # global parent element -> its 8 global children, by (i, j, k) half
    count = 0
    for b in sorted(blocks):
        rows = []
        for cell in blocks[b]:
            xc = x[cell]
            grid = {}
            for i in range(3):
                for j in range(3):
                    for k in range(3):
                        grid[(i, j, k)] = node(trilinear(xc, (i, j, k)))
            children = {}
            for i in range(2):
                for j in range(2):
                    for k in range(2):
                        children[(i, j, k)] = count + len(rows)
                        rows.append([grid[(i + c[0] // 2, j + c[1] // 2, k + c[2] // 2)]
                                     for c in CORNERS])
            child_of.append(children)
        count += len(rows)
        new_blocks[b] = np.array(rows)
    new_sides = {}
    for s, faces in side_sets.items():
        out = []
        for e, side in faces:
            axis, end = SIDES[side]
            for half, child in child_of[e].items():
                if half[axis] == end:
                    out.append((child, side))
        new_sides[s] = out
    x_new = np.array(points)
    # Curved side sets: their faces' nodes onto the cylinder.
    all_cells = np.concatenate([new_blocks[b] for b in sorted(new_blocks)])
    for s, radius in RADII.items():
        on = set()
        for e, side in new_sides.get(s, []):
            axis, end = SIDES[side]
            for c, ref in zip(all_cells[e], CORNERS):
                if ref[axis] // 2 == end:
                    on.add(int(c))
        for n in on:
            r = np.hypot(x_new[n, 0], x_new[n, 1])
            x_new[n, :2] *= radius / r
    return x_new, new_blocks, new_sides


def read(path):
    f = netcdf_file(path, "r", mmap=False)
    x = np.stack([f.variables[c][:] for c in ("coordx", "coordy", "coordz")], axis=1)
    ids = list(f.variables["eb_prop1"][:])
    blocks = {int(b): f.variables[f"connect{i + 1}"][:] - 1 for i, b in enumerate(ids)}
    sides = {}
    for i, s in enumerate(f.variables["ss_prop1"][:]):
        e = f.variables[f"elem_ss{i + 1}"][:] - 1
        side = f.variables[f"side_ss{i + 1}"][:]
        sides[int(s)] = list(zip(e.tolist(), side.tolist()))
    f.close()
    return x, blocks, sides


def write(path, x, blocks, sides):
    exodus_mesh.write(path, x, [(b, "HEX8", blocks[b] + 1) for b in sorted(blocks)],
                      [(s, [e + 1 for e, _ in sides[s]], [side for _, side in sides[s]])
                       for s in sorted(sides)], title="refine_ring_mesh.py")


def main():
    x, blocks, sides = read(sys.argv[1])
    for _ in range(int(sys.argv[3]) if len(sys.argv) > 3 else 1):
        x, blocks, sides = refine(x, blocks, sides)
    write(sys.argv[2], x, blocks, sides)
    print(f"{sys.argv[2]}: {len(x)} nodes, {sum(len(c) for c in blocks.values())} cells")


if __name__ == "__main__":
    main()
