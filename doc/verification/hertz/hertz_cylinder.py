#!/usr/bin/env python3
"""Hertz contact of a cylinder on a block, plane strain, the two bodies meshed apart (issue 30,
"Hertz"): writes the Exodus mesh of refinement level n and prints the analytic contact
half-width and peak pressure for a force per unit length. The runs and their comparison are
hertz_study.py (the table in hertz.md; level 1 is the test interface_hertz_cylinder_np1/2).

    python3 hertz_cylinder.py mesh N OUT.exo [D]  the mesh of level N (N = 1, 2, 4, ...); with
                                                 D [m], the cylinder moved down by D: the
                                                 bodies overlap (a bad input, for the tests)
    python3 hertz_cylinder.py analytic P         a and p0 for P [N/m] (also: E*, the data)
    python3 hertz_cylinder.py check              the mesh's own checks (levels 1, 2)

Geometry (metres; the symmetry plane x = 0 halves both bodies, one cell layer of thickness T
along z with rollers on both z faces: plane strain):
- block 1, the block: x in [0, W], y in [-H, 0], 8N x 8N cells graded towards the point
  of first contact (0, 0) by x = W sinh(b s) / sinh(b) (b = 6), likewise in depth;
- block 2, the cylinder: a quarter ring about the centre (0, R) (touching the block at the
  origin: g0 = 0 there, > 0 elsewhere), radii R / 2 .. R, angles -90 .. 0 degrees from the
  x axis, 12N (angle) x 6N (radius) cells graded towards the bottom point and the outer
  arc (b = 5): finer than the block's top at the contact (the secondary side).
Side sets: 1 block x = 0, 2 block bottom y = -H, 3 block top y = 0 (contact: primary),
4 block z faces; 5 cylinder x = 0, 6 cylinder outer arc within 45 degrees of the bottom
(contact: secondary), 7 cylinder inner arc r = R / 2 (the load: u_y = -delta), 8 cylinder
z faces. Nodes 1-based in Exodus, blocks 1 then 2.
"""
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "tests" / "support"))

R = 0.01  # cylinder radius [m]
W = H = 0.02  # block half-width and depth [m]
T = 0.001  # thickness along z [m]
LAMBDA, MU = 5.2e10, 2.6e10  # the contact box's aluminium [Pa]
B_BLOCK, B_CYLINDER = 6.0, 5.0  # sinh grading strengths [-]


def graded(n, b):
    """n + 1 points on [0, 1], fine near 0: sinh(b s) / sinh(b)."""
    return [math.sinh(b * i / n) / math.sinh(b) for i in range(n + 1)]


def hex_layer(points2d, ni, nj):
    """Nodes (x, y, z) of a 2D grid (points2d[j][i], (ni + 1) x (nj + 1)) extruded over z in
    [0, T], and the HEX8 connectivity (0-based), counterclockwise in (x, y) seen from +z."""
    nodes = []
    for z in (0.0, T):
        for j in range(nj + 1):
            for i in range(ni + 1):
                x, y = points2d[j][i]
                nodes.append((x, y, z))
    layer = (ni + 1) * (nj + 1)

    def node(i, j, k):
        return k * layer + j * (ni + 1) + i

    cells = []
    for j in range(nj):
        for i in range(ni):
            bottom = [node(i, j, 0), node(i + 1, j, 0), node(i + 1, j + 1, 0), node(i, j + 1, 0)]
            cells.append(bottom + [n + layer for n in bottom])
    return nodes, cells


def orientation(points2d):
    """+1 if the grid's (i, j) axes are counterclockwise, -1 if not."""
    (x0, y0), (x1, y1), (x2, y2) = points2d[0][0], points2d[0][1], points2d[1][0]
    return 1 if (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0) > 0 else -1


def bodies(level, overlap=0.0):
    """The two bodies' nodes and cells, each counterclockwise in (x, y)."""
    n = 8 * level
    xs = [W * s for s in graded(n, B_BLOCK)]
    ys = [-H * s for s in graded(n, B_BLOCK)]
    # Block: i along x, j along -y: clockwise, so take j from the bottom up.
    block = [[(x, y) for x in xs] for y in reversed(ys)]
    na, nr = 12 * level, 6 * level
    angles = [-math.pi / 2 + (math.pi / 2) * s for s in graded(na, B_CYLINDER)]
    radii = [R - (R / 2) * s for s in graded(nr, B_CYLINDER)]  # from the outer arc inwards
    # i along the angle (counterclockwise about the centre), j from the outer arc inwards.
    cylinder = [[(r * math.cos(a) if i > 0 else 0.0, R - overlap + r * math.sin(a))
                 for i, a in enumerate(angles)] for r in radii]
    if orientation(block) < 0 or orientation(cylinder) < 0:
        raise SystemExit("internal: a body's cells are clockwise")
    return (block, n, n), (cylinder, na, nr)


def sides_where(cells, nodes, on_face, first_element):
    import exodus_mesh
    connect = [[c + 1 for c in cell] for cell in cells]
    return exodus_mesh.hex8_sides_where(connect, nodes, on_face, first_element)


def write_mesh(level, path, overlap=0.0):
    import exodus_mesh
    (block2d, bi, bj), (cyl2d, ci, cj) = bodies(level, overlap)
    block_nodes, block_cells = hex_layer(block2d, bi, bj)
    cyl_nodes, cyl_cells = hex_layer(cyl2d, ci, cj)
    offset = len(block_nodes)
    nodes = block_nodes + cyl_nodes
    cyl_cells = [[c + offset for c in cell] for cell in cyl_cells]
    first_cyl = len(block_cells) + 1
    eps = 1e-12

    def radius(p):
        return math.hypot(p[0], p[1] - (R - overlap))

    side_sets = []
    for sid, cells, first, on in [
        (1, block_cells, 1, lambda p: abs(p[0]) < eps),
        (2, block_cells, 1, lambda p: abs(p[1] + H) < eps),
        (3, block_cells, 1, lambda p: abs(p[1]) < eps),
        (4, block_cells, 1, None),
        (5, cyl_cells, first_cyl, lambda p: abs(p[0]) < eps),
        (6, cyl_cells, first_cyl,
         lambda p: abs(radius(p) - R) < eps and p[0] <= R * math.sin(math.pi / 4) + eps),
        (7, cyl_cells, first_cyl, lambda p: abs(radius(p) - R / 2) < eps),
        (8, cyl_cells, first_cyl, None),
    ]:
        if on is None:  # both z faces
            e0, s0 = sides_where(cells, nodes, lambda p: abs(p[2]) < eps, first)
            e1, s1 = sides_where(cells, nodes, lambda p: abs(p[2] - T) < eps, first)
            elems, sides = e0 + e1, s0 + s1
        else:
            elems, sides = sides_where(cells, nodes, on, first)
        side_sets.append((sid, elems, sides))
    blocks = [(1, "HEX8", [[c + 1 for c in cell] for cell in block_cells]),
              (2, "HEX8", [[c + 1 for c in cell] for cell in cyl_cells])]
    exodus_mesh.write(path, nodes, blocks, side_sets,
                      title=f"Hertz cylinder on a block, level {level}")
    return nodes, blocks, side_sets


def e_star():
    """The plane-strain contact modulus of two bodies of the same material [Pa]:
    1 / E* = 2 (1 - nu^2) / E."""
    E = MU * (3 * LAMBDA + 2 * MU) / (LAMBDA + MU)
    nu = LAMBDA / (2 * (LAMBDA + MU))
    return E / (2 * (1 - nu * nu)), E, nu


def analytic(P):
    """Hertz, a cylinder of radius R on a half-space, force P per unit length [N/m]:
    a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a), p(x) = p0 sqrt(1 - x^2 / a^2).
    In the half model (x >= 0, thickness T) the contact force is P T / 2."""
    Es, _, _ = e_star()
    a = math.sqrt(4 * P * R / (math.pi * Es))
    return a, 2 * P / (math.pi * a)


def check():
    """The mesh's own checks: the sides found, the faces' counts, g0 >= 0 at the secondary's
    nodes (the cylinder above the block's top), the bodies share no node."""
    import tempfile
    for level in (1, 2):
        with tempfile.TemporaryDirectory() as tmp:
            nodes, blocks, side_sets = write_mesh(level, str(Path(tmp) / "hertz.exo"))
        counts = {sid: len(elems) for sid, elems, _ in side_sets}
        n = 8 * level
        na, nr = 12 * level, 6 * level
        assert counts[1] == n and counts[2] == n and counts[3] == n, counts
        assert counts[4] == 2 * n * n and counts[8] == 2 * na * nr, counts
        assert counts[5] == nr and counts[7] == na, counts
        assert 0 < counts[6] < na, counts
        block_nodes = {c for cell in blocks[0][2] for c in cell}
        cyl_nodes = {c for cell in blocks[1][2] for c in cell}
        assert not block_nodes & cyl_nodes
        assert min(nodes[c - 1][1] for c in cyl_nodes) == 0.0  # touching at the origin
        print(f"level {level}: {len(nodes)} nodes, {sum(len(b[2]) for b in blocks)} cells, "
              f"side sets {counts}: ok")


def main(argv):
    if len(argv) in (4, 5) and argv[1] == "mesh":
        write_mesh(int(argv[2]), argv[3], float(argv[4]) if len(argv) == 5 else 0.0)
    elif len(argv) == 3 and argv[1] == "analytic":
        P = float(argv[2])
        Es, E, nu = e_star()
        a, p0 = analytic(P)
        print(f"E = {E:.6g} Pa, nu = {nu:.6g}, E* = {Es:.6g} Pa, R = {R} m")
        print(f"P = {P:.6g} N/m: a = {a:.6g} m, p0 = {p0:.6g} Pa "
              f"(a / R = {a / R:.3g}; the half model's force {P * T / 2:.6g} N)")
    elif len(argv) == 2 and argv[1] == "check":
        check()
    else:
        raise SystemExit(__doc__)


if __name__ == "__main__":
    main(sys.argv)
