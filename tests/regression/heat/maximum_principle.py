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
import re
import subprocess
import sys

import h5py


def derived_deck(deck, work, capacity, method):
    with open(deck, encoding="utf-8") as f:
        xml = f.read()
    base = os.path.join(work, f"shock-{capacity}-{method.replace(' ', '-')}")
    xml, n = re.subn(r'(<Parameter name="Initial Temperature" type="double" value="[^"]*"/>)',
                     r'\1\n    <Parameter name="Capacity" type="string" value="' + capacity + '"/>',
                     xml)
    assert n == 1, "no Thermal/Initial Temperature in the deck"
    xml, n = re.subn(r'(<Parameter name="Method" type="string" value=")[^"]*"',
                     r'\g<1>' + method + '"', xml)
    assert n == 1, "no Time Stepping/Method in the deck"
    xml = xml.replace('<ParameterList name="Output">',
                      '<ParameterList name="Output">\n    <Parameter name="File Base" '
                      f'type="string" value="{base}"/>\n    <Parameter name="Every Steps" '
                      'type="int" value="1"/>', 1)
    path = base + ".xml"
    with open(path, "w", encoding="utf-8") as f:
        f.write(xml)
    return path, base


def main():
    kiln, deck, work, capacity, method = sys.argv[1:6]
    lower, upper = float(sys.argv[6]), float(sys.argv[7])
    expect = sys.argv[8] if len(sys.argv) > 8 else "bounded"
    os.makedirs(work, exist_ok=True)
    path, base = derived_deck(deck, work, capacity, method)
    subprocess.run([kiln, path], check=True, stdout=subprocess.DEVNULL)
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
