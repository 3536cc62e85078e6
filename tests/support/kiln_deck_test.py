#!/usr/bin/env python3
"""tests/support/kiln_deck.py without kiln: the XML of a deck (types, nesting, doubles that
read back exactly), derived decks (set_parameter, add_parameters and their refusals), the
results file of a deck, the MPI environment, run_kiln's exit status and log (a shell script
stands in for kiln), read_step on a small results file.

usage: kiln_deck_test.py
"""
import os
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET
from pathlib import Path

import h5py
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)


def parsed(text):
    """{path: (type, value)} of every Parameter of the XML text, in the order of the text."""
    found = {}

    def walk(element, path):
        for child in element:
            name = path + child.get("name")
            if child.tag == "ParameterList":
                walk(child, name + "/")
            else:
                found[name] = (child.get("type"), child.get("value"))
    walk(ET.fromstring(text), "")
    return found


class Xml(unittest.TestCase):
    def test_nesting(self):
        self.assertEqual(kd.xml({"L": {"B": True}}, "K"), '<ParameterList name="K">\n'
                         '  <ParameterList name="L">\n'
                         '    <Parameter name="B" type="bool" value="true"/>\n'
                         '  </ParameterList>\n</ParameterList>\n')

    def test_deck(self):
        deck = {"Physics": "Elasticity", "Steps": 3, "Flag": False,
                "Mesh": kd.box_mesh((1, 2, 0.5), (2, 2, 1), 10, cell_type="HEX27", phi=45),
                "BC": {"rollers": kd.displacement([1, 3], "xz", kd.expression("1e-3*x"))}}
        self.assertEqual(parsed(kd.xml(deck)), {
            "Physics": ("string", "Elasticity"), "Steps": ("int", "3"),
            "Flag": ("bool", "false"), "Mesh/Type": ("string", "Box"),
            "Mesh/Gap Side Set": ("int", "10"),
            "Mesh/Box/Size": ("Array(double)", "{1, 2, 0.5}"),
            "Mesh/Box/Cells": ("Array(int)", "{2, 2, 1}"),
            "Mesh/Box/Cell Type": ("string", "HEX27"), "Mesh/Box/Phi": ("double", "45"),
            "BC/rollers/Type": ("string", "Displacement"),
            "BC/rollers/Side Sets": ("Array(int)", "{1, 3}"),
            "BC/rollers/Components": ("Array(string)", "{x, z}"),
            "BC/rollers/Displacement/Type": ("string", "Expression"),
            "BC/rollers/Displacement/Expression": ("string", "1e-3*x")})

    def test_doubles_read_back(self):
        for value in (0.1, 5.2e10, 1e-12, -0.19999999999999998, 2.0 / 3.0, 298.0, 2.3e-05):
            text = kd.parameter("v", value)
            self.assertIn('type="double"', text)
            self.assertEqual(float(text.split('value="')[1].split('"')[0]), value)

    def test_no_type(self):
        for value in ([], [1, "x"], None, {1}):
            with self.assertRaises(TypeError):
                kd.parameter("v", value)


class Derived(unittest.TestCase):
    TEXT = """<ParameterList name="Kiln">
  <ParameterList name="Output">
    <Parameter name="Times" type="Array(double)" value="{0, 50, 150}"/>
  </ParameterList>
</ParameterList>
"""

    def test_set_and_add(self):
        text = kd.set_parameter(self.TEXT, "Times", [0, 50])
        text = kd.add_parameters(text, "Output", {"File Base": "a/b", "Every Steps": 1})
        self.assertEqual(list(parsed(text).items()), [
            ("Output/File Base", ("string", "a/b")), ("Output/Every Steps", ("int", "1")),
            ("Output/Times", ("Array(double)", "{0, 50}"))])

    def test_refused(self):
        with self.assertRaisesRegex(SystemExit, "0 parameters 'Method', expected 1"):
            kd.set_parameter(self.TEXT, "Method", "BDF2")
        with self.assertRaisesRegex(SystemExit, "no ParameterList 'Thermal'"):
            kd.add_parameters(self.TEXT, "Thermal", {"Capacity": "Lumped"})

    def test_results_file(self):
        with tempfile.TemporaryDirectory() as folder:
            plain = kd.write_deck(os.path.join(folder, "plain"), self.TEXT)
            named = kd.write_deck(os.path.join(folder, "named"), kd.add_parameters(
                self.TEXT, "Output", {"File Base": "out/x"}))
            self.assertEqual(kd.results_file("plain.xml", folder),
                             os.path.join(folder, "results", "plain.h5"))
            self.assertEqual(kd.results_file(plain), os.path.join("results", "plain.h5"))
            self.assertEqual(kd.results_file(named, folder), os.path.join(folder, "out/x.h5"))


class Runs(unittest.TestCase):
    def test_environment(self):
        env = kd.mpi_environment({"PMIX_RANK": "0", "OMPI_COMMAND": "x", "PATH": "/bin"})
        self.assertEqual(env, {"PATH": "/bin", "OMPI_ALLOW_RUN_AS_ROOT": "1",
                               "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
                               "OMPI_MCA_rmaps_base_oversubscribe": "1"})

    def test_exit_status_and_log(self):
        with tempfile.TemporaryDirectory() as folder:
            fake = kd.write_deck(os.path.join(folder, "fake"),
                                 'echo "ran $1 as root=$OMPI_ALLOW_RUN_AS_ROOT"; exit 3\n')
            log = os.path.join(folder, "fake.log")
            run = kd.run_kiln("/bin/sh", fake, args=["--restart"], expect=3, log=log)
            self.assertEqual((run.returncode, run.log), (3, "ran --restart as root=1\n"))
            self.assertEqual(Path(log).read_text(), run.log)
            with self.assertRaisesRegex(SystemExit, "exit 3, expected 0"):
                kd.run_kiln("/bin/sh", fake)
            self.assertEqual(kd.run_kiln("/bin/sh", fake, expect=None).returncode, 3)
            with self.assertRaisesRegex(SystemExit, "2 ranks need mpiexec"):
                kd.run_kiln("/bin/sh", fake, 2)

    def test_read_step(self):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "r.h5")
            with h5py.File(path, "w") as h5:
                h5["mesh/coordinates"] = np.eye(3)
                h5["mesh/connectivity"] = [[0, 1, 2]]
                h5["mesh/block_id"] = [7]
                for n, t in enumerate((0.0, 2.5)):
                    h5[f"steps/{n:06d}/temperature"] = [t, t, t]
                    h5[f"steps/{n:06d}"].attrs["time"] = t
                    h5[f"gap/steps/{n:06d}/contact_pressure"] = [t]
                h5["gap/node_a"], h5["gap/node_b"] = [0], [1]
            last, first = kd.read_step(path), kd.read_step(path, 0)
            self.assertEqual((last["time"], first["time"]), (2.5, 0.0))
            self.assertEqual(list(last["temperature"]), [2.5] * 3)
            self.assertEqual(list(last["gap/contact_pressure"]), [2.5])
            self.assertEqual((list(last["block"]), list(last["gap/node_b"])), ([7], [1]))


class Checks(unittest.TestCase):
    def test_counts_failures(self):
        check = kd.Checks()
        self.assertTrue(check(True, "a"))
        self.assertFalse(check(np.bool_(False), "b"))
        check(False, "c")
        self.assertEqual(check.failed, 2)


if __name__ == "__main__":
    unittest.main()
