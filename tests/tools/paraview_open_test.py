#!/usr/bin/env pvpython
"""Kiln's results of every cell type, opened with ParaView's own readers (issue 32, item 4).

usage: pvpython paraview_open_test.py KILN MPIEXEC INPUTS SHARED CASE

Runs one case in a temporary folder with Output/Format "HDF5 and Exodus", then opens
BASE.xmf with ParaView's XDMF reader and BASE.exo with its Exodus reader and checks, at the
last output time:
- the VTK cell types of the volume are those of the mesh's blocks (a quadratic cell shown as
  quadratic: HEX27 as VTK_TRIQUADRATIC_HEXAHEDRON, not as a linear hexahedron);
- every cell's volume, as ParaView computes it from the nodes in the order the file gives,
  is positive, and they add up to the body's volume (a node order ParaView reads differently
  from Kiln's gives a wrong or negative volume);
- the gap surface (XDMF) has the face type of the cut faces (QUAD9 as
  VTK_BIQUADRATIC_QUAD) and its faces add up to the gap's area;
- the displacement and temperature fields are there, with the values of the HDF5 file's last
  step (through the Exodus reader too).
Exit status 0 when all hold; 1 with the reason otherwise.
"""
import os
import re
import sys
import tempfile
from pathlib import Path

import numpy as np
from paraview import servermanager, simple

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "support"))
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)

# VTK cell type numbers (vtkCellType.h).
VTK = {"TETRA4": 10, "HEX8": 12, "WEDGE6": 13, "PYRAMID5": 14, "TETRA10": 24, "HEX20": 25,
       "HEX27": 29, "TRI3": 5, "QUAD4": 9, "TRI6": 22, "QUAD8": 23, "QUAD9": 28}

# Each case: the deck, what to change in it, the volume types, the gap's face type, the
# body's volume and the gap's area (m^3, m^2; None: no gap).
BOX = "inputs/contact-box-close.xml"
CUBE = "inputs/elastic-cube.xml"
CASES = {
    # TETRA10 and HEX20 cannot be cut by a gap (doc/contact.md): the elastic cube, no gap.
    "hex20": (CUBE, {"Cell Type": "HEX20", "Cells": "{4, 2, 2}"}, {"HEX20"}, None, 1.0, None),
    "hex27": (BOX, {"Cell Type": "HEX27"}, {"HEX27"}, "QUAD9", 0.04**3, 0.04**2),
    "tet10": (CUBE, {"Cell Type": "TETRA10", "Cells": "{4, 2, 2}"}, {"TETRA10"}, None, 1.0,
              None),
    "wedge": (BOX, {"Cell Type": "WEDGE6"}, {"WEDGE6"}, None, 0.04**3, 0.04**2),
    "pyramid": (BOX, {"Cell Type": "PYRAMID5"}, {"PYRAMID5"}, "QUAD4", 0.04**3, 0.04**2),
    "mixed": ("inputs/truchas/stretch-mixed.xml", {}, {"HEX8", "TETRA4", "WEDGE6", "PYRAMID5"},
              None, 4.0, None),
}


def fail(message):
    print("paraview_open_test: " + message)
    sys.exit(1)


def make_deck(inputs, shared, deck, changes, base):
    text = open(os.path.join(os.path.dirname(inputs), deck)).read()
    text = text.replace("../shared/", shared.rstrip("/") + "/")
    text = kd.add_parameters(text, "Output", {"Format": "HDF5 and Exodus", "File Base": base})
    # The box decks end at 50 s (the first output time after 0): enough to have fields.
    text = re.sub(r'(<ParameterList name="Output">.*?name="Times" type="Array\(double\)" '
                  r'value=")\{0, 50[^"]*\}', r"\g<1>{0, 50}", text, count=1, flags=re.S)
    for key, value in changes.items():
        # A Box parameter the deck gives is replaced, another one added.
        if f'<Parameter name="{key}" ' in text:
            text = kd.set_parameter(text, key, value)
        else:
            text = kd.add_parameters(text, "Box", {key: value})
    return kd.write_deck(base, text)


def pieces(data):
    """The unstructured grids of a (possibly composite) data object, by block name."""
    if not data.IsA("vtkCompositeDataSet"):
        return {"": data}
    found = {}
    it = data.NewIterator()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        meta = it.GetCurrentMetaData()
        name = meta.Get(data.NAME()) if meta is not None and meta.Has(data.NAME()) else ""
        found[name or str(len(found))] = it.GetCurrentDataObject()
        it.GoToNextItem()
    return found


QUADRATIC = {"HEX20", "HEX27", "TETRA10", "TRI6", "QUAD8", "QUAD9"}


def gauss_rule(cell_type):
    """Points and weights in VTK's parametric space of a quadratic cell (or face)."""
    g = [0.5 - 0.5 * np.sqrt(0.6), 0.5, 0.5 + 0.5 * np.sqrt(0.6)]
    w = [5 / 18, 8 / 18, 5 / 18]
    if cell_type in (VTK["HEX20"], VTK["HEX27"]):
        return [((a, b, c), wa * wb * wc) for a, wa in zip(g, w) for b, wb in zip(g, w)
                for c, wc in zip(g, w)]
    if cell_type in (VTK["QUAD8"], VTK["QUAD9"]):
        return [((a, b, 0.0), wa * wb) for a, wa in zip(g, w) for b, wb in zip(g, w)]
    if cell_type == VTK["TETRA10"]:
        a, b = 0.5854101966249685, 0.1381966011250105
        return [(p, 1 / 24) for p in ((a, b, b), (b, a, b), (b, b, a), (b, b, b))]
    if cell_type == VTK["TRI6"]:
        return [(p, 1 / 6) for p in ((2 / 3, 1 / 6, 0), (1 / 6, 2 / 3, 0), (1 / 6, 1 / 6, 0))]
    fail(f"no quadrature for VTK cell type {cell_type}")


def vtk_measure(grid, i):
    """The volume (area) of cell i as VTK's own shape functions of its type map it: the
    integral of det(dx/dr) (of |dx/dr x dx/ds|) over its parametric cell. ParaView's Cell Size
    filter skips quadratic cells (VTK 9.2), so those are measured here."""
    cell = grid.GetCell(i)
    n = cell.GetNumberOfPoints()
    x = np.array([cell.GetPoints().GetPoint(k) for k in range(n)])
    total = 0.0
    for point, weight in gauss_rule(grid.GetCellType(i)):
        dimension = cell.GetCellDimension()
        derivs = [0.0] * (dimension * n)
        cell.InterpolateDerivs(point, derivs)
        dxdr = np.array(derivs).reshape(dimension, n) @ x
        if dimension == 3:
            total += weight * np.linalg.det(dxdr)
        else:
            total += weight * np.linalg.norm(np.cross(dxdr[0], dxdr[1]))
    return total


def sizes(source, time, array):
    """(cell types, cell sizes, grid) of `source`'s blocks at `time`, as ParaView measures
    them: signed volumes (a node order misread gives a negative or a wrong volume), areas."""
    size = simple.CellSize(Input=source)
    size.ComputeVertexCount = size.ComputeLength = 0
    size.ComputeArea = int(array == "Area")
    size.ComputeVolume = int(array == "Volume")
    size.UpdatePipeline(time)
    out = {}
    for name, grid in pieces(servermanager.Fetch(size)).items():
        values = grid.GetCellData().GetArray(array)
        measure = np.array([values.GetValue(i) for i in range(values.GetNumberOfTuples())])
        types = {grid.GetCellType(i) for i in range(grid.GetNumberOfCells())}
        if types & {VTK[t] for t in QUADRATIC}:
            measure = np.array([vtk_measure(grid, i) for i in range(grid.GetNumberOfCells())])
        out[name] = (types, measure, grid)
    return out


def point_array(grid, name):
    array = grid.GetPointData().GetArray(name)
    if array is None:
        fail(f"no point field {name} (fields: "
             f"{[grid.GetPointData().GetArrayName(i) for i in range(grid.GetPointData().GetNumberOfArrays())]})")
    n, c = array.GetNumberOfTuples(), array.GetNumberOfComponents()
    return np.array([array.GetTuple(i) for i in range(n)]).reshape(n, c)


def check_volume(what, blocks, want_types, volume, wedge_sign=1.0, tolerance=1e-9):
    types = set().union(*(b[0] for b in blocks.values()))
    if types != {VTK[t] for t in want_types}:
        fail(f"{what}: ParaView reads cell types {sorted(types)}, expected "
             f"{sorted(VTK[t] for t in want_types)} ({sorted(want_types)})")
    # ParaView's Exodus reader keeps the Exodus node order of a wedge, whose triangle (0, 1, 2)
    # faces the other while VTK's faces away: every wedge of an Exodus file, Cubit's own too
    # (Truchas' brick-mixed.gen), has a negative volume there (wedge_sign -1).
    all_sizes = np.concatenate([np.where([t == VTK["WEDGE6"] for t in
                                          (b[2].GetCellType(i) for i in range(len(b[1])))],
                                         wedge_sign, 1.0) * b[1] for b in blocks.values()])
    if all_sizes.min() <= 0.0:
        fail(f"{what}: a piece of a cell of volume {all_sizes.min()} (node order misread)")
    if abs(all_sizes.sum() - volume) > tolerance * volume:
        fail(f"{what}: the cells' volumes add up to {all_sizes.sum()}, not {volume}")
    n_cells = sum(b[2].GetNumberOfCells() for b in blocks.values())
    print(f"{what}: types {sorted(types)}, {n_cells} cells, volume {all_sizes.sum():.12g}")


def main():
    if len(sys.argv) != 6 or sys.argv[5] not in CASES:
        fail("usage: paraview_open_test.py KILN MPIEXEC INPUTS SHARED " + "|".join(CASES))
    kiln, mpiexec, inputs, shared, case = sys.argv[1:]
    deck, changes, types, face, volume, area = CASES[case]
    heat = deck == BOX  # stretch-mixed and the cube are Elasticity alone
    with tempfile.TemporaryDirectory() as folder:
        base = os.path.join(folder, case)
        path = make_deck(inputs, shared, deck, changes, base)
        state = kd.read_step(kd.run_kiln(kiln, path, 2, mpiexec).results)
        time, displacement = state["time"], state["displacement"]

        xdmf = simple.XDMFReader(FileNames=[base + ".xmf"])
        xdmf.UpdatePipelineInformation()
        if abs(xdmf.TimestepValues[-1] - time) > 1e-12 * max(1.0, time):
            fail(f"the XDMF's last time is {xdmf.TimestepValues[-1]}, the HDF5 file's {time}")
        volumes = sizes(xdmf, time, "Volume")
        body = {k: v for k, v in volumes.items() if not k.startswith("gap")}
        check_volume("XDMF volume", body, types, volume)
        grid = next(iter(body.values()))[2]
        got = point_array(grid, "displacement")
        if got.shape != displacement.shape or np.abs(got - displacement).max() > 0.0:
            fail("XDMF: the displacement ParaView reads is not the HDF5 file's")
        if heat:
            point_array(grid, "temperature")
        if area is not None:
            gap = {k: v for k, v in sizes(xdmf, time, "Area").items() if k.startswith("gap")}
            if not gap:
                fail("XDMF: no gap surface")
            gap_types = set().union(*(b[0] for b in gap.values()))
            want = {VTK[face]} if face else {VTK["TRI3"], VTK["QUAD4"]}
            if not gap_types or not gap_types <= want:
                fail(f"XDMF gap: cell types {sorted(gap_types)}, expected {sorted(want)}")
            total = sum(b[1].sum() for b in gap.values())
            if abs(total - area) > 1e-9 * area:
                fail(f"XDMF gap: the faces add up to {total} m^2, not {area}")
            print(f"XDMF gap: types {sorted(gap_types)}, area {total:.12g}")

        exodus = simple.ExodusIIReader(FileName=base + ".exo")
        exodus.UpdatePipelineInformation()
        exodus.ElementBlocks = exodus.GetProperty("ElementBlocks").Available
        exodus.PointVariables = exodus.GetProperty("PointVariables").Available
        exodus.ApplyDisplacements = 0  # the reference shape: the volume is the body's
        blocks = sizes(exodus, time, "Volume")
        # The Exodus reader keeps the points in single precision (the file's are doubles).
        check_volume("Exodus volume", blocks, types, volume, wedge_sign=-1.0, tolerance=1e-6)
        # The Exodus reader gives each block its own points: compare by position.
        for grid in (b[2] for b in blocks.values()):
            u = point_array(grid, "displacement_")
            if np.abs(u).max() == 0.0 and np.abs(displacement).max() > 0.0:
                fail("Exodus: the displacement ParaView reads is zero")
    print("paraview_open_test: OK")


main()
