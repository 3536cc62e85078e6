#!/usr/bin/env python3
"""The search of a contact pair redone during a run (issue 30; doc/contact.md, "Small
sliding"): a patch test under sliding. Two bodies meshed apart (Exodus mesh written here):
body 1 (the primary side) x in [-4, 0] cm, y in [-3, 5] cm, z in [-2, 2] cm, 4 x 11 x 4 cells;
body 2 (the secondary side) x in [0, 4] cm, y in [-2, 2] cm, z in [-2, 2] cm, 5 x 6 x 3 cells
(faces 6.67 x 13.3 mm, diameter 14.9 mm: with "Search Update Fraction" 0.25 the search is
redone once a row has slid 3.73 mm). Steady elasticity with Poisson's ratio 0 (Lame lambda 0,
G = 26 GPa), frictionless ("Contact"). Body 1 moves as a whole along y by -5e-4 t m (held on its
end face 1 and on its contact face 10 at u_y = -5e-4 t, u_x = 0 on 1 and -2e-6 m on 10, u_z = 0
on 1): uniform strain -5e-5 along x. Body 2 is pressed onto it by u_x = -1e-5 m and pushed
along y by 1.5e-3 t m on its end face 2 (u_z = 0): it slides along the pair by 2 mm a second,
20 mm (three of body 1's faces) by t = 10 s, its whole contact face on body 1's at every time.
The exact state: in body 2 sigma_xx = 2 G (2e-6 - 1e-5) / 0.04 = -1.04e7 Pa, the other
components 0, the contact pressure p = 1.04e7 Pa at every row; in body 1 sigma_xx = 2 G
(-2e-6 / 0.04) = -2.6e6 Pa. Checked at every output time t = 0 .. 10 s to 1e-9 (of p): the
contact pressure of every row and the stress of every cell; the log's searches ("search N at
t = ..."): at t = 2, 4, 6, 8 and 10 s (6 in all with the set-up's).
With np 2 the same run on 1 rank as well: the displacements agree to 1e-12 m (the solver's
tolerance). A restart from the checkpoint at 5 s (after two searches) continues to 10 s with
the same results as the run without it (kiln-diff with zero tolerance) and the same history
apart from the wall time.
Beyond the margin: with "Search Distance" 1 mm and no "Sliding Distance" the rows' margins
hold the primary faces within 1 mm of each node's faces only: the search at 4 s (8 mm slid)
pairs a node outside them, and the run ends with exit 2 and the message (the pair, the node,
the time, what to change), its results and history up to 3 s, its checkpoint of 3 s with the
rows of the search at 2 s. Onto another gap: body 1 split at y = 3.55 cm (a split gap whose
nodes on the contact face the rows reach once the sliding body's edge passes 2.82 cm): the
search at 6 s ends the run with the message naming the gap, the files up to 5 s.
With "heat" (doc/heat.md, "Heat across the gap of a mortar pairing"): the same runs
thermo-elastic (expansion 0, so the mechanics is the one above), the pair with a Heat Transfer
term of constant "Conductance" h = 1e4 W/(m^2 K), body 1 held at T_1 = 300 K on its end face
and its contact face (so uniform: its contact face is wider than body 2's), body 2's end face
at T_2 = 400 K (k = 50 W/(m K)). The exact steady state: T linear in body 2 and a uniform flux
q = (T_2 - T_1) / (L/k + 1/h) = 1.11e5 W/m^2 across the gap (L = 4 cm), the heat flow
q x 16 cm^2: checked at every output time (every secondary node's gap_heat_flux, the
history's heat_flow_slide) to 1e-9, with the heat cells rebuilt at each search (the searches
at 2, 4, 6, 8, 10 s as above); np 2 = np 1; the restart after two searches bit for bit (its
checkpoint keeps the surfaces' u of the last search: contact/pair_heat_u); a checkpoint
without it (of an older Kiln) restarts bit for bit from 1 s (before any search) and is refused
(exit 1, the message) from 5 s (after two). Body 1 uniform, the cells of set-up would give the
same flux: held at its far end only, the heat entering body 1's contact face follows body 2
(its centre moves by 5 to 15 mm by 10 s; 0 with the cells of set-up). Beyond the margin the
same exit 2 and message, the checkpoint of 3 s with the u of the search at 2 s. (The split gap
case is the mechanics' alone.)
With the argument split-secondary: the secondary surface split across the ranks during the
searches (issue 30, "the search and the pairs correct when a body's surface is split across
ranks"; the plain np 2 run lets METIS cut body 1, the primary). Body 2 is meshed as two element
blocks, 2 (y < 0) and 3 (y > 0), with Kiln/Mesh/Partition "By Block": blocks 1 and 2 on rank 0,
block 3 on rank 1 at np 2, so that the rows of its contact face are owned by both ranks (both
ranks' slips decide the searches, and the gathered u of the surface comes from both owners).
The results' /mesh/cell_rank shows it: body 2's cells on the contact face lie on both ranks.
Then the same checks as the run above (uniform pressure and stress to 1e-9 at every output
time, the searches at 2 .. 10 s, slid to 15 mm, np 2 = np 1 to 1e-12 m); the restart, beyond
the margin and onto a gap are the plain run's only.
usage: sliding_patch.py KILN WORKDIR NP MPIEXEC [heat | split-secondary]"""
import csv
import math
import re
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
import exodus_mesh  # noqa: E402  (tests/support/exodus_mesh.py)
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)

kiln, work, n_ranks, mpiexec = sys.argv[1:5]
HEAT = sys.argv[5:6] == ["heat"]
split_secondary = sys.argv[5:6] == ["split-secondary"]
work = Path(work)
work.mkdir(parents=True, exist_ok=True)
kiln_diff = Path(__file__).resolve().parents[3] / "tools" / "kiln-diff"
check = kd.Checks()

G = 2.6e10
DELTA, D = 2e-6, 1e-5  # body 1's contact face moved by -DELTA along x, body 2's end by -D
P = 2.0 * G * (D - DELTA) / 0.04
SIGMA_1 = -2.0 * G * DELTA / 0.04
# With heat: T_1 on body 1, T_2 on body 2's end face, conductivity K, gap conductance H.
T_1, T_2, K, H = 300.0, 400.0, 50.0, 1.0e4
Q = (T_2 - T_1) / (0.04 / K + 1.0 / H)
AREA = 0.04 * 0.04  # body 2's contact face, on body 1's at every time


def block(x0, x1, y0, y1, z0, z1, n, first_node):
    """A structured HEX8 block: its node coordinates and 1-based connectivity."""
    nx, ny, nz = n
    nodes = [(x0 + (x1 - x0) * i / nx, y0 + (y1 - y0) * j / ny, z0 + (z1 - z0) * k / nz)
             for k in range(nz + 1) for j in range(ny + 1) for i in range(nx + 1)]

    def at(i, j, k):
        return first_node + i + (nx + 1) * (j + (ny + 1) * k)

    cells = [[at(i, j, k), at(i + 1, j, k), at(i + 1, j + 1, k), at(i, j + 1, k),
              at(i, j, k + 1), at(i + 1, j, k + 1), at(i + 1, j + 1, k + 1), at(i, j + 1, k + 1)]
             for k in range(nz) for j in range(ny) for i in range(nx)]
    return nodes, cells


def write_mesh(path, gap_y=None, split=False):
    """The two bodies; with gap_y, side set 30: the faces y = gap_y of body 1's cells below it
    (a gap to split body 1 at); with split, body 2 as blocks 2 (y < 0) and 3 (y > 0)."""
    nodes1, cells1 = block(-0.04, 0.0, -0.03, 0.05, -0.02, 0.02, (4, 11, 4), 1)
    nodes2, cells2 = block(0.0, 0.04, -0.02, 0.02, -0.02, 0.02, (5, 6, 3), len(nodes1) + 1)
    nodes = nodes1 + nodes2
    tol = 1e-12

    def below_zero(cell):
        return sum(nodes[n - 1][1] for n in cell) < 0.0

    blocks2 = [cells2]
    if split:
        blocks2 = [[c for c in cells2 if below_zero(c)], [c for c in cells2 if not below_zero(c)]]

    def sides(cells, first, on_face):
        return exodus_mesh.hex8_sides_where(cells, nodes, on_face, first)

    def sides2(on_face):
        """Body 2's faces on on_face, its blocks numbered on after body 1's cells."""
        elems, faces, first = [], [], len(cells1) + 1
        for cells in blocks2:
            e, f = sides(cells, first, on_face)
            elems, faces, first = elems + e, faces + f, first + len(cells)
        return elems, faces

    side_sets = [(1,) + sides(cells1, 1, lambda p: abs(p[0] + 0.04) < tol),
                 (10,) + sides(cells1, 1, lambda p: abs(p[0]) < tol),
                 (2,) + sides2(lambda p: abs(p[0] - 0.04) < tol),
                 (20,) + sides2(lambda p: abs(p[0]) < tol)]
    if gap_y is not None:
        elems, faces = sides(cells1, 1, lambda p: abs(p[1] - gap_y) < tol)
        below = [(e, f) for e, f in zip(elems, faces)
                 if sum(nodes[n - 1][1] for n in cells1[e - 1]) / 8 < gap_y]
        side_sets.append((30, [e for e, _ in below], [f for _, f in below]))
    exodus_mesh.write(str(path), nodes,
                      [(1, "HEX8", cells1)] + [(2 + b, "HEX8", cells)
                                               for b, cells in enumerate(blocks2)],
                      side_sets, title="sliding patch")


def deck(base, times, pair=None, checkpoint=None, mesh="sliding-patch.exo", gap=0,
         held=(1, 10)):
    entry = {"Primary Side Set": 10, "Secondary Side Set": 20, "Sliding Distance": 0.025}
    if pair is not None:
        entry = {"Primary Side Set": 10, "Secondary Side Set": 20, **pair}
    if HEAT:
        entry["Heat Transfer"] = {"Conductance": H}
    d = {"Physics": "Elasticity",
         "Mesh": {**kd.exodus_mesh(mesh, gap),
                  **({"Partition": "By Block"} if split_secondary else {})},
         "Material": kd.lame(0.0, G),
         "Mechanics": {
             "Boundary Conditions": {
                 "body 1 end": kd.displacement([1], ["x", "z"]),
                 "body 1 face": kd.displacement([10], ["x"], kd.constant(-DELTA)),
                 "body 1 along": kd.displacement([1, 10], ["y"], kd.expression("-5e-4*t")),
                 "pressed": kd.displacement([2], ["x"], kd.constant(-D)),
                 "pushed": kd.displacement([2], ["y"], kd.expression("1.5e-3*t")),
                 "level": kd.displacement([2], ["z"])},
             "Contact": {"Pairs": {"slide": entry}}},
         "Time Stepping": {"Method": "Steady"},
         "Output": {"File Base": base, "Times": [float(t) for t in times]}}
    if checkpoint is not None:
        d["Checkpoint"] = checkpoint
    if HEAT:
        d["Physics"] = "Thermo-Elasticity"
        d["Material"].update({"Thermal Expansion": 0.0, "Reference Temperature": T_1,
                              "Density": 2.7e3, "Specific Heat": 9.0e2,
                              "Conductivity": {"Type": "Constant", "Value": K}})
        d["Thermal"] = {"Initial Temperature": T_1,
                        "Boundary Conditions": {"body 1": kd.temperature(list(held), T_1),
                                                "body 2 end": kd.temperature([2], T_2)}}
    return d


def searches(log):
    return [float(t) for t in re.findall(r'pair "slide": search \d+ at t = ([0-9.e+-]+) s', log)]


def history(path):
    with open(path, encoding="utf-8") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    wall = rows[0].index("wall_time [s]")
    return [[v for i, v in enumerate(r) if i != wall] for r in rows]


write_mesh(work / "sliding-patch.exo", split=split_secondary)

# The run: uniform state at every output time, the searches logged.
base = "slide"
run = kd.run_kiln(kiln, kd.write_deck(str(work / base), deck(base, range(11))), n_ranks,
                  mpiexec, cwd=work, expect=0, log=work / "slide.log")
found = searches(run.log)
check(found == [2.0, 4.0, 6.0, 8.0, 10.0], f"searches redone at t = 2, 4, 6, 8, 10 s ({found})")
check('pair "slide": search 6 at t = 10 s' in run.log, "the sixth search (with the set-up's)")
with h5py.File(run.results, "r") as h5:
    steps = kd.step_names(h5)
check(len(steps) == 11, f"results at t = 0 .. 10 s ({len(steps)} steps)")
worst_p, worst_sigma, worst_q = 0.0, 0.0, 0.0
for k in range(len(steps)):
    step = kd.read_step(str(run.results), k)
    pressure = step["contact_pressure"]
    rows = np.isfinite(pressure)
    body2 = step["block"] >= 2
    sigma = step["stress"]
    exact = np.zeros_like(sigma)
    exact[:, 0] = np.where(body2, -P, SIGMA_1)
    worst_p = max(worst_p, float(np.abs(pressure[rows] - P).max()) / P)
    worst_sigma = max(worst_sigma, float(np.abs(sigma - exact).max()) / P)
    check(rows.sum() == 28, f"t = {step['time']} s: 28 rows ({rows.sum()})")
    if HEAT:
        # The flux at every secondary node (NaN off the pair): q.
        flux = step["gap_heat_flux"]
        at = np.isfinite(flux)
        check(at.sum() == 28, f"t = {step['time']} s: gap_heat_flux at 28 nodes ({at.sum()})")
        worst_q = max(worst_q, float(np.abs(flux[at] - Q).max()) / Q)
    # The table of the pair's rows: the same pressure at every row.
    with open(work / f"slide.pair_slide-{k:06d}.csv", encoding="utf-8") as f:
        table = [r for r in csv.DictReader(f)]
    table_p = np.array([float(r["contact_pressure [Pa]"]) for r in table])
    worst_p = max(worst_p, float(np.abs(table_p - P).max()) / P)
print(f"p = {P:.6g} Pa: max |p_j - p| / p = {worst_p:.3g}, max |sigma - exact| / p = "
      f"{worst_sigma:.3g} over t = 0 .. 10 s")
check(worst_p < 1e-9, f"the contact pressure uniform to 1e-9 ({worst_p:.3g})")
check(worst_sigma < 1e-9, f"the stress uniform to 1e-9 ({worst_sigma:.3g})")
if HEAT:
    with open(work / "slide.history.csv", encoding="utf-8") as f:
        table = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    column = table[0].index("heat_flow_slide [W]")
    # The rows after the initial state's: the solves at t = 0 .. 10 s.
    flows = np.array([float(r[column]) for r in table[2:]])
    worst_flow = float(np.abs(flows - Q * AREA).max()) / (Q * AREA)
    print(f"q = {Q:.6g} W/m^2: max |q_j - q| / q = {worst_q:.3g}, max |heat flow - q A| / (q A) "
          f"= {worst_flow:.3g} over t = 0 .. 10 s")
    check(len(flows) == 11, f"the history's heat flow at t = 0 .. 10 s ({len(flows)})")
    check(worst_q < 1e-9, f"gap_heat_flux = q to 1e-9 ({worst_q:.3g})")
    check(worst_flow < 1e-9, f"heat_flow_slide = q A to 1e-9 ({worst_flow:.3g})")
last = kd.read_step(str(run.results))
end_face = np.abs(last["x"][:, 0] - 0.04) < 1e-12
check(abs(last["displacement"][end_face, 1] - 1.5e-2).max() < 1e-12, "slid to u_y = 15 mm")

if split_secondary and int(n_ranks) > 1:
    # The secondary surface split across the ranks: body 2's cells on the contact face (x = 0)
    # on both.
    with h5py.File(run.results, "r") as h5:
        cell_rank = h5["mesh/cell_rank"][...]
    step = kd.read_step(str(run.results), 0)
    on_face = np.array([step["block"][c] >= 2 and np.abs(step["x"][cells, 0]).min() < 1e-12
                        for c, cells in enumerate(step["cells"])])
    ranks = sorted(set(int(r) for r in cell_rank[on_face]))
    print(f"body 2's {on_face.sum()} cells on the contact face: on ranks {ranks} "
          f"({[int((cell_rank[on_face] == r).sum()) for r in ranks]} cells)")
    check(ranks == list(range(int(n_ranks))),
          f"the secondary surface split across the {n_ranks} ranks ({ranks})")

# np 2 against np 1: the same state to the solver's tolerance.
if int(n_ranks) > 1:
    one = kd.run_kiln(kiln, kd.write_deck(str(work / "one"), deck("one", range(11))), 1,
                      mpiexec, cwd=work, expect=0)
    check(searches(one.log) == found, f"np 1 searches at the same times ({searches(one.log)})")
    apart, apart_T = 0.0, 0.0
    with h5py.File(one.results, "r") as h5:
        n_steps = len(kd.step_names(h5))
    for k in range(n_steps):
        a, b = kd.read_step(str(run.results), k), kd.read_step(str(one.results), k)
        order_a = np.lexsort(a["x"].T)
        order_b = np.lexsort(b["x"].T)
        apart = max(apart, float(np.abs(a["displacement"][order_a] -
                                        b["displacement"][order_b]).max()))
        if HEAT:
            apart_T = max(apart_T, float(np.abs(a["temperature"][order_a] -
                                                b["temperature"][order_b]).max()))
    print(f"np {n_ranks} against np 1: max |u| apart {apart:.3g} m, |T| {apart_T:.3g} K")
    check(apart < 1e-12, f"np {n_ranks} = np 1 to 1e-12 m ({apart:.3g})")
    check(apart_T < 1e-9, f"np {n_ranks} = np 1 to 1e-9 K ({apart_T:.3g})")

if split_secondary:
    sys.exit(1 if check.failed else 0)

# A restart after two searches: the same results and history as the run without it.
base = "restarted"
kd.run_kiln(kiln, kd.write_deck(str(work / "part1"),
                                deck(base, range(6), checkpoint={"At End": True})),
            n_ranks, mpiexec, cwd=work, expect=0)
checkpoint = work / (base + ".checkpoint.h5")
check(checkpoint.is_file(), "the checkpoint at 5 s")
part2 = kd.run_kiln(kiln, kd.write_deck(str(work / "part2"), deck(base, range(11))), n_ranks,
                    mpiexec, args=["--restart", checkpoint.name], cwd=work, expect=0)
check(searches(part2.log) == [6.0, 8.0, 10.0],
      f"the restart searches at 6, 8, 10 s ({searches(part2.log)})")
diff = subprocess.run([sys.executable, str(kiln_diff), "--abs", "0", "--rel", "0",
                       str(work / (base + ".h5")), str(work / "slide.h5")],
                      stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
check(diff.returncode == 0, "the restart's results = the run's, bit for bit "
      f"(kiln-diff --abs 0 --rel 0: {diff.stdout.strip()[-300:]})")
check(history(work / (base + ".history.csv")) == history(work / "slide.history.csv"),
      "the restart's history = the run's (apart from the wall time)")

if HEAT:
    # A checkpoint of a Kiln before the heat cells were rebuilt (no contact/pair_heat_u): at 1 s,
    # before any search, it restarts with the set-up's cells, the same results bit for bit; at
    # 5 s, after two searches, it is refused (exit 1) naming the pair and what to do.
    def older(base, times):
        kd.run_kiln(kiln, kd.write_deck(str(work / (base + "-part1")),
                                        deck(base, times, checkpoint={"At End": True})),
                    n_ranks, mpiexec, cwd=work, expect=0)
        with h5py.File(work / (base + ".checkpoint.h5"), "r+") as h5:
            del h5["contact/pair_heat_u"]
            del h5["contact"].attrs["n_pair_heat_u"]
        return kd.run_kiln(kiln, kd.write_deck(str(work / base), deck(base, range(11))), n_ranks,
                           mpiexec, args=["--restart", base + ".checkpoint.h5"], cwd=work,
                           expect=None)
    run = older("older-1", range(2))
    check(run.returncode == 0, f"older checkpoint at 1 s: restarted (exit {run.returncode})")
    diff = subprocess.run([sys.executable, str(kiln_diff), "--abs", "0", "--rel", "0",
                           str(work / "older-1.h5"), str(work / "slide.h5")],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    check(diff.returncode == 0, "older checkpoint at 1 s: the run's results bit for bit "
          f"({diff.stdout.strip()[-200:]})")
    run = older("older-5", range(6))
    errors = [line for line in run.log.splitlines() if line.startswith("kiln: error:")]
    message = errors[0] if errors else ""
    print(message)
    check(run.returncode == 1, f"older checkpoint at 5 s: refused (exit {run.returncode})")
    for part in ["has no heat cells of the contact pairs (contact/pair_heat_u)",
                 'pair "slide", which carries heat across its gap, was searched again',
                 "restart from a checkpoint of this Kiln, or run from the start"]:
        check(part in message, f"older checkpoint at 5 s: the message says {part!r}")

if HEAT:
    # The cells follow the slide: body 1 held at its far end only, the heat enters its contact
    # face where body 2 is now (its centre at y = 1.5 mm/s t), not where it was at set-up (the
    # cells of set-up would heat the same place at every time): the centre of T - T_1 on body
    # 1's contact face moves with body 2 (10.4 mm by 10 s as body 2 moves 15 mm, the heat
    # spreading in body 1; 0 with the cells of set-up).
    base = "follows"
    run = kd.run_kiln(kiln, kd.write_deck(str(work / base), deck(base, range(11), held=(1,))),
                      n_ranks, mpiexec, cwd=work, expect=0)
    check(searches(run.log) == found, f"follows: the same searches ({searches(run.log)})")
    centres = []
    for k in (0, 10):
        step = kd.read_step(str(run.results), k)
        # Body 1's nodes are the first 5 x 12 x 5 (write_mesh).
        on_face = (np.abs(step["x"][:, 0]) < 1e-12) & (np.arange(len(step["x"])) < 300)
        rise = step["temperature"][on_face] - T_1
        centres.append(float((rise * step["x"][on_face, 1]).sum() / rise.sum()))
    moved = centres[1] - centres[0]
    print(f"follows: the heated centre of body 1's contact face moved by {moved:.4g} m")
    check(0.005 < moved < 0.015, f"follows: the heated centre moves with body 2 ({moved:.4g} m)")

# Beyond the margin: exit 2 at the search that pairs a node outside it, the files up to 3 s.
base = "beyond"
run = kd.run_kiln(kiln, kd.write_deck(str(work / base),
                                      deck(base, range(11), pair={"Search Distance": 0.001})),
                  n_ranks, mpiexec, cwd=work, expect=2)
errors = [line for line in run.log.splitlines() if line.startswith("kiln: error:")]
check(len(errors) == 1, f"one error line ({len(errors)})")
message = errors[0] if errors else ""
print(message)
for part in ['pair "slide": at t = 4 s secondary node ', "has slid beyond the small-sliding limit",
             "outside the margin of primary faces linked to it at set-up",
             "raise the pair's \"Sliding Distance\"", "results up to the last accepted step"]:
    check(part in message, f"the message says {part!r}")
with h5py.File(run.results, "r") as h5:
    status = h5.attrs["status"]
    status = status.decode() if isinstance(status, bytes) else str(status)
    times = [float(h5["steps"][k].attrs["time"]) for k in kd.step_names(h5)]
check(status.startswith('stopped by an error at t = 3 s: pair "slide": at t = 4 s'),
      f"status {status[:60]!r}...")
check(times == [float(t) for t in range(4)], f"results at t = 0 .. 3 s ({times})")
check(math.isclose(float(history(work / (base + ".history.csv"))[-1][1]), 3.0),
      "the history ends at 3 s")
# The checkpoint of the last good state carries the rows of its last search (the second, at 2 s).
with h5py.File(work / (base + ".checkpoint.h5"), "r") as h5:
    rows = h5["contact/pair_rows"][...]
    when = float(h5["state"].attrs["time"])
check(when == 3.0 and rows[0] == 2 and rows[1] == 28,
      f"the checkpoint at 3 s with the rows of search 2 ({when}, {rows[:2]})")
if HEAT:
    # ... and the surfaces' u of that search (body 2 pushed by u_y = 3 mm at 2 s): the count
    # of values (3 per node of the two surfaces: 5 x 12 + 7 x 4), then u.
    with h5py.File(work / (base + ".checkpoint.h5"), "r") as h5:
        heat_u = h5["contact/pair_heat_u"][...]
    u = heat_u[1:].reshape(-1, 3)
    check(heat_u[0] == 3 * 88 and len(u) == 88 and abs(u[:, 1].max() - 3e-3) < 1e-12,
          f"the checkpoint's heat cells: u of the search at 2 s ({heat_u[0]}, {u[:, 1].max()})")
    sys.exit(1 if check.failed else 0)
# Onto another gap: body 1 split at y = 3.55 cm (its grid line 9 of 11; a split gap, side set
# 30), a node of which the sliding body's rows reach at 6 s (its edge at 3.2 cm): exit 2 with
# the message naming both, the files up to 5 s.
write_mesh(work / "sliding-patch-gap.exo", gap_y=-0.03 + 9 * 0.08 / 11)
base = "onto-gap"
run = kd.run_kiln(kiln, kd.write_deck(str(work / base), deck(base, range(11),
                                                            mesh="sliding-patch-gap.exo", gap=30)),
                  n_ranks, mpiexec, cwd=work, expect=2)
errors = [line for line in run.log.splitlines() if line.startswith("kiln: error:")]
message = errors[0] if errors else ""
print(message)
for part in ['pair "slide": at t = 6 s the search redone pairs secondary node ',
             "which is on gap side set 30", "cannot be on another pair or gap"]:
    check(part in message, f"onto a gap: the message says {part!r}")
check(searches(run.log) == [2.0, 4.0], f"onto a gap: searched at 2 and 4 s ({searches(run.log)})")
with h5py.File(run.results, "r") as h5:
    times = [float(h5["steps"][k].attrs["time"]) for k in kd.step_names(h5)]
check(times == [float(t) for t in range(6)], f"onto a gap: results at t = 0 .. 5 s ({times})")
sys.exit(1 if check.failed else 0)
