"""Tests of tools/kiln-diff on small synthetic Kiln result files.

usage: kiln_diff_test.py PATH/TO/kiln-diff [unittest arguments, e.g. a class name]

The files are made here with h5py in the layout of doc/output-format.md: a
2 x 2 x 2 box of hexahedra split at x = 1 into a gap, the 9 nodes on the gap
doubled (their twins appended, at the same coordinates), two output steps.
The values of every field differ between a node and its twin, so that a
comparison that pairs twins wrongly finds differences.
"""

import os
import subprocess
import sys
import tempfile
import unittest

import h5py
import numpy as np

KILN_DIFF = None  # set from the command line


def box_mesh():
    """Coordinates (36 x 3) and connectivity (8 x 8) of the split 2 x 2 x 2 box."""
    index = {}
    coordinates = []
    for k in range(3):
        for j in range(3):
            for i in range(3):
                index[i, j, k] = len(coordinates)
                coordinates.append((0.5 * i, 0.5 * j, 0.5 * k))
    twin = {}
    for k in range(3):
        for j in range(3):
            twin[1, j, k] = len(coordinates)
            coordinates.append(coordinates[index[1, j, k]])
    connectivity = []
    for k in range(2):
        for j in range(2):
            for i in range(2):
                corners = [(i, j, k), (i + 1, j, k), (i + 1, j + 1, k), (i, j + 1, k),
                           (i, j, k + 1), (i + 1, j, k + 1), (i + 1, j + 1, k + 1),
                           (i, j + 1, k + 1)]
                # the cells right of the gap (i = 1) use the twins
                connectivity.append([twin[c] if i == 1 and c[0] == 1 else index[c]
                                     for c in corners])
    return np.array(coordinates, dtype=float), np.array(connectivity, dtype=np.int64)


# A hexahedron (Exodus order) as two wedges (WEDGE6: the triangle 0 1 3 over 4 5 7, and
# 1 2 3 over 5 6 7).
WEDGES_OF_HEX = [[0, 1, 3, 4, 5, 7], [1, 2, 3, 5, 6, 7]]


def mixed_connectivity(connectivity, split):
    """The cells of `connectivity` with those in `split` cut into two wedges each, as
    Kiln writes mixed meshes: n columns for the largest cell, smaller rows ending in -1s
    (doc/output-format.md); 6 columns when every cell is split."""
    rows = []
    for c, cell in enumerate(connectivity):
        if c in split:
            rows.extend([cell[w] for w in WEDGES_OF_HEX])
        else:
            rows.append(cell)
    width = max(len(r) for r in rows)
    return np.array([list(r) + [-1] * (width - len(r)) for r in rows], dtype=np.int64)


def cell_centroids(coordinates, connectivity):
    used = connectivity >= 0
    x = coordinates[np.where(used, connectivity, 0)] * used[:, :, None]
    return x.sum(axis=1) / used.sum(axis=1)[:, None]


def fields_at(time, coordinates, connectivity):
    n = len(coordinates)
    x = coordinates
    side = np.zeros(n)  # +1 on the nodes of the cells right of the gap
    right = connectivity[cell_centroids(coordinates, connectivity)[:, 0] > 0.5]
    side[np.unique(right[right >= 0])] = 1.0  # the nodes of the cells right of the gap
    on_gap = np.isclose(x[:, 0], 0.5)
    temperature = 300.0 + time * (x[:, 0] + 2 * x[:, 1] + 3 * x[:, 2]) + 0.25 * side
    displacement = 1e-6 * np.column_stack([x[:, 0] + side, x[:, 1] - side, time * x[:, 2]])
    gap_opening = np.where(on_gap, 1e-7 * time * (1 + x[:, 1]) * (1 + side), np.nan)
    centroids = cell_centroids(x, connectivity)
    stress = np.column_stack([1e7 * (1 + time + centroids[:, 0]), 2e7 + centroids[:, 1],
                              -3e7 * np.ones(len(centroids)),
                              1e-4 * centroids[:, 2], np.zeros(len(centroids)),
                              5e5 * centroids[:, 0] * centroids[:, 1]])
    return {"temperature": temperature, "displacement": displacement,
            "gap_opening": gap_opening, "stress": stress}


class KilnFile:
    """A synthetic result file's content, changed by the tests before writing."""

    def __init__(self):
        self.coordinates, self.connectivity = box_mesh()
        self.block_id = np.where(np.arange(8) % 2 == 0, 1, 2).astype(np.int32)
        self.cell_rank = np.zeros(8, dtype=np.int32)
        self.times = [0.0, 2.5]
        self.steps = [fields_at(t, self.coordinates, self.connectivity) for t in self.times]
        self.step_names = [f"{i:06d}" for i in range(len(self.times))]

    def make_mixed(self, split):
        """The cells in `split` cut into two wedges each (block 3), the fields remade."""
        self.connectivity = mixed_connectivity(self.connectivity, split)
        n_cells = len(self.connectivity)
        self.block_id = np.where(np.any(self.connectivity == -1, axis=1)
                                 | (self.connectivity.shape[1] == 6), 3, 1).astype(np.int32)
        self.cell_rank = np.zeros(n_cells, dtype=np.int32)
        self.steps = [fields_at(t, self.coordinates, self.connectivity) for t in self.times]

    def renumber(self, node_order, cell_order):
        """New node i is old node node_order[i]; the same for cells."""
        new_index = np.empty(len(node_order) + 1, dtype=np.int64)
        new_index[node_order] = np.arange(len(node_order))
        new_index[-1] = -1  # the padding of smaller cells stays
        self.coordinates = self.coordinates[node_order]
        self.connectivity = new_index[self.connectivity[cell_order]]
        self.block_id = self.block_id[cell_order]
        self.cell_rank = self.cell_rank[cell_order]
        for step in self.steps:
            for name in step:
                order = cell_order if name == "stress" else node_order
                step[name] = step[name][order]

    def write(self, path):
        with h5py.File(path, "w") as f:
            f["/mesh/coordinates"] = self.coordinates
            f["/mesh/connectivity"] = self.connectivity
            f["/mesh/block_id"] = self.block_id
            f["/mesh/cell_rank"] = self.cell_rank
            for name, time, step in zip(self.step_names, self.times, self.steps):
                group = f.create_group(f"/steps/{name}")
                group.attrs["time"] = time
                group.attrs["dt"] = 0.5
                group.attrs["cycle"] = np.int32(3)
                for field, values in step.items():
                    group[field] = values
        return path


def twin_pairs():
    """(node, twin) index pairs of the box."""
    coordinates, _ = box_mesh()
    return [(int(np.nonzero(np.all(coordinates[:27] == coordinates[t], axis=1))[0][0]), t)
            for t in range(27, 36)]


class Case(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.a = KilnFile()
        self.b = KilnFile()

    def tearDown(self):
        self.folder.cleanup()

    def path(self, name):
        return os.path.join(self.folder.name, name)

    def diff(self, *options, a=None, b=None):
        """Runs kiln-diff on A and B (written now); returns (status, output)."""
        a = a or self.a.write(self.path("a.h5"))
        b = b or self.b.write(self.path("b.h5"))
        completed = subprocess.run([sys.executable, KILN_DIFF, *options, a, b],
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                   text=True, check=False)
        return completed.returncode, completed.stdout

    def assert_status(self, expected, result, *patterns):
        status, output = result
        self.assertEqual(status, expected, output)
        for pattern in patterns:
            self.assertIn(pattern, output)
        return output


class Compare(Case):
    def test_identical_files_agree(self):
        self.assert_status(0, self.diff(), "agree within the tolerances", "36 nodes, 8 cells")

    def test_one_entry_differs_and_is_reported(self):
        old = self.b.steps[1]["stress"][5, 3]
        self.b.steps[1]["stress"][5, 3] = 0.25
        output = self.assert_status(1, self.diff(), "stress[xy] at t = 2.5 s, cell 5 at ",
                                    f"A = {old:.17g}", "B = 0.25", "1 value(s) beyond")
        self.assertNotIn("temperature[", output)

    def test_a_twin_node_that_differs_is_reported_with_its_index(self):
        node, twin = twin_pairs()[4]
        self.b.steps[0]["displacement"][twin, 1] += 1e-9
        output = self.assert_status(1, self.diff(), f"displacement[y] at t = 0 s, node {twin} ")
        self.assertNotIn(f"node {node} ", output)

    def test_default_tolerances(self):
        # temperature ~300: 5.5e-6 relative is 1.65e-3
        self.b.steps[1]["temperature"][7] *= 1 + 5e-6
        self.assert_status(0, self.diff())
        self.b.steps[1]["temperature"][7] *= 1 + 1e-5
        self.assert_status(1, self.diff(), "temperature at t = 2.5 s, node 7")

    def test_absolute_tolerance_for_values_near_zero(self):
        self.a.steps[0]["stress"][2, 4] = 1e-12
        self.b.steps[0]["stress"][2, 4] = 5e-11  # relatively far, absolutely < 1e-10
        self.assert_status(0, self.diff())
        self.assert_status(1, self.diff("--abs", "1e-11"), "stress[yz] at t = 0 s, cell 2")

    def test_pass_rule_uses_the_mean_of_both_values(self):
        # |a-b| <= rel (|a|+|b|)/2: with rel 0.5, 1 vs 1.6 passes (0.6 <= 0.65), 1 vs 1.7
        # does not (0.7 > 0.675); relative to a alone both would fail, to b both pass.
        self.a.steps[0]["stress"][6, 4] = 1.0
        self.b.steps[0]["stress"][6, 4] = 1.6
        self.assert_status(0, self.diff("--abs", "0", "--rel", "0.5"))
        self.a, self.b = self.b, self.a
        self.assert_status(0, self.diff("--abs", "0", "--rel", "0.5"))
        self.a.steps[0]["stress"][6, 4] = 1.7
        self.assert_status(1, self.diff("--abs", "0", "--rel", "0.5"), "stress[yz] at t = 0 s")
        self.a, self.b = self.b, self.a
        self.assert_status(1, self.diff("--abs", "0", "--rel", "0.5"), "stress[yz] at t = 0 s")

    def test_rel_option(self):
        self.b.steps[1]["temperature"] *= 1 + 1e-4
        self.assert_status(1, self.diff())
        self.assert_status(0, self.diff("--rel", "2e-4"))

    def test_field_option_sets_one_field(self):
        self.b.steps[1]["stress"][:, 3] += 0.5  # xy is ~1e-4
        self.b.steps[1]["temperature"][3] += 0.01
        self.assert_status(1, self.diff(), "stress[xy]", "temperature at")
        output = self.assert_status(1, self.diff("--field", "stress:1:"), "temperature at")
        self.assertNotIn("stress[xy] at", output)
        self.assert_status(0, self.diff("--field", "stress:1:", "--field", "temperature::1e-4"))

    def test_field_option_rel_only(self):
        self.b.steps[1]["stress"][:, 0] *= 1 + 1e-5  # xx is ~1e7
        self.assert_status(1, self.diff(), "stress[xx]")
        self.assert_status(0, self.diff("--field=stress::2e-5"))
        self.assert_status(1, self.diff("--field=stress:1:5e-6"), "stress[xx]")

    def test_tolerance_file(self):
        self.b.steps[1]["stress"][:, 3] += 0.5
        with open(self.path("tolerances.txt"), "w", encoding="utf-8") as f:
            f.write("# field abs rel\nstress 1 -   # half a pascal of noise\n\n")
        self.assert_status(0, self.diff("--tolerances", self.path("tolerances.txt")))
        with open(self.path("tolerances.txt"), "w", encoding="utf-8") as f:
            f.write("* 0 1e-9\n")
        self.assert_status(1, self.diff("--tolerances", self.path("tolerances.txt")),
                           "stress[xy]")
        # --field wins over the file
        self.assert_status(0, self.diff("--tolerances", self.path("tolerances.txt"),
                                        "--field", "stress:1:"))

    def test_nan_equals_nan_but_not_a_number(self):
        # gap_opening is NaN off the gap in both files
        self.assertTrue(np.isnan(self.a.steps[0]["gap_opening"]).any())
        self.assert_status(0, self.diff())
        self.b.steps[1]["gap_opening"][0] = 0.0  # node 0 is off the gap: NaN in A
        self.assert_status(1, self.diff(), "gap_opening at t = 2.5 s, node 0 ", "A = nan",
                           "B = 0")
        self.b = KilnFile()
        self.b.steps[1]["temperature"][4] = np.nan
        self.assert_status(1, self.diff("--abs", "1e30"), "temperature at t = 2.5 s, node 4 ",
                           "B = nan")

    def test_infinity_equals_only_itself(self):
        self.a.steps[0]["stress"][1, 1] = np.inf
        self.b.steps[0]["stress"][1, 1] = np.inf
        self.assert_status(0, self.diff())
        self.b.steps[0]["stress"][1, 1] = 1e300
        self.assert_status(1, self.diff("--rel", "1"), "stress[yy] at t = 0 s, cell 1")

    def test_fields_option_compares_only_those(self):
        self.b.steps[0]["stress"][0, 3] += 1.0
        self.assert_status(1, self.diff(), "stress[xy]")
        output = self.assert_status(0, self.diff("--fields", "temperature", "--fields",
                                                 "displacement"), "2 fields")
        self.assertNotIn("stress", output)
        self.assert_status(0, self.diff("--fields", "temperature,gap_opening"))

    def test_cell_rank_and_step_attributes_are_ignored(self):
        self.b.cell_rank[:] = np.arange(8) % 3
        self.assert_status(0, self.diff())

    def test_largest_differences_first(self):
        self.b.steps[1]["temperature"][[3, 9, 20]] += [0.01, 0.5, 0.1]
        output = self.assert_status(1, self.diff("--max-report", "2"), "3 value(s) beyond")
        self.assertLess(output.index("node 9 "), output.index("node 20 "))
        self.assertNotIn("node 3 ", output)


class Matching(Case):
    def test_renumbered_nodes_and_cells_agree(self):
        rng = np.random.default_rng(7)
        self.b.renumber(rng.permutation(36), rng.permutation(8))
        self.assert_status(0, self.diff())

    def test_renumbered_difference_names_both_indices(self):
        rng = np.random.default_rng(11)
        node_order = rng.permutation(36)
        self.b.renumber(node_order, np.arange(8))
        new_index = int(np.nonzero(node_order == 13)[0][0])
        self.b.steps[0]["temperature"][new_index] += 1.0
        self.assert_status(1, self.diff(), f"node 13 (B: {new_index}) at (")

    def test_twins_swapped_are_told_apart(self):
        # B numbers each gap node's twin where A has the original, and back: matching by
        # coordinates alone would pair them wrongly and find the values of the other side.
        order = np.arange(36)
        for node, twin in twin_pairs():
            order[node], order[twin] = twin, node
        self.b.renumber(order, np.arange(8)[::-1])
        self.assert_status(0, self.diff())
        self.b.steps[1]["displacement"][twin_pairs()[0][0]] += 1e-8  # A's twin 27
        self.assert_status(1, self.diff(), "node 27 (B: ")

    def test_round_off_in_coordinates(self):
        rng = np.random.default_rng(3)
        self.b.coordinates += rng.uniform(-1e-13, 1e-13, self.b.coordinates.shape)
        self.assert_status(0, self.diff())

    def test_round_off_across_bucket_faces(self):
        # kiln-diff hashes coordinates to a grid through the origin with a power-of-2
        # spacing (1/8 here), whose faces pass through the nodes of A (multiples of 1/2):
        # B's nodes just below them land in the neighbouring bucket and must still be
        # found, with A and B either way round.
        x = self.b.coordinates
        self.b.coordinates = np.where(x > 0, x - 1e-13, x + 1e-13)
        self.b.renumber(np.arange(36)[::-1], np.arange(8))
        self.assert_status(0, self.diff())
        self.assert_status(0, self.diff(a=self.b.write(self.path("b.h5")),
                                        b=self.a.write(self.path("a.h5"))))

    def test_steps_matched_by_time_not_by_number(self):
        self.b.step_names = ["000001", "000000"]  # written in the other order
        self.assert_status(0, self.diff())

    def test_other_fields_placed_by_their_rows(self):
        # a field not in doc/output-format.md: a node field (36 rows), renumbered
        for f in (self.a, self.b):
            for step in f.steps:
                step["heat_flux"] = np.arange(36.0) + 10 * f.coordinates[:, 0]
        self.b.renumber(np.arange(36)[::-1], np.arange(8))
        self.assert_status(0, self.diff())
        self.b.steps[1]["heat_flux"][0] += 1.0  # A's node 35
        self.assert_status(1, self.diff(), "heat_flux at t = 2.5 s, node 35 (B: 0)")

    def test_cells_with_rotated_node_order(self):
        self.b.connectivity = np.roll(self.b.connectivity, 3, axis=1)
        self.assert_status(0, self.diff())


class MixedCells(Case):
    """Meshes of wedges, and of wedges and hexahedra in one connectivity padded with -1."""

    def setUp(self):
        super().setUp()
        for f in (self.a, self.b):
            f.make_mixed({0, 2, 5})

    def test_identical_mixed_files_agree(self):
        self.assertEqual(self.a.connectivity.shape, (11, 8))
        self.assert_status(0, self.diff())

    def test_renumbered_mixed_files_agree(self):
        rng = np.random.default_rng(5)
        self.b.renumber(rng.permutation(36), rng.permutation(11))
        self.assert_status(0, self.diff())

    def test_difference_in_a_wedge_is_reported(self):
        rng = np.random.default_rng(13)
        cell_order = rng.permutation(11)
        self.b.renumber(np.arange(36)[::-1], cell_order)
        wedge = int(np.nonzero(self.a.connectivity[:, -1] == -1)[0][1])
        self.b.steps[1]["stress"][int(np.nonzero(cell_order == wedge)[0][0]), 0] *= 1.001
        self.assert_status(1, self.diff(), f"stress[xx] at t = 2.5 s, cell {wedge} ")

    def test_twins_of_wedges_are_told_apart(self):
        order = np.arange(36)
        for node, twin in twin_pairs():
            order[node], order[twin] = twin, node
        self.b.renumber(order, np.arange(11)[::-1])
        self.assert_status(0, self.diff())

    def test_wedges_only(self):
        for f in (self.a, self.b):
            f.__init__()
            f.make_mixed(set(range(8)))
        self.assertEqual(self.a.connectivity.shape, (16, 6))
        self.b.renumber(np.arange(36)[::-1], np.arange(16)[::-1])
        self.assert_status(0, self.diff())

    def test_padding_inside_a_row(self):
        self.b.connectivity[0, 2] = -1
        self.assert_status(2, self.diff(), "/mesh/connectivity row 0",
                           "is not its cell's nodes followed by -1s")

    def test_other_cell_type_at_the_same_place(self):
        self.b.__init__()  # hexahedra where A has wedges: other cells
        self.assert_status(2, self.diff(), "the meshes do not match")

    def test_extract_keeps_the_padding(self):
        run = self.a.write(self.path("run.h5"))
        gold = self.path("gold.h5")
        self.assert_status(0, self.diff("--extract", "--fields", "stress", a=run, b=gold))
        with h5py.File(gold, "r") as f:
            self.assertTrue(np.array_equal(f["/mesh/connectivity"][...], self.a.connectivity))
        self.assert_status(0, self.diff("--fields", "stress", a=run, b=gold))


class CannotCompare(Case):
    def test_missing_file(self):
        self.assert_status(2, self.diff(b=self.path("none.h5")),
                           "cannot compare: B file", "no such file")

    def test_garbage_file(self):
        with open(self.path("garbage.h5"), "wb") as f:
            f.write(b"\x89HDF not really" + bytes(range(256)) * 8)
        self.assert_status(2, self.diff(a=self.path("garbage.h5")),
                           "A file", "is not an HDF5 file or is damaged")

    def test_truncated_file(self):
        self.b.write(self.path("b.h5"))
        with open(self.path("b.h5"), "rb") as f:
            data = f.read()
        with open(self.path("cut.h5"), "wb") as f:
            f.write(data[:len(data) // 2])
        self.assert_status(2, self.diff(b=self.path("cut.h5")), "cannot compare: B file")

    def test_hdf5_file_that_is_not_a_kiln_file(self):
        with h5py.File(self.path("other.h5"), "w") as f:
            f["/data"] = np.zeros(3)
        self.assert_status(2, self.diff(b=self.path("other.h5")),
                           "is not a Kiln result file: it has no dataset /mesh/coordinates")

    def test_different_output_times(self):
        self.b.times = [0.0, 3.0]
        self.assert_status(2, self.diff(), "the output times differ", "only in A: 2.5",
                           "only in B: 3")

    def test_different_number_of_steps(self):
        self.b.times, self.b.steps, self.b.step_names = [0.0], self.b.steps[:1], ["000000"]
        self.assert_status(2, self.diff(), "the output times differ: A has 2 steps")

    def test_field_in_one_file_only(self):
        del self.b.steps[1]["gap_opening"]
        del self.b.steps[0]["gap_opening"]
        self.assert_status(2, self.diff(), "different fields: only in A: gap_opening")
        self.assert_status(0, self.diff("--fields", "temperature"))
        self.assert_status(2, self.diff("--fields", "gap_opening"), "gap_opening (not in B)")

    def test_field_missing_at_one_step(self):
        del self.b.steps[1]["stress"]
        self.assert_status(2, self.diff(), "field stress is missing at t = 2.5 s in B")

    def test_field_of_another_shape(self):
        self.b.steps[0]["displacement"] = self.b.steps[0]["displacement"][:, :2]
        self.b.steps[1]["displacement"] = self.b.steps[1]["displacement"][:, :2]
        self.assert_status(2, self.diff(), "field displacement at t = 0 s has shape")

    def test_field_of_neither_size(self):
        for f in (self.a, self.b):
            for step in f.steps:
                step["odd"] = np.zeros(5)
        self.assert_status(2, self.diff(), "field odd has 5 rows; the mesh has 36 nodes and "
                           "8 cells")

    def test_node_moved(self):
        self.b.coordinates[5] += [0.01, 0, 0]
        self.assert_status(2, self.diff(), "the meshes do not match")

    def test_other_number_of_cells(self):
        self.b.connectivity = self.b.connectivity[:7]
        self.b.block_id, self.b.cell_rank = self.b.block_id[:7], self.b.cell_rank[:7]
        self.assert_status(2, self.diff(), "the meshes do not match: A has 36 nodes and 8 "
                           "cells, B 36 nodes and 7 cells")

    def test_other_block(self):
        self.b.block_id[3] = 7
        self.assert_status(2, self.diff(), "cell 3 is in block 2 in A, 7 in B")

    def test_twins_that_belong_to_the_same_cells(self):
        # a twin that no cell uses cannot be told from another one
        for f in (self.a, self.b):
            f.coordinates = np.vstack([f.coordinates, f.coordinates[0], f.coordinates[0]])
            for step in f.steps:
                for name in ("temperature", "displacement", "gap_opening"):
                    step[name] = np.concatenate([step[name], step[name][:2]])
        self.assert_status(0, self.diff())  # numbered alike: no matching needed
        self.b.renumber(np.arange(38)[::-1], np.arange(8))
        self.assert_status(2, self.diff(), "cannot match the 3 coincident nodes at (0, 0, 0)")

    def test_bad_options(self):
        self.assert_status(2, self.diff("--field", "stress:1"), "expected NAME:ABS:REL")
        self.assert_status(2, self.diff("--field", "stress:x:"), "\"x\" is not a number")
        self.assert_status(2, self.diff("--abs", "-1"), "must be a finite number >= 0")
        self.assert_status(2, self.diff("--field", "stres:1:"),
                           "tolerance for a field neither file has: stres")
        self.assert_status(2, self.diff("--tolerances", self.path("none.txt")),
                           "tolerance file")


class Extract(Case):
    def test_extract_selected_fields(self):
        run = self.a.write(self.path("run.h5"))
        gold = self.path("gold.h5")
        self.assert_status(0, self.diff("--extract", "--fields", "temperature,stress",
                                        a=run, b=gold), "wrote")
        with h5py.File(gold, "r") as f:
            self.assertEqual(sorted(f["/steps/000001"].keys()), ["stress", "temperature"])
            self.assertNotIn("cell_rank", f["/mesh"])
            self.assertEqual(f["/steps/000001"].attrs["time"], 2.5)
        self.assert_status(0, self.diff("--fields", "temperature,stress", a=run, b=gold))
        self.assert_status(2, self.diff(a=run, b=gold), "only in A: displacement, gap_opening")
        self.b.steps[0]["stress"][1, 1] *= 1.001
        self.assert_status(1, self.diff("--fields", "temperature,stress", b=gold,
                                        a=self.b.write(self.path("b.h5"))), "stress[yy]")

    def test_extract_missing_field(self):
        run = self.a.write(self.path("run.h5"))
        self.assert_status(2, self.diff("--extract", "--fields", "strain", a=run,
                                        b=self.path("gold.h5")), "no field strain")
        self.assertFalse(os.path.exists(self.path("gold.h5.tmp")))

    def test_help(self):
        completed = subprocess.run([sys.executable, KILN_DIFF, "--help"], check=False,
                                   stdout=subprocess.PIPE, text=True)
        self.assertEqual(completed.returncode, 0)
        self.assertIn("exit status: 0 the files agree, 1 they differ, 2", completed.stdout)


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: kiln_diff_test.py PATH/TO/kiln-diff [unittest arguments]")
    KILN_DIFF = sys.argv.pop(1)
    unittest.main(verbosity=2)
