#!/usr/bin/env python3
"""Writes a 2 x 1 x 1 HEX8 Exodus II mesh (side sets 1 and 2 on x = 0 and x = 2) with
scipy.io.netcdf, which stores the variables in the order they are defined: "coordx" first,
as netCDF variable 0 (the case the Exodus library misreads as all zeros).

usage: scipy_exodus.py OUT.exo [--duplicate-face | --flat]
--duplicate-face: side set 1 lists its face twice, and "coordx" comes after "eb_status"
(variable 0), so that the Exodus library reads the coordinates right.
--flat: every y is 0 (a mesh with no extent in y)."""
import sys

import numpy as np
from scipy.io import netcdf_file

out = sys.argv[1]
duplicate = "--duplicate-face" in sys.argv[2:]
flat = "--flat" in sys.argv[2:]
xs = [0.0, 1.0, 2.0]
nodes = [(x, y, z) for z in (0.0, 1.0) for y in (0.0, 1.0) for x in xs]
index = {p: i + 1 for i, p in enumerate(nodes)}


def hexa(x0):
    x1 = x0 + 1.0
    corners = [(x0, 0, 0), (x1, 0, 0), (x1, 1, 0), (x0, 1, 0),
               (x0, 0, 1), (x1, 0, 1), (x1, 1, 1), (x0, 1, 1)]
    return [index[(float(a), float(b), float(c))] for a, b, c in corners]


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
f.createDimension("num_side_sets", 2)
f.createDimension("num_el_in_blk1", 2)
f.createDimension("num_nod_per_el1", 8)
f.createDimension("num_side_ss1", 2 if duplicate else 1)
f.createDimension("num_side_ss2", 1)
if duplicate:
    f.createVariable("eb_status", "i", ("num_el_blk",))[:] = [1]
for d, name in enumerate(("coordx", "coordy", "coordz")):
    v = f.createVariable(name, "d", ("num_nodes",))
    v[:] = [0.0 if flat and d == 1 else p[d] for p in nodes]
f.createVariable("time_whole", "d", ("time_step",))
if not duplicate:
    f.createVariable("eb_status", "i", ("num_el_blk",))[:] = [1]
v = f.createVariable("eb_prop1", "i", ("num_el_blk",))
v[:] = [1]
v.name = b"ID"
v = f.createVariable("connect1", "i", ("num_el_in_blk1", "num_nod_per_el1"))
v[:] = [hexa(0.0), hexa(1.0)]
v.elem_type = b"HEX8"
v = f.createVariable("ss_status", "i", ("num_side_sets",))
v[:] = [1, 1]
v = f.createVariable("ss_prop1", "i", ("num_side_sets",))
v[:] = [1, 2]
v.name = b"ID"
v = f.createVariable("elem_ss1", "i", ("num_side_ss1",))
v[:] = [1, 1] if duplicate else [1]
v = f.createVariable("side_ss1", "i", ("num_side_ss1",))
v[:] = [4, 4] if duplicate else [4]
v = f.createVariable("elem_ss2", "i", ("num_side_ss2",))
v[:] = [2]
v = f.createVariable("side_ss2", "i", ("num_side_ss2",))
v[:] = [2]
f.close()
