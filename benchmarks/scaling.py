#!/usr/bin/python3
"""The scaling study (issue 12): Kiln on the contact box (closing, the generated rotated box)
and on the elastic cube, on 1 and 2 ranks, and two copies of a one-rank run at once.

    benchmarks/scaling.py                      # the whole study (long: N = 64 is 1.1 M unknowns)
    benchmarks/scaling.py --box 16 32 --cube 20 40 --end-time 60
    benchmarks/scaling.py --box 64 --cube --repeat 3   # np 1, np 2, two copies, in turn, 3 rounds

For every run it records, from Kiln's log and its Teuchos timer table (the slowest rank):
the unknowns, the wall time of the whole process and per step, split into assembly
(residual and Jacobian), preconditioner set-up, linear solve (Belos), output (results and
checkpoints) and the rest; Newton and linear iterations; Jacobians and preconditioners built;
the peak resident memory of every rank (GNU time) and its sum, and bytes per unknown.

It writes to --out (default doc/scaling/): runs.csv (one row per run), README.md (tables:
the runs, strong scaling np 1 -> 2 on each mesh, weak scaling at equal unknowns per rank,
and the parallel efficiency against the throughput of two one-rank copies run at once, the
real limit of a two-core machine whose memory bandwidth the ranks share), and PNG plots.
The command line and the machine are written beside the figures.
"""
import argparse
import csv
import datetime
import os
import pathlib
import platform
import re
import subprocess
import sys
import tempfile
import time

HERE = pathlib.Path(__file__).resolve().parent.parent
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
           "OMPI_MCA_rmaps_base_oversubscribe": "1"}

# Kiln's timers (doc/architecture.md) and Trilinos' that make up the split.
TIMERS = {
    "assembly": ["Kiln: 5 assembly (Jacobian)", "Kiln: 5 assembly (residual)"],
    "preconditioner": ["Kiln: 7 preconditioner set-up"],
    "linear_solve": ["Stratimikos: BelosLOWS"],
    "output": ["Kiln: 4 output", "Kiln: 6 checkpoint"],
}


def deck_box(n, end_time, base):
    """The contact box closing (inputs/contact-box-close.xml) on n^3 cells to end_time."""
    text = (HERE / "inputs/contact-box-close.xml").read_text()
    text = text.replace('value="{4, 4, 4}"', f'value="{{{n}, {n}, {n}}}"')
    text = re.sub(r'<Parameter name="Times" type="Array\(double\)" value="\{[^}]*\}"/>',
                  f'<Parameter name="Times" type="Array(double)" value="{{{end_time:g}}}"/>'
                  f'<Parameter name="File Base" type="string" value="{base}"/>', text)
    return text


def deck_cube(n, base):
    """The elastic cube (inputs/elastic-cube.xml) on n^3 cells."""
    text = (HERE / "inputs/elastic-cube.xml").read_text()
    text = text.replace('value="{60, 60, 60}"', f'value="{{{n}, {n}, {n}}}"')
    text = text.replace('<Parameter name="Times" type="Array(double)" value="{0}"/>',
                        '<Parameter name="Times" type="Array(double)" value="{0}"/>'
                        f'<Parameter name="File Base" type="string" value="{base}"/>')
    return text


def timer_max(log, name):
    """MaxOverProcs of a Teuchos timer [s], 0 if absent."""
    for line in log.splitlines():
        if line.startswith(name + " "):
            fields = re.findall(r"([0-9.eE+-]+) \((\d+)\)", line[len(name):])
            if len(fields) >= 3:  # min, mean, max over the ranks
                return float(fields[2][0])
            if len(fields) == 1:  # one rank
                return float(fields[0][0])
    return 0.0


def kiln_flags(kiln):
    """--timers if this kiln prints its timer table only when asked."""
    help_text = subprocess.run([kiln, "--help"], capture_output=True, text=True).stdout
    return ["--timers"] if "--timers" in help_text else []


def launch(kiln, deck, np, work, tag, alone=True):
    """Starts `mpirun -np np kiln deck` with GNU time on every rank; returns the process.
    `alone` false: another mpirun runs at the same time, so this one binds its ranks to no
    core (Open MPI binds each mpirun's rank 0 to core 0: two copies would share one core)."""
    wrapper = work / "rank.sh"
    if not wrapper.exists():
        wrapper.write_text('#!/bin/sh\nexec /usr/bin/time -f "%M" -o "$KILN_RSS.$OMPI_COMM_WORLD_RANK" '
                           '"$@"\n')
        wrapper.chmod(0o755)
    env = dict(os.environ, **MPI_ENV, KILN_RSS=str(work / f"{tag}.rss"))
    binding = [] if alone else ["--bind-to", "none"]
    command = ["mpirun", "-np", str(np), *binding, str(wrapper), kiln, *kiln_flags(kiln), str(deck)]
    log = open(work / f"{tag}.log", "w")
    return subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT, env=env, cwd=work)


def record(case, n, np, work, tag, wall, copies=1):
    """The figures of a finished run from its log and its ranks' peak RSS."""
    log = (work / f"{tag}.log").read_text()
    # The summary: "status: complete" and "steps: N" (before, one "done: N steps" line).
    if "status: complete" not in log and "done:" not in log:
        sys.exit(f"scaling.py: {case} N={n} np={np} failed; its log:\n{log[-3000:]}")
    unknowns = int(re.search(r"unknowns: (\d+)", log).group(1))
    steps_found = re.search(r"^steps: (\d+)$", log, re.M) or re.search(r"done: (\d+) steps?", log)
    steps = int(steps_found.group(1)) if case == "box" else 1
    # Every solve's line (the initial equilibrium's too): "Newton K (L linear)".
    solves = re.findall(r"Newton (\d+) \((\d+) linear\)", log)
    newton = sum(int(k) for k, _ in solves)
    linear = sum(int(l) for _, l in solves)
    rss = [int((work / f"{tag}.rss.{r}").read_text().split()[-1]) * 1024 for r in range(np)]
    row = {"case": case, "N": n, "np": np, "copies": copies, "unknowns": unknowns,
           "steps": steps, "newton": newton, "linear": linear, "wall_s": round(wall, 3),
           "wall_per_step_s": round(wall / max(steps, 1), 4)}
    accounted = 0.0
    for part, names in TIMERS.items():
        seconds = sum(timer_max(log, name) for name in names)
        row[part + "_s"] = round(seconds, 3)
        accounted += seconds
    row["rest_s"] = round(wall - accounted, 3)
    row["jacobians"] = int(re.search(r"\((\d+)\)", next(
        (l for l in log.splitlines() if l.startswith("Kiln: 5 assembly (Jacobian)")), "(0)")).group(1))
    row["preconditioners"] = int(re.search(r"\((\d+)\)", next(
        (l for l in log.splitlines() if l.startswith("Kiln: 7 preconditioner set-up")), "(0)")).group(1))
    row["peak_rss_max_MiB"] = round(max(rss) / 2**20, 1)
    row["peak_rss_sum_MiB"] = round(sum(rss) / 2**20, 1)
    row["bytes_per_unknown"] = round(sum(rss) / unknowns)
    row["linear_per_newton"] = round(linear / max(newton, 1), 1)
    return row


def run_once(kiln, case, n, np, args, work, repeat, copies):
    """One run of a case on `np` ranks, or `copies` one-rank runs at once: its row."""
    procs, tags = [], []
    start = time.perf_counter()
    for copy in range(copies):
        tag = f"{case}{n}-np{np}-c{copy}-r{repeat}"
        deck = work / f"{tag}.xml"
        base = work / f"{tag}-out"
        deck.write_text(deck_box(n, args.end_time, base) if case == "box" else deck_cube(n, base))
        procs.append(launch(kiln, deck, np, work, tag, alone=copies == 1))
        tags.append(tag)
    for p in procs:
        p.wait()
    wall = time.perf_counter() - start
    print(f"  {case} N={n} np={np} copies={copies} round {repeat + 1}: {wall:.2f} s", flush=True)
    return record(case, n, np, work, tags[0], wall, copies)


def run(kiln, case, n, args, work):
    """Every variant of a mesh (each rank count alone, then two one-rank copies at once) in
    turn, --repeat rounds of them, so that the machine's drift falls on all variants alike
    (the strong scaling and the efficiency compare them); of each variant the run of median
    wall time."""
    variants = [(np, 1) for np in args.np]
    if not args.no_copies and 1 in args.np:
        variants.append((1, 2))
    runs = {variant: [] for variant in variants}
    for repeat in range(args.repeat):
        for np, copies in variants:
            runs[(np, copies)].append(run_once(kiln, case, n, np, args, work, repeat, copies))
    rows = []
    for variant in variants:
        ordered = sorted(runs[variant], key=lambda r: r["wall_s"])
        rows.append(ordered[len(ordered) // 2])
    return rows


def markdown(rows, command, repeat):
    runs = ("one run per case" if repeat == 1 else
            f"medians of {repeat} runs per case, the variants of a mesh run in turn")
    lines = ["# Scaling study", "",
             f"Made by `{command}` on {datetime.date.today()} ({platform.node()}, "
             f"{os.cpu_count()} cores); {runs}. Times are the whole "
             "process; the split is the slowest rank's Teuchos timers. See "
             "`benchmarks/scaling.py` for what each column means.", "",
             "## Runs", ""]
    keys = ["case", "N", "np", "copies", "unknowns", "steps", "newton", "linear",
            "linear_per_newton", "jacobians", "preconditioners", "wall_s", "wall_per_step_s",
            "assembly_s", "preconditioner_s", "linear_solve_s", "output_s", "rest_s",
            "peak_rss_max_MiB", "peak_rss_sum_MiB", "bytes_per_unknown"]
    lines.append("| " + " | ".join(keys) + " |")
    lines.append("|" + "---|" * len(keys))
    for r in rows:
        lines.append("| " + " | ".join(str(r[k]) for k in keys) + " |")
    single = {(r["case"], r["N"], r["np"]): r for r in rows if r["copies"] == 1}
    pairs = {(r["case"], r["N"]): r for r in rows if r["copies"] == 2}
    lines += ["", "## Strong scaling (np 1 -> 2, the same mesh)", "",
              "speed-up = wall(np 1) / wall(np 2); efficiency = speed-up / 2; against two "
              "copies: speed-up / (2 wall(np 1) / wall(two np 1 copies at once)), the "
              "throughput two ranks can reach on this machine.", "",
              "| case | N | unknowns | wall np 1 [s] | wall np 2 [s] | speed-up | efficiency | "
              "two copies [s] | efficiency vs two copies |", "|---|---|---|---|---|---|---|---|---|"]
    for (case, n, np), r1 in sorted(single.items()):
        if np != 1 or (case, n, 2) not in single:
            continue
        r2 = single[(case, n, 2)]
        speedup = r1["wall_s"] / r2["wall_s"]
        both = pairs.get((case, n))
        limit = 2 * r1["wall_s"] / both["wall_s"] if both else None
        lines.append(f"| {case} | {n} | {r1['unknowns']} | {r1['wall_s']} | {r2['wall_s']} | "
                     f"{speedup:.2f} | {speedup / 2:.0%} | {both['wall_s'] if both else '-'} | "
                     f"{(speedup / limit) if limit else float('nan'):.0%} |")
    lines += ["", "## Weak scaling (about equal unknowns per rank)", "",
              "| case | np 1: N, unknowns, wall/step [s] | np 2: N, unknowns/rank, wall/step [s] | "
              "ratio |", "|---|---|---|---|"]
    for (case, n, np), r1 in sorted(single.items()):
        if np != 1:
            continue
        partners = [r for (c, m, p), r in single.items() if c == case and p == 2]
        if not partners:
            continue
        r2 = min(partners, key=lambda r: abs(r["unknowns"] / 2 - r1["unknowns"]))
        if not 0.5 < r2["unknowns"] / 2 / r1["unknowns"] < 2:
            continue
        lines.append(f"| {case} | {n}, {r1['unknowns']}, {r1['wall_per_step_s']} | {r2['N']}, "
                     f"{r2['unknowns'] // 2}, {r2['wall_per_step_s']} | "
                     f"{r2['wall_per_step_s'] / r1['wall_per_step_s']:.2f} |")
    return "\n".join(lines) + "\n"


def plots(rows, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    for case in sorted({r["case"] for r in rows}):
        fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
        for np in (1, 2):
            sel = sorted((r for r in rows if r["case"] == case and r["np"] == np
                          and r["copies"] == 1), key=lambda r: r["unknowns"])
            if not sel:
                continue
            u = [r["unknowns"] for r in sel]
            axes[0].loglog(u, [r["wall_per_step_s"] for r in sel], "o-", label=f"np {np}")
            axes[1].semilogx(u, [r["linear_per_newton"] for r in sel], "o-", label=f"np {np}")
            axes[2].semilogx(u, [r["bytes_per_unknown"] for r in sel], "o-", label=f"np {np}")
        axes[0].set(xlabel="unknowns", ylabel="wall time per step [s]", title=case)
        axes[1].set(xlabel="unknowns", ylabel="linear iterations per Newton iteration")
        axes[2].set(xlabel="unknowns", ylabel="peak RSS summed over ranks / unknown [B]")
        for a in axes:
            a.grid(True, which="both", alpha=0.3)
            a.legend()
        fig.tight_layout()
        fig.savefig(out / f"{case}.png", dpi=100)
        plt.close(fig)
        sel = [r for r in rows if r["case"] == case and r["copies"] == 1]
        fig, ax = plt.subplots(figsize=(8, 4.5))
        labels = [f"N={r['N']} np={r['np']}" for r in sel]
        bottom = [0.0] * len(sel)
        for part in ["assembly", "preconditioner", "linear_solve", "output", "rest"]:
            values = [max(r[part + "_s"], 0.0) / max(r["steps"], 1) for r in sel]
            ax.bar(labels, values, bottom=bottom, label=part)
            bottom = [b + v for b, v in zip(bottom, values)]
        ax.set(ylabel="seconds per step", title=f"{case}: where the time goes")
        ax.legend()
        plt.setp(ax.get_xticklabels(), rotation=30, ha="right")
        fig.tight_layout()
        fig.savefig(out / f"{case}-split.png", dpi=100)
        plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--box", type=int, nargs="*", default=[16, 32, 48, 64],
                        help="cells per edge of the contact box runs")
    parser.add_argument("--cube", type=int, nargs="*", default=[20, 40, 60],
                        help="cells per edge of the elastic cube runs")
    parser.add_argument("--np", type=int, nargs="*", default=[1, 2])
    parser.add_argument("--end-time", type=float, default=60.0,
                        help="end of the contact box runs [s]; the gap closes at 50-55 s")
    parser.add_argument("--repeat", type=int, default=1,
                        help="rounds of every variant of a mesh, run in turn (median kept)")
    parser.add_argument("--no-copies", action="store_true",
                        help="skip the two one-rank copies run at once")
    parser.add_argument("--kiln", default=str(HERE / "build/src/app/kiln"))
    parser.add_argument("--out", default=str(HERE / "doc/scaling"))
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        work = pathlib.Path(tmp)
        for case, sizes in (("box", args.box), ("cube", args.cube)):
            for n in sizes:
                rows.extend(run(args.kiln, case, n, args, work))
    with open(out / "runs.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    command = "benchmarks/scaling.py " + " ".join(sys.argv[1:])
    (out / "README.md").write_text(markdown(rows, command.strip(), args.repeat))
    plots(rows, out)
    print((out / "README.md").read_text())


if __name__ == "__main__":
    main()
