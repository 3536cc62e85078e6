#!/usr/bin/env python3
"""Hertz, a cylinder pressed on a block (issue 30, Verification): runs kiln on the meshes of
hertz_cylinder.py at the given levels and compares the contact half-width and the peak pressure
with the analytic ones for the force the run gives; prints the table of hertz.md and the
observed orders. Run with a Python 3 that has numpy, scipy and h5py (/usr/bin/python3):

    python3 hertz_study.py KILN [--levels 1 2 4] [--np 1] [--mpiexec mpirun]
    python3 hertz_study.py KILN --levels 1 --check     the test: exit status 1 if level 1 is
                                                        off (peak pressure beyond 10 %, a(P)
                                                        more than one cell from the last
                                                        loaded node)

The contact pressure of a pair is not in the results yet (contact_pressure holds the split
gap's only), so it is recovered from the displacement: the internal force of the cylinder's
cells (HEX8, 2 x 2 x 2 Gauss points, the same linear elasticity) at each node of its contact
arc (side set 6) balances the contact force there; the pressure is its component along the
arc's inward normal over the node's share of the arc's area (the integral of its shape
function: what the dual mortar basis lumps, D_jj). The force per unit length is P = 2 / T
times the sum (the half model, x >= 0, thickness T).
"""
import argparse
import math
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import hertz_cylinder as hc  # noqa: E402

DECK = HERE / "hertz-cylinder.xml"
GAUSS = [-1 / math.sqrt(3), 1 / math.sqrt(3)]
CORNERS = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
                    [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], dtype=float)


def elasticity():
    """The 6 x 6 isotropic stiffness (Voigt: xx, yy, zz, xy, yz, xz; engineering shears)."""
    C = np.zeros((6, 6))
    C[:3, :3] = hc.LAMBDA
    C[:3, :3] += 2 * hc.MU * np.eye(3)
    C[3:, 3:] = hc.MU * np.eye(3)
    return C


def internal_forces(X, u, cells):
    """sum over the cells of B^T sigma (2 x 2 x 2 Gauss points), by node: (n_nodes, 3)."""
    C = elasticity()
    f = np.zeros_like(X)
    for cell in cells:
        x, d = X[cell], u[cell]
        fe = np.zeros((8, 3))
        for a in GAUSS:
            for b in GAUSS:
                for c in GAUSS:
                    xi = np.array([a, b, c])
                    # dN/dxi of the trilinear shape functions
                    dN = np.array([[CORNERS[i, k] / 8 * np.prod([1 + CORNERS[i, m] * xi[m]
                                                                  for m in range(3) if m != k])
                                    for k in range(3)] for i in range(8)])
                    J = x.T @ dN
                    G = dN @ np.linalg.inv(J)  # dN/dx, (8, 3)
                    grad = d.T @ G  # du_i/dx_j
                    eps = np.array([grad[0, 0], grad[1, 1], grad[2, 2], grad[0, 1] + grad[1, 0],
                                    grad[1, 2] + grad[2, 1], grad[0, 2] + grad[2, 0]])
                    s = C @ eps
                    S = np.array([[s[0], s[3], s[5]], [s[3], s[1], s[4]], [s[5], s[4], s[2]]])
                    fe += G @ S * np.linalg.det(J)
        f[cell] += fe
    return f


def contact_arc(X, cyl_nodes):
    """The cylinder's nodes on its outer arc within 45 degrees of the bottom (side set 6), at
    z = 0, by increasing x, and their partners at z = T."""
    r = np.hypot(X[:, 0], X[:, 1] - hc.R)
    on = [n for n in cyl_nodes if abs(r[n] - hc.R) < 1e-12 and
          X[n, 0] <= hc.R * math.sin(math.pi / 4) + 1e-12]
    bottom = sorted((n for n in on if abs(X[n, 2]) < 1e-12), key=lambda n: X[n, 0])
    top = {(round(X[n, 0], 15), round(X[n, 1], 15)): n for n in on if abs(X[n, 2]) > 1e-12}
    return bottom, [top[(round(X[n, 0], 15), round(X[n, 1], 15))] for n in bottom]


def run(kiln, level, np_ranks, workdir, mpiexec="mpirun"):
    """Runs the deck on the mesh of the level; returns (X, u, blocks) at the last output."""
    import h5py
    mesh = Path(workdir) / f"hertz-{level}.exo"
    nodes, blocks, _ = hc.write_mesh(level, str(mesh))
    base = Path(workdir) / f"hertz-{level}"
    deck = Path(workdir) / f"hertz-{level}.xml"
    text = DECK.read_text().replace(
        '<ParameterList name="Output">',
        '<ParameterList name="Output">\n    <Parameter name="File Base" type="string" '
        f'value="{base}"/>')
    deck.write_text(text)
    cmd = [kiln, "--mesh", str(mesh), str(deck)]
    if np_ranks > 1:
        cmd = [mpiexec, "--oversubscribe", "-np", str(np_ranks)] + cmd
    out = subprocess.run(cmd, capture_output=True, text=True, cwd=workdir)
    if out.returncode != 0:
        raise SystemExit(f"kiln failed on level {level}:\n{out.stdout}\n{out.stderr}")
    with h5py.File(f"{base}.h5", "r") as f:
        X = f["mesh/coordinates"][:]
        last = sorted(f["steps"].keys())[-1]
        u = f["steps"][last]["displacement"][:]
    if np.abs(X - np.array(nodes)).max() > 0:
        raise SystemExit("internal: the results' nodes are not the mesh's")
    return X, u, blocks, out.stdout


def measure(kiln, level, np_ranks, workdir, mpiexec):
    X, u, blocks, _ = run(kiln, level, np_ranks, workdir, mpiexec)
    cyl_cells = np.array(blocks[1][2]) - 1
    f = internal_forces(X, u, cyl_cells)
    bottom, top = contact_arc(X, set(cyl_cells.ravel().tolist()))
    x = X[bottom, 0]
    s = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(X[bottom, 0]),
                                                  np.diff(X[bottom, 1])))])  # arc length
    share = np.zeros(len(s))  # the nodes' shares of the arc length (linear shape functions)
    share[:-1] += np.diff(s) / 2
    share[1:] += np.diff(s) / 2
    area = share * hc.T / 2  # each of the two nodes through the thickness
    n_out = np.stack([X[bottom, 0], X[bottom, 1] - hc.R, 0 * x], axis=1) / hc.R
    force = np.array([-(f[b] @ n) - (f[t] @ n) for b, t, n in zip(bottom, top, n_out)])
    p = force / (2 * area)
    P = 2 / hc.T * force.sum()  # per unit length, both halves
    loaded = np.nonzero(p > 1e-6 * p.max())[0]
    if P <= 0 or len(loaded) == 0 or loaded.max() + 1 >= len(x):
        raise SystemExit(f"level {level}: the cylinder does not press on the block as it should "
                         f"(P = {P:.4e} N/m, {len(loaded)} of {len(x)} arc nodes loaded)")
    last = loaded.max()
    a_exact, p0_exact = hc.analytic(P)
    # The ellipse p0 sqrt(1 - x^2 / a^2) through the bottom node's and the last loaded node's
    # pressures: a measure of a itself (the mid-point above is tied to where the nodes are).
    ratio = min(p[last] / p[0], 1 - 1e-12)
    a_fit = x[last] / math.sqrt(1 - ratio * ratio) if last > 0 else math.nan
    return dict(level=level, P=P, p0=p[0], p0_exact=p0_exact, a_exact=a_exact, a_fit=a_fit,
                a_last=x[last], a_open=x[last + 1], h=x[last + 1] - x[last],
                loaded=len(loaded), p=p, x=x)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("kiln")
    ap.add_argument("--levels", type=int, nargs="+", default=[1, 2, 4])
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--mpiexec", default="mpirun")
    ap.add_argument("--check", action="store_true")
    args = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for level in args.levels:
            rows.append(measure(os.path.abspath(args.kiln), level, args.np, tmp, args.mpiexec))
    print("level  P [N/m]    p0 [Pa]    p0(P) [Pa]  err p0   a(P) [um]  last loaded / first "
          "open node x [um]  a mid err  cell [um]  a fit [um]  a fit err")
    for r in rows:
        mid = (r["a_last"] + r["a_open"]) / 2
        r["err_p0"] = r["p0"] / r["p0_exact"] - 1
        r["err_a"] = mid / r["a_exact"] - 1
        r["err_fit"] = r["a_fit"] / r["a_exact"] - 1
        print(f"{r['level']:5d}  {r['P']:.4e} {r['p0']:.4e} {r['p0_exact']:.4e} "
              f"{100 * r['err_p0']:+6.1f}%  {1e6 * r['a_exact']:8.1f}   "
              f"{1e6 * r['a_last']:7.1f} / {1e6 * r['a_open']:7.1f}            "
              f"{100 * r['err_a']:+6.1f}%  {1e6 * r['h']:7.1f}    {1e6 * r['a_fit']:7.1f}    "
              f"{100 * r['err_fit']:+6.1f}%")
    for r0, r1 in zip(rows, rows[1:]):
        ratio = r1["level"] / r0["level"]
        orders = []
        for key in ("err_p0", "err_a", "err_fit"):
            e0, e1 = abs(r0[key]), abs(r1[key])
            orders.append(math.log(e0 / e1) / math.log(ratio) if e0 > 0 and e1 > 0 else math.nan)
        print(f"observed order, levels {r0['level']} -> {r1['level']}: peak pressure "
              f"{orders[0]:.2f}, half-width (mid-point) {orders[1]:.2f}, (ellipse through "
              f"the last loaded node) {orders[2]:.2f}")
    if args.check:
        bad = []
        for r in rows:
            if abs(r["err_p0"]) > 0.10:
                bad.append(f"level {r['level']}: peak pressure {r['p0']:.4e} Pa is "
                           f"{100 * r['err_p0']:+.1f}% off p0(P) = {r['p0_exact']:.4e} Pa")
            if abs(r["a_exact"] - r["a_last"]) > r["h"]:
                bad.append(f"level {r['level']}: a(P) = {r['a_exact']:.4e} m is more than a "
                           f"cell ({r['h']:.4e} m) from the last loaded node, x = "
                           f"{r['a_last']:.4e} m")
        if bad:
            print("\n".join(bad))
            return 1
        print("hertz check: OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
