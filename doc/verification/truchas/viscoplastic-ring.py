"""Check of inputs/truchas/viscoplastic-ring.xml: Truchas' viscoplastic-ring test.py.

test.py compares, with truchas.compare_max (the largest absolute difference of the arrays, in
the field's unit), Truchas' cell fields with its golden output: at t = 0 sigma to 5e-3 Pa,
epsilon to 1e-10 and the gap normal traction to 5e-3 Pa; at t = 0.5 s sigma to 2e2 Pa,
epsilon and the plastic strain to 5e-9. These are regression tolerances of one code on one
mesh (5e-3 Pa of stresses of 3e7 Pa is 2e-10 relative): no other discretization meets them.
Truchas' solid mechanics is not Kiln's (its stress is a cell value of its own node-based
scheme, Kiln's the average of Q1's stress over the cell), and the coarse mesh's curved faces
are chords, so the two differ by their discretization errors.

Which is right: the initial state (t = 0, uniform 550 K, stress-free at 800 K) has an exact
solution. With the sliding interface (normal displacement continuous, no shear) and free top
and outer faces, the plane-stress Lame solution of a plug shrink-fitted in a ring is exact in
3D: sigma_r + sigma_theta is uniform in each body, so sigma_z = 0 with a uniform eps_z per
body (different in the two: the interface slides), u_z = eps_z z (the roller at z = 0), and
the interface carries no shear. Plug (r < a = 0.0254 m): sigma_r = sigma_theta = -p; ring
(a < r < b = 0.0508 m): sigma_r = A - B/r^2, sigma_theta = A + B/r^2, A = p a^2/(b^2 - a^2),
B = A b^2; p from the continuity of u_r at a:

    p = (alpha_g - alpha_a) dT / ((1 - nu_g)/E_g + ((b^2 + a^2)/(b^2 - a^2) + nu_a)/E_a)

= 28.486 MPa with dT = -250 K. Both codes' t = 0 fields are compared with it (at the cell
centroids: the cells' stresses; at the gap nodes: the interface pressure); see
doc/verification/truchas/README.md for Kiln on meshes refined by refine_ring_mesh.py.
"""
import sys
from pathlib import Path

import h5py
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import truchas_fields as tf  # noqa: E402

TEST = "viscoplastic-ring"
GOLDEN = "../shared/truchas-tests/viscoplastic-ring/viscoplastic-ring_golden/viscoplastic-ring.h5"
CHANGES = []

A_PLUG, B_RING = 0.0254, 0.0508  # [m]
DT = 550.0 - 800.0  # initial temperature - stress-free temperature [K]
GRAPHITE = dict(lam=3.4e9, G=2.76e9, alpha=7.0e-6)
ALUMINIUM = dict(lam=5.2e10, G=2.6e10, alpha=2.2e-5)


def young_poisson(m):
    lam, G = m["lam"], m["G"]
    return G * (3 * lam + 2 * G) / (lam + G), lam / (2 * (lam + G))


def interface_pressure(dT=DT, q=0.0):
    """The exact interface pressure [Pa] with both bodies dT from the stress-free temperature
    and a pressure q on the outer radius (q = 0 in the Truchas test; q > 0 in
    tests/regression/interfaces/ring_sliding.py)."""
    Eg, ng = young_poisson(GRAPHITE)
    Ea, na = young_poisson(ALUMINIUM)
    a2, b2 = A_PLUG ** 2, B_RING ** 2
    return (((GRAPHITE["alpha"] - ALUMINIUM["alpha"]) * dT + 2 * q * b2 / ((b2 - a2) * Ea))
            / ((1 - ng) / Eg + ((b2 + a2) / (b2 - a2) + na) / Ea))


def exact_stress(points, in_plug, dT=DT, q=0.0):
    """The exact stress at `points` (Kiln's order xx yy zz xy yz xz) of interface_pressure's
    state: sigma_r = A - B/r^2, sigma_theta = A + B/r^2 in the ring."""
    p = interface_pressure(dT, q)
    a2, b2 = A_PLUG ** 2, B_RING ** 2
    A = (p * a2 - q * b2) / (b2 - a2)
    B = (p - q) * a2 * b2 / (b2 - a2)
    r2 = points[:, 0] ** 2 + points[:, 1] ** 2
    c2, s2, cs = points[:, 0] ** 2 / r2, points[:, 1] ** 2 / r2, points[:, 0] * points[:, 1] / r2
    srr = np.where(in_plug, -p, A - B / r2)
    stt = np.where(in_plug, -p, A + B / r2)
    sigma = np.zeros((len(points), 6))
    sigma[:, 0] = srr * c2 + stt * s2
    sigma[:, 1] = srr * s2 + stt * c2
    sigma[:, 3] = (srr - stt) * cs
    return sigma


def exact_strain(sigma, in_plug, dT=DT):
    """eps = ((1 + nu) sigma - nu tr(sigma) I)/E + alpha dT I, per body."""
    eps = np.zeros_like(sigma)
    for m, where in ((GRAPHITE, in_plug), (ALUMINIUM, ~in_plug)):
        E, nu = young_poisson(m)
        s = sigma[where]
        e = (1 + nu) / E * s
        e[:, :3] -= (nu / E * s[:, :3].sum(axis=1))[:, None]
        e[:, :3] += m["alpha"] * dT
        eps[where] = e
    return eps


def golden_path():
    return Path(__file__).resolve().parents[3] / GOLDEN


def kiln_gap_pressure(results, step_name):
    """Kiln's contact pressure at its gap nodes (both copies; > 0 in compression)."""
    with h5py.File(results, "r") as h5:
        p = h5["steps"][step_name]["contact_pressure"][...]
    return p[~np.isnan(p)]


def t0_errors(results, dT=DT, q=0.0):
    """The errors of Kiln's first output step (this run) against the exact state of dT and q:
    max |sigma - exact| over the cells [Pa], max |eps - exact|, max |p - exact| over the gap
    nodes [Pa], and the step; also for the study on refined meshes (README) and
    tests/regression/interfaces/ring_sliding.py."""
    step = tf.kiln_steps(results)[0]
    in_plug = np.hypot(step.centroids[:, 0], step.centroids[:, 1]) < A_PLUG
    sigma = exact_stress(step.centroids, in_plug, dT, q)
    with h5py.File(results, "r") as h5:
        name = sorted(h5["steps"].keys())[0]
    p = kiln_gap_pressure(results, name)
    return (float(np.abs(step.stress - sigma).max()),
            float(np.abs(step.strain - exact_strain(sigma, in_plug, dT)).max()),
            float(np.abs(p - interface_pressure(dT, q)).max()), step)


def figures(results, deck):
    golden = tf.golden_series(golden_path(), 1)
    kiln_sigma_error, kiln_eps_error, kiln_p_error, step = t0_errors(results)
    index = tf.match(step.centroids, golden.centroids)
    in_plug = np.hypot(golden.centroids[:, 0], golden.centroids[:, 1]) < A_PLUG
    sigma = exact_stress(golden.centroids, in_plug)
    eps = exact_strain(sigma, in_plug)
    p_exact = interface_pressure()
    gold_traction = golden.fields["Gap Normal Traction"]
    gold_p = -gold_traction[~np.isnan(gold_traction)]
    golden_errors = (float(np.abs(golden.fields["sigma"] - sigma).max()),
                     float(np.abs(golden.fields["epsilon"] - eps).max()),
                     float(np.abs(gold_p - p_exact).max()))
    d_sigma = float(np.abs(step.stress[index] - golden.fields["sigma"]).max())
    d_eps = float(np.abs(step.strain[index] - golden.fields["epsilon"]).max())
    with h5py.File(results, "r") as h5:
        name = sorted(h5["steps"].keys())[0]
    kiln_p = kiln_gap_pressure(results, name)
    # test.py compares the gap node arrays in Truchas' order; the pressure is uniform in the
    # exact state, so the sorted values are compared (each code's spread about p).
    d_p = float(np.abs(np.sort(kiln_p) - np.sort(gold_p)).max()) if len(kiln_p) == len(gold_p) \
        else float("inf")
    closer = "Kiln is the closer to the exact t = 0 state (the next rows)"
    rows = [
        dict(tf.figure("max |sigma - sigma_golden| over cells and components [Pa], t = 0",
                       d_sigma, "<= 5e-3 (test.py)", d_sigma <= 5e-3 and step.time == 0.0,
                       golden=0.0), explained=closer),
        dict(tf.figure("max |eps - eps_golden| over cells and components, t = 0", d_eps,
                       "<= 1e-10 (test.py)", d_eps <= 1e-10, golden=0.0), explained=closer),
        dict(tf.figure("max |p - p_golden| over the gap nodes (sorted) [Pa], t = 0", d_p,
                       "<= 5e-3 (test.py)", d_p <= 5e-3, golden=0.0), explained=closer),
    ]
    # Counted: Kiln's error against the exact state, no larger than the golden's (by the
    # margins measured on this mesh, README), and each within its bound.
    for quantity, kiln_error, golden_error, bound in (
            ("max |sigma - exact| over cells and components [Pa], t = 0", kiln_sigma_error,
             golden_errors[0], 6.0e6),
            ("max |eps - exact| over cells and components, t = 0", kiln_eps_error,
             golden_errors[1], 1.0e-4),
            ("max |p - exact| over the gap nodes [Pa], t = 0 (exact p = 28.486 MPa)",
             kiln_p_error, golden_errors[2], 2.0e6)):
        rows.append(tf.figure(quantity, kiln_error,
                              f"<= {bound:g} and <= the golden's error",
                              kiln_error <= bound and kiln_error <= golden_error,
                              golden=golden_error, exact=0.0))
    rows.append(plane_nodes_figure(results, name))
    rows += final_figures(results, step)
    return rows


def plane_nodes_figure(results, name):
    """The gap nodes on the symmetry planes x = 0 and y = 0: their area-weighted normal leans
    out of the plane (their gap faces lie on one side), and the roller there leaves contact
    the normal projected into the plane (doc/contact.md, "Conditions at gap nodes"), which is
    the exact radial direction. Their pressure against the exact p tests that projection."""
    error, n = plane_nodes_error(results, name, interface_pressure())
    return tf.figure(f"max |p - exact| at the {n} gap nodes on the planes x = 0 and y = 0 "
                     "[Pa], t = 0", error,
                     "<= 2e5 (the normal projected into the roller's plane)",
                     error <= 2.0e5 and n > 0, exact=0.0)


def plane_nodes_error(results, name, p_exact):
    """(max |p - p_exact| over the gap nodes on x = 0 or y = 0, their number)."""
    with h5py.File(results, "r") as h5:
        x = h5["mesh/coordinates"][...]
        p = h5["steps"][name]["contact_pressure"][...]
    on_plane = ~np.isnan(p) & ((np.abs(x[:, 0]) < 1e-9) | (np.abs(x[:, 1]) < 1e-9))
    return float(np.abs(p[on_plane] - p_exact).max()), int(on_plane.sum())


def equivalent(e):
    """The equivalent strain sqrt(2/3 e : e) of tensor rows (shears counted twice)."""
    return np.sqrt(2.0 / 3.0 * ((e[:, :3] ** 2).sum(axis=1) + 2 * (e[:, 3:] ** 2).sum(axis=1)))


def final_figures(results, first):
    """t = 0.5 s: test.py's comparisons (shown, not counted: there is no exact state after
    t = 0, and the two codes already differ at t = 0 by their discretizations, rows above),
    and what is counted: the step reached 0.5 s, the cell temperatures are the golden's to 5%
    of its cooling (test.py does not check T), the plug (elastic) has no plastic strain,
    and the ring's largest equivalent plastic strain is within a factor 2 of the golden's
    (the same flow law on different discretizations of the stress that drives it). That
    largest value is not converged on this mesh in either code (the MTS flow is steep in the
    stress, which peaks at the interface: Kiln 1.69e-5 here, 7.4e-5 on the once-split mesh;
    README), so the factor 2 is a check of this mesh only."""
    golden = tf.golden_series(golden_path(), 2)
    step = tf.kiln_steps(results)[-1]
    index = tf.match(step.centroids, golden.centroids)
    with h5py.File(results, "r") as h5:
        plastic = h5["steps"][sorted(h5["steps"].keys())[-1]]["plastic_strain"][...][index]
    in_plug = np.hypot(golden.centroids[:, 0], golden.centroids[:, 1]) < A_PLUG
    gold_plastic = equivalent(golden.fields["e_plastic"])
    d_sigma = float(np.abs(step.stress[index] - golden.fields["sigma"]).max())
    d_eps = float(np.abs(step.strain[index] - golden.fields["epsilon"]).max())
    d_plastic = float(np.abs(plastic - gold_plastic).max())
    shown = "not counted: no exact state at 0.5 s; the t = 0 rows show the discretizations' " \
            "difference, which dominates"
    ratio = float(plastic[~in_plug].max() / gold_plastic[~in_plug].max())
    # The heat equation (not in test.py): Kiln's nodal T averaged over each cell's nodes
    # against Truchas' cell T; both cool by about 1.36 K by 0.5 s.
    T_cell = np.array([step.T[nodes].mean() for nodes in tf.cell_nodes(step.cells)])[index]
    d_T = float(np.abs(T_cell - golden.fields["Z_TEMP"]).max())
    drop = float(550.0 - golden.fields["Z_TEMP"].min())
    return [
        dict(tf.figure("max |sigma - sigma_golden| [Pa], t = 0.5 s", d_sigma,
                       "<= 2e2 (test.py)", d_sigma <= 2e2, golden=0.0), explained=shown),
        dict(tf.figure("max |eps - eps_golden|, t = 0.5 s", d_eps, "<= 5e-9 (test.py)",
                       d_eps <= 5e-9, golden=0.0), explained=shown),
        dict(tf.figure("max |eps_p - eps_p_golden| (equivalent plastic strain; test.py: the "
                       "tensor's components), t = 0.5 s", d_plastic, "<= 5e-9 (test.py)",
                       d_plastic <= 5e-9, golden=0.0), explained=shown),
        tf.figure(f"max |T - T_golden| over the cells [K], t = 0.5 s (the golden cools by "
                  f"{drop:.3g} K)", d_T, "<= 5% of the golden's cooling (two discretizations)",
                  d_T <= 0.05 * drop, golden=0.0),
        tf.figure("largest equivalent plastic strain in the plug (elastic), t = 0.5 s",
                  float(plastic[in_plug].max()), "0", plastic[in_plug].max() == 0.0
                  and step.time == 0.5 and first.time == 0.0, exact=0.0),
        tf.figure("largest equivalent plastic strain in the ring / the golden's, t = 0.5 s",
                  ratio, "in [0.5, 2]", 0.5 <= ratio <= 2.0,
                  golden=float(gold_plastic[~in_plug].max())),
    ]
