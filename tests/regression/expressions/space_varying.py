#!/usr/bin/env python3
"""Values that vary in space (Type "Expression", Initial Temperature Expression) in whole runs.

Usage: space_varying.py KILN WORK_DIR NP MPIEXEC

1. Displacement patch test: on a rotated, translated box (no gap), every face held at
   u = G x by three Displacement conditions whose values are formulas in x, y, z; the
   elastic solution is that linear field, so every node (interior ones included) must carry
   G x to rounding (the expression is evaluated at each node's own position).
2. Initial temperature field: a heat run whose initial temperature is 300 + 10x + 5yz; the
   state written at t = 0 must be that field at every node.
3. Traction formulas: a box held on its x- face and pulled on its x+ face by
   "Traction Expressions" {"1e6*(1 + 2*t)", "0", "0"} at t = 1 gives the displacements of
   "Traction" {3e6, 0, 0} (to rounding); {"3e6 + 1e7*(y - y0)", "0", "0"}, whose mean over
   the face is 3e6 Pa, gives different ones (the formula is evaluated at the Gauss points).
"""
import os
import subprocess
import sys

import h5py
import numpy as np

G = np.array([[1e-3, 2e-4, -3e-4], [5e-4, -1e-3, 1e-4], [-2e-4, 3e-4, 2e-3]])

MESH = """  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="Box"/>
    <Parameter name="Gap Side Set" type="int" value="0"/>
    <ParameterList name="Box">
      <Parameter name="Size" type="Array(double)" value="{0.4, 0.3, 0.2}"/>
      <Parameter name="Cells" type="Array(int)" value="{4, 3, 3}"/>
      <Parameter name="Phi" type="double" value="30"/>
      <Parameter name="Theta" type="double" value="20"/>
      <Parameter name="Translation" type="Array(double)" value="{0.1, -0.2, 0.3}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Material">
    <Parameter name="Young's Modulus" type="double" value="2e11"/>
    <Parameter name="Poisson's Ratio" type="double" value="0.3"/>
  </ParameterList>
"""


def displacement_deck(base):
    conditions = ""
    for d, c in enumerate("xyz"):
        formula = " + ".join(f"({G[d][k]!r})*{v}" for k, v in enumerate("xyz"))
        conditions += f"""      <ParameterList name="u_{c}">
        <Parameter name="Type" type="string" value="Displacement"/>
        <Parameter name="Side Sets" type="Array(int)" value="{{1, 2, 3, 4, 5, 6}}"/>
        <Parameter name="Components" type="Array(string)" value="{{{c}}}"/>
        <ParameterList name="Displacement">
          <Parameter name="Type" type="string" value="Expression"/>
          <Parameter name="Expression" type="string" value="{formula}"/>
        </ParameterList>
      </ParameterList>
"""
    return f"""<ParameterList name="Kiln">
  <Parameter name="Physics" type="string" value="Elasticity"/>
{MESH}  <ParameterList name="Mechanics">
    <ParameterList name="Boundary Conditions">
{conditions}    </ParameterList>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="File Base" type="string" value="{base}"/>
  </ParameterList>
</ParameterList>
"""


def initial_deck(base):
    return f"""<ParameterList name="Kiln">
  <Parameter name="Physics" type="string" value="Heat Conduction"/>
{MESH}  <ParameterList name="Thermal">
    <Parameter name="Initial Temperature Expression" type="string" value="300 + 10*x + 5*y*z"/>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="File Base" type="string" value="{base}"/>
    <Parameter name="Times" type="Array(double)" value="{{0, 1}}"/>
  </ParameterList>
</ParameterList>
"""


def traction_deck(load):
    def deck(base):
        return f"""<ParameterList name="Kiln">
  <Parameter name="Physics" type="string" value="Elasticity"/>
{MESH.replace('<Parameter name="Phi" type="double" value="30"/>', '').replace('<Parameter name="Theta" type="double" value="20"/>', '')}  <ParameterList name="Mechanics">
    <ParameterList name="Boundary Conditions">
      <ParameterList name="clamped">
        <Parameter name="Type" type="string" value="Displacement"/>
        <Parameter name="Side Sets" type="Array(int)" value="{{1}}"/>
        <Parameter name="Components" type="Array(string)" value="{{x, y, z}}"/>
      </ParameterList>
      <ParameterList name="pulled">
        <Parameter name="Type" type="string" value="Traction"/>
        <Parameter name="Side Sets" type="Array(int)" value="{{2}}"/>
        {load}
      </ParameterList>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="File Base" type="string" value="{base}"/>
    <Parameter name="Times" type="Array(double)" value="{{0, 1}}"/>
  </ParameterList>
</ParameterList>
"""
    return deck


def run(kiln, deck_text, work, name, n_ranks, mpiexec):
    base = os.path.join(work, name)
    with open(base + ".xml", "w", encoding="utf-8") as f:
        f.write(deck_text(base))
    command = [kiln, base + ".xml"]
    if int(n_ranks) > 1:
        command = [mpiexec, "-np", n_ranks] + command
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return h5py.File(base + ".h5", "r")


def main():
    kiln, work, n_ranks, mpiexec = sys.argv[1:5]
    os.makedirs(work, exist_ok=True)
    failures = 0
    with run(kiln, displacement_deck, work, "displacement", n_ranks, mpiexec) as h5:
        x = h5["mesh/coordinates"][...]
        u = h5["steps"][sorted(h5["steps"].keys())[-1]]["displacement"][...]
    exact = x @ G.T
    err = np.abs(u - exact).max() / np.abs(exact).max()
    print(f"displacement patch test: {len(x)} nodes, max |u - G x| / max |G x| = {err:.2e}")
    if not err < 1e-10:
        print("FAIL: the displacement is not G x")
        failures += 1
    with run(kiln, initial_deck, work, "initial", n_ranks, mpiexec) as h5:
        x = h5["mesh/coordinates"][...]
        T0 = h5["steps"][sorted(h5["steps"].keys())[0]]["temperature"][...]
    exact = 300 + 10 * x[:, 0] + 5 * x[:, 1] * x[:, 2]
    err = np.abs(T0 - exact).max()
    print(f"initial temperature field: max |T(0) - (300 + 10x + 5yz)| = {err:.2e} K")
    if not err < 1e-12:
        print("FAIL: the initial temperature is not the formula")
        failures += 1
    displacements = {}
    y0 = -0.2 - 0.15  # the translated box's y = -Ly/2 face (no rotation)
    for name, load in (
        ("vector", '<Parameter name="Traction" type="Array(double)" value="{3e6, 0, 0}"/>'),
        ("formula", '<Parameter name="Traction Expressions" type="Array(string)" '
                    'value="{1e6*(1 + 2*t), 0, 0}"/>'),
        ("varying", '<Parameter name="Traction Expressions" type="Array(string)" '
                    f'value="{{3e6 + 1e7*(y - ({y0 + 0.15})), 0, 0}}"/>')):
        with run(kiln, traction_deck(load), work, "traction-" + name, n_ranks, mpiexec) as h5:
            displacements[name] = h5["steps"][sorted(h5["steps"].keys())[-1]]["displacement"][...]
    scale = np.abs(displacements["vector"]).max()
    same = np.abs(displacements["formula"] - displacements["vector"]).max() / scale
    differ = np.abs(displacements["varying"] - displacements["vector"]).max() / scale
    print(f"traction formulas: |u(formula) - u(vector)| / |u| = {same:.2e}, "
          f"|u(varying) - u(vector)| / |u| = {differ:.2e}")
    if not same < 1e-10:
        print("FAIL: a formula of t gives another load than the same vector")
        failures += 1
    if not differ > 1e-3:
        print("FAIL: a traction varying over the face gives the uniform one's displacements")
        failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
