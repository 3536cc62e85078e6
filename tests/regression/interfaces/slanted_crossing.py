#!/usr/bin/env python3
"""Gaps that cross at an angle (issue 34; doc/contact.md, "Gaps that cross"): the normals of
the gaps at a crossing node are not perpendicular, so the node's frame is not orthonormal (its
unknowns are the components along the normals, its rows those of the dual basis). Meshes
written here: `kiln --write-mesh` of the crossing decks' box (unrotated), its coordinates
mapped in the box frame, then rotated (a rotation by 0.7 rad about (1, 2, 3)), written back
by scipy.io.netcdf (Kiln warns that the Exodus library misreads such a file, and reads it).

Usage: slanted_crossing.py KILN INPUTS_DIR WORK_DIR NP MPIEXEC

1. The box of inputs/contact-box-crossing3.xml held by rollers on its six faces, SHEARED
   (x += 0.3 z, y += 0.3 z in the box frame: the planes z = const stay, x = const and
   y = const slant, no two of the three mid-planes perpendicular, nor the slanted faces to
   the gap planes they cut), cut by its three mid-planes (side sets 10, 11, 12) and by two
   (10, 12), at a uniform temperature (Initial Temperature, no thermal condition: it stays).
   a. Heated (308 K, dT = 10 K above T_ref): the exact state is u = 0, sigma =
      -3 K alpha dT I = -4.576e7 Pa I (hydrostatic) in every cell, every pair closed with
      pressure p = 4.576e7 Pa, whatever the shape of the bodies: to 1e-9 (u to 1e-9 of
      alpha dT L/2; the stress and the pressures to 1e-9 of 4.576e7 Pa). The pressure of a
      pair (the gap tables, BASE.gap*-NNNNNN.csv) is p itself where its node's rollers are
      perpendicular to the normal n, the crossing nodes inside the box included (normals not
      perpendicular); where a roller leans to n (the slanted faces meet the gaps obliquely)
      contact acts along n' (n with the rollers' directions projected out, doc/contact.md,
      "Conditions at gap nodes") and the pair's pressure is the force along n' per area,
      p n.n'.
   b. Cooled (288 K), three gaps: each eighth of the box is held by the rollers of its three
      outer faces, whose planes meet at one of the box's corners c (linearly independent
      normals: nothing rigid is free), and shrinks freely toward it: the exact state is
      u = alpha dT (x - c) on each body, sigma = 0, every pair open (opening > 0, no
      pressure). Checked: every node's u is alpha dT (x - c) for one of the box's corners c
      to 1e-9 of L; sigma = 0 to 1e-9 of 4.576e7 Pa; every gap node open, with
      contact_pressure 0. Two gaps: each quarter is held on both slanted faces y = +-L/2 as
      well, so it does not shrink freely (its state is not checked against a closed form):
      the run ends cleanly and every gap node is open with no pressure.
2. inputs/contact-box-crossing.xml (the seed's closing box heated to 308 K, gaps at x = 0 and
   z = 0) with the gap x = 0 slanted to the plane x = 0.25 z of the box frame (the nodes
   inside the box moved by x += 0.25 z (1 - (2x/L)^2), so that the outer faces and the gap
   z = 0 stay where they are and every cell face stays plane): a uniform state is not changed
   by where the body is cut, so at 150 s it is the spec's closed state of the uncut box, to the
   temperature's floor as the unslanted deck (interface_deck_contact-box-crossing_np1/2, by
   the same module doc/verification/interfaces/contact-box-close.py: von Mises and trace),
   every pair closed, with pressure 2.288e7 Pa n.n' (n' as in 1a: the slanted gap meets the
   rollers on z = +-L/2 obliquely) to the same floor. Restarted from its checkpoint at 53 s
   (the unknowns in frames that are not orthonormal), u at 150 s is the uninterrupted run's
   to 1e-9.
"""
import importlib.util
import math
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import h5py
import numpy as np
from scipy.io import netcdf_file

ALPHA, DT, K = 2.2e-5, 10.0, 5.2e10 + 2.0 / 3.0 * 2.6e10
SIGMA = 3.0 * K * ALPHA * DT  # 4.576e7 Pa
L = 0.04
SHEAR, SLANT = 0.3, 0.25

failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        failures.append(what)


def rotation():
    """A rotation by 0.7 rad about (1, 2, 3) (Rodrigues)."""
    a = np.array([1.0, 2.0, 3.0]) / math.sqrt(14.0)
    w = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(0.7) * w + (1 - math.cos(0.7)) * w @ w


def set_parameter(parent, name, kind, value):
    for p in parent.findall("Parameter"):
        if p.get("name") == name:
            parent.remove(p)
    ET.SubElement(parent, "Parameter", name=name, type=kind, value=value)


def sublist(parent, name):
    for p in parent.findall("ParameterList"):
        if p.get("name") == name:
            return p
    return ET.SubElement(parent, "ParameterList", name=name)


def write_deck(base, path, mesh_file, gaps, temperature=None, times=None, file_base=None):
    """The deck `base` with its box written to mesh_file (Exodus, gaps as given), and with a
    uniform `temperature` (no thermal condition) if given."""
    root = ET.parse(base).getroot()
    mesh = sublist(root, "Mesh")
    for child in list(mesh):
        mesh.remove(child)
    set_parameter(mesh, "Type", "string", "Exodus")
    set_parameter(mesh, "Gap Side Sets", "Array(int)", "{" + ", ".join(map(str, gaps)) + "}")
    exodus = ET.SubElement(mesh, "ParameterList", name="Exodus")
    set_parameter(exodus, "File", "string", mesh_file)
    set_parameter(exodus, "Coordinate Scale", "double", "1")
    thermal = sublist(root, "Thermal")
    if temperature is not None:
        set_parameter(thermal, "Initial Temperature", "double", str(temperature))
        for child in thermal.findall("ParameterList"):
            if child.get("name") == "Boundary Conditions":
                thermal.remove(child)
    if times is not None:
        set_parameter(sublist(root, "Output"), "Times", "Array(double)", times)
    if file_base is not None:
        set_parameter(sublist(root, "Output"), "File Base", "string", file_base)
    ET.ElementTree(root).write(path)


def box_mesh(kiln, base, work, name, transform):
    """kiln --write-mesh of the unrotated box of deck `base`, its coordinates mapped by
    transform (box frame, N x 3) and rotated; returns the file name."""
    unrotated = os.path.join(work, name + "-box.xml")
    root = ET.parse(base).getroot()
    box = sublist(sublist(root, "Mesh"), "Box")
    set_parameter(box, "Phi", "double", "0")
    set_parameter(box, "Theta", "double", "0")
    ET.ElementTree(root).write(unrotated)
    path = os.path.join(work, name + ".exo")
    subprocess.run([kiln, "--write-mesh", path, unrotated], check=True, cwd=work,
                   stdout=subprocess.DEVNULL)
    f = netcdf_file(path, "a", mmap=False)
    x = np.stack([f.variables[c][:].copy() for c in ("coordx", "coordy", "coordz")], axis=1)
    y = transform(x) @ rotation().T
    for d, c in enumerate(("coordx", "coordy", "coordz")):
        f.variables[c][:] = y[:, d]
    f.close()
    return name + ".exo"


def run(kiln, deck, work, n_ranks, mpiexec, base=None, options=()):
    command = [kiln, deck] + list(options)
    if int(n_ranks) > 1:
        command = [mpiexec, "-np", str(n_ranks)] + command
    done = subprocess.run(command, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True)
    check(done.returncode == 0, f"{os.path.basename(deck)}: the run ends cleanly")
    if done.returncode != 0:
        print(done.stdout)
        raise SystemExit(f"{len(failures)} check(s) failed")
    base = base or os.path.splitext(os.path.basename(deck))[0]
    results = os.path.join(work, "results", base + ".h5")
    with h5py.File(results, "r") as h5:
        last = h5["steps"][sorted(h5["steps"].keys())[-1]]
        fields = {k: last[k][...] for k in last.keys()}
        fields["time"] = float(last.attrs["time"])
        fields["x"] = h5["mesh/coordinates"][...]
    fields["log"] = done.stdout
    return fields, results


def pair_tables(results, gaps):
    """The last step's gap tables of results/BASE.h5: {gap id: (points, pressures)}."""
    base = results[:-3]
    tables = {}
    for k, gap in enumerate(gaps):
        stem = f"{base}.gap-" if k == 0 else f"{base}.gap_{gap}-"
        last = sorted(f for f in os.listdir(os.path.dirname(base))
                      if os.path.join(os.path.dirname(base), f).startswith(stem))[-1]
        t = np.genfromtxt(os.path.join(os.path.dirname(base), last), delimiter=",",
                          names=True, deletechars="", replace_space=" ")
        t = np.atleast_1d(t)
        tables[gap] = (np.stack([t["x [m]"], t["y [m]"], t["z [m]"]], axis=1),
                       t["contact_pressure [Pa]"])
    return tables


def leaning_pressure_error(results, gaps, p, normal, to_box, rollers):
    """The largest |P / (p n.n') - 1| over the pairs of the gaps: normal(gap, X) the gap's unit
    normal (box frame, at box-frame points X), to_box(x) the box-frame points of points x,
    rollers: the outer faces (1..6: x-, x+, y-, y+, z-, z+) held by rollers, whose box-frame
    unit normals are normal(face, X) too."""
    worst, n_pairs = 0.0, 0
    for gap, (x, pressure) in pair_tables(results, gaps).items():
        X = to_box(x)
        for i in range(len(X)):
            n = normal(gap, X[i])
            held = []
            for face in rollers:
                axis, side = (face - 1) // 2, (-1, 1)[(face - 1) % 2]
                if abs(X[i][axis] - side * L / 2) < 1e-9 * L:
                    d = normal(face, X[i])
                    for h in held:
                        d = d - np.dot(d, h) * h
                    held.append(d / np.linalg.norm(d))
            free = n - sum(np.dot(n, h) * h for h in held) if held else n
            along = np.dot(n, free / np.linalg.norm(free))
            worst = max(worst, abs(pressure[i] / (p * along) - 1))
            n_pairs += 1
    return worst, n_pairs


def sheared(x):
    y = x.copy()
    y[:, 0] += SHEAR * x[:, 2]
    y[:, 1] += SHEAR * x[:, 2]
    return y


def slanted(x):
    y = x.copy()
    y[:, 0] += SLANT * x[:, 2] * (1.0 - (2.0 * x[:, 0] / L) ** 2)
    return y


def sheared_box(kiln, inputs, work, n_ranks, mpiexec):
    base = os.path.join(inputs, "contact-box-crossing3.xml")
    mesh = box_mesh(kiln, base, work, "sheared", sheared)
    shear = sheared(np.eye(3)).T  # the map's matrix M (x -> M x; sheared() maps rows)

    def normal(side_set, X):
        # Gap 10, 11, 12 and faces 1-2, 3-4, 5-6: the planes x, y, z = const before the shear;
        # a normal m maps to M^-T m. Box-frame vectors, rotated like the mesh.
        m = np.eye(3)[side_set - 10 if side_set >= 10 else (side_set - 1) // 2]
        n = np.linalg.solve(shear.T, m)
        return rotation() @ (n / np.linalg.norm(n))

    def to_box(x):
        # Points before the shear and the rotation (the faces are at +-L/2 there).
        return np.linalg.solve(shear, (x @ rotation()).T).T

    corners = sheared(np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1)
                                for sz in (-1, 1)]) * (L / 2)) @ rotation().T
    for gaps in ([10, 11, 12], [10, 12]):
        tag = "".join(map(str, gaps))
        # a. heated: hydrostatic, u = 0, every pair closed.
        deck = os.path.join(work, f"sheared-{tag}-heated.xml")
        write_deck(base, deck, mesh, gaps, temperature=308.0, times="{0, 5}")
        f, results = run(kiln, deck, work, n_ranks, mpiexec)
        what = f"sheared box, gaps {gaps}, heated"
        on_gap = ~np.isnan(f["contact_pressure"])
        s = f["stress"]
        du = float(np.abs(f["displacement"]).max() / (ALPHA * DT * L / 2))
        dd = float(np.abs(s[:, :3] / -SIGMA - 1).max())
        ds = float(np.abs(s[:, 3:]).max() / SIGMA)
        dp, n_pairs = leaning_pressure_error(results, gaps, SIGMA, normal, to_box, range(1, 7))
        print(f"      {what}: u {du:.3g}, sigma_ii {dd:.3g}, sigma_ij {ds:.3g}, p {dp:.3g}")
        check(on_gap.sum() > 0 and np.all(f["contact_active"][on_gap] == 1),
              f"{what}: every gap node in contact ({on_gap.sum()})")
        check(du <= 1e-9, f"{what}: u = 0 to {du:.3g} of alpha dT L/2")
        check(dd <= 1e-9 and ds <= 1e-9,
              f"{what}: sigma = -4.576e7 Pa I to {dd:.3g} (diagonal), {ds:.3g} (shear)")
        check(n_pairs > 0 and dp <= 1e-9,
              f"{what}: the {n_pairs} pairs' pressure 4.576e7 Pa n.n' to {dp:.3g}")
        # b. cooled: each body shrinks toward its outer corner, sigma = 0, every pair open.
        deck = os.path.join(work, f"sheared-{tag}-cooled.xml")
        write_deck(base, deck, mesh, gaps, temperature=288.0, times="{0, 5}")
        f, _ = run(kiln, deck, work, n_ranks, mpiexec)
        what = f"sheared box, gaps {gaps}, cooled"
        on_gap = ~np.isnan(f["contact_pressure"])
        c = f["x"] - f["displacement"] / (-ALPHA * DT)
        du = float(np.min(np.linalg.norm(c[:, None, :] - corners[None, :, :], axis=2),
                          axis=1).max() / L)
        ds = float(np.abs(f["stress"]).max() / SIGMA)
        print(f"      {what}: u {du:.3g}, sigma {ds:.3g}")
        if len(gaps) == 3:
            check(du <= 1e-9,
                  f"{what}: u = alpha dT (x - c), c a corner of the box, to {du:.3g}")
            check(ds <= 1e-9, f"{what}: sigma = 0 to {ds:.3g} of 4.576e7 Pa")
        check(on_gap.sum() > 0 and np.all(f["gap_opening"][on_gap] > 0) and
              np.all(f["contact_pressure"][on_gap] == 0.0),
              f"{what}: every gap node open, no pressure")


def slanted_seed(kiln, inputs, work, n_ranks, mpiexec):
    base = os.path.join(inputs, "contact-box-crossing.xml")
    mesh = box_mesh(kiln, base, work, "slanted", slanted)
    deck = os.path.join(work, "slanted-crossing.xml")
    write_deck(base, deck, mesh, [10, 12])
    module = (Path(inputs).parent / "doc" / "verification" / "interfaces" /
              "contact-box-close.py")
    spec = importlib.util.spec_from_file_location("one_gap", module)
    one_gap = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(one_gap)
    f, results = run(kiln, deck, work, n_ranks, mpiexec)
    on_gap = ~np.isnan(f["contact_pressure"])
    check(on_gap.sum() > 0 and np.all(f["contact_active"][on_gap] == 1),
          f"slanted gap: every gap node in contact at {f['time']:g} s")

    def normal(side_set, X):
        # The slanted gap x = SLANT z (box frame); the other planes as generated.
        m = np.array([1.0, 0.0, -SLANT]) if side_set == 10 else np.eye(3)[
            side_set - 10 if side_set >= 10 else (side_set - 1) // 2]
        return rotation() @ (m / np.linalg.norm(m))

    dp, n_pairs = leaning_pressure_error(results, [10, 12], one_gap.SIGMA / 2, normal,
                                         lambda x: x @ rotation(), [1, 2, 3, 5, 6])
    check(n_pairs > 0 and dp <= one_gap.FLOOR,
          f"slanted gap: the {n_pairs} pairs' pressure 2.288e7 Pa n.n' to {dp:.3g} "
          f"(<= {one_gap.FLOOR:g})")
    for figure in one_gap.closed_state(results, "slanted gap")[:2]:
        check(figure["passed"], f"{figure['quantity']}: {figure['kiln']:.3g} "
              f"({figure['tolerance']})")
    # Restarted at 53 s (the checkpoint holds the unknowns, in the frames that are not
    # orthonormal at the crossing): the same state at 150 s.
    deck = os.path.join(work, "slanted-restart.xml")
    write_deck(base, deck, mesh, [10, 12], times="{0, 50, 53}",
               file_base="results/slanted-restart")
    run(kiln, deck, work, n_ranks, mpiexec, "slanted-restart")
    write_deck(base, deck, mesh, [10, 12], file_base="results/slanted-restart")
    g, _ = run(kiln, deck, work, n_ranks, mpiexec, "slanted-restart",
               ["--restart", "results/slanted-restart.checkpoint.h5"])
    du = float(np.abs(g["displacement"] - f["displacement"]).max() /
               np.abs(f["displacement"]).max())
    check("the 3 output steps up to t = 53 s" in g["log"] and g["time"] == f["time"] and
          du <= 1e-9,
          f"slanted gap restarted at 53 s: u at {g['time']:g} s as uninterrupted to {du:.3g}")


def main():
    kiln, inputs, work, n_ranks, mpiexec = sys.argv[1:6]
    kiln, inputs = os.path.abspath(kiln), os.path.abspath(inputs)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    sheared_box(kiln, inputs, work, n_ranks, mpiexec)
    slanted_seed(kiln, inputs, work, n_ranks, mpiexec)
    if failures:
        raise SystemExit(f"{len(failures)} check(s) failed")


if __name__ == "__main__":
    main()
