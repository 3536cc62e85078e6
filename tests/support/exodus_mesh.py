"""Writes small Exodus II meshes for tests with scipy.io.netcdf (netCDF classic, no Exodus
library): the one writer of tests/cli/scipy_exodus.py, tests/input_errors/meshes/
make_mixed_exodus.py, tests/regression/interfaces/plug_in_tube.py and
doc/verification/truchas/refine_ring_mesh.py.

Import it from a test script beside tests/support/:
    sys.path.insert(0, str(Path(__file__).resolve().parents[N] / "support"))
    import exodus_mesh
"""
import numpy as np
from scipy.io import netcdf_file

# Exodus HEX8 sides (1-based) as 0-based local nodes, in the order of the Exodus manual.
HEX8_SIDES = [(0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (0, 4, 7, 3), (0, 3, 2, 1),
              (4, 5, 6, 7)]


def write(path, nodes, blocks, side_sets, title="kiln test mesh", coordinates_first=False):
    """Writes the mesh to path.

    nodes: 3-tuples of coordinates; blocks: (id, Exodus type, connectivity: rows of 1-based
    node numbers); side_sets: (id, elements, sides), 1-based elements numbered across the
    blocks in order, Exodus side numbers.
    coordinates_first: store "coordx" as netCDF variable 0, which the Exodus library misreads
    as all zeros (tests/cli/scipy_exodus.py keeps a mesh that does so Kiln's reader is tested
    on it); by default time_whole comes first."""
    f = netcdf_file(path, "w", version=2)
    f.api_version = np.float32(5.22)
    f.version = np.float32(5.22)
    f.floating_point_word_size = np.int32(8)
    f.file_size = np.int32(1)
    f.title = title.encode()
    f.createDimension("time_step", None)
    f.createDimension("len_string", 33)
    f.createDimension("len_line", 81)
    f.createDimension("four", 4)
    f.createDimension("num_dim", 3)
    f.createDimension("num_nodes", len(nodes))
    f.createDimension("num_elem", sum(len(b[2]) for b in blocks))
    f.createDimension("num_el_blk", len(blocks))
    f.createDimension("num_side_sets", len(side_sets))
    if not coordinates_first:
        f.createVariable("time_whole", "d", ("time_step",))
    for d, name in enumerate(("coordx", "coordy", "coordz")):
        f.createVariable(name, "d", ("num_nodes",))[:] = [p[d] for p in nodes]
    if coordinates_first:
        f.createVariable("time_whole", "d", ("time_step",))
    f.createVariable("eb_status", "i", ("num_el_blk",))[:] = [1] * len(blocks)
    v = f.createVariable("eb_prop1", "i", ("num_el_blk",))
    v[:] = [b[0] for b in blocks]
    v.name = b"ID"
    for k, (_, kind, connect) in enumerate(blocks, start=1):
        f.createDimension(f"num_el_in_blk{k}", len(connect))
        f.createDimension(f"num_nod_per_el{k}", len(connect[0]))
        v = f.createVariable(f"connect{k}", "i", (f"num_el_in_blk{k}", f"num_nod_per_el{k}"))
        v[:] = connect
        v.elem_type = kind.encode()
    f.createVariable("ss_status", "i", ("num_side_sets",))[:] = [1] * len(side_sets)
    v = f.createVariable("ss_prop1", "i", ("num_side_sets",))
    v[:] = [s[0] for s in side_sets]
    v.name = b"ID"
    for k, (_, elems, sides) in enumerate(side_sets, start=1):
        f.createDimension(f"num_side_ss{k}", len(elems))
        f.createVariable(f"elem_ss{k}", "i", (f"num_side_ss{k}",))[:] = elems
        f.createVariable(f"side_ss{k}", "i", (f"num_side_ss{k}",))[:] = sides
    f.close()


def hex8_sides_where(connect, nodes, on_face, first_element=1):
    """(elements, sides) of the HEX8 faces whose four nodes all satisfy on_face(point);
    connect: the block's rows of 1-based node numbers, its first element numbered
    first_element."""
    elems, sides = [], []
    for e, cell in enumerate(connect, start=first_element):
        for s, local in enumerate(HEX8_SIDES, start=1):
            if all(on_face(nodes[cell[i] - 1]) for i in local):
                elems.append(e)
                sides.append(s)
    return elems, sides
