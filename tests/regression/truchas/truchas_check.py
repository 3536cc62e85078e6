#!/usr/bin/env python3
"""Runs a deck of inputs/truchas/ and applies its check module (the Truchas test's own check,
doc/verification/truchas/NAME.py: the same module the verification report uses).

Usage: truchas_check.py KILN DECK SIDECARS WORK_DIR NP MPIEXEC

Passes if every figure of the module is within the Truchas test's tolerance, or carries an
"explained" note (a golden shown to be less accurate by the module's other figures).
"""
import importlib.util
import os
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)


def main():
    kiln, deck, sidecars, work, n_ranks, mpiexec = sys.argv[1:7]
    deck = Path(deck)
    spec = importlib.util.spec_from_file_location("check", Path(sidecars) / f"{deck.stem}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    # The decks name their Exodus mesh relative to the checkout: given here by --mesh.
    section_spec = importlib.util.spec_from_file_location(
        "truchas_section", Path(sidecars).parent / "truchas_section.py")
    section = importlib.util.module_from_spec(section_spec)
    section_spec.loader.exec_module(section)

    def run(deck, folder):
        os.makedirs(folder, exist_ok=True)
        mesh = section.mesh_file(deck)
        args = ["--mesh", mesh] if mesh is not None else []
        return kd.run_kiln(kiln, deck, n_ranks, mpiexec, args, cwd=folder).results

    results = run(deck, work)
    # A Truchas test that runs two inputs: the module's companions run beside it.
    companions = {name: run(deck.parent / f"{name}.xml", Path(work) / "companions" / name)
                  for name in getattr(module, "COMPANIONS", [])}
    found = module.figures(results, deck, companions=companions) if companions else \
        module.figures(results, deck)
    failed = 0
    for f in found:
        # A figure outside the Truchas test's tolerance whose golden is shown to be the less
        # accurate (by the module's other figures) carries "explained" and does not fail.
        verdict = "pass" if f["passed"] else ("explained: " + f["explained"]
                                              if f.get("explained") else "FAIL")
        print(f"{module.TEST}: {f['quantity']}: Kiln {f['kiln']:.6g}, tolerance {f['tolerance']}"
              f", golden {f.get('golden')}, exact {f.get('exact')}: {verdict}")
        failed += not f["passed"] and not f.get("explained")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
