#!/usr/bin/python3
"""Checks a verification report made by doc/verification/report.py (the CTest
verification_report_quick, tests/regression/verification/).

    check_report.py [--run [--build DIR] [--np N]] [--full] DIR

With --run, first runs `report.py --quick --build DIR --np N --out DIR` (its runs in
DIR/work). Then checks DIR/report.md and the PNGs beside it:

- the table of uniform states has its eight rows (four runs, at t = 0 and at the end), each
  with the gap state the spec expects and errors below the bounds of BOUNDS;
- the section with the errors of the original statement lists them;
- the gap events: variant A closes and opens between 50 and 53 s (the spec), variant B
  closes within the first 5 s;
- the closing time under refinement: at least two meshes (four with --full), every closing
  time between 50 and 53 s, and each difference smaller than the one before;
- the heat convergence orders: the order of the last refinement within 0.1 of 1 (backward
  Euler) and 2 (BDF2, space), as the unit test asserts;
- the elasticity convergence table: both bars on four meshes, the last orders within 0.1
  of 2 (displacement, L2) and 1 (cell stress, L2);
- the section "Gaps that cross" (every figure within its bound), the Truchas section (doc/verification/truchas_section.py): a row for every deck of
  inputs/truchas/ and each figure within its test's tolerance, or, with no deck, the line
  saying so;
- the PNG files exist, are PNG files under 300 KB, and report.md shows each of them.

Then checks the checker: the same report with one error raised above its bound must fail.
Exit status 0 when every check passes, 1 otherwise.
"""

import argparse
import re
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import truchas_section  # noqa: E402  (beside this file)

# Bounds of the errors of the uniform states. The spec: a trilinear mesh represents them
# exactly, so a correct code reproduces them to round-off; Kiln reproduces them to the
# accuracy of its iterative solves (Newton 1e-8 relative, GMRES 1e-10), and the final
# states carry what is left of the transient (1.5e-6 K of temperature spread at 150 s in
# variant A: 1e-7 of the stress). Observed at most 1e-7 (stress, strain, contact pressure),
# 3e-13 m (opening), 1e-6 K (temperature); a bound 10 to 100 times above that fails at a
# change of 1e-6 of the state.
BOUNDS = {
    "T error [K]": 1e-5,       # of a 10 to 110 K change
    "stress": 1e-6,            # relative to the largest exact stress component
    "strain": 1e-6,            # relative to the largest exact strain component
    "contact pressure": 1e-6,  # relative to the largest exact stress component
    "gap opening [m]": 1e-11,  # 1e-6 of the 1.17e-5 m opening
}
STATES = {("A-close", 0): "open", ("A-close", 150): "closed",
          ("A-open", 0): "closed", ("A-open", 150): "open",
          ("B-close", 0): "open", ("B-close", 600): "closed",
          ("B-open", 0): "closed", ("B-open", 600): "open"}
PNGS = ["temperature-A.png", "gap-A.png", "stress-A.png", "temperature-B.png", "gap-B.png",
        "stress-B.png", "closing-time.png", "heat-convergence.png"]
SPEC_ERRORS = ["transpose", "sigma'_yy", "eps'_zz", "theta"]


def cells(line):
    """The cells of a markdown table row (a pipe escaped as \\| stays in its cell)."""
    return [c.strip().replace("\\|", "|")
            for c in re.split(r"(?<!\\)\|", line.strip().strip("|"))]


def table_rows(text, header_start):
    """The rows (lists of cells) of the markdown table whose header starts with
    `header_start`."""
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if line.startswith(header_start):
            header = cells(line)
            rows = []
            for row in lines[i + 2:]:
                if not row.startswith("|"):
                    break
                rows.append(dict(zip(header, cells(row))))
            return rows
    return None


def number(text):
    try:
        return float(text.replace("*", ""))
    except ValueError:
        return float("nan")


def check(text, full, truchas=HERE.parent.parent / "inputs" / "truchas"):
    """The failures of report.md's text (an empty list when it passes)."""
    failures = []

    rows = table_rows(text, "| run | t [s] |")
    if rows is None:
        return ["no table of uniform states (| run | t [s] | ...)"]
    seen = set()
    for row in rows:
        key = (row.get("run"), number(row.get("t [s]", "nan")))
        if key not in STATES:
            failures.append(f"unexpected row {row}")
            continue
        seen.add(key)
        gap = row["gap: Kiln (expected)"]
        if not gap.startswith(STATES[key] + " "):
            failures.append(f"{key[0]} at t = {key[1]:g} s: gap {gap}, the spec: "
                            f"{STATES[key]}")
        for column, bound in BOUNDS.items():
            value = number(row.get(column, "nan"))
            if not value <= bound:  # NaN fails
                failures.append(f"{key[0]} at t = {key[1]:g} s: {column} error "
                                f"{row.get(column)} above {bound:g}")
    for key in STATES:
        if key not in seen:
            failures.append(f"no row for {key[0]} at t = {key[1]:g} s")

    section = re.search(r"^## Errors of the original statement\n(.*?)^## ", text, re.S | re.M)
    if section is None:
        failures.append("no section \"Errors of the original statement\"")
    else:
        for word in SPEC_ERRORS:
            if word not in section.group(1):
                failures.append(f"the errors of the original statement do not mention {word}")

    events = dict(re.findall(r"(\w-\w+): gap (?:closed|opened) at ([0-9.]+) s", text))
    for run, lo, hi in (("A-close", 50, 53), ("A-open", 50, 53), ("B-close", 0, 5)):
        t = number(events.get(run, "nan"))
        if not lo <= t <= hi:
            failures.append(f"{run}: gap event at {events.get(run)} s, the spec: "
                            f"between {lo} and {hi} s")

    refinement = table_rows(text, "| cells | h [mm] |")
    if refinement is None:
        failures.append("no table of the closing time under refinement")
    else:
        times = [number(r["closing time [s]"]) for r in refinement]
        if len(times) < (4 if full else 2):
            failures.append(f"closing time on {len(times)} meshes only")
        if not all(50 <= t <= 53 for t in times):
            failures.append(f"closing times {times} not all between 50 and 53 s")
        differences = [abs(b - a) for a, b in zip(times, times[1:])]
        if any(not d2 < d1 for d1, d2 in zip(differences, differences[1:])):
            failures.append(f"the closing time does not converge: differences {differences}")

    heat = table_rows(text, "| test | h or dt |")
    if heat is None:
        failures.append("no table of the heat convergence tests")
    else:
        expected = {"time, backward Euler": 1.0, "time, BDF2": 2.0}
        if full:
            expected["space (BDF2, L2)"] = 2.0
        for test, order in expected.items():
            orders = [number(r["order"]) for r in heat
                      if r["test"] == test and r["h or dt"] != "fitted over all" and r["order"]]
            if not orders or not abs(orders[-1] - order) <= 0.1:
                failures.append(f"heat convergence, {test}: orders {orders}, expected the last "
                                f"within 0.1 of {order}")
    failures += check_elastic(text)
    failures += check_energy(text)
    failures += check_corefined(text, full)
    failures += check_truchas(text, truchas)
    failures += check_interfaces(text)
    return failures


def check_elastic(text):
    """The elasticity convergence table: both cases on four meshes, the last orders within
    0.1 of 2 (displacement) and 1 (cell stress), as the test asserts."""
    rows = table_rows(text, "| case | cells along the bar |")
    if rows is None:
        return ["no table of the elasticity convergence orders"]
    failures = []
    for case in ("bar under its own weight (Elasticity)",
                 "bar under a linear temperature (Thermo-Elasticity)"):
        mine = [r for r in rows if r["case"] == case]
        if len(mine) < 4:
            failures.append(f"elasticity convergence, {case}: {len(mine)} meshes, expected 4")
            continue
        for column, expected in (("order u", 2.0), ("order stress", 1.0)):
            last = number(mine[-1][column])
            if not abs(last - expected) <= 0.1:
                failures.append(f"elasticity convergence, {case}: {column} {last}, expected "
                                f"within 0.1 of {expected}")
    return failures


def check_corefined(text, full):
    """The closing time with space and time refined together: every mesh closes within the
    spec's 50 to 53 s; in the full report four meshes whose differences shrink."""
    rows = table_rows(text, "| cells | h [mm] | largest step [s] |")
    if not rows:
        return ["no table of the closing time with space and time refined together"]
    failures = []
    events = [number(r["closing time [s]"]) for r in rows]
    for r, t in zip(rows, events):
        if not 50.0 <= t <= 53.0:
            failures.append(f"co-refined closing time on {r['cells']}: {t} s, outside 50..53 s")
    if full:
        if len(rows) < 4:
            failures.append(f"co-refined closing time: {len(rows)} meshes, expected 4")
        elif not abs(events[3] - events[2]) < abs(events[2] - events[1]) < \
                abs(events[1] - events[0]):
            failures.append(f"co-refined closing times {events}: the differences do not shrink")
    return failures


def check_energy(text):
    """The energy balance: every step's stored energy equals the heat in to 1e-8."""
    rows = table_rows(text, "| step | t [s] | stored [J] |")
    if not rows:
        return ["no table of the energy balance"]
    failures = []
    for row in rows:
        error = number(row["relative difference"])
        if not error <= 1e-8:
            failures.append(f"energy balance, step {row['step']}: stored and heat in differ by "
                            f"{error} (relative), above 1e-8")
    if len(rows) < 5:
        failures.append(f"energy balance: {len(rows)} steps, expected at least 5")
    return failures


def check_interfaces(text):
    """The section "Gaps that cross": a row set per deck of report.py's INTERFACE_DECKS, every
    figure within its bound."""
    match = re.search(r"^## Gaps that cross\n(.*?)(?=^## |\Z)", text, re.S | re.M)
    if match is None:
        return ["no section \"Gaps that cross\""]
    rows = table_rows(match.group(1), "| deck | case |")
    if rows is None:
        return ["no table in the section \"Gaps that cross\""]
    failures = []
    shown = {row["deck"] for row in rows}
    for name in ("contact-box-close.xml", "contact-box-crossing.xml",
                 "contact-box-crossing3.xml"):
        if name not in shown:
            failures.append(f"Gaps that cross: no row for {name}")
    for row in rows:
        if row["within bound"] != "yes":
            failures.append(f"Gaps that cross, {row['deck']}: {row['quantity']} = {row['Kiln']}, "
                            f"not within {row['tolerance']}")
    return failures


def check_truchas(text, folder):
    """The Truchas section: one row set per deck of `folder` (the "No deck" line when it has
    none), every figure within its test's tolerance or explained by its module."""
    match = re.search(r"^## Truchas tests\n(.*?)(?=^## |\Z)", text, re.S | re.M)
    if match is None:
        return ["no section \"Truchas tests\""]
    body = match.group(1)
    names = {deck.name for deck in truchas_section.decks(folder)}
    if not names:
        return [] if "No deck in" in body else [f"no deck in {folder}, but the Truchas section "
                                                  "does not say so"]
    rows = table_rows(body, truchas_section.HEADER[:20])
    if rows is None:
        return [f"{len(names)} decks in {folder}, but no table in the Truchas section"]
    failures = []
    shown = {row["deck"] for row in rows}
    for name in sorted(names - shown):
        failures.append(f"Truchas deck {name}: no row in the report")
    for row in rows:
        # "no: the golden is the less accurate (...)": shown so by the deck's other figures.
        if row["within tolerance"] != "yes" and \
                not row["within tolerance"].startswith("no: the golden is the less accurate"):
            failures.append(f"Truchas deck {row['deck']}: {row['quantity']} = {row['Kiln']}, "
                            f"not within the test's tolerance ({row['tolerance']})")
    return failures


def check_pngs(folder, text):
    failures = []
    for name in PNGS:
        path = folder / name
        if not path.is_file():
            failures.append(f"{path}: missing")
            continue
        data = path.read_bytes()
        if not data.startswith(b"\x89PNG\r\n\x1a\n"):
            failures.append(f"{path}: not a PNG file")
        if len(data) > 300_000:
            failures.append(f"{path}: {len(data) // 1000} KB, keep the plots under 300 KB")
        if f"]({name})" not in text:
            failures.append(f"report.md does not show {name}")
    return failures


def raise_one_error(text):
    """The report with the stress error of its first uniform state raised to 1e-3."""
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if line.startswith("| run | t [s] |"):
            header = [c.strip() for c in line.strip("|").split("|")]
            cells = lines[i + 2].strip("|").split("|")
            cells[header.index("stress")] = " 1.0e-03 "
            lines[i + 2] = "|" + "|".join(cells) + "|"
            break
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", type=Path, help="the folder of report.md and the PNGs")
    parser.add_argument("--run", action="store_true", help="run report.py --quick first")
    parser.add_argument("--build", type=Path, default=HERE.parent.parent / "build")
    parser.add_argument("--np", type=int, default=1)
    parser.add_argument("--full", action="store_true",
                        help="a full report: four meshes, the spatial heat test")
    args = parser.parse_args()

    if args.run:
        command = [sys.executable, str(HERE / "report.py"), "--quick", "--build",
                   str(args.build), "--np", str(args.np), "--out", str(args.folder)]
        print("check_report.py: " + " ".join(command), flush=True)
        if subprocess.call(command) != 0:
            print("check_report.py: FAILED: report.py failed")
            return 1
    report = args.folder / "report.md"
    if not report.is_file():
        print(f"check_report.py: FAILED: {report}: no such file")
        return 1
    text = report.read_text()
    failures = check(text, args.full) + check_pngs(args.folder, text)
    if not check(raise_one_error(text), args.full):
        failures.append("the check passes a report with a stress error of 1e-3: it cannot fail")
    for failure in failures:
        print(f"check_report.py: FAILED: {failure}")
    if failures:
        return 1
    print(f"check_report.py: {report}: every check passed (8 uniform states, gap events, "
          "closing time, heat convergence orders, 8 PNG files)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
