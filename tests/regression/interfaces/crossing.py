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
"""
import os
import re
import subprocess
import sys

import h5py
import numpy as np

def run(kiln, inputs, work, deck, n_ranks, mpiexec):
    os.makedirs(work, exist_ok=True)
    command = [kiln, os.path.join(inputs, deck + ".xml")]
    if int(n_ranks) > 1:
        command = [mpiexec, "-np", n_ranks] + command
    done = subprocess.run(command, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True)
    if done.returncode != 0:
        print(done.stdout)
        raise SystemExit(f"{deck}: exit {done.returncode}")
    with h5py.File(os.path.join(work, "results", deck + ".h5"), "r") as h5:
        last = h5["steps"][sorted(h5["steps"].keys())[-1]]
        fields = {k: last[k][...] for k in last.keys()}
        fields["time"] = float(last.attrs["time"])
        fields["x"] = h5["mesh/coordinates"][...]
    return fields, done.stdout


def box_frame(x, phi=45.0, theta=-30.0):
    """Coordinates in the box's own frame (Kiln's rotation_matrix: Rx(theta) Ry(phi))."""
    p, t = np.radians(phi), np.radians(theta)
    cp, sp, ct, st = np.cos(p), np.sin(p), np.cos(t), np.sin(t)
    A = np.array([[cp, 0.0, sp], [st * sp, ct, -st * cp], [-ct * sp, st, ct * cp]])
    return x @ A


def bonded_gap_12(kiln, inputs, work, n_ranks, mpiexec):
    """contact-box-crossing with gap 12 bonded; its fields at 50 s."""
    os.makedirs(work, exist_ok=True)
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
    text = text.replace("""  </ParameterList>
  <ParameterList name="Time Stepping">""", gaps, 1)
    deck = os.path.join(work, "crossing-bonded.xml")
    with open(deck, "w", encoding="utf-8") as f:
        f.write(text)
    command = [kiln, deck]
    if int(n_ranks) > 1:
        command = [mpiexec, "-np", n_ranks] + command
    done = subprocess.run(command, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True)
    if done.returncode != 0:
        print(done.stdout)
        raise SystemExit(f"crossing-bonded: exit {done.returncode}")
    with h5py.File(os.path.join(work, "results", "crossing-bonded.h5"), "r") as h5:
        step = next(h5["steps"][k] for k in sorted(h5["steps"].keys())
                    if float(h5["steps"][k].attrs["time"]) == 50.0)
        return h5["mesh/coordinates"][...], {k: step[k][...] for k in step.keys()}


def main():
    kiln, inputs, work, n_ranks, mpiexec = sys.argv[1:6]
    failed = 0

    def check(ok, what):
        nonlocal failed
        print(f"{'pass' if ok else 'FAIL'}: {what}")
        failed += not ok

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
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
