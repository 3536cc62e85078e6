"""The verification report's section on the Truchas tests Kiln can pose (inputs/truchas/).

Every deck inputs/truchas/NAME.xml declares its check in a sidecar module
doc/verification/truchas/NAME.py, which defines

    TEST = "heat_conduction/3d-ss-hc-linear-hex"   # the Truchas test it ports
    CHANGES = []        # optional: (list path, parameter, type, value) changes of the deck,
                        # as report.py's derive_deck takes them (e.g. the output times)
    COMPANIONS = []     # optional: other decks of inputs/truchas/ whose results the check
                        # compares with (a Truchas test that runs two inputs); figures()
                        # then takes companions={name: results}
    def figures(results, deck):
        '''results: the run's HDF5 file (pathlib.Path), deck: the derived deck. Returns a list
        of dicts: quantity (str), kiln (float), tolerance (str: the Truchas test's, e.g.
        "max abs error <= 1e-10"), passed (bool: Kiln's figure within that tolerance),
        golden (float or None: the Truchas golden output's value), exact (float or None:
        the exact or refined answer, given where the golden differs from it), and optionally
        explained (str: why a figure outside the Truchas tolerance is the golden's error,
        shown by the module's other figures; such a figure does not fail the test).'''

A new deck plugs in by adding its sidecar: the report runs every deck of inputs/truchas/ and
stops with an error naming a deck that has none. With no deck, the section says so.
"""

import importlib.util
import xml.etree.ElementTree as ET
from pathlib import Path

HEADER = "| deck | Truchas test | quantity | Kiln | tolerance | golden | exact | within tolerance |"


class SidecarError(Exception):
    """A deck has no sidecar, or its sidecar is malformed."""


def decks(folder, names=None):
    """The decks of inputs/truchas/ (sorted; none when the folder does not exist), or of
    `folder` those named in `names` (stems)."""
    folder = Path(folder)
    found = sorted(folder.glob("*.xml")) if folder.is_dir() else []
    return found if names is None else [d for d in found if d.stem in names]


def mesh_file(deck):
    """The absolute path of the Exodus mesh of `deck` (Mesh/Exodus/"File", which the decks of
    inputs/truchas/ give relative to the checkout, e.g. ../shared/truchas-tests/...), or None
    for a generated mesh."""
    root = ET.parse(deck).getroot()
    mesh = root.find("./ParameterList[@name='Mesh']")
    if mesh is None:
        return None
    kind = mesh.find("./Parameter[@name='Type']")
    file = mesh.find("./ParameterList[@name='Exodus']/Parameter[@name='File']")
    if kind is None or kind.get("value") != "Exodus" or file is None:
        return None
    checkout = Path(deck).resolve().parents[2]  # inputs/truchas/NAME.xml
    return (checkout / file.get("value")).resolve()


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


def changes_of(deck, module):
    """The changes of `deck` as its module asks (CHANGES) and its Exodus mesh as an absolute
    path."""
    changes = list(getattr(module, "CHANGES", []))
    mesh = mesh_file(deck)
    if mesh is not None:
        changes.append(("Mesh/Exodus", "File", "string", str(mesh)))
    return changes


def run_all(folder, sidecars, run_case, names=None, prefix="truchas"):
    """Runs every deck through run_case(name, source, changes) -> (deck, results, changes)
    and returns the rows: (deck name, TEST, figure dict). A module's COMPANIONS get the
    results of those decks."""
    rows = []
    runs = {}
    modules = {}
    for deck in decks(folder, names):
        module = load_sidecar(deck, sidecars)
        modules[deck.stem] = (deck, module)
        derived, results, _ = run_case(f"{prefix}-{deck.stem}", deck, changes_of(deck, module))
        runs[deck.stem] = (derived, results)
    for stem, (deck, module) in modules.items():
        derived, results = runs[stem]
        companions = getattr(module, "COMPANIONS", [])
        missing = [c for c in companions if c not in runs]
        if missing:
            raise SidecarError(f"{sidecars}/{stem}.py: COMPANIONS {', '.join(missing)} are not "
                               f"decks of {folder}")
        if companions:
            figures = module.figures(results, derived,
                                     companions={c: runs[c][1] for c in companions})
        else:
            figures = module.figures(results, derived)
        if not figures:
            raise SidecarError(f"{sidecars}/{stem}.py: figures() returned no figure")
        for figure in figures:
            missing = {"quantity", "kiln", "tolerance", "passed"} - set(figure)
            if missing:
                raise SidecarError(f"{sidecars}/{stem}.py: a figure without "
                                   f"{', '.join(sorted(missing))}")
            rows.append((deck.name, module.TEST, figure))
    return rows


def value(x):
    return "" if x is None else f"{x:.6g}"


def verdict(figure):
    """yes, NO, or "no: golden less accurate (...)" for an explained figure."""
    if figure["passed"]:
        return "yes"
    if figure.get("explained"):
        return "no: the golden is the less accurate (" + figure["explained"].replace("|", "\\|") + ")"
    return "NO"


def section(folder_shown, rows, title="Truchas tests", intro=None, header=HEADER):
    """The report's lines: the Truchas section, or another of decks with check modules."""
    md = [f"## {title}", "",
          intro or f"Every deck of `{folder_shown}` is run; its check module "
          "`doc/verification/truchas/NAME.py` gives Kiln's figure, the Truchas test's "
          "tolerance, the golden output's value and, where the golden differs from it, the "
          "exact or refined answer (see `doc/verification/truchas_section.py`).", ""]
    if not rows:
        md += [f"No deck in `{folder_shown}` yet.", ""]
        return md
    md += [header, "|---|---|---|---:|---|---:|---:|---|"]
    for name, test, f in rows:
        quantity, tolerance = (str(f[k]).replace("|", "\\|") for k in ("quantity", "tolerance"))
        md.append(f"| {name} | {test} | {quantity} | {f['kiln']:.6g} | {tolerance} | "
                  f"{value(f.get('golden'))} | {value(f.get('exact'))} | "
                  f"{verdict(f)} |")
    md.append("")
    return md
