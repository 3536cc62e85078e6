"""The verification report's section on the Truchas tests Kiln can pose (inputs/truchas/).

Every deck inputs/truchas/NAME.xml declares its check in a sidecar module
doc/verification/truchas/NAME.py, which defines

    TEST = "heat_conduction/3d-ss-hc-linear-hex"   # the Truchas test it ports
    CHANGES = []        # optional: (list path, parameter, type, value) changes of the deck,
                        # as report.py's derive_deck takes them (e.g. the output times)
    def figures(results, deck):
        '''results: the run's HDF5 file (pathlib.Path), deck: the derived deck. Returns a list
        of dicts: quantity (str), kiln (float), tolerance (str: the Truchas test's, e.g.
        "max abs error <= 1e-10"), passed (bool: Kiln's figure within that tolerance),
        golden (float or None: the Truchas golden output's value), exact (float or None:
        the exact or refined answer, given where the golden differs from it).'''

A new deck plugs in by adding its sidecar: the report runs every deck of inputs/truchas/ and
stops with an error naming a deck that has none. With no deck, the section says so.
"""

import importlib.util
from pathlib import Path

HEADER = "| deck | Truchas test | quantity | Kiln | tolerance | golden | exact | within tolerance |"


class SidecarError(Exception):
    """A deck has no sidecar, or its sidecar is malformed."""


def decks(folder):
    """The decks of inputs/truchas/ (sorted; none when the folder does not exist)."""
    folder = Path(folder)
    return sorted(folder.glob("*.xml")) if folder.is_dir() else []


def load_sidecar(deck, sidecars):
    """The check module of `deck` (sidecars/STEM.py)."""
    path = Path(sidecars) / f"{deck.stem}.py"
    if not path.is_file():
        raise SidecarError(f"{deck}: no check module {path}; add one defining TEST and "
                           "figures(results, deck) (see doc/verification/truchas_section.py)")
    spec = importlib.util.spec_from_file_location(f"truchas_check_{deck.stem}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    for name in ("TEST", "figures"):
        if not hasattr(module, name):
            raise SidecarError(f"{path}: defines no {name} (see "
                               "doc/verification/truchas_section.py)")
    return module


def run_all(folder, sidecars, run_case):
    """Runs every deck through run_case(name, source, changes) -> (deck, results, changes)
    and returns the rows: (deck name, TEST, figure dict)."""
    rows = []
    for deck in decks(folder):
        module = load_sidecar(deck, sidecars)
        derived, results, _ = run_case(f"truchas-{deck.stem}", deck,
                                       list(getattr(module, "CHANGES", [])))
        figures = module.figures(results, derived)
        if not figures:
            raise SidecarError(f"{sidecars}/{deck.stem}.py: figures() returned no figure")
        for figure in figures:
            missing = {"quantity", "kiln", "tolerance", "passed"} - set(figure)
            if missing:
                raise SidecarError(f"{sidecars}/{deck.stem}.py: a figure without "
                                   f"{', '.join(sorted(missing))}")
            rows.append((deck.name, module.TEST, figure))
    return rows


def value(x):
    return "" if x is None else f"{x:.6g}"


def section(folder_shown, rows):
    """The report's lines."""
    md = ["## Truchas tests", "",
          f"Every deck of `{folder_shown}` is run; its check module "
          "`doc/verification/truchas/NAME.py` gives Kiln's figure, the Truchas test's "
          "tolerance, the golden output's value and, where the golden differs from it, the "
          "exact or refined answer (see `doc/verification/truchas_section.py`).", ""]
    if not rows:
        md += [f"No deck in `{folder_shown}` yet.", ""]
        return md
    md += [HEADER, "|---|---|---|---:|---|---:|---:|---|"]
    for name, test, f in rows:
        quantity, tolerance = (str(f[k]).replace("|", "\\|") for k in ("quantity", "tolerance"))
        md.append(f"| {name} | {test} | {quantity} | {f['kiln']:.6g} | {tolerance} | "
                  f"{value(f.get('golden'))} | {value(f.get('exact'))} | "
                  f"{'yes' if f['passed'] else 'NO'} |")
    md.append("")
    return md
