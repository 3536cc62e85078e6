"""What the Python regression tests of closed-form states share (tests/regression/*/*.py): the
XML of a boundary condition, and a kiln run of a deck written into a temporary folder with the
fields of its last output step read back from the HDF5 results (doc/output-format.md).

A script imports it by putting tests/support on sys.path, as for exodus_mesh.py.
"""
import os
import subprocess
import tempfile

import h5py
import numpy as np


def condition_xml(name, kind, side_sets, components=None, value=None):
    """A boundary condition's sublist: `kind` ("Temperature", "Displacement", ...) on the side
    sets, with its "Components" and a constant value (the sublist named after the kind), if
    given."""
    text = f"""
      <ParameterList name="{name}">
        <Parameter name="Type" type="string" value="{kind}"/>
        <Parameter name="Side Sets" type="Array(int)" value="{{{', '.join(map(str, side_sets))}}}"/>"""
    if components is not None:
        text += f"""
        <Parameter name="Components" type="Array(string)" value="{{{components}}}"/>"""
    if value is not None:
        text += f"""
        <ParameterList name="{kind}">
          <Parameter name="Value" type="double" value="{value}"/>
        </ParameterList>"""
    return text + """
      </ParameterList>"""


def run_last_step(kiln, mpiexec, n_ranks, name, deck, fields, mesh=("coordinates",)):
    """Writes deck(base) (base: the results' File Base in a temporary folder) to BASE.xml, runs
    kiln on n_ranks ranks and returns ({mesh dataset: array}, {field: array of the last output
    step}), or None after printing kiln's output if it failed."""
    with tempfile.TemporaryDirectory() as folder:
        base = os.path.join(folder, name)
        with open(base + ".xml", "w") as f:
            f.write(deck(base))
        run = subprocess.run([mpiexec, "-np", str(n_ranks), kiln, base + ".xml"],
                             capture_output=True, text=True)
        if run.returncode != 0:
            print(f"kiln failed:\n{run.stdout[-3000:]}{run.stderr[-3000:]}")
            return None
        with h5py.File(base + ".h5", "r") as h5:
            mesh_data = {key: np.array(h5["mesh"][key]) for key in mesh}
            step = h5["steps"][sorted(h5["steps"].keys())[-1]]
            return mesh_data, {key: np.array(step[key]) for key in fields}
