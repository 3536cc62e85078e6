#!/usr/bin/env python3
"""A thermal shock makes no new temperature extremum (a discrete maximum principle).

Usage: maximum_principle.py KILN DECK WORK_DIR CAPACITY METHOD LOWER UPPER [EXPECT]

Runs KILN on DECK (inputs/contact-box-close-convection.xml: the box at 288 K meets 398 K air
through h = 1e5 W/(m^2 K)) with Kiln/Thermal/"Capacity" = CAPACITY and Time Stepping/Method
= METHOD, the state written after every step, and reads every step's temperatures from the
results file. Passes if every temperature of every step is within [LOWER, UPPER] K, or, with
EXPECT = "undershoot", if some temperature is below LOWER (the consistent capacity's
undershoot, which shows that the check can fail).
"""
import os
import sys
from pathlib import Path

import h5py

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)


def derived_deck(deck, work, capacity, method):
    with open(deck, encoding="utf-8") as f:
        xml = f.read()
    base = os.path.join(work, f"shock-{capacity}-{method.replace(' ', '-')}")
    xml = kd.add_parameters(xml, "Thermal", {"Capacity": capacity})
    xml = kd.set_parameter(xml, "Method", method)
    xml = kd.add_parameters(xml, "Output", {"File Base": base, "Every Steps": 1})
    return kd.write_deck(base, xml), base


def main():
    kiln, deck, work, capacity, method = sys.argv[1:6]
    lower, upper = float(sys.argv[6]), float(sys.argv[7])
    expect = sys.argv[8] if len(sys.argv) > 8 else "bounded"
    os.makedirs(work, exist_ok=True)
    path, base = derived_deck(deck, work, capacity, method)
    kd.run_kiln(kiln, path)
    low, high, n_steps = float("inf"), float("-inf"), 0
    with h5py.File(base + ".h5", "r") as h5:
        for name, step in h5["steps"].items():
            T = step["temperature"][...]
            low, high = min(low, T.min()), max(high, T.max())
            n_steps += 1
    print(f"{capacity}, {method}: {n_steps} states, temperatures in [{low!r}, {high!r}] K; "
          f"bounds [{lower}, {upper}] K")
    if n_steps < 10:
        print("FAIL: fewer than 10 states written")
        return 1
    if expect == "undershoot":
        if low >= lower:
            print(f"FAIL: expected an undershoot below {lower} K")
            return 1
        return 0
    if low < lower or high > upper:
        print("FAIL: a new extremum")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
