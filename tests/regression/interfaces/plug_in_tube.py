#!/usr/bin/env python3
"""A roller on planes cutting a curved gap (issue 34, Verification): a quarter of a solid
cylinder (the plug, 0 <= r <= a, block 1) in a quarter of a thick tube (a <= r <= b, block 2),
HEX8, conforming at r = a, where side set 10 is the gap. The symmetry planes x = 0 and y = 0
hold both bodies by rollers, and so do z = 0 and z = h (plane strain); the outer surface r = b
is free. The plug is heated by dT above the stress-free temperature T_ref, the tube stays at
T_ref (no heat crosses the gap: Gap Conductance 0, so both temperatures are uniform and exact),
so the plug presses on the tube.

Usage: plug_in_tube.py KILN WORK_DIR NP MPIEXEC

The analytic answer (Lame; plane strain, one material: lambda, G, beta = (3 lambda + 2G) alpha,
K = lambda + G). Radial displacement u(r), eps_rr = u', eps_tt = u/r, eps_zz = 0:
  sigma_rr = lambda (u' + u/r) + 2G u' - beta dT,  sigma_tt = lambda (u' + u/r) + 2G u/r - beta dT
and equilibrium (r sigma_rr)' = sigma_tt gives u'' + u'/r - u/r^2 = 0: u = A r + D/r.
  plug (dT): u = A r (bounded at r = 0): sigma_rr = sigma_tt = 2K A - beta dT
  tube (0):  u = C r + D/r: sigma_rr = 2K C - 2G D/r^2,  sigma_tt = 2K C + 2G D/r^2
Free at b: K C = G D/b^2. In contact at a: A a = C a + D/a and 2K A - beta dT = sigma_rr(a).
Eliminating A and C: D = beta dT a^2 / (2 (lambda + 2G)), hence
  contact pressure  p      = -sigma_rr(a) = G beta dT (1 - a^2/b^2) / (lambda + 2G)
  radial displacement u(a) = D (1/a + G a / (K b^2))
  hoop stress       sigma_tt(b) = 4 G D / b^2.
(p > 0: the gap is closed, so Contact and Sliding have the same answer.)

Checks, on meshes with 2n segments on the quarter circle, n = 2, 4, 8 (written here):
1. Every gap pair in contact; the contact pressure (the largest error over the pairs), the
   radial displacement at r = a (the largest error over the gap nodes, both copies) and the
   hoop stress at r = b (extrapolated linearly to r = b from the two outer cells of each
   angular column of the tube, against sigma_tt(b); the largest error over the columns)
   converge at second order: the observed order from n = 4 to 8 is at least 1.8 for each.
   What is measured (orders 2.0 for the three at np 1 and 2) is recorded in
   doc/verification/plug-in-tube.md.
2. The rollers hold at every node on the planes, gap nodes (both copies, also those where the
   gap meets x = 0 or y = 0 and z = 0 or h) included: |u_x| on x = 0 and |u_y| on y = 0 below
   1e-12 of the largest displacement.
3. Kind "Sliding" (normal held, tangential free) gives the same displacements as Contact on
   the n = 4 mesh, to 1e-9 of the largest displacement, and the same pressures to 1e-9 of p;
   so do the rollers given as held components (Type "Displacement", Components x on x = 0,
   y on y = 0, z on z = 0 and h) instead of "Normal Displacement".
"""
import math
import os
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
import exodus_mesh  # noqa: E402  (tests/support/exodus_mesh.py)
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)

A, B, H = 0.01, 0.02, 0.0025  # plug radius, tube outer radius, height [m]
LAMBDA, G, ALPHA, DT, T_REF = 5.2e10, 2.6e10, 2.2e-5, 10.0, 298.0
GAP, X0, Y0, Z0, ZH, OUTER, PLUG_Z0 = 10, 1, 2, 3, 4, 5, 6  # side set ids
LEVELS = (2, 4, 8, 16)


def exact():
    """p, u(a), sigma_tt(b) of the Lame solution (the module's text)."""
    beta = (3 * LAMBDA + 2 * G) * ALPHA
    d = beta * DT * A**2 / (2 * (LAMBDA + 2 * G))
    return {"pressure": G * beta * DT * (1 - A**2 / B**2) / (LAMBDA + 2 * G),
            "u_a": d * (1 / A + G * A / ((LAMBDA + G) * B**2)),
            "hoop_b": 4 * G * d / B**2}


def quarter_disk(n):
    """The plug's cross-section: quads (4 points, counter-clockwise) of an O-grid with 2n
    segments on the quarter circle: an n x n core square [0, a/2]^2 and two n x n blocks
    between its outer edges and the arc (points blended linearly along the rays)."""
    c = A / 2
    quads = []
    core = [[(c * i / n, c * j / n) for j in range(n + 1)] for i in range(n + 1)]
    for i in range(n):
        for j in range(n):
            quads.append([core[i][j], core[i + 1][j], core[i + 1][j + 1], core[i][j + 1]])
    for swap in (False, True):
        grid = []
        for k in range(n + 1):  # from the core's edge (k = 0) to the arc (k = n)
            t = k / n
            row = []
            for j in range(n + 1):
                theta = math.pi / 4 * j / n
                edge = (c, c * j / n)
                arc = (A * math.cos(theta), A * math.sin(theta))
                p = ((1 - t) * edge[0] + t * arc[0], (1 - t) * edge[1] + t * arc[1])
                row.append((p[1], p[0]) if swap else p)
            grid.append(row)
        for k in range(n):
            for j in range(n):
                quads.append([grid[k][j], grid[k + 1][j], grid[k + 1][j + 1], grid[k][j + 1]])
    return quads


def quarter_ring(n):
    """The tube's cross-section: 2n segments on the quarter circle, n cells from a to b."""
    quads = []
    for k in range(n):
        r0, r1 = A + (B - A) * k / n, A + (B - A) * (k + 1) / n
        for j in range(2 * n):
            t0, t1 = math.pi / 2 * j / (2 * n), math.pi / 2 * (j + 1) / (2 * n)
            quads.append([(r * math.cos(t), r * math.sin(t))
                          for r, t in ((r0, t0), (r1, t0), (r1, t1), (r0, t1))])
    return quads


def write_mesh(n, path):
    """The HEX8 mesh (one layer 0 <= z <= h) of level n; returns nothing."""
    nodes, index = [], {}

    def node(p):
        key = tuple(round(v / A, 9) + 0.0 for v in p)
        if key not in index:
            nodes.append(p)
            index[key] = len(nodes)
        return index[key]

    def hexes(quads):
        cells = []
        for q in quads:
            area = sum(q[i][0] * q[(i + 1) % 4][1] - q[(i + 1) % 4][0] * q[i][1]
                       for i in range(4))
            if area < 0:
                q = q[::-1]
            cells.append([node((x, y, 0.0)) for x, y in q] +
                         [node((x, y, H)) for x, y in q])
        return cells

    plug, tube = hexes(quarter_disk(n)), hexes(quarter_ring(n))
    tol = 1e-9 * A

    def sides(connect, first, on_face):
        return exodus_mesh.hex8_sides_where(connect, nodes, on_face, first)

    def radius(p):
        return math.hypot(p[0], p[1])

    side_sets = [(GAP,) + sides(plug, 1, lambda p: abs(radius(p) - A) < tol)]
    for ss, where in ((X0, lambda p: abs(p[0]) < tol), (Y0, lambda p: abs(p[1]) < tol),
                      (Z0, lambda p: abs(p[2]) < tol), (ZH, lambda p: abs(p[2] - H) < tol)):
        e1, s1 = sides(plug, 1, where)
        e2, s2 = sides(tube, len(plug) + 1, where)
        side_sets.append((ss, e1 + e2, s1 + s2))
    side_sets.append((OUTER,) + sides(tube, len(plug) + 1, lambda p: abs(radius(p) - B) < tol))
    side_sets.append((PLUG_Z0,) + sides(plug, 1, lambda p: abs(p[2]) < tol))
    exodus_mesh.write(path, nodes, [(1, "HEX8", plug), (2, "HEX8", tube)], side_sets,
                      title=f"plug in tube, level {n}")


NORMAL_ROLLERS = {"symmetry and plane strain rollers": kd.normal_displacement([X0, Y0, Z0, ZH])}

COMPONENT_ROLLERS = {f"{c} held": kd.displacement(sets, c)
                     for c, sets in (("x", [X0]), ("y", [Y0]), ("z", [Z0, ZH]))}


def deck(mesh, base, kind, rollers):
    return {"Problem Name": "plug in tube",
            "Physics": "Thermo-Elasticity",
            "Mesh": kd.exodus_mesh(mesh, GAP),
            "Material": {**kd.lame(LAMBDA, G), "Thermal Expansion": ALPHA,
                         "Reference Temperature": T_REF, "Density": 2.7e3,
                         "Specific Heat": 9.0e2,
                         "Conductivity": {"Type": "Constant", "Value": 2.4e2}},
            "Thermal": {"Gap Conductance": 0.0, "Boundary Conditions": {
                "plug heated": kd.temperature([PLUG_Z0], T_REF + DT),
                "tube at the reference": kd.temperature([OUTER], T_REF)}},
            "Mechanics": {"Boundary Conditions": rollers, "Contact": {"Kind": kind}},
            "Time Stepping": {"Method": "Steady"},
            "Solver": {"Absolute Tolerance": 1e-9},
            "Output": {"File Base": base}}


def run(kiln, work, n, kind, n_ranks, mpiexec, rollers=NORMAL_ROLLERS):
    """Runs level n with the Kind; returns the last step's fields, the mesh and the gap."""
    mesh = os.path.join(work, f"plug-in-tube-{n}.exo")
    if not os.path.exists(mesh):
        write_mesh(n, mesh)
    name = "" if rollers is NORMAL_ROLLERS else "-components"
    base = os.path.join(work, f"plug-in-tube-{n}-{kind}{name}")
    done = kd.run_kiln(kiln, kd.write_deck(base, deck(mesh, base, kind, rollers)), n_ranks,
                       mpiexec)
    r = kd.read_step(done.results)
    return {"x": r["x"], "cells": r["cells"], "block": r["block"], "u": r["displacement"],
            "stress": r["stress"], "node_a": r["gap/node_a"], "node_b": r["gap/node_b"],
            "pressure": r["gap/contact_pressure"], "active": r["gap/contact_active"]}


def hoop_at_b(r):
    """sigma_tt extrapolated to r = b from the two outer cells of each angular column."""
    x = r["x"][r["cells"]]  # cells x 8 x 3
    centre = x.mean(axis=1)
    radius = np.hypot(centre[:, 0], centre[:, 1])
    theta = np.arctan2(centre[:, 1], centre[:, 0])
    s = r["stress"]  # xx yy zz xy yz xz
    c, n = np.cos(theta), np.sin(theta)
    hoop = s[:, 0] * n * n + s[:, 1] * c * c - 2 * s[:, 3] * n * c
    tube = np.flatnonzero(r["block"] == 2)
    values = []
    for t in np.unique(np.round(theta[tube], 9)):
        column = tube[np.isclose(theta[tube], t, atol=1e-9)]
        outer = column[np.argsort(radius[column])][-2:]
        (r1, r2), (s1, s2) = radius[outer], hoop[outer]
        values.append(s2 + (s2 - s1) * (B - r2) / (r2 - r1))
    return np.array(values)


def errors(r, ex):
    gap_nodes = np.concatenate([r["node_a"], r["node_b"]])
    x, u = r["x"][gap_nodes], r["u"][gap_nodes]
    u_r = (x[:, 0] * u[:, 0] + x[:, 1] * u[:, 1]) / np.hypot(x[:, 0], x[:, 1])
    return {"pressure": np.abs(r["pressure"] - ex["pressure"]).max() / ex["pressure"],
            "u_a": np.abs(u_r - ex["u_a"]).max() / ex["u_a"],
            "hoop_b": np.abs(hoop_at_b(r) - ex["hoop_b"]).max() / ex["hoop_b"]}


def main():
    kiln, work, n_ranks, mpiexec = sys.argv[1:5]
    os.makedirs(work, exist_ok=True)
    check = kd.Checks()

    ex = exact()
    print(f"exact: p = {ex['pressure']:.6e} Pa, u(a) = {ex['u_a']:.6e} m, "
          f"sigma_tt(b) = {ex['hoop_b']:.6e} Pa")
    table, results = [], {}
    for n in LEVELS:
        r = results[n] = run(kiln, work, n, "Contact", n_ranks, mpiexec)
        check(np.all(r["active"] == 1) and np.all(r["pressure"] > 0),
              f"level {n}: all {len(r['active'])} gap pairs in contact")
        scale = np.abs(r["u"]).max()
        on_x0, on_y0 = np.abs(r["x"][:, 0]) < 1e-9 * A, np.abs(r["x"][:, 1]) < 1e-9 * A
        gap = np.zeros(len(r["x"]), bool)
        gap[np.concatenate([r["node_a"], r["node_b"]])] = True
        held = max(np.abs(r["u"][on_x0, 0]).max(), np.abs(r["u"][on_y0, 1]).max())
        check(held <= 1e-12 * scale and (gap & on_x0).sum() == 4 and (gap & on_y0).sum() == 4,
              f"level {n}: rollers hold on x = 0 and y = 0, gap nodes included "
              f"({(gap & on_x0).sum()} and {(gap & on_y0).sum()} of them): largest "
              f"|u_x|, |u_y| {held:.3g} m (largest |u| {scale:.3g} m)")
        table.append((n, errors(r, ex)))
    print("   n  pressure      order   u(a)          order   hoop(b)       order")
    orders = {}
    for i, (n, e) in enumerate(table):
        line = f"{n:4d}"
        for k in ("pressure", "u_a", "hoop_b"):
            order = math.log2(table[i - 1][1][k] / e[k]) if i else float("nan")
            orders[k] = order
            line += f"  {e[k]:.4e}  {order:5.2f}"
        print(line)
    for k, order in orders.items():
        check(order >= 1.8, f"{k}: relative error of order {order:.2f} from n = "
              f"{LEVELS[-2]} to {LEVELS[-1]} (at least 1.8)")

    n = LEVELS[1]
    contact, sliding = results[n], run(kiln, work, n, "Sliding", n_ranks, mpiexec)
    du = np.abs(sliding["u"] - contact["u"]).max() / np.abs(contact["u"]).max()
    dp = np.abs(sliding["pressure"] - contact["pressure"]).max() / ex["pressure"]
    check(du <= 1e-9 and dp <= 1e-9,
          f"level {n}: Sliding = Contact, displacements to {du:.3g}, pressures to {dp:.3g}")
    held = run(kiln, work, n, "Contact", n_ranks, mpiexec, COMPONENT_ROLLERS)
    du = np.abs(held["u"] - contact["u"]).max() / np.abs(contact["u"]).max()
    dp = np.abs(held["pressure"] - contact["pressure"]).max() / ex["pressure"]
    check(du <= 1e-9 and dp <= 1e-9,
          f"level {n}: rollers as held components (Displacement, x on x = 0, y on y = 0, z on "
          f"z = 0, h) = Normal Displacement, displacements to {du:.3g}, pressures to {dp:.3g}")
    sys.exit(1 if check.failed else 0)


if __name__ == "__main__":
    main()
