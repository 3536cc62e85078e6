#!/usr/bin/python3
"""Kiln against deal.II 9.4 with Trilinos ML on the elastic cube, side by side (issue 12:
"Elastic cube N = 60: <= 0.7x the wall time of deal.II 9.4 with Trilinos ML, np 1 and 2").

NEEDS deal.II: `apt-get install libdeal.ii-dev` (Debian 12: deal.II 9.4.1, about 150
packages). setup.sh does NOT install it: it is a dependency of this benchmark only.

    benchmarks/dealii_cube.py                  # N = 60, np 1 and 2, 3 repeats (the target)
    benchmarks/dealii_cube.py --repeat 1 10 20 # quick check

The problem is inputs/elastic-cube.xml: the unit cube, N^3 Q1 hexahedra, E = 1, nu = 0.25,
u = 0 on z = 0, body force (1, 2, 0), CG to 1e-8 of ||b||. Kiln runs that deck sized to N
(as benchmarks/scaling.py does; it writes its results and checkpoint at t = 0, part of its
time); deal.II runs benchmarks/dealii_cube/elastic_cube.cc (built here on first use, Release,
into benchmarks/dealii_cube/build/), CG + TrilinosWrappers::PreconditionAMG: ML smoothed
aggregation, Chebyshev smoother, 2 sweeps, aggregation threshold 0, the six rigid-body modes
as near-null space, coarse KLU; one thread per rank; no output files.

For each N and np the two programs run alternately (deal.II first in even repeats, Kiln
first in odd ones), under the same `mpirun --oversubscribe --bind-to BIND -np NP` and the
same environment (any OMPI_MCA_* you export applies to both). The wall time is the whole
mpirun process. The table gives medians over the repeats, the CG iterations and max |u|
(the largest absolute nodal displacement component; Kiln's from its results file) of the
median run, and Kiln / deal.II. It exits 1 if a run fails, if the unknowns differ, or if the
two max |u| differ by more than 1e-3 relative (N = 20: 5.82106, N = 60: 5.84373).
"""
import argparse
import datetime
import os
import pathlib
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = pathlib.Path(__file__).resolve().parent.parent
SOURCE = HERE / "benchmarks/dealii_cube"
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"}
TOLERANCE = 1e-3  # relative difference of max |u| allowed between the two codes


def fail(message):
    sys.exit(f"dealii_cube.py: FAILED: {message}")


def build_dealii(build):
    """Configures and builds the deal.II program (-j1) unless it is newer than its sources."""
    exe = build / "elastic_cube"
    sources = [SOURCE / "CMakeLists.txt", SOURCE / "elastic_cube.cc"]
    if exe.exists() and all(exe.stat().st_mtime >= s.stat().st_mtime for s in sources):
        return exe
    if not any(pathlib.Path(p).exists() for p in ("/usr/share/cmake/deal.II/deal.IIConfig.cmake",
                                                   os.environ.get("DEAL_II_DIR", "/nonexistent"))):
        fail("deal.II not found: `apt-get install libdeal.ii-dev` (a benchmark-only dependency "
             "that setup.sh does not install), or set DEAL_II_DIR")
    print(f"building {exe} ...", file=sys.stderr, flush=True)
    for command in (["cmake", "-S", str(SOURCE), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release"],
                    ["cmake", "--build", str(build), "-j1"]):
        done = subprocess.run(command, capture_output=True, text=True)
        if done.returncode != 0:
            fail(f"{' '.join(command)}:\n{done.stdout[-3000:]}{done.stderr[-3000:]}")
    return exe


def deck_cube(n, base):
    """The elastic cube (inputs/elastic-cube.xml) on n^3 cells, results to base (scaling.py)."""
    text = (HERE / "inputs/elastic-cube.xml").read_text()
    sized = text.replace('value="{60, 60, 60}"', f'value="{{{n}, {n}, {n}}}"')
    times = '<Parameter name="Times" type="Array(double)" value="{0}"/>'
    if (sized == text and n != 60) or times not in sized:
        fail("inputs/elastic-cube.xml no longer has the Cells/Times entries this script edits")
    return sized.replace(times, times + f'<Parameter name="File Base" type="string" value="{base}"/>')


def max_abs_u(h5):
    """Largest absolute displacement component of output step 0 of a Kiln results file."""
    try:
        import h5py
        import numpy
        with h5py.File(h5, "r") as f:
            return float(numpy.abs(f["steps/000000/displacement"][...]).max())
    except ImportError:  # not Debian's python3: h5dump (hdf5-tools), as elastic_cube.sh
        dump = subprocess.run(["h5dump", "-d", "/steps/000000/displacement", "-y", "-w", "0",
                               str(h5)], check=True, capture_output=True, text=True).stdout
        data = dump[dump.index("DATA {"):]
        return max(abs(float(v)) for v in re.findall(r"-?\d+\.?\d*(?:[eE][-+]?\d+)?",
                                                        data[data.index("{") + 1:data.index("}")]))


def mpirun(np, bind, command, work, tag):
    """Runs command under mpirun; returns (wall seconds of the whole process, its output)."""
    full = ["mpirun", "--oversubscribe", "--bind-to", bind, "-np", str(np), *command]
    start = time.perf_counter()
    done = subprocess.run(full, capture_output=True, text=True, cwd=work,
                          env=dict(os.environ, **MPI_ENV))
    wall = time.perf_counter() - start
    log = done.stdout + done.stderr
    (work / f"{tag}.log").write_text(log)
    if done.returncode != 0:
        fail(f"{' '.join(full)} exited with {done.returncode}; its output:\n{log[-3000:]}")
    return wall, log


def run_dealii(exe, n, np, bind, work, tag):
    wall, log = mpirun(np, bind, [str(exe), str(n)], work, tag)
    values = dict(re.findall(r"^([^:\n]+): (.+)$", log, re.M))
    try:
        return {"wall": wall, "unknowns": int(values["unknowns"]),
                "iterations": int(values["CG iterations"]), "max_u": float(values["max |u|"]),
                "phases": {k[5:-4]: float(v) for k, v in values.items() if k.startswith("time ")}}
    except KeyError as missing:
        fail(f"deal.II printed no {missing}; its output:\n{log[-3000:]}")


def run_kiln(kiln, n, np, bind, work, tag):
    base = work / tag
    deck = work / f"{tag}.xml"
    deck.write_text(deck_cube(n, base))
    wall, log = mpirun(np, bind, [kiln, str(deck)], work, tag)
    if "status: complete" not in log:
        fail(f"Kiln N={n} np={np} did not complete; its output:\n{log[-3000:]}")
    # The summary's count: every solve's Krylov iterations.
    linear = int(re.search(r"^linear iterations: (\d+)$", log, re.M).group(1))
    result = {"wall": wall, "unknowns": int(re.search(r"^unknowns: (\d+)", log, re.M).group(1)),
              "iterations": linear, "max_u": max_abs_u(base.with_suffix(".h5"))}
    for f in work.glob(f"{tag}.*"):  # results, checkpoints, history: not needed any more
        if f.suffix != ".log":
            f.unlink()
    return result


def check(n, np, d, k):
    if d["unknowns"] != k["unknowns"]:
        fail(f"N={n} np={np}: unknowns differ: deal.II {d['unknowns']}, Kiln {k['unknowns']}")
    rel = abs(d["max_u"] - k["max_u"]) / max(abs(d["max_u"]), 1e-300)
    if rel > TOLERANCE:
        fail(f"N={n} np={np}: max |u| differs by {rel:.2e} relative (> {TOLERANCE:g}): "
             f"deal.II {d['max_u']:.6g}, Kiln {k['max_u']:.6g}. Not the same problem?")


def median_run(runs):
    """The run of median wall time (the lower middle one for an even count)."""
    ordered = sorted(runs, key=lambda r: r["wall"])
    return ordered[(len(ordered) - 1) // 2], statistics.median(r["wall"] for r in runs)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("sizes", metavar="N", type=int, nargs="*", default=[60],
                        help="cells per edge (default 60)")
    parser.add_argument("--np", type=int, nargs="+", default=[1, 2], help="ranks (default 1 2)")
    parser.add_argument("--repeat", type=int, default=3, help="runs of each code per case; "
                        "the median is kept (default 3)")
    parser.add_argument("--bind", default="none", help="mpirun --bind-to for both codes "
                        "(default none: the two cores are shared with other work)")
    parser.add_argument("--kiln", default=os.environ.get("KILN", str(HERE / "build/src/app/kiln")))
    parser.add_argument("--build", default=str(SOURCE / "build"),
                        help="build directory of the deal.II program (default "
                        "benchmarks/dealii_cube/build, ignored by git)")
    args = parser.parse_args()
    if not os.access(args.kiln, os.X_OK):
        fail(f"no Kiln executable at {args.kiln} (build Kiln first, or --kiln PATH)")
    exe = build_dealii(pathlib.Path(args.build).resolve())

    rows = []
    with tempfile.TemporaryDirectory(prefix="dealii_cube.") as tmp:
        work = pathlib.Path(tmp)
        for n in args.sizes:
            for np in args.np:
                runs = {"deal.II": [], "Kiln": []}
                for r in range(args.repeat):
                    order = ["deal.II", "Kiln"] if r % 2 == 0 else ["Kiln", "deal.II"]
                    for code in order:
                        tag = f"{'dealii' if code == 'deal.II' else 'kiln'}-n{n}-np{np}-r{r}"
                        result = (run_dealii(exe, n, np, args.bind, work, tag) if code == "deal.II"
                                  else run_kiln(args.kiln, n, np, args.bind, work, tag))
                        runs[code].append(result)
                        print(f"  N={n} np={np} repeat {r + 1}/{args.repeat} {code}: "
                              f"{result['wall']:.2f} s, {result['iterations']} CG iterations, "
                              f"max |u| {result['max_u']:.6g}", file=sys.stderr, flush=True)
                    check(n, np, runs["deal.II"][-1], runs["Kiln"][-1])
                d, d_wall = median_run(runs["deal.II"])
                k, k_wall = median_run(runs["Kiln"])
                rows.append((n, np, d, d_wall, k, k_wall))

    print(f"Elastic cube, Kiln against deal.II {exe.name} (deal.II 9.4, Trilinos ML): "
          f"`benchmarks/dealii_cube.py {' '.join(sys.argv[1:])}` on {datetime.date.today()} "
          f"({platform.node()}, {os.cpu_count()} cores); mpirun --oversubscribe --bind-to "
          f"{args.bind}; whole-process wall time, median of {args.repeat}.\n")
    print("| N | np | unknowns | deal.II wall [s] | deal.II CG it. | deal.II max abs(u) "
          "| Kiln wall [s] | Kiln CG it. | Kiln max abs(u) | Kiln/deal.II |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for n, np, d, d_wall, k, k_wall in rows:
        print(f"| {n} | {np} | {d['unknowns']} | {d_wall:.2f} | {d['iterations']} | "
              f"{d['max_u']:.6g} | {k_wall:.2f} | {k['iterations']} | {k['max_u']:.6g} | "
              f"{k_wall / d_wall:.2f} |")
    print("\ndeal.II's own split of its median run [s] (MPI_Wtime between barriers; the rest "
          "of the wall time is MPI start-up, library loading and exit):\n")
    phases = list(rows[0][2]["phases"]) if rows else []
    print("| N | np | " + " | ".join(phases) + " |")
    print("|---|---|" + "---|" * len(phases))
    for n, np, d, *_ in rows:
        print(f"| {n} | {np} | " + " | ".join(f"{d['phases'][p]:.3f}" for p in phases) + " |")


if __name__ == "__main__":
    main()
