#!/usr/bin/env python3
"""Rollers (Normal Displacement) on every element type: a uniaxial stretch, exact.

usage: roller_stretch_test.py KILN MPIEXEC CELL_TYPE

The unit cube [0, 1]^3 on 2^3 cells of CELL_TYPE, held by rollers on x = 0, y = 0, z = 0 and
moved by d = 1e-3 along the normal of x = 1 (a Normal Displacement, not a component): the
uniaxial stress state u = (d x, -nu d y, -nu d z) is linear, so every type must give it to
round-off. A roller's direction at a node is the node's normal on its faces; on the faces
of TETRA10 (TRI6) and HEX20 (QUAD8) the corners' shape functions integrate to zero or to a
negative share of the area, so a normal weighted by them is none (TETRA10: NaN) or the
inward one (HEX20: the corners moved by -d). Exit status 0 when the field is exact.
"""
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

D = 1e-3
LAMBDA, MU = 1.0, 1.0
NU = LAMBDA / (2 * (LAMBDA + MU))

DECK = """<ParameterList name="Kiln">
  <Parameter name="Physics" type="string" value="Elasticity"/>
  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="Box"/>
    <Parameter name="Gap Side Set" type="int" value="0"/>
    <ParameterList name="Box">
      <Parameter name="Size" type="Array(double)" value="{{1, 1, 1}}"/>
      <Parameter name="Cells" type="Array(int)" value="{{2, 2, 2}}"/>
      <Parameter name="Translation" type="Array(double)" value="{{0.5, 0.5, 0.5}}"/>
      <Parameter name="Cell Type" type="string" value="{cell_type}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Material">
    <Parameter name="Lame Lambda" type="double" value="{lam}"/>
    <Parameter name="Shear Modulus" type="double" value="{mu}"/>
  </ParameterList>
  <ParameterList name="Mechanics">
    <ParameterList name="Boundary Conditions">
      <ParameterList name="rollers">
        <Parameter name="Type" type="string" value="Normal Displacement"/>
        <Parameter name="Side Sets" type="Array(int)" value="{{1, 3, 5}}"/>
      </ParameterList>
      <ParameterList name="pulled">
        <Parameter name="Type" type="string" value="Normal Displacement"/>
        <Parameter name="Side Sets" type="Array(int)" value="{{2}}"/>
        <ParameterList name="Displacement">
          <Parameter name="Value" type="double" value="{d}"/>
        </ParameterList>
      </ParameterList>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Relative Tolerance" type="double" value="1e-12"/>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="File Base" type="string" value="{base}"/>
  </ParameterList>
</ParameterList>
"""


def main():
    kiln, mpiexec, cell_type = sys.argv[1:4]
    with tempfile.TemporaryDirectory() as folder:
        base = os.path.join(folder, "stretch")
        with open(base + ".xml", "w") as f:
            f.write(DECK.format(cell_type=cell_type, lam=LAMBDA, mu=MU, d=D, base=base))
        run = subprocess.run([mpiexec, "-np", "1", kiln, base + ".xml"], capture_output=True,
                             text=True)
        if run.returncode != 0:
            print(f"roller_stretch_test: kiln failed ({run.returncode}):\n{run.stdout[-3000:]}"
                  f"{run.stderr[-3000:]}")
            return 1
        with h5py.File(base + ".h5", "r") as h5:
            x = np.array(h5["mesh/coordinates"])
            last = sorted(h5["steps"].keys())[-1]
            u = np.array(h5["steps"][last]["displacement"])
    exact = np.column_stack([D * x[:, 0], -NU * D * x[:, 1], -NU * D * x[:, 2]])
    error = np.abs(u - exact).max() / D if np.all(np.isfinite(u)) else np.inf
    worst = int(np.argmax(np.abs(u - exact).max(axis=1))) if np.isfinite(error) else -1
    print(f"{cell_type}: {len(x)} nodes, largest error {error:.3g} of d"
          + (f" (node {worst + 1} at {x[worst]}: {u[worst]} vs {exact[worst]})" if error > 1e-10
             else ""))
    return 0 if error <= 1e-10 else 1


sys.exit(main())
