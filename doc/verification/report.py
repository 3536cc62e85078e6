#!/usr/bin/python3
"""The verification report of Kiln's reference problem, the contact box, from one command.

    doc/verification/report.py [--build build] [--np 2] [--quick] [--out DIR] [--work DIR]

Runs kiln on decks derived from the four contact-box decks of inputs/ (variant A:
contact-box-{close,open}.xml, variant B: contact-box-{close,open}-convection.xml; only the
output times change, dense where the plots need them), and the closing deck on 4^3 to 32^3
cells (Mesh/Box/"Cells", to 56 s) for the closing time under refinement; the runs go to a
work folder (default BUILD/verification-work). It then

- compares the initial and final uniform states of each run with the analytic states of
  the spec (../shared/spec/contact-box.md), through tools/contact_box_report.cpp
  (BUILD/tools/kiln_contact_box_report): the formulas live there only;
- runs the heat-conduction convergence tests (BUILD/tests/verification_heat_convergence, on one
  rank) and reads the errors they print;
- runs the elasticity and thermo-elasticity convergence tests
  (BUILD/tests/verification_elastic_convergence, one rank) and reads their errors;
- runs every deck of inputs/truchas/ (--truchas) and tabulates the figures its check
  module doc/verification/truchas/NAME.py gives (doc/verification/truchas_section.py);
- writes OUT/report.md (default doc/verification/; with --quick BUILD/verification-quick/)
  with the tables, the spec's list of errors of the original statement and PNG plots.

--quick (for the test, doc/verification/check_report.py): coarser output times, the
refinement on 4^3 and 8^3 cells only, the temporal heat tests only.

Exit status 0 when every run succeeded and was compared (the report states the errors, it
does not judge them: check_report.py does), 1 when a run or a tool failed, 2 for a bad
command line. Uses Debian's python3-h5py, python3-numpy and python3-matplotlib
(packages/install.sh).
"""

import argparse
import csv
import datetime
import math
import os
import re
import shlex
import shutil
import subprocess
import sys
import time
import xml.etree.ElementTree as ET
from pathlib import Path

try:
    import h5py
    import numpy as np
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
except ImportError as error:  # pragma: no cover - depends on the machine
    sys.stderr.write(f"report.py: {error}; install python3-h5py, python3-numpy and "
                     "python3-matplotlib (packages/install.sh)\n")
    sys.exit(1)

HERE = Path(__file__).resolve().parent
SOURCE = HERE.parent.parent
sys.path.insert(0, str(HERE))
import truchas_section  # noqa: E402  (beside this file)

# The decks of inputs/ whose check modules are in doc/verification/interfaces/.
INTERFACE_DECKS = ["contact-box-close", "contact-box-crossing", "contact-box-crossing3"]
INTERFACE_HEADER = truchas_section.HEADER.replace("Truchas test", "case").replace(
    "within tolerance", "within bound")
NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|[-+]?nan|[-+]?inf"


class ReportError(Exception):
    """A run or a tool failed: the report cannot be made (exit status 1)."""


# --- output times -------------------------------------------------------------------------

def grid(start, stop, step):
    """start, start + step, ... up to stop (included), rounded to 1e-9 s."""
    n = int(round((stop - start) / step))
    return [round(start + k * step, 9) for k in range(n + 1)]


def output_times(variant, quick):
    """The output times of the derived decks. Kiln's time stepper lands on every output time
    (the steps are shortened to reach them), so dense output also means shorter steps.
    Variant A: every second (every 0.25 s from 45 to 56 s, where the gap closes or opens) to
    150 s; variant B: every 0.01 s to 0.5 s (the gap closes within 0.2 s, opens within 2 s),
    then coarser to 600 s. The spec's times (0, 50, 53, 150 and 0, 5, 600) are among them."""
    if variant == "A":
        if quick:
            times = grid(0, 150, 5) + grid(46, 56, 0.5) + [53]
        else:
            times = grid(0, 150, 1) + grid(45, 56, 0.25)
    else:
        if quick:
            times = grid(0, 0.3, 0.025) + grid(0.3, 2, 0.1) + grid(2, 10, 1) + \
                grid(10, 100, 10) + grid(100, 600, 100)
        else:
            times = grid(0, 0.5, 0.01) + grid(0.5, 2, 0.05) + grid(2, 10, 0.25) + \
                grid(10, 60, 1) + grid(60, 600, 10)
    return sorted(set(times))


# --- decks ----------------------------------------------------------------------------------

def find_list(root, path, create=False):
    """The ParameterList at `path` ("Mesh/Box") below the root list."""
    node = root
    for name in path.split("/"):
        child = next((c for c in node.findall("ParameterList") if c.get("name") == name), None)
        if child is None:
            if not create:
                return None
            child = ET.SubElement(node, "ParameterList", name=name)
        node = child
    return node


def get_parameter(root, path, name):
    """The value (text) of parameter `name` in the list at `path`, or None."""
    node = find_list(root, path)
    if node is None:
        return None
    p = next((c for c in node.findall("Parameter") if c.get("name") == name), None)
    return None if p is None else p.get("value")


def set_parameter(root, path, name, type_, value):
    node = find_list(root, path, create=True)
    p = next((c for c in node.findall("Parameter") if c.get("name") == name), None)
    if p is None:
        p = ET.SubElement(node, "Parameter", name=name)
    p.set("type", type_)
    p.set("value", value)


def array_text(values):
    return "{" + ", ".join(repr(float(v)) if not float(v).is_integer() else str(int(v))
                           for v in values) + "}"


def derive_deck(source, target, changes, result_base):
    """Writes `target`: the deck `source` with `changes` [(path, name, type, value)] and its
    results at `result_base` (no checkpoint at the end). Returns the list of changes."""
    tree = ET.parse(source)
    root = tree.getroot()
    changes = list(changes) + [("Output", "File Base", "string", str(result_base)),
                               ("Checkpoint", "At End", "bool", "false")]
    for path, name, type_, value in changes:
        set_parameter(root, path, name, type_, value)
    ET.indent(tree, space="  ")
    def short(value):
        if len(value) < 60:
            return value
        return value[:52] + (" ...}" if value.startswith("{") else " ...")
    header = (f"<!--\n  Derived by doc/verification/report.py from {source.relative_to(SOURCE)}:"
              "\n" + "".join(f"  {path}/\"{name}\" = {short(value)}\n"
                             for path, name, _, value in changes) + "-->\n")
    target.write_text(header + ET.tostring(root, encoding="unicode") + "\n")
    return changes


# --- running ---------------------------------------------------------------------------------

class Runner:
    def __init__(self, build, np_, work, reuse=False):
        self.build, self.np, self.work, self.reuse = build, np_, work, reuse
        self.reused = {}  # run: the Kiln commit it ran
        self.kiln = build / "src" / "app" / "kiln"
        self.report_tool = build / "tools" / "kiln_contact_box_report"
        self.heat_test = build / "tests" / "verification_heat_convergence"
        self.elastic_test = build / "tests" / "verification_elastic_convergence"
        for exe in (self.kiln, self.report_tool, self.heat_test, self.elastic_test):
            if not os.access(exe, os.X_OK):
                raise ReportError(f"{exe}: not built (cmake --build {build})")
        self.mpiexec = shutil.which("mpirun") or shutil.which("mpiexec")
        if self.mpiexec is None:
            raise ReportError("no mpirun on the PATH (packages/install.sh: openmpi-bin)")
        self.env = dict(os.environ, OMPI_MCA_rmaps_base_oversubscribe="1")
        if os.geteuid() == 0:  # Open MPI refuses root unless told
            self.env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        self.wall = {}

    def mpi(self, np_, command, log, label):
        """Runs `command` on np_ ranks, its output to `log`; the wall time in self.wall."""
        full = [self.mpiexec, "-np", str(np_)] + [str(c) for c in command]
        print(f"report.py: {label}: {' '.join(shlex.quote(c) for c in full)}", flush=True)
        start = time.monotonic()
        with open(log, "w") as out:
            status = subprocess.call(full, stdout=out, stderr=subprocess.STDOUT, env=self.env,
                                     cwd=log.parent)
        self.wall[label] = time.monotonic() - start
        if status != 0:
            tail = "".join(Path(log).read_text(errors="replace").splitlines(True)[-15:])
            raise ReportError(f"{label} failed (exit status {status}); the end of {log}:\n{tail}")
        print(f"report.py: {label}: {self.wall[label]:.1f} s", flush=True)

    def run_case(self, name, source, changes):
        """kiln on a deck derived from `source`; returns (deck, results.h5, changes). With
        --reuse, a finished run of the same derived deck on as many ranks is used as it is
        (its wall time and the Kiln commit it ran in run.txt)."""
        folder = self.work / name
        deck = folder / f"{name}.xml"
        base = folder / "results" / name
        record = folder / "run.txt"
        if self.reuse and record.is_file() and deck.is_file():
            previous = deck.read_text()
            derive_deck(source, deck, changes, base)
            run = dict(line.split(" ", 1) for line in record.read_text().splitlines())
            if deck.read_text() == previous and run.get("np") == str(self.np) and \
                    base.with_suffix(".h5").is_file():
                self.wall[name] = float(run["wall"])
                self.reused[name] = run["commit"]
                print(f"report.py: {name}: reused (run by Kiln {run['commit']})", flush=True)
                return deck, base.with_suffix(".h5"), changes
        shutil.rmtree(folder, ignore_errors=True)
        folder.mkdir(parents=True)
        changes = derive_deck(source, deck, changes, base)
        self.mpi(self.np, [self.kiln, deck], folder / "log.txt", name)
        record.write_text(f"wall {self.wall[name]}\nnp {self.np}\ncommit {kiln_commit()}\n")
        return deck, base.with_suffix(".h5"), changes

    def contact_box_report(self, deck, results, step, folder):
        """kiln_contact_box_report on one output step (copied alone to a file of its own,
        since the tool reads the last step); its output."""
        single = folder / f"step-{step}.h5"
        with h5py.File(results, "r") as src, h5py.File(single, "w") as dst:
            src.copy(src["/mesh"], dst, "mesh")
            dst.create_group("steps")
            src.copy(src[f"/steps/{step}"], dst["/steps"], "000000")
        done = subprocess.run([str(self.report_tool), deck.name, single.name],
                              capture_output=True, text=True, cwd=folder)
        if done.returncode != 0:
            raise ReportError(f"kiln_contact_box_report {deck} {single} failed:\n"
                              f"{done.stdout}{done.stderr}")
        return done.stdout

    def heat_convergence(self, quick):
        """The heat convergence unit tests on one rank (their errors do not depend on the
        rank count, and they are several times faster there on a loaded machine); their
        output. --quick: the temporal tests only."""
        folder = self.work / "heat-convergence"
        shutil.rmtree(folder, ignore_errors=True)
        folder.mkdir(parents=True)
        command = [self.heat_test, "--gtest_color=no"]
        if quick:
            command.append("--gtest_filter=*HeatConvergence.BackwardEuler*:*HeatConvergence.Bdf2*")
        self.mpi(1, command, folder / "log.txt", "heat convergence tests")
        return (folder / "log.txt").read_text()

    def elastic_convergence(self):
        """The elasticity and thermo-elasticity convergence tests on one rank (4 to 32 cells
        along a bar, seconds); their output."""
        folder = self.work / "elastic-convergence"
        shutil.rmtree(folder, ignore_errors=True)
        folder.mkdir(parents=True)
        self.mpi(1, [self.elastic_test, "--gtest_color=no"], folder / "log.txt",
                 "elastic convergence tests")
        return (folder / "log.txt").read_text()


# --- reading results -------------------------------------------------------------------------

DEFAULT_TENSOR_COMPONENTS = ("xx", "yy", "zz", "xy", "xz", "yz")  # doc/output-format.md
TENSOR_COMPONENTS = ("xx", "yy", "zz", "xy", "yz", "xz")  # the order of the plots


def tensor_components(dataset):
    """{"xx": column, ...} of a 6-component tensor dataset (rows x 6). The one place that
    knows the stored order: the dataset's attribute `components` (comma-separated names such
    as "xx,yy,zz,xy,yz,xz" or "stress_xx,...") when it has one, else Kiln's documented Voigt
    order xx yy zz xy xz yz (doc/output-format.md)."""
    names = DEFAULT_TENSOR_COMPONENTS
    if "components" in dataset.attrs:
        value = dataset.attrs["components"]
        if isinstance(value, np.ndarray):
            value = ",".join(v.decode() if isinstance(v, bytes) else str(v)
                             for v in value.ravel())
        if isinstance(value, bytes):
            value = value.decode()
        names = tuple(n.strip().lower().rsplit("_", 1)[-1] for n in str(value).split(",")
                      if n.strip())
    if dataset.ndim != 2 or dataset.shape[1] != len(names) or \
            sorted(names) != sorted(DEFAULT_TENSOR_COMPONENTS):
        raise ReportError(f"{dataset.file.filename}:{dataset.name}: expected 6 tensor "
                          f"components xx yy zz xy xz yz, got shape {dataset.shape} and "
                          f"components {names}")
    data = dataset[:]
    return {name: data[:, k] for k, name in enumerate(names)}


def step_names(f):
    return sorted(f["/steps"].keys())


class Geometry:
    """The gap nodes of each side and the end-face nodes of a contact-box result file. The
    gap nodes are those with a gap opening (NaN elsewhere); the gap's plane is fitted to
    them, and the end faces are the nodes farthest from it (no rotation formula needed)."""

    def __init__(self, f):
        x = f["/mesh/coordinates"][:]
        connectivity = f["/mesh/connectivity"][:]
        block = f["/mesh/block_id"][:]
        first = f[f"/steps/{step_names(f)[0]}"]
        gap = ~np.isnan(first["gap_opening"][:])
        centre = x[gap].mean(axis=0)
        normal = np.linalg.svd(x[gap] - centre)[2][-1]
        distance = np.abs((x - centre) @ normal)
        self.end = distance > distance.max() * (1 - 1e-9)
        side_1 = np.zeros(len(x), bool)
        first_side = np.unique(connectivity[block == block.min()])
        side_1[first_side[first_side >= 0]] = True  # rows padded with -1 on a mixed mesh
        self.gap_1, self.gap_2 = gap & side_1, gap & ~side_1
        self.gap = gap
        self.n_cells = len(connectivity)


def gap_series(path):
    """times, largest and smallest gap opening at every output step of a result file."""
    with h5py.File(path, "r") as f:
        names = step_names(f)
        times = np.array([f[f"/steps/{s}"].attrs["time"] for s in names])
        opening = [f[f"/steps/{s}/gap_opening"][:] for s in names]
    return times, np.array([np.nanmax(g) for g in opening]), \
        np.array([np.nanmin(g) for g in opening])


def full_series(path):
    """Every quantity the plots need, per output step."""
    with h5py.File(path, "r") as f:
        geometry = Geometry(f)
        names = step_names(f)
        s = {k: [] for k in ("time", "T_end", "T_gap_1", "T_gap_2", "T_mean", "pressure",
                             "pressure_min", "pressure_max", "opening_max", "opening_min",
                             "in_contact") + TENSOR_COMPONENTS}
        for name in names:
            step = f[f"/steps/{name}"]
            T = step["temperature"][:]
            pressure = step["contact_pressure"][:][geometry.gap]
            opening = step["gap_opening"][:][geometry.gap]
            s["time"].append(step.attrs["time"])
            s["T_end"].append(T[geometry.end].mean())
            s["T_gap_1"].append(T[geometry.gap_1].mean())
            s["T_gap_2"].append(T[geometry.gap_2].mean())
            s["T_mean"].append(T.mean())
            s["pressure"].append(pressure.mean())
            s["pressure_min"].append(pressure.min())
            s["pressure_max"].append(pressure.max())
            s["opening_max"].append(opening.max())
            s["opening_min"].append(opening.min())
            s["in_contact"].append(step["contact_active"][:][geometry.gap].mean())
            # The box mesh has cells of equal volume: the cell mean is the volume average.
            for component, values in tensor_components(step["stress"]).items():
                s[component].append(values.mean())
        first, last = names[0], names[-1]
    series = {k: np.array(v) for k, v in s.items()}
    series["steps"] = (first, last)
    return series


def history_gap(results):
    """(time, largest gap opening) of every accepted step, from the run's history CSV."""
    with open(str(results)[:-len(".h5")] + ".history.csv", newline="") as f:
        rows = list(csv.DictReader(f))

    def column(name):
        key = next(k for k in rows[0] if k.split(" [")[0] == name)
        return np.array([float(r[key]) for r in rows])

    return column("time"), column("max_gap")


def corefined_section(corefined):
    md = ["## Closing time with space and time refined together", "",
          "The closing deck (variant A) on n^3 cells with fixed time steps of 4/n s "
          "(`Time Stepping`: `Initial Step` = `Maximum Step` = 4/n, `Growth Factor` 1, `Error "
          "Control` false: 1 s on 4^3 ... 0.125 s on 32^3; BDF2, second order in time as Q1 "
          "is in space), run to 56 s; the closing time is where "
          "the largest gap opening of the accepted steps (the history's `max_gap`) reaches "
          "zero, extrapolated from the last two steps with an open gap. Above, the output "
          "times fixed the steps near the closing at 0.25 s on every mesh, so the time error "
          "stayed while the cells shrank; here both go down together.", "",
          "| cells | h [mm] | largest step [s] | steps | closing time [s] | "
          "difference to the coarser [s] | ratio | observed order | wall time [s] |",
          "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    events = [r["event"] for r in corefined]
    for k, r in enumerate(corefined):
        d = events[k] - events[k - 1] if k else None
        ratio = (events[k - 1] - events[k - 2]) / d if k >= 2 and d else None
        order = math.log2(abs(ratio)) if ratio else None
        md.append(f"| {r['n']}^3 | {r['h'] * 1e3:g} | {r['dt']:g} | {r['steps']} | "
                  f"{r['event']:.4f} | {'' if d is None else f'{d:+.4f}'} | "
                  f"{'' if ratio is None else f'{ratio:.2f}'} | "
                  f"{'' if order is None else f'{order:.2f}'} | {r['wall']:.0f} |")
    if len(events) >= 3:
        a, b, c = events[-3:]
        md += ["", f"Richardson extrapolation of the last three with order 2: "
               f"{c + (c - b) / 3:.4f} s. The closing time is when the last pair closes (the "
               "largest opening reaches zero): each refinement adds pairs, and the last to close "
               "sit at the gap's edge, where the temperature lags most, so the time settles "
               "more slowly than a smooth field would (compare the ratios); the spec's window, "
               "50 to 53 s, holds on every mesh."]
    md.append("")
    return md


def gap_event_time(times, opening, closing):
    """The time `opening` (per output step) reaches 0 (closing) or leaves 0 (opening): the
    line through the last two outputs where it is positive before the first where it is zero
    (closing), or the first two after the last zero (opening), extrapolated to zero. With the
    largest opening over the gap nodes, the closing time is when the last pair closes; with
    the smallest, the opening time is when the last pair opens (Kiln's log: "the gap has
    closed", "the gap has opened"). Returns (time, (output before, output after)), or
    (None, None) when there is no such event. Zero: below 1e-6 of the largest value of the
    run (the opening of a closed pair is solver noise, 1e-19 to 1e-14 m)."""
    zero = 1e-6 * np.max(opening)
    is_open = opening > zero
    for k in range(1, len(times)):
        if closing and is_open[k - 1] and not is_open[k] and k >= 2 and is_open[k - 2]:
            t0, t1, g0, g1 = times[k - 2], times[k - 1], opening[k - 2], \
                opening[k - 1]
            return t1 + g1 * (t1 - t0) / (g0 - g1), (times[k - 1], times[k])
        if not closing and not is_open[k - 1] and is_open[k] and k + 1 < len(times) and \
                is_open[k + 1]:
            t1, t2, g1, g2 = times[k], times[k + 1], opening[k], opening[k + 1]
            return t1 - g1 * (t2 - t1) / (g2 - g1), (times[k - 1], times[k])
    return None, None


# --- the report tool's table -----------------------------------------------------------------

ROW = re.compile(r"^  (sigma' \w\w \[Pa\]|eps' \w\w \[-\]|contact pressure \[Pa\]|"
                 r"gap opening \[m\])\s+(" + NUMBER + r") \.\. (" + NUMBER + r")\s+(" + NUMBER +
                 r")\s+(" + NUMBER + r")( \w+)?( abs\.)?\s*$")
HEAD = re.compile(r"^contact box at t = (\S+) s: gap (closed|open|partly closed) \((\d+) of "
                  r"(\d+) pairs in contact\), T = (" + NUMBER + r") K \(spread (" + NUMBER +
                  r") K\)")


def parse_table(text):
    """The state and the rows of kiln_contact_box_report's output."""
    head = next((HEAD.match(l) for l in text.splitlines() if HEAD.match(l)), None)
    if head is None:
        raise ReportError("kiln_contact_box_report printed no \"contact box at t = ...\" line:\n"
                          + text)
    table = {"time": float(head.group(1)), "gap": head.group(2), "T": float(head.group(5)),
             "T_spread": float(head.group(6)), "rows": {}}
    for line in text.splitlines():
        m = ROW.match(line)
        if m:
            table["rows"][m.group(1)] = {"min": float(m.group(2)), "max": float(m.group(3)),
                                         "exact": float(m.group(4)),
                                         "error": float(m.group(5))}
    return table


def table_errors(table):
    """The largest error of each group of rows (relative; absolute [m] for the opening)."""
    rows = table["rows"]

    def largest(prefix):
        errors = [r["error"] for name, r in rows.items() if name.startswith(prefix)]
        return max(errors) if errors else float("nan")
    return {"stress": largest("sigma'"), "strain": largest("eps'"),
            "pressure": largest("contact pressure"), "opening": largest("gap opening")}


# --- heat convergence tests ------------------------------------------------------------------

def parse_heat(text):
    """{"space": [(h, L2 error)], "Backward Euler": [(dt, error)], "BDF2": [...]} from the
    output of verification_heat_convergence (each rank may print the same lines)."""
    space, time_ = {}, {"Backward Euler": {}, "BDF2": {}}
    for line in text.splitlines():
        m = re.match(r"^cells (\d+) x \d+ x \d+: L2 error (" + NUMBER + ")", line)
        if m:
            space[1.0 / int(m.group(1))] = float(m.group(2))  # the test's box: L = 1 m
        m = re.match(r"^(Backward Euler|BDF2) dt (" + NUMBER + r"): max nodal error (" +
                     NUMBER + ")", line)
        if m:
            time_[m.group(1)][float(m.group(2))] = float(m.group(3))
    result = {"space": sorted(space.items(), reverse=True)}  # coarse to fine
    result.update({k: sorted(v.items(), reverse=True) for k, v in time_.items()})
    return result


ELASTIC_CASES = (("own weight", "bar under its own weight (Elasticity)"),
                 ("thermal", "bar under a linear temperature (Thermo-Elasticity)"))


def parse_elastic(text):
    """{case: [(cells, L2 error of u_z, L2 error of the cell stress)]} from the lines
    "<case> cells N: L2 error u E, sigma S" of verification_elastic_convergence."""
    found = {key: [] for key, _ in ELASTIC_CASES}
    for key, cells, u, sigma in re.findall(
            rf"^(own weight|thermal) cells (\d+): L2 error u ({NUMBER}), sigma ({NUMBER})",
            text, re.M):
        found[key].append((int(cells), float(u), float(sigma)))
    return found


def elastic_section(elastic):
    """The report's lines on the elasticity convergence orders."""
    md = ["## Elasticity and thermo-elasticity: convergence order", "",
          "`tests/verification/elastic_convergence_test.cpp` (run as "
          "`build/tests/verification_elastic_convergence` on 1 rank): a bar of length 1 m "
          "(0.25 x 0.25 m, 2 x 2 x N cells) on rollers on its four sides, u_z = 0 at its "
          "bottom, the top free; E = 1 Pa, nu = 0.25. Under its own weight (b_z = -1 N/m^3) "
          "sigma_zz = b_z (L - z) and u_z = b_z (L z - z^2/2) / M (M = lambda + 2G); under a "
          "steady T = T_ref + 10 z / L (temperature held on the end faces, alpha = 1e-3/K) "
          "sigma_zz = 0, sigma_xx = sigma_yy = (lambda/M - 1) beta (T - T_ref) and "
          "u_z = 10 beta z^2 / (2 M L). Both stresses vary linearly along the bar. Theory: the "
          "fields are one-dimensional and Q1 is then exact at the nodes, so the L2 error of "
          "u_z is the interpolation error of a quadratic (order 2) and the cell-averaged "
          "stress, constant per cell against a linear stress, has an L2 error of order 1 (it "
          "equals the exact stress at the cell centres). Three-dimensional manufactured "
          "solutions without a source (harmonic fields) on every element type, and with "
          "E(T): [manufactured-solutions.md](manufactured-solutions.md). The test "
          "asserts the last orders (2 +- 0.1, 1 +- 0.1).", "",
          "| case | cells along the bar | L2 error u_z [m^2.5] | order u | "
          "L2 error stress [Pa m^1.5] | order stress |", "|---|---:|---:|---:|---:|---:|"]
    for key, label in ELASTIC_CASES:
        points = elastic[key]
        for k, (n, u, sigma) in enumerate(points):
            if k:
                _, u0, s0 = points[k - 1]
                orders = f"{math.log2(u0 / u):.3f} | {sigma:.4e} | {math.log2(s0 / sigma):.3f}"
            else:
                orders = f" | {sigma:.4e} | "
            md.append(f"| {label} | {n} | {u:.4e} | {orders} |")
    md.append("")
    return md


def fitted_order(points):
    """Least-squares slope of log(error) against log(h) over all points, and the order of
    the last two points (the finest)."""
    if len(points) < 2:
        return float("nan"), float("nan")
    h, e = np.log([p[0] for p in points]), np.log([p[1] for p in points])
    slope = np.polyfit(h, e, 1)[0]
    last = (e[-1] - e[-2]) / (h[-1] - h[-2]) if h[-1] != h[-2] else float("nan")
    return slope, last


# --- plots -------------------------------------------------------------------------------------

def time_axis(ax, variant):
    if variant == "B":  # the gap event within 2 s, the uniform state at 600 s
        ax.set_xscale("symlog", linthresh=0.1, linscale=0.5)
        ax.set_xlim(0, 600)
    ax.set_xlabel("time [s]")
    ax.grid(True, which="both", alpha=0.3)


def data_ticks(ax, values):
    """Ticks at the data on a logarithmic x axis, labelled plainly."""
    ax.set_xticks(values)
    ax.xaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))


def save(fig, path):
    for ax in fig.axes:
        if ax.get_xscale() == "log":  # no labels on the minor ticks (they overlap)
            ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def plot_temperature(variant, cases, path):
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8), sharey=True)
    for ax, case in zip(axes, cases):
        s = case["series"]
        ax.plot(s["time"], s["T_end"], label="end faces (mean)")
        ax.plot(s["time"], s["T_gap_1"], label="gap, side of block 1 (mean)")
        ax.plot(s["time"], s["T_gap_2"], "--", label="gap, side of block 2 (mean)")
        ax.plot(s["time"], s["T_mean"], ":", color="k", label="whole body (nodal mean)")
        mark_event(ax, case)
        ax.set_title(title(case), fontsize=9)
        time_axis(ax, variant)
    axes[0].set_ylabel("temperature [K]")
    axes[0].legend(fontsize=8)
    save(fig, path)


def mark_event(ax, case):
    """The gap event as a red dashed line (its time is in the title)."""
    if case.get("event") is not None:
        ax.axvline(case["event"], color="r", lw=0.8, ls="--")


def title(case):
    if case.get("event") is None:
        return case["title"] + ": no gap event"
    return f"{case['title']}: gap {case['event_word']} at {case['event']:.2f} s (red)"


def plot_gap(variant, cases, path):
    fig, axes = plt.subplots(3, 2, figsize=(10, 7.5), sharex="col")
    for column, case in enumerate(cases):
        s = case["series"]
        ax = axes[0, column]
        ax.fill_between(s["time"], s["pressure_min"] / 1e6, s["pressure_max"] / 1e6,
                        alpha=0.3, label="min .. max over the gap nodes")
        ax.plot(s["time"], s["pressure"] / 1e6, label="mean over the gap nodes")
        ax.set_ylabel("contact pressure [MPa]\n(> 0 in compression)")
        ax.set_title(title(case), fontsize=9)
        time_axis(ax, variant)
        mark_event(ax, case)
        ax = axes[1, column]
        ax.plot(s["time"], s["opening_max"] * 1e6, label="largest")
        ax.plot(s["time"], s["opening_min"] * 1e6, "--", label="smallest")
        ax.set_ylabel("gap opening [µm]")
        time_axis(ax, variant)
        mark_event(ax, case)
        ax = axes[2, column]
        ax.plot(s["time"], 100 * s["in_contact"])
        ax.set_ylabel("gap pairs in contact [%]")
        ax.set_ylim(-5, 105)
        time_axis(ax, variant)
        mark_event(ax, case)
    for ax in axes[:-1].ravel():
        ax.set_xlabel("")
    axes[0, 0].legend(fontsize=8)
    axes[1, 0].legend(fontsize=8)
    save(fig, path)


def plot_stress(variant, cases, path):
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, case in zip(axes, cases):
        s = case["series"]
        for k, component in enumerate(TENSOR_COMPONENTS):
            line, = ax.plot(s["time"], s[component] / 1e6, label=f"sigma' {component}")
            for table in case["tables"]:
                exact = table["rows"].get(f"sigma' {component} [Pa]")
                if exact is not None:
                    ax.plot([table["time"]], [exact["exact"] / 1e6], "o", mfc="none",
                            color=line.get_color(), ms=7)
        mark_event(ax, case)
        ax.set_title(title(case), fontsize=9)
        time_axis(ax, variant)
    for ax in axes:
        ax.set_ylabel("stress, mean over the cells [MPa]")
    axes[0].legend(fontsize=8, ncol=2, title="mesh frame; o: analytic uniform state",
                   title_fontsize=8)
    save(fig, path)


ENERGY_FLUX = 1.0e4  # W/m^2 into the box through each end face
ENERGY_AREA = 2 * 0.04 * 0.04  # the two end faces of the 4 cm box [m^2]


def energy_deck(source, target):
    """The closing contact box as heat conduction alone, its end faces heated by a constant
    flux instead of a temperature (the heat in is then known exactly: q A t)."""
    root = ET.parse(source).getroot()
    physics = next(c for c in root.findall("Parameter") if c.get("name") == "Physics")
    physics.set("value", "Heat Conduction")
    for block in list(root):
        if block.get("name") == "Mechanics":
            root.remove(block)
    ends = find_list(root, "Thermal/Boundary Conditions/heated ends")
    for child in list(ends):
        if child.get("name") in ("Type", "Temperature"):
            ends.remove(child)
    ET.SubElement(ends, "Parameter", name="Type", type="string", value="Heat Flux")
    flux = ET.SubElement(ends, "ParameterList", name="Heat Flux")
    ET.SubElement(flux, "Parameter", name="Value", type="double", value=repr(ENERGY_FLUX))
    set_parameter(root, "Output", "Times", "Array(double)", "{0, 10, 20, 30}")
    target.parent.mkdir(parents=True, exist_ok=True)
    ET.ElementTree(root).write(target)
    return target


def energy_balance(results):
    """Per accepted step of the run's history: the energy stored since t = 0 (thermal_energy,
    int rho c T dV) against the heat in through the end faces, q A t."""
    history = Path(str(results)[:-len(".h5")] + ".history.csv")
    with open(history, newline="") as f:
        rows = list(csv.DictReader(f))

    def column(row, name):
        return float(next(v for k, v in row.items() if k.split(" [")[0] == name))

    E0 = column(rows[0], "thermal_energy")
    steps = []
    for row in rows[1:]:
        t = column(row, "time")
        stored = column(row, "thermal_energy") - E0
        heat_in = ENERGY_FLUX * ENERGY_AREA * t
        steps.append({"step": int(column(row, "step")), "t": t, "stored": stored,
                      "in": heat_in, "error": abs(stored - heat_in) / heat_in})
    return steps


def energy_section(steps):
    md = ["## Energy balance", "",
          "The closing contact box as heat conduction alone (4^3 cells, the gap with its "
          f"conductance, BDF2 with adaptive steps), its end faces heated by a flux of "
          f"{ENERGY_FLUX:g} W/m^2 instead of a temperature, insulated elsewhere: the heat in "
          f"through the {ENERGY_AREA:g} m^2 of the two faces is q A t = "
          f"{ENERGY_FLUX * ENERGY_AREA:g} W x t exactly. Every accepted step's energy stored "
          "since t = 0 (the history's `thermal_energy`, int rho c T dV, minus its initial "
          "value) against it. The capacity rows sum to the stored energy's rate and the "
          "conduction and gap rows to zero, and BDF2 (its first step backward Euler) "
          "integrates a linear energy exactly: the balance holds to the Newton tolerance at "
          "every step.", "",
          "| step | t [s] | stored [J] | heat in [J] | relative difference |",
          "|---:|---:|---:|---:|---:|"]
    md += [f"| {s['step']} | {s['t']:.6g} | {s['stored']:.9g} | {s['in']:.9g} | "
           f"{s['error']:.1e} |" for s in steps]
    md += ["", f"Largest relative difference: {max(s['error'] for s in steps):.1e} "
           f"over {len(steps)} steps.", ""]
    return md


def plot_closing(refinement, path):
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    ax = axes[0]
    for r in refinement:
        window = (r["times"] >= 49.9) & (r["times"] <= 52.1)
        ax.plot(r["times"][window], r["opening"][window] * 1e6, ".-", ms=3,
                label=f"{r['n']}^3 cells: {r['event']:.3f} s")
        ax.axvline(r["event"], color=ax.lines[-1].get_color(), lw=0.6, ls="--")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("largest gap opening [µm]")
    ax.set_title("closing deck: the gap closing under refinement", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(True, alpha=0.3)
    ax = axes[1]
    h = np.array([r["h"] for r in refinement])
    t = np.array([r["event"] for r in refinement])
    if len(refinement) >= 2:
        differences = np.abs(np.diff(t))
        ax.loglog(h[1:] * 1e3, differences, "o-",
                  label="|t_close(h) - t_close(2h)|")
        if len(differences) >= 2:
            slope = np.polyfit(np.log(h[1:]), np.log(differences), 1)[0]
            ax.loglog(h[1:] * 1e3, differences[-1] * (h[1:] / h[-1]) ** 2, ":", color="gray",
                      label="order 2")
            ax.set_title(f"differences of the closing time: fitted order {slope:.2f}",
                         fontsize=10)
        ax.legend(fontsize=8)
    ax.set_xlabel("cell size h [mm]")
    data_ticks(ax, h[1:] * 1e3)
    ax.set_ylabel("difference [s]")
    ax.grid(True, which="both", alpha=0.3)
    save(fig, path)


def plot_heat(heat, path):
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    ax = axes[0]
    if heat["space"]:
        h, e = zip(*heat["space"])
        slope, last = fitted_order(heat["space"])
        ax.loglog(h, e, "o-", label=f"BDF2, L2 error: fitted order {slope:.2f}")
        ax.loglog(h, e[-1] * (np.array(h) / h[-1]) ** 2, ":", color="gray", label="order 2")
        data_ticks(ax, h)
        ax.legend(fontsize=8)
    else:
        ax.text(0.5, 0.5, "not run (--quick)", ha="center", transform=ax.transAxes)
    ax.set_xlabel("cell size h along the mode [m]")
    ax.set_ylabel("L2 error at t = 5e-3 s [K m^1.5]")
    ax.set_title("space: cosine mode decay, rotated box", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax = axes[1]
    for method, order in (("Backward Euler", 1), ("BDF2", 2)):
        if heat[method]:
            dt, e = zip(*heat[method])
            slope, last = fitted_order(heat[method])
            line, = ax.loglog(dt, e, "o-", label=f"{method}: fitted order {slope:.2f}")
            ax.loglog(dt, e[-1] * (np.array(dt) / dt[-1]) ** order, ":",
                      color=line.get_color(), lw=0.8, label=f"order {order}")
            data_ticks(ax, dt)
    ax.set_xlabel("time step dt [s]")
    ax.set_ylabel("max nodal error at t = 0.1 s [K]")
    ax.set_title("time: error against the semi-discrete solution (8 x 2 x 2)", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    save(fig, path)


# --- the report --------------------------------------------------------------------------------

CASES = [  # key, variant, deck, title, gap event
    ("A-close", "A", "contact-box-close.xml", "variant A, closing (heated ends)", "closed"),
    ("A-open", "A", "contact-box-open.xml", "variant A, opening (cooled ends)", "opened"),
    ("B-close", "B", "contact-box-close-convection.xml",
     "variant B, closing (convection, 398 K air)", "closed"),
    ("B-open", "B", "contact-box-open-convection.xml",
     "variant B, opening (convection, 288 K air)", "opened"),
]


def expected_temperatures(deck):
    """(initial, final) uniform temperature of a contact-box deck: the initial temperature,
    and the end value of a prescribed smooth step or the ambient temperature of convection
    on the end faces."""
    root = ET.parse(deck).getroot()
    initial = float(get_parameter(root, "Thermal", "Initial Temperature"))
    bcs = find_list(root, "Thermal/Boundary Conditions")
    bc = bcs.findall("ParameterList")[0].get("name")
    path = f"Thermal/Boundary Conditions/{bc}"
    kind = get_parameter(root, path, "Type")
    if kind == "Temperature":
        final = get_parameter(root, path + "/Temperature", "End Value") or \
            get_parameter(root, path + "/Temperature", "Value")
    else:
        final = get_parameter(root, path + "/Ambient Temperature", "Value")
    return initial, float(final)


def spec_errors(spec):
    """The section "Errors in the original statement" of the spec, as written there."""
    text = spec.read_text()
    m = re.search(r"^## Errors in the original statement\n(.*?)(?=^## |\Z)", text, re.S | re.M)
    if m is None:
        raise ReportError(f"{spec}: no section \"## Errors in the original statement\"")
    return m.group(1).strip()


def shown(path):
    """A path as the report shows it: relative to the checkout when inside it."""
    try:
        return str(Path(path).relative_to(SOURCE))
    except ValueError:
        return str(path)


def kiln_commit():
    try:
        commit = subprocess.run(["git", "-C", str(SOURCE), "rev-parse", "--short=10", "HEAD"],
                                capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", str(SOURCE), "status", "--porcelain",
                                "--untracked-files=no", "--", "src", "tools", "tests",
                                "inputs", "CMakeLists.txt"],
                               capture_output=True, text=True).stdout.strip()
        described = subprocess.run(["git", "-C", str(SOURCE), "describe", "--tags", "--always"],
                                   capture_output=True, text=True).stdout.strip()
        date = subprocess.run(["git", "-C", str(SOURCE), "show", "-s", "--format=%cI", "HEAD"],
                              capture_output=True, text=True).stdout.strip()
        return (commit + (f" ({described}, committed {date})" if described else "")
                + (" with local changes to src/tools/tests/inputs" if dirty else ""))
    except (OSError, subprocess.CalledProcessError):
        return "unknown (not a git checkout)"


def fmt(value, digits=1):
    return "n/a" if value is None or (isinstance(value, float) and math.isnan(value)) else \
        f"{value:.{digits}e}"


def summary_table(cases):
    lines = ["| run | t [s] | gap: Kiln (expected) | mean T [K] (expected) | T error [K] | "
             "T spread [K] | stress | strain | contact pressure | gap opening [m] |",
             "|---|---:|---|---|---:|---:|---:|---:|---:|---:|"]
    for case in cases:
        for table, expected_T, T in zip(case["tables"], case["expected_T"],
                                        case["series"]["T_mean"][[0, -1]]):
            expected_gap = "closed" if expected_T > case["T_ref"] else "open"
            errors = table_errors(table)
            lines.append(
                f"| {case['key']} | {table['time']:g} | {table['gap']} ({expected_gap}) | "
                f"{table['T']:.6f} ({expected_T:g}) | {fmt(abs(T - expected_T))} | "
                f"{fmt(table['T_spread'])} | {fmt(errors['stress'])} | {fmt(errors['strain'])} | "
                f"{fmt(errors['pressure'])} | {fmt(errors['opening'])} |")
    return "\n".join(lines)


def time_steps(log, until):
    """The (time, step size) of every accepted step in a kiln log, to `until` [s]."""
    steps = re.findall(r"^step \d+: t = (\S+) s, dt = (\S+) s", Path(log).read_text(), re.M)
    return [s for s in steps if float(s[0]) <= until]


def write_report(out, args, cases, refinement, corefined, heat, elastic, truchas, energy, runner,
                 spec, started, elapsed, interfaces=()):
    same_steps = len({tuple(r["steps"]) for r in refinement}) == 1
    command = "doc/verification/report.py " + " ".join(
        shlex.quote(a) for a in sys.argv[1:])
    version = subprocess.run([str(runner.kiln), "--version"], capture_output=True,
                             text=True).stdout.strip()
    md = [f"# Verification report: the contact box{' (--quick)' if args.quick else ''}", "",
          f"Generated by `{command}` on {started:%Y-%m-%d %H:%M} from Kiln commit "
          f"{kiln_commit()} ({version}),"
          f" kiln on {args.np} MPI rank{'s' if args.np > 1 else ''}; "
          f"{elapsed / 60:.1f} min in all. Do not edit: rerun the command.", "",
          "The reference problem and its analytic uniform states: "
          "[`../shared/spec/contact-box.md`](../../../shared/spec/contact-box.md). "
          "The decks are those of `inputs/` with denser output times (Kiln's time stepper "
          "lands on every output time, so the steps are at most as long as the output "
          "intervals); the derived decks and the results are in the work folder "
          f"(`{shown(args.work)}`)."]
    if runner.reused:
        md += ["", "**Reused runs** (`--reuse`): " + ", ".join(
            f"{name} (Kiln {commit})" for name, commit in runner.reused.items()) + "."]
    if args.quick:
        md += ["", "**Quick mode** (for the test): coarser output times, the refinement on "
               "4^3 and 8^3 cells only, the temporal heat tests only."]

    md += ["", "## Uniform states against the analytic solution", "",
           "The initial state (the equilibrium at t = 0) and the final state of each run, "
           "compared by `kiln_contact_box_report` (tools/contact_box_report.cpp, which "
           "computes the spec's formulas from the deck's material and rotation). Errors: "
           "max |Kiln - exact| over the cells (gap nodes) divided by the largest exact "
           "component of the tensor (the stress's for the contact pressure); absolute for the gap "
           "opening [m]; T error: |mean T over the nodes - the temperature the deck starts "
           "at or drives to|; T spread: max - min over the nodes.", "",
           summary_table(cases), "",
           "The spec: \"A trilinear hexahedral mesh represents these uniform states exactly, "
           "so a correct code reproduces them to round-off\"; here to the accuracy of the "
           "iterative solves (Newton to 1e-8 relative, GMRES 1e-10), and the final "
           "temperatures to how far the transient has decayed.", ""]
    for case in cases:
        for label, text in case["raw_tables"]:
            md += [f"<details><summary>{case['key']} at t = {label} s: "
                   "kiln_contact_box_report</summary>", "", "```",
                   text.rstrip(), "```", "", "</details>", ""]

    md += ["## Errors of the original statement", "",
           "From the spec (section \"Errors in the original statement\"); the analytic "
           "values above follow the corrected statement:", "", spec_errors(spec), ""]

    for variant, label in (("A", "Variant A: prescribed end temperatures (smooth step "
                                 "over 0 .. 100 s)"),
                           ("B", "Variant B: convection at the end faces")):
        pair = [c for c in cases if c["variant"] == variant]
        events = ", ".join(f"{c['key']}: gap {c['event_word']} at "
                           f"{c['event']:.3f} s (between the outputs at {c['bracket'][0]:g} "
                           f"and {c['bracket'][1]:g} s)" if c["event"] is not None
                           else f"{c['key']}: no gap event found"
                           for c in pair)
        md += [f"## {label}", "",
               "Gap events, as in Kiln's log: the gap has closed when the largest opening "
               "over the gap nodes reaches zero (the last pair closes), opened when the "
               "smallest leaves zero (the last pair opens); the time from the two nearest "
               f"outputs with a positive opening, extrapolated linearly: {events}.", "",
               f"![temperature, variant {variant}](temperature-{variant}.png)", "",
               f"![gap, variant {variant}](gap-{variant}.png)", "",
               f"![stress, variant {variant}](stress-{variant}.png)", ""]

    md += ["## Closing time under refinement", "",
           "The closing deck (variant A) on n^3 cells (`Mesh/Box/\"Cells\"`), run to 56 s with "
           "the output times of variant A (every second, every 0.25 s from 45 s): the "
           "closing time is where the largest gap opening reaches zero (linear extrapolation "
           "from the two last outputs with an open gap). " + (
               "The time steps to 56 s are the same on every mesh (kiln's logs), so the "
               "differences are those of the spatial discretization." if same_steps else
               "**The time steps differ between the meshes** (kiln's logs): the differences "
               "mix spatial and temporal errors."), "",
           "| cells | h [mm] | closing time [s] | difference to the coarser [s] | ratio | "
           "observed order | largest opening at 50 s [m] | its ratio | wall time [s] |",
           "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]

    def convergence(values):
        """Differences to the coarser mesh, their ratios and the observed orders."""
        differences = [None] + [b - a for a, b in zip(values, values[1:])]
        ratios = [None, None] + [a / b if b else None
                                 for a, b in zip(differences[1:], differences[2:])]
        orders = [math.log2(abs(r)) if r else None for r in ratios]
        return differences, ratios, orders

    def cell(value, form):
        return "" if value is None else format(value, form)
    differences, ratios, orders = convergence([r["event"] for r in refinement])
    opening_ratios = convergence([r["opening_50"] for r in refinement])[1]
    for k, r in enumerate(refinement):
        md.append(f"| {r['n']}^3 | {r['h'] * 1e3:g} | {r['event']:.4f} | "
                  f"{cell(differences[k], '+.4f')} | {cell(ratios[k], '.2f')} | "
                  f"{cell(orders[k], '.2f')} | {r['opening_50']:.5e} | "
                  f"{cell(opening_ratios[k], '.2f')} | {r['wall']:.0f} |")
    if len(refinement) >= 3:
        steps = [abs(d) for d in differences[1:]]
        fitted = np.polyfit(np.log([r["h"] for r in refinement[1:]]), np.log(steps), 1)[0]
        a, b, c = (r["event"] for r in refinement[-3:])
        p = orders[-1]
        extrapolated = c + (c - b) / (2 ** p - 1) if p and p > 0 else float("nan")
        md += ["", f"Fitted order of the differences: {fitted:.2f}; observed order of the "
               f"last three meshes {p:.2f}; Richardson extrapolation of the closing time with "
               f"it: {extrapolated:.4f} s (with order 2: {c + (c - b) / 3:.4f} s). The gap "
               "closes pair by pair over about its last half second; compare the ratios of "
               "the closing time with those of the largest opening at 50 s, before the "
               "first pair touches."]
    md += ["", "![closing time under refinement](closing-time.png)", ""]

    md += ["## Heat conduction: convergence order", "",
           "`tests/verification/heat_convergence_test.cpp` (run as "
           "`build/tests/verification_heat_convergence` on 1 rank): the decay of one cosine "
           "mode in a rotated box, insulated but for two faces held at T0. Space: BDF2 with small fixed "
           "steps on 4 x 2 x 2 ... 32 x 16 x 16 cells, L2 error against the exact solution. "
           "Time: 8 x 2 x 2 cells, max nodal error against the exact semi-discrete solution, "
           "so the time-stepping error alone. The test asserts the order of the last "
           "refinement (2 +- 0.1 in space, 1 +- 0.1 for backward Euler, 2 +- 0.1 for BDF2).",
           "", "| test | h or dt | error | order |", "|---|---:|---:|---:|"]
    for key, label in (("space", "space (BDF2, L2)"), ("Backward Euler", "time, backward Euler"),
                       ("BDF2", "time, BDF2")):
        points = heat[key]
        for k, (h, e) in enumerate(points):
            order = math.log(points[k - 1][1] / e) / math.log(points[k - 1][0] / h) if k else None
            md.append(f"| {label} | {h:g} | {e:.4e} | {'' if order is None else f'{order:.3f}'} |")
        if points:
            slope, _ = fitted_order(points)
            md.append(f"| {label} | fitted over all | | **{slope:.3f}** |")
        else:
            md.append(f"| {label} | not run (--quick) | | |")
    md += ["", "![heat convergence](heat-convergence.png)", ""]

    md += corefined_section(corefined)
    md += energy_section(energy)
    md += elastic_section(elastic)
    md += truchas_section.section(shown(args.truchas), truchas)
    md += truchas_section.section(
        "inputs/", list(interfaces), title="Gaps that cross",
        intro="The decks `inputs/contact-box-crossing.xml` (gaps at x = 0 and z = 0 of the "
              "box) and `inputs/contact-box-crossing3.xml` (three gaps, held on six faces), "
              "checked by `doc/verification/interfaces/NAME.py` against the one-gap box "
              "(`contact-box-close`) and the exact closed states; the exact states are met "
              "to the temperature's own distance from 308 K at 150 s (doc/contact.md).",
        header=INTERFACE_HEADER)

    md += ["## Runs", "", "| run | wall time [s] |", "|---|---:|"]
    md += [f"| {label} | {seconds:.1f} |" for label, seconds in runner.wall.items()]
    md.append("")
    (out / "report.md").write_text("\n".join(md))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", type=Path, default=SOURCE / "build",
                        help="Kiln's build folder (default: build/ of the checkout)")
    parser.add_argument("--np", type=int, default=2, help="MPI ranks of the kiln runs (2)")
    parser.add_argument("--quick", action="store_true",
                        help="small and few runs (the test): no 16^3, 32^3, spatial heat test")
    parser.add_argument("--out", type=Path, help="where report.md and the PNGs go (default: "
                        "doc/verification/, with --quick BUILD/verification-quick/)")
    parser.add_argument("--work", type=Path, help="the runs' folder (default "
                        "BUILD/verification-work, with --quick BUILD/verification-quick/work)")
    parser.add_argument("--reuse", action="store_true",
                        help="reuse the finished kiln runs of the work folder whose derived "
                        "deck is unchanged (to remake the plots and tables; the report "
                        "names them)")
    parser.add_argument("--spec", type=Path,
                        default=SOURCE.parent / "shared" / "spec" / "contact-box.md",
                        help="the contact-box spec (default ../shared/spec/contact-box.md)")
    parser.add_argument("--truchas", type=Path, default=SOURCE / "inputs" / "truchas",
                        help="the folder of the Truchas decks (default inputs/truchas/)")
    parser.add_argument("--truchas-checks", type=Path, default=HERE / "truchas",
                        help="their check modules, NAME.py per NAME.xml (default "
                        "doc/verification/truchas/)")
    args = parser.parse_args()
    if args.np < 1:
        parser.error("--np must be at least 1")
    args.build = args.build.resolve()
    if args.out is None:
        args.out = args.build / "verification-quick" if args.quick else HERE
    if args.work is None:
        args.work = args.out / "work" if args.quick else args.build / "verification-work"
    args.out, args.work = args.out.resolve(), args.work.resolve()
    if args.work == HERE or HERE in args.work.parents:
        parser.error("--work must be outside the source tree's doc/verification/")
    try:
        return report(args)
    except ReportError as error:
        sys.stderr.write(f"report.py: error: {error}\n")
        return 1


def report(args):
    started, start = datetime.datetime.now(), time.monotonic()
    if not args.spec.is_file():
        raise ReportError(f"{args.spec}: no such file (the spec of the contact box; --spec)")
    args.out.mkdir(parents=True, exist_ok=True)
    args.work.mkdir(parents=True, exist_ok=True)
    runner = Runner(args.build, args.np, args.work, args.reuse)

    cases = []
    for key, variant, deck_name, title, event_word in CASES:
        times = output_times(variant, args.quick)
        deck, results, _ = runner.run_case(
            key, SOURCE / "inputs" / deck_name,
            [("Output", "Times", "Array(double)", array_text(times))])
        case = {"key": key, "variant": variant, "title": title, "event_word": event_word,
                "deck": deck, "results": results, "series": full_series(results)}
        root = ET.parse(deck).getroot()
        case["T_ref"] = float(get_parameter(root, "Material", "Reference Temperature"))
        case["expected_T"] = expected_temperatures(deck)
        case["tables"], case["raw_tables"] = [], []
        for step in case["series"]["steps"]:
            text = runner.contact_box_report(deck, results, step, deck.parent)
            table = parse_table(text)
            case["tables"].append(table)
            case["raw_tables"].append((f"{table['time']:g}", text))
        s = case["series"]
        closing = event_word == "closed"
        case["event"], case["bracket"] = gap_event_time(
            s["time"], s["opening_max"] if closing else s["opening_min"], closing=closing)
        cases.append(case)

    refinement = []
    a_close = cases[0]
    for n in (4, 8) if args.quick else (4, 8, 16, 32):
        if n == 4:  # the variant A run is the 4^3 run (same deck, same times to 56 s)
            results, wall = a_close["results"], runner.wall["A-close"]
        else:
            times = [t for t in output_times("A", args.quick) if t <= 56]
            _, results, _ = runner.run_case(
                f"A-close-{n}", SOURCE / "inputs" / "contact-box-close.xml",
                [("Output", "Times", "Array(double)", array_text(times)),
                 ("Mesh/Box", "Cells", "Array(int)", f"{{{n}, {n}, {n}}}")])
            wall = runner.wall[f"A-close-{n}"]
        steps = time_steps(results.parent.parent / "log.txt", 56)
        times, largest, _ = gap_series(results)
        event, _ = gap_event_time(times, largest, closing=True)
        if event is None:
            raise ReportError(f"{results}: the gap does not close before 56 s on {n}^3 cells")
        refinement.append({"n": n, "h": 0.04 / n, "times": times, "opening": largest,
                           "event": event, "wall": wall, "steps": steps,
                           "opening_50": float(largest[np.argmin(np.abs(times - 50))])})

    # Space and time together: the steps limited to 4/n s (1 s on 4^3 ... 0.125 s on 32^3), the
    # closing time from every step's largest gap opening (the history), not from outputs.
    corefined = []
    for n in (4, 8) if args.quick else (4, 8, 16, 32):
        dt = 4.0 / n
        _, results, _ = runner.run_case(
            f"A-close-{n}-dt", SOURCE / "inputs" / "contact-box-close.xml",
            [("Output", "Times", "Array(double)", "{0, 56}"),
             ("Mesh/Box", "Cells", "Array(int)", f"{{{n}, {n}, {n}}}"),
             ("Time Stepping", "Initial Step", "double", repr(dt)),
             ("Time Stepping", "Maximum Step", "double", repr(dt)),
             ("Time Stepping", "Minimum Step", "double", repr(dt / 64)),
             ("Time Stepping", "Growth Factor", "double", "1"),
             ("Time Stepping", "Error Control", "bool", "false")])
        times, largest = history_gap(results)
        event, _ = gap_event_time(times, largest, closing=True)
        if event is None:
            raise ReportError(f"{results}: the gap does not close before 56 s on {n}^3 cells")
        corefined.append({"n": n, "h": 0.04 / n, "dt": dt, "event": event,
                          "wall": runner.wall[f"A-close-{n}-dt"], "steps": len(times) - 1})

    heat = parse_heat(runner.heat_convergence(args.quick))
    if not heat["Backward Euler"] or not heat["BDF2"] or (not args.quick and not heat["space"]):
        raise ReportError("verification_heat_convergence printed no errors (or not all of them); "
                          f"see {args.work / 'heat-convergence' / 'log.txt'}")

    for variant in ("A", "B"):
        pair = [c for c in cases if c["variant"] == variant]
        plot_temperature(variant, pair, args.out / f"temperature-{variant}.png")
        plot_gap(variant, pair, args.out / f"gap-{variant}.png")
        plot_stress(variant, pair, args.out / f"stress-{variant}.png")
    plot_closing(refinement, args.out / "closing-time.png")
    plot_heat(heat, args.out / "heat-convergence.png")

    elastic = parse_elastic(runner.elastic_convergence())
    if any(len(points) < 2 for points in elastic.values()):
        raise ReportError("verification_elastic_convergence printed no errors (or not all of "
                          f"them); see {args.work / 'elastic-convergence' / 'log.txt'}")
    try:
        truchas = truchas_section.run_all(args.truchas, args.truchas_checks, runner.run_case)
        # The interfaces (issue 34): the crossing decks against the one-gap box and the exact
        # states, through the same check modules (doc/verification/interfaces/).
        interfaces = truchas_section.run_all(SOURCE / "inputs", HERE / "interfaces",
                                             runner.run_case, names=INTERFACE_DECKS,
                                             prefix="interfaces")
    except truchas_section.SidecarError as error:
        raise ReportError(str(error)) from error

    source = energy_deck(SOURCE / "inputs" / "contact-box-close.xml",
                         args.work / "energy-source.xml")
    _, energy_results, _ = runner.run_case("energy-balance", source, [])
    energy = energy_balance(energy_results)

    write_report(args.out, args, cases, refinement, corefined, heat, elastic, truchas, energy,
                 runner, args.spec, started, time.monotonic() - start, interfaces)
    print(summary_table(cases))
    print("closing time: " + ", ".join(f"{r['n']}^3 {r['event']:.4f} s" for r in refinement))
    print(f"report.py: wrote {args.out / 'report.md'} and the PNGs "
          f"({time.monotonic() - start:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
