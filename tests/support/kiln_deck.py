"""Kiln decks and runs for the Python test scripts: the one place for the deck fragments they
share (a parameter list, a box mesh, materials, boundary conditions), for deriving a deck from
another, for running kiln under mpirun and for reading a results file.

A deck is a nested dict, written as XML by `xml`: a dict value is a ParameterList, anything
else a Parameter whose type follows from the Python value (bool, int, float, str; a list or
tuple of them an Array; a float is a double even when whole: write 298.0, not 298).
    deck = {"Physics": "Elasticity",
            "Mesh": box_mesh((1, 1, 1), (2, 2, 2)),
            "Material": lame(1.0, 1.0),
            "Mechanics": {"Boundary Conditions": {"rollers": normal_displacement([1, 3, 5])}},
            "Output": {"File Base": base}}
    run = run_kiln(kiln, write_deck(base, deck), 2, mpiexec)
    state = read_step(run.results)

Import it from a test script beside tests/support/:
    sys.path.insert(0, str(Path(__file__).resolve().parents[N] / "support"))
    import kiln_deck
"""
import os
import re
import subprocess
from collections import namedtuple

import h5py
import numpy as np

# ---------------------------------------------------------------------------------------------
# XML


def _type_of(value):
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, int):
        return "int"
    if isinstance(value, float):
        return "double"
    if isinstance(value, str):
        return "string"
    if isinstance(value, (list, tuple)) and value:
        kinds = {_type_of(v) for v in value}
        if kinds <= {"int", "double"}:
            return "Array(double)" if "double" in kinds else "Array(int)"
        if kinds == {"string"}:
            return "Array(string)"
    raise TypeError(f"no Teuchos type for {value!r}")


def _text_of(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (list, tuple)):
        return "{" + ", ".join(_text_of(v) for v in value) + "}"
    if isinstance(value, float):  # the shortest text that reads back as the same double
        short = f"{value:g}"
        return short if float(short) == value else repr(value)
    return str(value)


def parameter(name, value):
    """One <Parameter/> element, its type from the Python value."""
    return (f'<Parameter name="{name}" type="{_type_of(value)}" '
            f'value="{_text_of(value)}"/>')


def xml(entries, name="Kiln", indent=0):
    """The ParameterList `name` of `entries` (a dict: a dict value is a sublist)."""
    pad = " " * indent
    lines = [f'{pad}<ParameterList name="{name}">']
    for key, value in entries.items():
        if isinstance(value, dict):
            lines.append(xml(value, key, indent + 2).rstrip("\n"))
        else:
            lines.append(f"{pad}  {parameter(key, value)}")
    lines.append(f"{pad}</ParameterList>")
    return "\n".join(lines) + "\n"


def write_deck(base, deck):
    """Writes the deck (a dict, or XML text) to BASE.xml and returns that path."""
    path = base + ".xml"
    with open(path, "w", encoding="utf-8") as f:
        f.write(deck if isinstance(deck, str) else xml(deck))
    return path


# ---------------------------------------------------------------------------------------------
# Fragments


def box_mesh(size, cells, gap_side_set=0, **box):
    """Mesh of the box generator; `box` adds Box parameters by their Kiln names with spaces
    as underscores (cell_type="HEX27", translation=(...), phi=45.0, theta=-30.0)."""
    def kiln_value(value):  # coordinates and angles are doubles, whole or not
        return _floats(value) if not isinstance(value, str) else value

    extra = {key.replace("_", " ").title(): kiln_value(v) for key, v in box.items()}
    return {"Type": "Box", "Gap Side Set": gap_side_set,
            "Box": {"Size": _floats(size), "Cells": [int(n) for n in cells], **extra}}


def exodus_mesh(path, gap_side_set=0):
    """Mesh read from an Exodus II file."""
    return {"Type": "Exodus", "Gap Side Set": gap_side_set, "Exodus": {"File": path}}


def lame(lame_lambda, shear_modulus):
    """Elastic constants as Lame's lambda and the shear modulus [Pa]."""
    return {"Lame Lambda": float(lame_lambda), "Shear Modulus": float(shear_modulus)}


def young(youngs_modulus, poissons_ratio):
    """Elastic constants as Young's modulus [Pa] and Poisson's ratio."""
    return {"Young's Modulus": float(youngs_modulus), "Poisson's Ratio": float(poissons_ratio)}


def constant(value):
    """The sublist of a condition's constant value."""
    return {"Value": float(value)}


def expression(formula):
    """The sublist of a condition's value given as a formula in x, y, z, t."""
    return {"Type": "Expression", "Expression": formula}


def _floats(values):
    """A double or a list of doubles (a whole number given as an int included)."""
    return [float(v) for v in values] if isinstance(values, (list, tuple)) else float(values)


def _condition(kind, side_sets):
    return {"Type": kind, "Side Sets": [int(s) for s in side_sets]}


def displacement(side_sets, components, value=None):
    """Type "Displacement": the components held (to 0 without a value sublist)."""
    condition = {**_condition("Displacement", side_sets), "Components": list(components)}
    return condition if value is None else {**condition, "Displacement": value}


def normal_displacement(side_sets, value=None):
    """Type "Normal Displacement" (rollers without a value)."""
    condition = _condition("Normal Displacement", side_sets)
    return condition if value is None else {**condition, "Displacement": constant(value)}


def traction(side_sets, vector=None, expressions=None):
    """Type "Traction": a vector [Pa] or three formulas ("Traction Expressions")."""
    return {**_condition("Traction", side_sets),
            **({"Traction": _floats(vector)} if vector is not None else
               {"Traction Expressions": list(expressions)})}


def pressure(side_sets, value):
    """Type "Pressure" of a constant value [Pa] (negative: a tension)."""
    return {**_condition("Pressure", side_sets), "Pressure": constant(value)}


def temperature(side_sets, value):
    """Type "Temperature" of a constant value [K]."""
    return {**_condition("Temperature", side_sets), "Temperature": constant(value)}


# ---------------------------------------------------------------------------------------------
# Decks derived from a deck's text


def set_parameter(text, name, value, count=1):
    """Sets the value of the `count` Parameters called `name` (any type, kept) in the deck text;
    fails unless there are exactly that many."""
    text, n = re.subn(rf'(<Parameter name="{re.escape(name)}" type="[^"]*" value=")[^"]*"',
                      lambda m: m.group(1) + _text_of(value) + '"', text)
    if n != count:
        raise SystemExit(f"the deck has {n} parameters {name!r}, expected {count}")
    return text


def add_parameters(text, list_name, entries):
    """Adds the Parameters `entries` (a dict) at the start of the first ParameterList called
    `list_name` of the deck text; fails if there is none."""
    opening = f'<ParameterList name="{list_name}">'
    if opening not in text:
        raise SystemExit(f"the deck has no ParameterList {list_name!r}")
    added = "".join(f"\n    {parameter(k, v)}" for k, v in entries.items())
    return text.replace(opening, opening + added, 1)


# ---------------------------------------------------------------------------------------------
# Runs


def mpi_environment(environment=None):
    """The environment for mpiexec: as root (OMPI_ALLOW_RUN_AS_ROOT), oversubscribed, and
    without the variables of an MPI singleton (pvpython starts as one: they make mpiexec's
    kiln fail)."""
    singleton = ("PMIX_", "OMPI_COMMAND", "OMPI_ARGV", "OMPI_APP_CTX_", "OMPI_MCA_ess",
                 "OMPI_MCA_orte_", "OMPI_MCA_pmix")
    env = {k: v for k, v in (os.environ if environment is None else environment).items()
           if not k.startswith(singleton)}
    env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    return env


Run = namedtuple("Run", "deck results log returncode")


def run_kiln(kiln, deck, n_ranks=1, mpiexec=None, args=(), cwd=None, expect=0, log=None):
    """Runs kiln on the deck file (then `args`, e.g. ["--restart", FILE]) on n_ranks ranks:
    under `mpiexec -np N` when mpiexec is given, else kiln alone (then n_ranks must be 1), in
    the environment of mpi_environment(). stdout and stderr together are the log (also
    written to the file `log` if given). Stops the script (exit 1, the last 6000 characters
    of the log printed) unless kiln exits with `expect` (None: any status, the caller
    checks). Returns Run(deck, results, log, returncode); results: the HDF5 file of the
    deck's Output/File Base, read from the deck (relative to cwd)."""
    command = [kiln, str(deck), *map(str, args)]
    if mpiexec:
        command = [mpiexec, "-np", str(n_ranks)] + command
    elif int(n_ranks) != 1:
        raise SystemExit(f"run_kiln: {n_ranks} ranks need mpiexec")
    done = subprocess.run(command, cwd=cwd, env=mpi_environment(), stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True)
    if log is not None:
        with open(log, "w", encoding="utf-8") as f:
            f.write(done.stdout)
    if expect is not None and done.returncode != expect:
        print(done.stdout[-6000:])
        raise SystemExit(f"{' '.join(command)}: exit {done.returncode}, expected {expect}")
    return Run(str(deck), results_file(deck, cwd), done.stdout, done.returncode)


def results_file(deck, cwd=None):
    """The HDF5 results file of the deck: its Output/File Base (the default "" means
    results/<deck name>) + .h5, relative to cwd."""
    with open(os.path.join(cwd or ".", deck), encoding="utf-8") as f:
        text = f.read()
    m = re.search(r'<ParameterList name="Output">(?:(?!<ParameterList).)*?'
                  r'<Parameter name="File Base" type="string" value="([^"]+)"', text, re.S)
    name = os.path.splitext(os.path.basename(str(deck)))[0]
    base = m.group(1) if m else os.path.join("results", name)
    return os.path.join(cwd or "", base) + ".h5"


# ---------------------------------------------------------------------------------------------
# Results


class Checks:
    """check(ok, what) prints "pass: what" or "FAIL: what" and counts the failures
    (check.failed), so that a script reports every check before it exits."""

    def __init__(self):
        self.failed = 0

    def __call__(self, ok, what):
        print(f"{'pass' if ok else 'FAIL'}: {what}")
        self.failed += not ok
        return ok


def step_names(h5):
    """The names of /steps in order of output."""
    return sorted(h5["steps"].keys())


def read_step(path, which=-1):
    """One output step of a results file as a dict: "x" (node coordinates), "cells"
    (connectivity), "block" (cell block ids), "time", every field of the step by name, and
    for a file with a gap surface "gap/node_a", "gap/node_b" and "gap/<field>" of the step.
    which: the step's index in output order (-1: the last)."""
    with h5py.File(path, "r") as h5:
        key = step_names(h5)[which]
        step = h5["steps"][key]
        state = {"x": h5["mesh/coordinates"][...], "cells": h5["mesh/connectivity"][...],
                 "block": h5["mesh/block_id"][...], "time": float(step.attrs["time"])}
        state.update({name: np.array(step[name]) for name in step.keys()})
        if "gap" in h5:
            gap = h5["gap"]
            state["gap/node_a"], state["gap/node_b"] = gap["node_a"][...], gap["node_b"][...]
            state.update({"gap/" + name: np.array(v)
                          for name, v in gap["steps"][key].items()})
    return state
