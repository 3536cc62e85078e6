#!/usr/bin/python3
"""Element types against HEX8 (issue 32): assembly time per unknown and Krylov iterations.

    benchmarks/element_types.py                    # N = 24, np 1, 3 rounds
    benchmarks/element_types.py --n 16 --np 2 --repeat 5 --types HEX8 TETRA10 HEX27

The problem is the elastic cube (inputs/elastic-cube.xml: unit cube, E = 1, nu = 0.25,
clamped at z = 0, body force (1, 2, 0), CG + MueLu to 1e-8) on the box generator's mesh of
each "Cell Type". The meshes have (nearly) the same nodes, hence unknowns: the linear types
(HEX8, TETRA4, WEDGE6) on N^3 hexahedra (split into 6 tetrahedra or 2 wedges each), the
quadratic ones (HEX27, TETRA10; HEX20 without the face and cell centres) on (N/2)^3.

For every type it prints, from Kiln's --timers table (the slowest rank) and its summary:
the unknowns, the time of one Jacobian and of one residual assembly per unknown [ns]
("Kiln: 5 assembly (Jacobian)" and "(residual)", divided by their call counts and the
unknowns) and their ratio to HEX8's, and the linear (Krylov) iterations of the solve and
their ratio to HEX8's. Issue 32's bounds: TETRA10 and HEX27 assembly within 3x of HEX8
per unknown; the Krylov iterations of a tet mesh within 1.5x of a hex mesh of the same
unknowns (TETRA4 and TETRA10 vs HEX8; TETRA10 vs HEX27, the quadratic pair). The types run in turn,
--repeat rounds (the machine's drift falls on all alike); the times are the medians.
"""
import argparse
import os
import pathlib
import re
import statistics
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent.parent
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
           "OMPI_MCA_rmaps_base_oversubscribe": "1"}
TYPES = ["HEX8", "TETRA4", "WEDGE6", "HEX20", "HEX27", "TETRA10"]
QUADRATIC = {"HEX20", "HEX27", "TETRA10"}
# The bounds: (type, against, what, bound).
BOUNDS = [("TETRA10", "HEX8", "jacobian_ns", 3.0), ("TETRA10", "HEX8", "residual_ns", 3.0),
          ("HEX27", "HEX8", "jacobian_ns", 3.0), ("HEX27", "HEX8", "residual_ns", 3.0),
          ("TETRA4", "HEX8", "linear", 1.5), ("TETRA10", "HEX8", "linear", 1.5),
          ("TETRA10", "HEX27", "linear", 1.5)]


def deck(cell_type, n, base):
    """The elastic cube on the box of `cell_type` with n^3 hexahedra (n/2 for quadratic)."""
    cells = n // 2 if cell_type in QUADRATIC else n
    text = (HERE / "inputs/elastic-cube.xml").read_text()
    text = text.replace('<Parameter name="Cells" type="Array(int)" value="{60, 60, 60}"/>',
                        f'<Parameter name="Cells" type="Array(int)" value="{{{cells}, {cells}, {cells}}}"/>'
                        f'<Parameter name="Cell Type" type="string" value="{cell_type}"/>')
    text = text.replace('<Parameter name="Times" type="Array(double)" value="{0}"/>',
                        '<Parameter name="Times" type="Array(double)" value="{0}"/>'
                        f'<Parameter name="File Base" type="string" value="{base}"/>')
    return text


def timer(log, name):
    """(seconds, calls) of a Teuchos timer: the slowest rank's time (MaxOverProcs), or the
    one rank's."""
    for line in log.splitlines():
        if line.startswith(name + " "):
            fields = re.findall(r"([0-9.eE+-]+) \((\d+)\)", line[len(name):])
            if not fields:
                break
            seconds, calls = fields[2] if len(fields) >= 3 else fields[0]
            return float(seconds), int(calls)
    sys.exit(f"element_types.py: no timer {name!r} in the log")


def run(kiln, cell_type, n, np, work):
    """One run: its figures."""
    base = work / f"{cell_type}-out"
    path = work / f"{cell_type}.xml"
    path.write_text(deck(cell_type, n, base))
    command = ["mpirun", "-np", str(np), kiln, "--timers", str(path)]
    done = subprocess.run(command, capture_output=True, text=True, cwd=work,
                          env=dict(os.environ, **MPI_ENV))
    log = done.stdout + done.stderr
    if done.returncode != 0 or "status: complete" not in log:
        sys.exit(f"element_types.py: {cell_type} failed:\n{log[-3000:]}")
    unknowns = int(re.search(r"unknowns: (\d+)", log).group(1))
    linear = sum(int(l) for l in re.findall(r"Newton \d+ \((\d+) linear\)", log))
    jac_s, jac_calls = timer(log, "Kiln: 5 assembly (Jacobian)")
    res_s, res_calls = timer(log, "Kiln: 5 assembly (residual)")
    return {"unknowns": unknowns, "linear": linear,
            "jacobian_ns": 1e9 * jac_s / max(jac_calls, 1) / unknowns,
            "residual_ns": 1e9 * res_s / max(res_calls, 1) / unknowns}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--n", type=int, default=24,
                        help="hexahedra per edge of the linear meshes (even) [-]")
    parser.add_argument("--np", type=int, default=1)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--types", nargs="*", default=TYPES, choices=TYPES)
    parser.add_argument("--kiln", default=str(HERE / "build/src/app/kiln"))
    args = parser.parse_args()
    if args.n % 2:
        sys.exit("element_types.py: --n must be even (the quadratic meshes have n/2 cells)")
    runs = {t: [] for t in args.types}
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(args.repeat):
            for t in args.types:
                runs[t].append(run(args.kiln, t, args.n, args.np, pathlib.Path(tmp)))
    rows = {}
    for t, rs in runs.items():
        rows[t] = {k: statistics.median(r[k] for r in rs) for k in rs[0]}
    hex8 = rows.get("HEX8")
    print(f"elastic cube, N = {args.n}, np {args.np}, medians of {args.repeat} rounds "
          f"(assembly: one call's time per unknown)")
    print(f"{'type':8} {'unknowns':>9} {'jac_ns':>8} {'xHEX8':>6} {'res_ns':>8} {'xHEX8':>6} "
          f"{'linear':>6} {'xHEX8':>6}")
    for t, r in rows.items():
        ratio = (lambda k: f"{r[k] / hex8[k]:6.2f}") if hex8 else (lambda k: f"{'-':>6}")
        print(f"{t:8} {r['unknowns']:9.0f} {r['jacobian_ns']:8.1f} {ratio('jacobian_ns')} "
              f"{r['residual_ns']:8.1f} {ratio('residual_ns')} {r['linear']:6.0f} {ratio('linear')}")
    print("issue 32's bounds:")
    for t, against, key, bound in BOUNDS:
        if t in rows and against in rows:
            ratio = rows[t][key] / rows[against][key]
            verdict = "ok" if ratio <= bound else "MISSED"
            print(f"  {t} / {against} {key}: {ratio:.2f} (bound {bound}) {verdict}")


if __name__ == "__main__":
    main()
