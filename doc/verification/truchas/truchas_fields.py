"""Shared reading for the check modules of the Truchas decks (not a deck's module itself: no
deck inputs/truchas/truchas_fields.xml exists, so the report never loads it as one).

- kiln_steps(results): Kiln's output steps (time, node coordinates, cells, displacement,
  temperature and, per cell, stress and strain in Kiln's order xx yy zz xy yz xz);
- golden_series(path, n): Truchas' golden output series n (Simulations/MAIN/Series Data/
  Series n; its mesh under Meshes/DEFAULT, connectivity 1-based), with its tensors reordered
  from Truchas' xx yy zz xy xz yz into Kiln's order;
- cell_nodes(cells) / centroids(x, cells): each cell's nodes (a row of /mesh/connectivity
  without its -1 padding: a mixed mesh's rows are padded to the most nodes, output-format.md)
  and its centroid (the mean of its distinct nodes: also right for Truchas' degenerate hexes);
- match(points, reference): for each reference point, the index of the equal point (the
  meshes are matched by coordinates, never by index);
- figure(...): one row of the report (doc/verification/truchas_section.py).
"""
import h5py
import numpy as np

# Truchas' tensor columns xx yy zz xy xz yz, taken in Kiln's order xx yy zz xy yz xz.
TRUCHAS_TO_KILN = [0, 1, 2, 3, 5, 4]


def cell_nodes(cells):
    """The nodes of each cell: its row of a connectivity table without the -1 padding."""
    return [row[row >= 0] for row in cells]


def centroids(x, cells):
    """The centroid of each cell, the mean of its distinct nodes (Kiln's rows padded with -1;
    Truchas' tets, wedges and pyramids written as hexes with repeated nodes)."""
    return np.array([x[np.unique(nodes)].mean(axis=0) for nodes in cell_nodes(cells)])


class Step:
    """One output step of a Kiln run (SI units; stress and strain per cell)."""

    def __init__(self, group, x, cells):
        self.time = float(group.attrs["time"])
        self.x = x
        self.cells = cells
        self.centroids = centroids(x, cells)
        self.T = group["temperature"][...] if "temperature" in group else None
        self.u = group["displacement"][...]
        self.stress = group["stress"][...]
        self.strain = group["strain"][...]
        if group["stress"].attrs["components"].decode() != "xx,yy,zz,xy,yz,xz":
            raise ValueError(f"{group.name}/stress: unexpected components "
                             f"{group['stress'].attrs['components']}")


def kiln_steps(results):
    with h5py.File(results, "r") as h5:
        x = h5["mesh/coordinates"][...]
        cells = h5["mesh/connectivity"][...]
        return [Step(h5["steps"][name], x, cells) for name in sorted(h5["steps"].keys())]


class Series:
    """One series of a Truchas golden output (cell tensors in Kiln's order)."""

    def __init__(self, path, n):
        with h5py.File(path, "r") as h5:
            self.x = h5["Meshes/DEFAULT/Nodal Coordinates"][...]
            mesh = h5["Meshes/DEFAULT/Element Connectivity"]
            self.cells = mesh[...] - int(mesh.attrs.get("Offset", 1))
            group = h5[f"Simulations/MAIN/Series Data/Series {n}"]
            self.time = float(group.attrs["time"])
            self.fields = {}
            for name, data in group.items():
                values = data[...]
                if values.ndim == 2 and values.shape[1] == 6:
                    values = values[:, TRUCHAS_TO_KILN]
                self.fields[name] = values
        self.centroids = centroids(self.x, self.cells)


def golden_series(path, n):
    return Series(path, n)


def match(points, reference, tolerance=1e-9):
    """Index into `points` of each point of `reference` (equal to `tolerance` times the
    extent); an error if some reference point has no partner."""
    scale = max(float(np.ptp(reference, axis=0).max()), 1.0)
    d = np.linalg.norm(points[None, :, :] - reference[:, None, :], axis=2)
    index = d.argmin(axis=1)
    worst = float(d[np.arange(len(reference)), index].max())
    if worst > tolerance * scale:
        raise ValueError(f"the meshes differ: a point is {worst:g} from the nearest one")
    return index


def figure(quantity, kiln, tolerance_text, passed, golden=None, exact=None):
    return {"quantity": quantity, "kiln": float(kiln), "tolerance": tolerance_text,
            "passed": bool(passed), "golden": None if golden is None else float(golden),
            "exact": None if exact is None else float(exact)}


def uniform_state_figures(steps, temperature, strain, stress, stress_scale, u_exact, tolerance,
                          where):
    """Figures of a state that Q1 reproduces exactly (a uniform strain and stress, a linear
    displacement), each the largest error over the output steps (t = 0 and 1 s): of the
    nodal temperature (uniform and constant: insulated) against `temperature`, of the nodal
    displacement relative to its scale, of the cell strains, and of the cell stresses
    relative to `stress_scale` (the thermal stress beta dT, whose cancellation the
    stress-free states test), each against `tolerance` (round-off). strain, stress: 6
    components in Kiln's order; u_exact(x) -> the exact displacement at the points x; where:
    the deck's name for the rows."""
    errors = {"T": 0.0, "u": 0.0, "eps": 0.0, "sigma": 0.0}
    u_scale = 1.0
    e_scale = max(float(np.abs(strain).max()), 1.0)
    for step in steps:
        exact_u = u_exact(step.x)
        u_scale = max(float(np.abs(exact_u).max()), 1.0)
        errors["T"] = max(errors["T"], float(np.abs(step.T - temperature).max()) / temperature)
        errors["u"] = max(errors["u"], float(np.abs(step.u - exact_u).max()) / u_scale)
        errors["eps"] = max(errors["eps"],
                            float(np.abs(step.strain - np.asarray(strain)).max()) / e_scale)
        errors["sigma"] = max(errors["sigma"], float(np.abs(step.stress - np.asarray(stress))
                                                     .max()) / stress_scale)
    text = f"<= {tolerance:g} (round-off: Q1 holds the exact state)"
    t = "t = 0 and 1 s"
    rows = [
        figure(f"max |T - {temperature:g} K| / {temperature:g} K at the nodes, {t}",
               errors["T"], text, errors["T"] <= tolerance, exact=0.0),
        figure(f"max |u - u_exact| / {u_scale:g} m at the nodes, {t}", errors["u"], text,
               errors["u"] <= tolerance, exact=0.0),
        figure(f"max |eps - eps_exact| / {e_scale:g} over the cells and components, {t}",
               errors["eps"], text, errors["eps"] <= tolerance, exact=0.0),
        figure(f"max |sigma - sigma_exact| / {stress_scale:g} Pa over the cells and "
               f"components, {t}", errors["sigma"], text, errors["sigma"] <= tolerance,
               exact=0.0),
    ]
    times = [step.time for step in steps]
    if times != [0.0, 1.0]:
        rows.append(figure(f"{where}: output times {times}, expected [0, 1]", len(times),
                           "the outputs of the Truchas input", False))
    return rows


def free_expansion_figures(results, normal, point, beta, tolerance, where):
    """thermoelastic1..3: T = 2 K, T_ref = 1 K, alpha = 1/K, insulated; free expansion, eps =
    I, sigma = 0, held at most by a roller on the plane through `point` with unit `normal`
    (None: not held). The displacement is x - q up to the rigid motions the conditions leave
    free; Kiln's Minimum Norm picks the one with no component in them (sum over the nodes of
    u . r = 0), which is u = x - q with q the nodes' centroid projected onto the roller's
    plane (the centroid itself without a roller): its translations along the free directions
    sum to zero, and sum (x - q) . (w x (x - c)) = (c - q) . (w x sum (x - c)) = 0 for any
    rotation w about an axis through the centroid c."""
    steps = kiln_steps(results)
    centroid = steps[0].x.mean(axis=0)
    q = centroid
    if normal is not None:
        normal = np.asarray(normal, dtype=float)
        q = centroid - np.dot(centroid - np.asarray(point), normal) * normal
    return uniform_state_figures(steps, 2.0, [1, 1, 1, 0, 0, 0], [0] * 6, beta,
                                 lambda x: x - q, tolerance, where)


def face_mean(x, u, at=1.0):
    """The mean of the nodal field u over the face x = `at` of a box mesh: the trapezoidal
    weights of its nodes on their (y, z) grid, exact for a Q1 field's trace."""
    on = np.abs(x[:, 0] - at) < 1e-9
    weights = np.ones(int(on.sum()))
    for axis in (1, 2):
        v = np.round(x[on, axis], 12)
        grid = np.unique(v)
        h = np.diff(grid)
        w = np.zeros(len(grid))
        w[:-1] += h / 2
        w[1:] += h / 2
        weights *= w[np.searchsorted(grid, v)]
    return (weights[:, None] * u[on]).sum(axis=0) / weights.sum()


def stretch_pair_figures(normal_results, component_results, axis, test):
    """test-stretch-<axis>.py: the bar moved 1 m along <axis> by a normal condition
    (stretch-n<axis>) and by a component one (stretch-<axis>) gives the same displacement: to
    round-off in Kiln (1e-14 m counted; the test's 0.0 shown, explained: the normal condition
    puts the node's unknowns in a frame built from the face's normal, the component one keeps
    them on the coordinate axes, and the eliminations round differently)."""
    d = "xyz".index(axis)
    normal = kiln_steps(normal_results)[-1]
    component = kiln_steps(component_results)[-1]
    index = match(component.x, normal.x)
    difference = float(np.abs(normal.u - component.u[index]).max())
    moved = np.isclose(normal.x[:, d], 1.0)
    face = float(np.abs(normal.u[moved, d] - 1.0).max())
    quantity = f"max |u_n{axis} - u_{axis}| [m], t = 1 s"
    return [
        dict(figure(quantity, difference, f"<= 0 ({test})", difference == 0.0, exact=0.0),
             explained="round-off of two frames (truchas_fields.stretch_pair_figures)"),
        figure(quantity, difference, "<= 1e-14 (round-off)",
               difference <= 1e-14 and normal.time == 1.0, exact=0.0),
        figure(f"max |u_{axis} - 1| on the moved face [m]", face, "0 (the condition)",
               face == 0.0, exact=0.0),
    ]


def stretch_end_figures(results, axis):
    """stretch-<axis>: the clamped face does not move and the moved face moves by 1 m along
    <axis>, exactly (the conditions)."""
    d = "xyz".index(axis)
    step = kiln_steps(results)[-1]
    held = np.isclose(step.x[:, d], 0.0)
    moved = np.isclose(step.x[:, d], 1.0)
    clamp = float(np.abs(step.u[held]).max())
    face = float(np.abs(step.u[moved, d] - 1.0).max())
    return [
        figure("max |u| on the clamped face [m], t = 1 s", clamp, "0 (the condition)",
               clamp == 0.0 and step.time == 1.0, exact=0.0),
        figure(f"max |u_{axis} - 1| on the moved face [m]", face, "0 (the condition)",
               face == 0.0, exact=0.0),
    ]


def trilinear(x, values, points):
    """The trilinear interpolant at `points` of the nodal `values` of a structured box mesh
    with nodes `x` (a tensor grid, in any order): exact for a Q1 field, so the hex
    solution is evaluated where another mesh's nodes are."""
    axes = [np.unique(np.round(x[:, a], 12)) for a in range(3)]
    grid = np.zeros(tuple(len(g) for g in axes) + values.shape[1:])
    grid[tuple(np.searchsorted(g, np.round(x[:, a], 12)) for a, g in enumerate(axes))] = values
    result = np.zeros((len(points),) + values.shape[1:])
    index, weight = [], []
    for a, g in enumerate(axes):
        i = np.clip(np.searchsorted(g, points[:, a], side="right") - 1, 0, len(g) - 2)
        index.append(i)
        weight.append(np.clip((points[:, a] - g[i]) / (g[i + 1] - g[i]), 0.0, 1.0))
    for corner in range(8):
        bits = [(corner >> a) & 1 for a in range(3)]
        w = np.ones(len(points))
        for a in range(3):
            w = w * (weight[a] if bits[a] else 1.0 - weight[a])
        result += w[:, None] * grid[index[0] + bits[0], index[1] + bits[1], index[2] + bits[2]]
    return result


HEX_GOLDEN = "../shared/truchas-tests/sm-stretch/stretch-hex_golden/stretch-hex.h5"


def stretch_mesh_figures(results, checkout, test, golden=None, tolerance=1e-10):
    """stretch-tet/-wed/-mixed (test-stretch-<mesh>.py): the displacement at t = 0 against
    the golden output where Truchas keeps one (`golden`, matched by coordinates), to the
    test's 1e-10 m; against the same stretch on Truchas' 40 x 10 x 10 hex mesh (the golden
    of stretch-hex, interpolated trilinearly: exact for its Q1 field) where it keeps none; and
    the two conditions, the clamped face (x = -2) at rest and the moved face (x = 2) at
    u_x = 1e-8 m, exactly."""
    step = kiln_steps(results)[0]
    at_zero = step.time == 0.0
    rows = []
    text = f"<= {tolerance:g} ({test})"
    if golden is not None:
        series = golden_series(checkout / golden, 1)
        du = float(np.abs(step.u[match(step.x, series.x)] - series.fields["Displacement"]).max())
        rows.append(figure("max |u - u_golden| [m], t = 0", du, text,
                           du <= tolerance and at_zero, golden=0.0))
    hex_series = golden_series(checkout / HEX_GOLDEN, 1)
    on_hex = trilinear(hex_series.x, hex_series.fields["Displacement"], step.x)
    dh = float(np.abs(step.u - on_hex).max())
    rows.append(figure("max |u - u_hex golden| [m] at the nodes, t = 0 (stretch-hex's golden "
                       "interpolated)", dh, text, dh <= tolerance and at_zero))
    clamped = np.isclose(step.x[:, 0], -2.0)
    moved = np.isclose(step.x[:, 0], 2.0)
    clamp = float(np.abs(step.u[clamped]).max())
    face = float(np.abs(step.u[moved, 0] - 1e-8).max())
    rows += [
        figure("max |u| on the clamped face [m], t = 0", clamp, "0 (the condition)",
               clamp == 0.0 and at_zero, exact=0.0),
        figure("max |u_x - 1e-8| on the moved face [m], t = 0", face, "0 (the condition)",
               face == 0.0 and at_zero, exact=0.0),
    ]
    return rows
