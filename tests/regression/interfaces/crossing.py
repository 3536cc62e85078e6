#!/usr/bin/env python3
"""Gaps that cross (Mesh/"Gap Side Sets"), in whole runs: the mesh and the pairs of
inputs/contact-box-crossing.xml and inputs/contact-box-crossing3.xml, and a Kind per gap. Their
states against the one-gap box and the exact ones are checked by their modules in
doc/verification/interfaces/ (tests interface_deck_*, and the verification report).

Usage: crossing.py KILN INPUTS_DIR WORK_DIR NP MPIEXEC

1. contact-box-crossing (gaps at x = 0 and z = 0, four quarters; the 5 nodes on the crossing
   line have four copies): 180 nodes, 30 pairs per gap, every pair in contact at 150 s, with
   no opening.
2. contact-box-crossing with Contact/Gaps giving side set 12 the Kind "Bonded" (a Kind per
   gap): at 50 s, colder than 298 K, gap 10 is open (every node of it off gap 12 has an
   opening > 0 and no pressure) while gap 12 stays shut (zero opening) and carries a
   tension, which contact cannot (contact_pressure negative on average over its nodes off
   gap 10 and below -1e5 Pa: -3.4e5 and -7.5e5 Pa measured).
3. contact-box-crossing3 (three gaps, the centre node with eight copies): 216 nodes, 36 pairs
   per gap, every gap node in contact.
4. Every gap in the outputs (doc/output-format.md, "Several gaps"), in each of the runs above
   and in contact-box-crossing heated at face 1 only (heat crosses gap 10, not gap 12), written
   as HDF5 and Exodus: the history has the six columns of each gap (NAME_gapID) after the
   unchanged ones; at every output step, each gap's table BASE.gap-NNNNNN.csv (first gap) or
   BASE.gap_ID-NNNNNN.csv has one row per pair of that gap, and its sums give that step's
   history figures of the gap to 1e-9: normal_force_gapID = sum of contact_pressure x area,
   contact_area_gapID and active_pairs_gapID over the pairs in contact, gap_heat_flow_gapID =
   sum of gap_heat_flux x area, min/max_gap_gapID the extremes of gap_opening; the columns
   without suffix are the sums (extremes) over the gaps. The HDF5 file has a surface per gap
   (/gap, /gap_ID; their fields the tables'), the XDMF file a Temporal collection per gap
   (each data item a dataset of the HDF5 file with its dimensions), the Exodus file a side
   set per gap (gap, gap_ID) and the columns as global variables. With
   gap 12 bonded, at 50 s its normal force is a tension (< -100 N; -930 N measured) where
   gap 10 is open (0), and at 150 s gap 10's is a compression (> 0). Heated at one end, heat
   crosses gap 10 (|flow| > 0.1 W at 50 s; 21 W measured) and not gap 12 (< 1e-6 of it).
   Restarted at 53 s, the bonded run's results continue with each gap's surface of the
   replayed steps as written (the pairs' own values where the gaps cross), to 1e-9.
"""
import os
import re
import sys
from pathlib import Path

import h5py
import numpy as np
from scipy.io import netcdf_file

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)


def run(kiln, inputs, work, deck, n_ranks, mpiexec):
    os.makedirs(work, exist_ok=True)
    done = kd.run_kiln(kiln, os.path.join(inputs, deck + ".xml"), n_ranks, mpiexec, cwd=work)
    return kd.read_step(done.results), done.log


def gap_outputs(work, base, gap_ids, check, what):
    """The per-gap outputs of results/BASE.* (item 4 of the module's text); returns the history
    as a dict of columns."""
    results = os.path.join(work, "results", base)
    history = np.genfromtxt(results + ".history.csv", delimiter=",", names=True,
                            deletechars="", replace_space=" ")
    column = {n.split(" [")[0]: history[n] for n in history.dtype.names}
    blocks = ["min_gap", "max_gap", "active_pairs", "contact_area", "normal_force",
              "gap_heat_flow"]
    names = [f"{b}_gap{i}" for i in gap_ids for b in blocks]
    check(list(column)[-len(names):] == names and "normal_force" in column,
          f"{what}: the history's columns per gap {names[:6]} ...")
    # The tolerance: 1e-9 of the largest value of the figure over the gaps and steps (of a
    # heat flow at least 1e-3 W: the flows of a uniform temperature are round-off, 1e-13 W).
    scale = {b: max(1e-3 if b == "gap_heat_flow" else 1e-300,
                    max(np.nanmax(np.abs(column[f"{b}_gap{i}"])) for i in gap_ids))
             for b in blocks}
    bad = []
    with h5py.File(results + ".h5", "r") as h5:
        steps = sorted(h5["steps"].keys())
        for number, key in enumerate(steps):
            time = float(h5["steps"][key].attrs["time"])
            row = np.flatnonzero(column["time"] == time)[-1]
            sums = {b: 0.0 for b in ["normal_force", "contact_area", "active_pairs"]}
            for g, gap_id in enumerate(gap_ids):
                name = "gap" if g == 0 else f"gap_{gap_id}"
                table = np.genfromtxt(f"{results}.{name}-{number:06d}.csv", delimiter=",",
                                      names=True, deletechars="", replace_space=" ")
                t = {n.split(" [")[0]: table[n] for n in table.dtype.names}
                surface = h5[name]
                if len(t["pair"]) != len(surface["area"]) or np.any(t["area"] != surface["area"]):
                    bad.append(f"{name} step {key}: table and /{name} differ in their pairs")
                if np.any(t["contact_pressure"] !=
                          surface["steps"][key]["contact_pressure"][...]):
                    bad.append(f"{name} step {key}: contact_pressure of table and /{name} differ")
                active = t["contact_active"] == 1.0
                figures = {"normal_force": np.sum(t["contact_pressure"] * t["area"]),
                           "contact_area": np.sum(t["area"][active]),
                           "active_pairs": float(active.sum()),
                           "gap_heat_flow": np.sum(t["gap_heat_flux"] * t["area"]),
                           "min_gap": t["gap_opening"].min(), "max_gap": t["gap_opening"].max()}
                for b, value in figures.items():
                    recorded = column[f"{b}_gap{gap_id}"][row]
                    if not np.isnan(value) and abs(value - recorded) > 1e-9 * scale[b]:
                        bad.append(f"{b}_gap{gap_id} at {time} s: history {recorded:.17g}, "
                                   f"table {value:.17g}")
                for b in sums:
                    sums[b] += column[f"{b}_gap{gap_id}"][row]
            for b, total in sums.items():
                if abs(total - column[b][row]) > 1e-9 * max(1.0, abs(column[b][row])):
                    bad.append(f"{b} at {time} s: {column[b][row]} is not the sum {total}")
    check(not bad, f"{what}: {len(steps)} output steps, each gap's table sums to its history "
          f"figures and the unsuffixed ones to their sums" + "".join("\n  " + b for b in bad[:5]))
    with open(results + ".xmf", encoding="utf-8") as f:
        xmf = f.read()
    grids = re.findall(r'<Grid Name="(gap[_0-9]*)" GridType="Collection"', xmf)
    expected = ["gap"] + [f"gap_{i}" for i in gap_ids[1:]]
    # Every data item a dataset of the file with the item's dimensions.
    items = re.findall(r'<DataItem Dimensions="([0-9 ]+)"[^>]*>[^:<]+:(/[^<]+)</DataItem>', xmf)
    with h5py.File(results + ".h5", "r") as h5:
        wrong = [p for d, p in items
                 if p not in h5 or h5[p].shape != tuple(int(n) for n in d.split())]
    check(grids == expected and all(f"/{n}/coordinates" in xmf for n in expected) and
          not wrong and items,
          f"{what}: XDMF gap collections {grids}, its {len(items)} data items in the HDF5 "
          f"file {wrong[:3]}")
    return column


def exodus_gaps(path, gap_ids, column, check, what):
    """The Exodus file's side sets per gap and the history's columns as global variables."""
    exo = netcdf_file(path, "r", mmap=False)
    side_sets = [bytes(r).decode().strip("\0") for r in exo.variables["ss_names"][:]]
    expected = ["gap"] + [f"gap_{i}" for i in gap_ids[1:]]
    globals_ = [bytes(r).decode().strip("\0") for r in exo.variables["name_glo_var"][:]]
    values = exo.variables["vals_glo_var"][:]
    force = values[-1, globals_.index(f"normal_force_gap{gap_ids[-1]}")]
    check(all(n in side_sets for n in expected) and
          force == column[f"normal_force_gap{gap_ids[-1]}"][-1],
          f"{what}: Exodus side sets {[n for n in side_sets if n.startswith('gap')]}, "
          f"normal_force_gap{gap_ids[-1]} {force:.6g} N as in the history")


def box_frame(x, phi=45.0, theta=-30.0):
    """Coordinates in the box's own frame (Kiln's rotation_matrix: Rx(theta) Ry(phi))."""
    p, t = np.radians(phi), np.radians(theta)
    cp, sp, ct, st = np.cos(p), np.sin(p), np.cos(t), np.sin(t)
    A = np.array([[cp, 0.0, sp], [st * sp, ct, -st * cp], [-ct * sp, st, ct * cp]])
    return x @ A


def bonded_text(inputs):
    """The deck contact-box-crossing with gap 12 bonded."""
    with open(os.path.join(inputs, "contact-box-crossing.xml"), encoding="utf-8") as f:
        text = f.read()
    gaps = """    <ParameterList name="Contact">
      <ParameterList name="Gaps">
        <ParameterList name="z = 0 bonded">
          <Parameter name="Side Set" type="int" value="12"/>
          <Parameter name="Kind" type="string" value="Bonded"/>
        </ParameterList>
      </ParameterList>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Time Stepping">"""
    return text.replace("""  </ParameterList>
  <ParameterList name="Time Stepping">""", gaps, 1)


def run_deck(kiln, work, name, text, n_ranks, mpiexec, *args):
    """Runs the deck `text` as WORK/NAME.xml (extra kiln arguments `args`); its log."""
    deck = kd.write_deck(os.path.join(work, name), text)
    return kd.run_kiln(kiln, deck, n_ranks, mpiexec, args, cwd=work).log


def restarted_gaps(kiln, inputs, work, n_ranks, mpiexec, check):
    """The bonded deck run to 53 s, then restarted to 150 s: the gap surfaces of every step,
    those of the earlier run replayed included, equal the uninterrupted run's."""
    text = bonded_text(inputs).replace(
        '''<ParameterList name="Output">''', '''<ParameterList name="Output">
    <Parameter name="File Base" type="string" value="results/crossing-restart"/>''', 1)
    run_deck(kiln, work, "crossing-restart", text.replace("{0, 50, 53, 150}", "{0, 50, 53}", 1),
             n_ranks, mpiexec)
    log = run_deck(kiln, work, "crossing-restart", text, n_ranks, mpiexec, "--restart",
                   "results/crossing-restart.checkpoint.h5")
    bad = []
    with h5py.File(os.path.join(work, "results", "crossing-restart.h5"), "r") as a, \
            h5py.File(os.path.join(work, "results", "crossing-bonded.h5"), "r") as b:
        steps = sorted(b["steps"].keys())
        for surface in ["gap", "gap_12"]:
            for key in steps:
                for field in ["gap_opening", "contact_pressure", "contact_active"]:
                    x = a[surface]["steps"][key][field][...]
                    y = b[surface]["steps"][key][field][...]
                    if not np.allclose(x, y, rtol=1e-9, atol=1e-9 * np.abs(y).max()):
                        bad.append(f"/{surface}/steps/{key}/{field}")
    check("the 3 output steps up to t = 53 s" in log and len(steps) == 4 and not bad,
          f"bonded gap 12 restarted at 53 s: each gap's surface at the {len(steps)} steps "
          f"(3 replayed) equals the uninterrupted run's {bad[:3]}")


def bonded_gap_12(kiln, inputs, work, n_ranks, mpiexec):
    """contact-box-crossing with gap 12 bonded; its fields at 50 s."""
    os.makedirs(work, exist_ok=True)
    run_deck(kiln, work, "crossing-bonded", bonded_text(inputs), n_ranks, mpiexec)
    with h5py.File(os.path.join(work, "results", "crossing-bonded.h5"), "r") as h5:
        step = next(h5["steps"][k] for k in sorted(h5["steps"].keys())
                    if float(h5["steps"][k].attrs["time"]) == 50.0)
        return h5["mesh/coordinates"][...], {k: step[k][...] for k in step.keys()}


def one_end_heated(kiln, inputs, work, n_ranks, mpiexec):
    """contact-box-crossing heated at face 1 only, written as HDF5 and Exodus; its .exo path."""
    with open(os.path.join(inputs, "contact-box-crossing.xml"), encoding="utf-8") as f:
        text = f.read()
    heated = text.replace('''<Parameter name="Side Sets" type="Array(int)" value="{1, 2}"/>''',
                          '''<Parameter name="Side Sets" type="Array(int)" value="{1}"/>''', 1)
    heated = heated.replace('''<ParameterList name="Output">''', '''<ParameterList name="Output">
    <Parameter name="Format" type="string" value="HDF5 and Exodus"/>''', 1)
    assert heated.count('value="{1}"') == 1 and "HDF5 and Exodus" in heated
    run_deck(kiln, work, "crossing-heated", heated, n_ranks, mpiexec)
    return os.path.join(work, "results", "crossing-heated.exo")


def main():
    kiln, inputs, work, n_ranks, mpiexec = sys.argv[1:6]
    check = kd.Checks()

    two, log = run(kiln, inputs, work, "contact-box-crossing", n_ranks, mpiexec)
    check(two["time"] == 150.0 and len(two["x"]) == 180, f"crossing: {len(two['x'])} nodes")
    pairs = [int(n) for n in re.findall(r"gap at side set \d+: (\d+) node pairs", log)]
    check(pairs == [30, 30], f"crossing: pairs per gap {pairs}")
    on_gap = ~np.isnan(two["contact_pressure"])
    check(on_gap.sum() == 100 and np.all(two["contact_active"][on_gap] == 1.0),
          f"crossing: {on_gap.sum()} gap nodes, all in contact")
    u_scale = np.abs(two["displacement"]).max()
    g = np.abs(two["gap_opening"][on_gap]).max() / u_scale
    check(g <= 1e-9, f"crossing: gap_opening 0 to {g:.3g} of the largest displacement")

    x, f = bonded_gap_12(kiln, inputs, work, n_ranks, mpiexec)
    local = box_frame(x)
    on_gap = ~np.isnan(f["contact_pressure"])
    on_10 = on_gap & (np.abs(local[:, 0]) < 1e-9) & (np.abs(local[:, 2]) > 1e-9)
    on_12 = on_gap & (np.abs(local[:, 2]) < 1e-9) & (np.abs(local[:, 0]) > 1e-9)
    u_scale = np.abs(f["displacement"]).max()
    check(on_10.sum() == 40 and on_12.sum() == 40,
          f"bonded gap 12: {on_10.sum()} and {on_12.sum()} nodes on gaps 10 and 12 only")
    check(np.all(f["gap_opening"][on_10] > 1e-3 * u_scale) and
          np.all(f["contact_pressure"][on_10] == 0.0),
          "bonded gap 12, t = 50 s: gap 10 (Contact) open, no pressure")
    g12 = np.abs(f["gap_opening"][on_12]).max() / u_scale
    p12 = f["contact_pressure"][on_12]
    check(g12 <= 1e-9 and p12.mean() < 0.0 and p12.min() < -1e5,
          f"bonded gap 12, t = 50 s: gap 12 shut (opening {g12:.3g} of max |u|), in tension "
          f"(contact_pressure mean {p12.mean():.3g} Pa, down to {p12.min():.3g} Pa)")

    three, log = run(kiln, inputs, work, "contact-box-crossing3", n_ranks, mpiexec)
    check(three["time"] == 150.0 and len(three["x"]) == 216, f"crossing3: {len(three['x'])} nodes")
    pairs = [int(n) for n in re.findall(r"gap at side set \d+: (\d+) node pairs", log)]
    check(pairs == [36, 36, 36], f"crossing3: pairs per gap {pairs}")
    on_gap = ~np.isnan(three["contact_pressure"])
    check(np.all(three["contact_active"][on_gap] == 1.0), "crossing3: every gap node in contact")

    # 4. Every gap in the outputs.
    gap_outputs(work, "contact-box-crossing", [10, 12], check, "crossing")
    gap_outputs(work, "contact-box-crossing3", [10, 11, 12], check, "crossing3")
    bonded = gap_outputs(work, "crossing-bonded", [10, 12], check, "bonded gap 12")
    at_50 = np.flatnonzero(bonded["time"] == 50.0)[-1]
    f10, f12 = bonded["normal_force_gap10"][at_50], bonded["normal_force_gap12"][at_50]
    f10_end = bonded["normal_force_gap10"][-1]
    check(f12 < -100.0 and f10 == 0.0 and f10_end > 1e3,
          f"bonded gap 12: normal force at 50 s {f12:.6g} N (tension) on gap 12, {f10} on the "
          f"open gap 10; gap 10 at 150 s {f10_end:.6g} N (compression)")
    heated = one_end_heated(kiln, inputs, work, n_ranks, mpiexec)
    column = gap_outputs(work, "crossing-heated", [10, 12], check, "heated at face 1")
    at_50 = np.flatnonzero(column["time"] == 50.0)[-1]
    q10, q12 = column["gap_heat_flow_gap10"][at_50], column["gap_heat_flow_gap12"][at_50]
    check(abs(q10) > 0.1 and abs(q12) < 1e-6 * abs(q10),
          f"heated at face 1, 50 s: {q10:.6g} W across gap 10, {q12:.3g} W across gap 12")
    exodus_gaps(heated, [10, 12], column, check, "heated at face 1")
    restarted_gaps(kiln, inputs, work, n_ranks, mpiexec, check)
    return 1 if check.failed else 0


if __name__ == "__main__":
    sys.exit(main())
