#!/usr/bin/env python3
"""The tensor order each document states is the order the results hold.

Usage: tensor_order_docs.py KILN DECK DOC_DIR

Runs KILN on DECK (its output times cut to {0}: the equilibrium at t = 0 is enough) and
reads the `components` attribute of /steps/*/stress, strain and thermal_strain. Every
document that tells users how to read a tensor (user-guide.md, mechanics.md,
output-format.md) must say "stored in the order **a b c d e f**" at least once, and every
such statement must name the order written. A script written from the guide once swapped
two shear stresses (issue 35, item 4).
"""
import os
import re
import sys
import tempfile
from pathlib import Path

import h5py

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)

DOCUMENTS = ["user-guide.md", "mechanics.md", "output-format.md"]
STATEMENT = re.compile(r"stored\s+in\s+the\s+order\s+\*\*([a-z ]+?)\*\*")


def stated_orders(path):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    return [" ".join(m.group(1).split()) for m in STATEMENT.finditer(text)]


def written_orders(kiln, deck, work):
    with open(deck, encoding="utf-8") as f:
        xml = f.read()
    base = os.path.join(work, "tensor-order")
    xml = kd.set_parameter(xml, "Times", [0])
    xml = kd.add_parameters(xml, "Output", {"File Base": base})
    kd.run_kiln(kiln, kd.write_deck(os.path.join(work, "deck"), xml))
    orders = {}
    with h5py.File(base + ".h5", "r") as h5:
        steps = h5["steps"]
        step = steps[sorted(steps.keys())[0]]
        for name in ("stress", "strain", "thermal_strain"):
            components = step[name].attrs["components"]
            if isinstance(components, bytes):
                components = components.decode()
            orders[name] = " ".join(str(components).split(","))
    return orders


def main():
    kiln, deck, doc_dir = sys.argv[1:4]
    failures = []
    with tempfile.TemporaryDirectory() as work:
        written = written_orders(kiln, deck, work)
    orders = set(written.values())
    if len(orders) != 1:
        failures.append(f"the tensors are written in different orders: {written}")
    order = sorted(orders)[0]
    print(f"written: {order}")
    for name in DOCUMENTS:
        stated = stated_orders(os.path.join(doc_dir, name))
        print(f"{name}: {stated}")
        if not stated:
            failures.append(f"doc/{name} states no tensor order (\"stored in the order **...**\")")
        for s in stated:
            if s != order:
                failures.append(f"doc/{name} says the tensors are stored as {s}; the files hold {order}")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
