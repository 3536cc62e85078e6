#!/usr/bin/env python3
"""The small-sliding limit of a contact pair between separately meshed bodies (issue 30;
doc/contact.md, "Small sliding"), in whole runs. The contact box's halves meshed apart
(4 cm cube, x < 0 in 4 x 4 x 4 cells, x > 0 in 5 x 3 x 6: the secondary faces 6.67 x 13.3 mm,
diameter 14.9 mm), frictionless ("Contact"), steady elasticity: the half x < 0 held on its end
face (side set 1), the half x > 0 pressed onto it by u_x = -1e-5 m on its end face (2) and
pushed sideways by u_y = 2e-3 t m there (u_z = 0), so that it slides along the pair by about
u_y(t). With the default "Search Update Fraction" 0.25 the search is redone when a row has slid
3.73 mm since the last one: at t = 2, 4 and 6 s, and at t = 8 s (16 mm), where the secondary
nodes at y = 2 cm have slid off the primary surface (beyond its edge by more than their faces'
13.3 mm along y):
exit 2 and the message (the pair, the node, the time, what to change), the results finished
with "stopped by an error at t = 7 s" and t = 0 .. 7 s in them, the history up to 7 s and a
checkpoint of the last good state, all readable. The same with backward Euler steps of 0.75 s
(a time-dependent run): searched at 2, 4 and 6 s, it ends at its last accepted step before
8 s, results and history up to it. Pushed by u_y = 5e-4 t m instead (5 mm by 10 s) the deck runs
to the end, searched again once, at 8 s. A pair with a Heat Transfer term is searched again
like the others (its rows and its heat cells): thermo-elastic at 298 K, pushed at 2 mm/s, it
is searched again at 2, 4 and 6 s and ends at 8 s, slid off, with the same message, its
results up to 7 s.
usage: small_sliding.py KILN WORKDIR NP MPIEXEC"""
import csv
import re
import sys
from pathlib import Path

import h5py

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)

kiln, work, n_ranks, mpiexec = sys.argv[1:5]
work = Path(work)
work.mkdir(parents=True, exist_ok=True)
check = kd.Checks()


def deck(base, speed=2e-3, stepping=None, heat=False):
    pair = {"Primary Side Set": 10, "Secondary Side Set": 20}
    if heat:
        pair["Heat Transfer"] = {"Conductance": 1e4}
    mesh = kd.box_mesh((0.04, 0.04, 0.04), (8, 4, 4))
    mesh["Box"]["Second Half Cells"] = [5, 3, 6]
    return {"Physics": "Elasticity",
            "Mesh": mesh,
            "Material": kd.lame(5.2e10, 2.6e10),
            "Mechanics": {
                "Boundary Conditions": {
                    "held": kd.displacement([1], ["x", "y", "z"]),
                    "pressed": kd.displacement([2], ["x"], kd.constant(-1e-5)),
                    "pushed": kd.displacement([2], ["y"], kd.expression(f"{speed}*t")),
                    "level": kd.displacement([2], ["z"])},
                "Contact": {"Pairs": {"slide": pair}}},
            "Time Stepping": stepping or {"Method": "Steady"},
            "Output": {"File Base": base, "Times": [float(t) for t in range(11)]}}


def status_of(h5):
    value = h5.attrs["status"]
    return value.decode() if isinstance(value, bytes) else str(value)


def searches(log):
    return [float(t) for t in re.findall(r'pair "slide": search \d+ at t = ([0-9.e+-]+) s', log)]


# Beyond the limit: exit 2, the message, the results up to 7 s kept.
base = "beyond"
run = kd.run_kiln(kiln, kd.write_deck(str(work / base), deck(base)), n_ranks, mpiexec,
                  cwd=work, expect=2)
errors = [line for line in run.log.splitlines() if line.startswith("kiln: error:")]
check(len(errors) == 1, f"one error line ({len(errors)})")
message = errors[0] if errors else ""
print(message)
check(searches(run.log) == [2.0, 4.0, 6.0], f"searched again at 2, 4, 6 s ({searches(run.log)})")
for part in ['pair "slide": at t = 8 s secondary node ', "has slid off the primary surface",
             "no longer covered", "needs a larger primary surface",
             "raise the pair's \"Sliding Distance\"", "The results up to the last accepted step"]:
    check(part in message, f"the message says {part!r}")
results = work / (base + ".h5")
check(results.is_file() and not (work / (base + ".running.h5")).exists(), "results finished")
with h5py.File(results, "r") as h5:
    status = status_of(h5)
    times = [float(h5["steps"][k].attrs["time"]) for k in kd.step_names(h5)]
check(status.startswith('stopped by an error at t = 7 s: pair "slide": at t = 8 s'),
      f"status {status[:60]!r}...")
check(times == [float(t) for t in range(8)], f"results at t = 0 .. 7 s ({times})")
last = kd.read_step(str(results))
check(abs(last["time"] - 7.0) < 1e-12 and "displacement" in last, "the last step readable")
# The last good state is that of 7 s: body 2 pushed by u_y = 14 mm.
end_face = abs(last["x"][:, 0] - 0.02) < 1e-12
uy = last["displacement"][end_face, 1]
check(end_face.sum() == 28 and abs(uy - 1.4e-2).max() < 1e-12,
      f"at 7 s u_y = 14 mm on the end face ({end_face.sum()} nodes)")
with open(work / (base + ".history.csv"), encoding="utf-8") as f:
    rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
history_times = [float(r[1]) for r in rows[1:]]  # step, time, ...: the initial state, 0 .. 7 s
check(history_times == [0.0] + [float(t) for t in range(8)],
      f"history at t = 0 .. 7 s ({history_times})")
# The checkpoint of the last good state: after the 8 solves at 0 .. 7 s.
checkpoint = work / (base + ".checkpoint-000008.h5")
check(checkpoint.is_file() and not (work / (base + ".checkpoint-000009.h5")).exists(),
      f"the checkpoint of 7 s, {checkpoint.name}, and none after it")
check("its last good state is in" in run.log and checkpoint.name in run.log,
      "the log says where the last good state is")

# The same with time steps (backward Euler, steps of at most 0.75 s, so that they do not fall on
# whole seconds only): the run ends at the last accepted step before the limit, its state kept.
base = "stepped"
stepping = {"Method": "Backward Euler", "Initial Step": 0.75, "Maximum Step": 0.75}
run = kd.run_kiln(kiln, kd.write_deck(str(work / base), deck(base, stepping=stepping)), n_ranks,
                  mpiexec, cwd=work, expect=2)
with h5py.File(work / (base + ".h5"), "r") as h5:
    status = status_of(h5)
    times = [float(h5["steps"][k].attrs["time"]) for k in kd.step_names(h5)]
m = re.match(r"stopped by an error at t = ([0-9.e+-]+) s: pair \"slide\": at t = ([0-9.e+-]+) s",
             status)
check(m is not None and 7.0 < float(m.group(2)) <= 8.0 and float(m.group(1)) < float(m.group(2)),
      f"stepped: stopped at the last accepted step before the limit ({status[:70]!r})")
check(searches(run.log) == [2.0, 4.0, 6.0],
      f"stepped: searched again at 2, 4, 6 s ({searches(run.log)})")
check(times[:8] == [float(t) for t in range(8)] and times[-1] == float(m.group(1)) if m else False,
      f"stepped: results at 0 .. 7 s and the last accepted step ({times})")
with open(work / (base + ".history.csv"), encoding="utf-8") as f:
    rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
check(m is not None and float(rows[-1][1]) == float(m.group(1)),
      f"stepped: the history ends at the last accepted step ({rows[-1][1]})")

# Slower, within the limit: the same deck runs to the end, searched again at 8 s.
base = "within"
run = kd.run_kiln(kiln, kd.write_deck(str(work / base), deck(base, 5e-4)), n_ranks, mpiexec,
                  cwd=work, expect=0)
check(searches(run.log) == [8.0], f"within: searched again at 8 s ({searches(run.log)})")
with h5py.File(work / (base + ".h5"), "r") as h5:
    times = [float(h5["steps"][k].attrs["time"]) for k in kd.step_names(h5)]
check(times == [float(t) for t in range(11)], f"within: results at t = 0 .. 10 s")
# A pair with heat: searched again as the others (rows and heat cells), it ends once slid off.
base = "heat"
d = deck(base, heat=True)
d["Physics"] = "Thermo-Elasticity"
d["Material"].update({"Thermal Expansion": 2.2e-5, "Reference Temperature": 298.0,
                      "Density": 2.7e3, "Specific Heat": 9.0e2,
                      "Conductivity": {"Type": "Constant", "Value": 2.4e2}})
d["Thermal"] = {"Initial Temperature": 298.0,
                "Boundary Conditions": {"ends": kd.temperature([1, 2], 298.0)}}
run = kd.run_kiln(kiln, kd.write_deck(str(work / base), d), n_ranks, mpiexec, cwd=work, expect=2)
errors = [line for line in run.log.splitlines() if line.startswith("kiln: error:")]
message = errors[0] if errors else ""
print(message)
check(searches(run.log) == [2.0, 4.0, 6.0],
      f"heat: searched again at 2, 4, 6 s ({searches(run.log)})")
for part in ['pair "slide": at t = 8 s secondary node ', "has slid off the primary surface",
             "raise the pair's \"Sliding Distance\""]:
    check(part in message, f"heat: the message says {part!r}")
with h5py.File(work / (base + ".h5"), "r") as h5:
    times = [float(h5["steps"][k].attrs["time"]) for k in kd.step_names(h5)]
check(times == [float(t) for t in range(8)], f"heat: results at t = 0 .. 7 s ({times})")
sys.exit(1 if check.failed else 0)
