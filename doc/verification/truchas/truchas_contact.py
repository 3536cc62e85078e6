"""Shared checks of Truchas' sm-contact decks contact-1 and contact-2 (not a deck's module
itself: no deck inputs/truchas/truchas_contact.xml exists).

The cube (rot-gap-xyz.gen) is cut by gaps 10 and 11 into four quarters; face 1 is clamped, so
the two quarters on it are held, and the two others (the "free quarters") are held only by
frictionless contact: along the cube's x by gap 10, against each other along y by gap 11.
Each free quarter may translate along the cube's y and z and turn about its x axis wherever
nothing holds it: with the pairs between them open, six motions, V. The solutions of the
problem differ only by such motions c (u + V c) that keep every pair between the free
quarters from penetrating (g >= 0): a convex set, and the minimum-norm solution is its
element of least sum over the nodes of |u|^2 (what Kiln's "Free Motions" = "Minimum Norm"
gives, doc/contact.md). minimum_norm(u) finds it by a small quadratic programme over c.

- frame(...): the cube's axes from the bodies (x from the clamped quarters to the free ones,
  y from one free quarter to the other) and the free quarters;
- motions(...): V, the six rigid motions of the free quarters, one column each;
- minimum_norm(...): the minimum-norm element of u's solution set, and the shift V c;
- figures(...): the rows of contact-1.py and contact-2.py.
"""
import importlib.util
from pathlib import Path

import h5py
import numpy as np
from scipy.optimize import minimize

_spec = importlib.util.spec_from_file_location("contact0", Path(__file__).with_name("contact-0.py"))
contact0 = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(contact0)


def bodies(cells, n_nodes):
    """The connected parts of the mesh (cells that share a node), one label per node."""
    parent = list(range(n_nodes))

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a
    for nodes in cells:
        for n in nodes[1:]:
            parent[find(n)] = find(nodes[0])
    return np.array([find(n) for n in range(n_nodes)])


def frame(x, body, u):
    """(R, free): the cube's axes as rows of R and the labels of the two free quarters (the
    quarters with no clamped node, u = 0)."""
    labels = sorted(set(body))
    clamped = [b for b in labels if np.any(np.all(u[body == b] == 0.0, axis=1))]
    free = [b for b in labels if b not in clamped]
    if len(clamped) != 2 or len(free) != 2:
        raise ValueError(f"expected two clamped and two free quarters, found {clamped}, {free}")
    centre = {b: x[body == b].mean(axis=0) for b in labels}
    ex = sum(centre[b] for b in free) - sum(centre[b] for b in clamped)
    ex /= np.linalg.norm(ex)
    ey = centre[free[0]] - centre[free[1]]
    ey -= ey.dot(ex) * ex
    ey /= np.linalg.norm(ey)
    return np.array([ex, ey, np.cross(ex, ey)]), free


def motions(x, body, R, free):
    """V: per free quarter, the translations along the cube's y and z and the turn about its x
    axis through the two quarters' centre (1 m, 1 m and 1 mrad), one column each."""
    centre = x[np.isin(body, free)].mean(axis=0)
    columns = []
    for b in free:
        on = body == b
        for k in (1, 2):
            v = np.zeros_like(x)
            v[on] = R[k]
            columns.append(v.ravel())
        v = np.zeros_like(x)
        v[on] = np.cross(R[0], x[on] - centre) * 1e3
        columns.append(v.ravel())
    return np.array(columns).T


def free_pairs(x, body, R, free):
    """The pairs between the free quarters: (node of free[1], node of free[0]), the opening
    along R[1] being u[second] - u[first]."""
    size = np.abs(x).max()
    a_nodes = np.where(body == free[1])[0]
    pairs = []
    for i in np.where(body == free[0])[0]:
        d = np.linalg.norm(x[a_nodes] - x[i], axis=1)
        if d.min() < 1e-9 * size:
            pairs.append((a_nodes[int(np.argmin(d))], i))
    return np.array(pairs)


def minimum_norm(u, x, body):
    """(u_min, shift): the minimum-norm element of u's solution set (u + V c, g >= min(g(u),
    0) at every pair between the free quarters) and V c."""
    R, free = frame(x, body, u)
    V = motions(x, body, R, free)
    pairs = free_pairs(x, body, R, free)

    def opening(w):
        w = w.reshape(-1, 3)
        return (w[pairs[:, 1]] - w[pairs[:, 0]]) @ R[1]
    scale = np.abs(u).max()
    u0 = u.ravel() / scale
    g0 = opening(u0)
    G = np.array([opening(v) for v in V.T]).T
    floor = np.minimum(g0, 0.0)
    result = minimize(lambda c: np.sum((u0 + V @ c) ** 2), np.zeros(V.shape[1]),
                      jac=lambda c: 2.0 * V.T @ (u0 + V @ c),
                      constraints=[{"type": "ineq", "fun": lambda c: g0 - floor + G @ c,
                                    "jac": lambda c: G}],
                      method="SLSQP", options={"ftol": 1e-20, "maxiter": 500})
    shift = (V @ result.x).reshape(-1, 3) * scale
    return u + shift, shift


def gap_pairs(results):
    """(P, g) of every pair of every gap at the first output step, from each gap's own surface
    (/gap, /gap_<id>): the node fields show one pair of a node where gaps cross."""
    pressures, openings = [], []
    with h5py.File(results, "r") as h5:
        for name in h5:
            if name.startswith("gap") and "steps" in h5[name]:
                steps = h5[name]["steps"]
                first = steps[sorted(steps.keys())[0]]
                pressures.append(first["contact_pressure"][...])
                openings.append(first["gap_opening"][...])
    return np.concatenate(pressures), np.concatenate(openings)


def figures(results, deck, test, tolerance, golden_path):
    """The rows of the report for contact-1 or contact-2 (module docstrings)."""
    kiln, gold, node = contact0.matched_golden(results, deck, golden=golden_path)
    x_golden = gold["x"]
    body = bodies(gold["cells"], len(x_golden))
    u = kiln["displacement"][node]
    u_gold = gold["displacement"]
    u_scale = np.abs(u).max()
    difference = float(np.abs(u - u_gold).max())
    gold_min, gold_shift = minimum_norm(u_gold, x_golden, body)
    to_gold_min = float(np.abs(u - gold_min).max())
    kiln_min, kiln_shift = minimum_norm(u, x_golden, body)
    not_minimum = float(np.abs(kiln_shift).max())
    p, g = gap_pairs(results)
    p_scale = np.abs(p).max()
    tension = float(max(0.0, -p.min()) / p_scale)
    complementarity = float(np.abs(p * g).max() / (p_scale * u_scale))
    penetration = float(max(0.0, -g.min()) / u_scale)
    return [
        {"quantity": "max |u - u_golden| [m], t = 0", "kiln": difference,
         "tolerance": f"<= {tolerance:g} ({test})", "passed": difference <= tolerance,
         "golden": 0.0, "exact": None,
         "explained": "the golden carries free rigid motions of the free quarters (a "
                      f"translation of up to {np.linalg.norm(gold_shift, axis=1).max():.2g} m, "
                      "next row): "
                      "Truchas' iterative solver stops on one of the many solutions"},
        {"quantity": "max |u - u_golden,min| [m] (the golden's minimum-norm element)",
         "kiln": to_gold_min, "tolerance": f"<= {tolerance:g} ({test})",
         "passed": to_gold_min <= tolerance,
         "golden": float(np.linalg.norm(gold_shift, axis=1).max()),
         "exact": None},
        {"quantity": "max |u - u_min| [m] (Kiln's distance from its own minimum-norm element)",
         "kiln": not_minimum, "tolerance": "<= 1e-12 max |u|",
         "passed": not_minimum <= 1e-12 * u_scale, "golden": None, "exact": 0.0},
        {"quantity": "largest tension across a gap / max p", "kiln": tension,
         "tolerance": "<= 1e-9 (p >= 0; pairs held shut carry round-off)",
         "passed": tension <= 1e-9, "golden": None, "exact": 0.0},
        {"quantity": "max |p g| / (max p max |u|)", "kiln": complementarity,
         "tolerance": "<= 1e-12 (p g = 0)", "passed": complementarity <= 1e-12,
         "golden": None, "exact": 0.0},
        {"quantity": "largest penetration / max |u|", "kiln": penetration,
         "tolerance": "<= 1e-12 (g >= 0)", "passed": penetration <= 1e-12,
         "golden": None, "exact": 0.0},
    ]
