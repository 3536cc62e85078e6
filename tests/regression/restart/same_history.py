#!/usr/bin/python3
"""The time history and the gap tables of a restarted run against an uninterrupted one.

usage: same_history.py FULL_BASE RESTARTED_BASE

- RESTARTED_BASE.history.csv has one row per step, 0, 1, ... N, none twice (the rows of the
  earlier run up to the checkpoint, then the restarted run's), the same rows as
  FULL_BASE.history.csv: every column but the wall time to 1e-9 relative (of the column's
  largest value), the steps, times and Newton iterations exactly;
- RESTARTED_BASE.h5's /history holds the same values as its CSV, bit for bit;
- the gap tables BASE.gap-NNNNNN.csv are the same files with the same values (1e-9).
Exit status 0 if so, 1 with the differences otherwise.
"""
import glob
import os
import sys

import h5py
import numpy as np


def read_csv(path):
    """The column names (the headers "NAME [UNIT]" without their units) and the values."""
    with open(path) as f:
        names = [h.split(" [")[0] for h in f.readline().strip().split(",")]
        rows = [[float(v) for v in line.strip().split(",")] for line in f if line.strip()]
    return names, np.array(rows)


def close(a, b, exact=False):
    if exact:
        return np.array_equal(a, b, equal_nan=True)
    scale = np.nanmax(np.abs(np.concatenate([a, b]))) if a.size else 0.0
    both_nan = np.isnan(a) & np.isnan(b)
    return bool(np.all(both_nan | (np.abs(a - b) <= 1e-9 * scale + 1e-300)))


def main(full, restarted):
    problems = []
    names, a = read_csv(full + ".history.csv")
    names_b, b = read_csv(restarted + ".history.csv")
    if names != names_b:
        problems.append(f"the columns differ: {names} and {names_b}")
    elif a.shape != b.shape:
        problems.append(f"{a.shape[0]} rows against {b.shape[0]}")
    else:
        steps = b[:, names.index("step")]
        if not np.array_equal(steps, np.arange(len(steps))):
            problems.append(f"the restarted run's steps are not 0, 1, 2, ...: {steps.tolist()}")
        for c, name in enumerate(names):
            if name == "wall_time":
                continue
            exact = name in ("step", "time", "newton_iterations")
            if not close(a[:, c], b[:, c], exact):
                worst = int(np.nanargmax(np.abs(a[:, c] - b[:, c])))
                problems.append(f"{name} differs, most at step {worst}: {a[worst, c]!r} and "
                                f"{b[worst, c]!r}")
        with h5py.File(restarted + ".h5", "r") as f:
            for c, name in enumerate(names):
                stored = f["/history/" + name][...]
                if not np.array_equal(stored, b[:, c], equal_nan=True):
                    problems.append(f"{restarted}.h5: /history/{name} differs from the CSV")
    tables = sorted(os.path.basename(p)[len(os.path.basename(full)):]
                    for p in glob.glob(full + ".gap-*.csv"))
    tables_b = sorted(os.path.basename(p)[len(os.path.basename(restarted)):]
                      for p in glob.glob(restarted + ".gap-*.csv"))
    if not tables or tables != tables_b:
        problems.append(f"the gap tables differ: {tables} and {tables_b}")
    else:
        for t in tables:
            _, x = read_csv(full + t)
            _, y = read_csv(restarted + t)
            if x.shape != y.shape or not all(close(x[:, c], y[:, c]) for c in range(x.shape[1])):
                problems.append(f"gap table {t} differs")
    for p in problems:
        print("same_history.py:", p)
    if not problems:
        print(f"same_history.py: {len(b)} history rows and {len(tables)} gap tables agree")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
