#!/usr/bin/env python3
"""Writes a 2 x 1 x 1 HEX8 Exodus II mesh of two 1 m cells (side sets 1 and 2 on x = 0 and
x = 2) with scipy.io.netcdf, which stores "coordx" as netCDF variable 0 (the case the Exodus
library misreads as all zeros).

usage: scipy_exodus.py OUT.exo [--duplicate-face | --flat | --unmerged]
--duplicate-face: side set 1 lists its face twice.
--flat: every y is 0 (a mesh with no extent in y).
--unmerged: the two cells touch at x = 1 without sharing nodes (two bodies whose coincident
nodes are not merged), and side set 10 is cell 1's face at x = 1."""
import sys

import numpy as np
from scipy.io import netcdf_file

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

f = netcdf_file(out, "w", version=2)
f.api_version = np.float32(5.22)
f.version = np.float32(5.22)
f.floating_point_word_size = np.int32(8)
f.file_size = np.int32(1)
f.title = b"scipy mesh"
f.createDimension("time_step", None)
f.createDimension("len_string", 33)
f.createDimension("len_line", 81)
f.createDimension("four", 4)
f.createDimension("num_dim", 3)
f.createDimension("num_nodes", len(nodes))
f.createDimension("num_elem", 2)
f.createDimension("num_el_blk", 1)
f.createDimension("num_side_sets", len(side_sets))
f.createDimension("num_el_in_blk1", 2)
f.createDimension("num_nod_per_el1", 8)
for d, name in enumerate(("coordx", "coordy", "coordz")):
    v = f.createVariable(name, "d", ("num_nodes",))
    v[:] = [0.0 if flat and d == 1 else p[d] for p in nodes]
f.createVariable("time_whole", "d", ("time_step",))
f.createVariable("eb_status", "i", ("num_el_blk",))[:] = [1]
v = f.createVariable("eb_prop1", "i", ("num_el_blk",))
v[:] = [1]
v.name = b"ID"
v = f.createVariable("connect1", "i", ("num_el_in_blk1", "num_nod_per_el1"))
v[:] = connect
v.elem_type = b"HEX8"
f.createVariable("ss_status", "i", ("num_side_sets",))[:] = [1] * len(side_sets)
v = f.createVariable("ss_prop1", "i", ("num_side_sets",))
v[:] = [s[0] for s in side_sets]
v.name = b"ID"
for k, (_, elems, sides) in enumerate(side_sets, start=1):
    f.createDimension(f"num_side_ss{k}", len(elems))
    f.createVariable(f"elem_ss{k}", "i", (f"num_side_ss{k}",))[:] = elems
    f.createVariable(f"side_ss{k}", "i", (f"num_side_ss{k}",))[:] = sides
f.close()
