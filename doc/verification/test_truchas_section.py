#!/usr/bin/python3
"""Unit test of the Truchas section of the verification report (truchas_section.py and
check_report.check_truchas), with no kiln run: zero decks, a deck without its check module,
a deck whose module plugs in (a pass and a figure out of tolerance). The CTest
verification_report_truchas_section."""

import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import check_report  # noqa: E402
import truchas_section  # noqa: E402

FAILURES = []


def expect(condition, what):
    if not condition:
        FAILURES.append(what)


def fake_run(name, source, changes):
    return source, source.with_suffix(".h5"), changes


SIDECAR = '''TEST = "heat_conduction/fake"
CHANGES = [("Output", "Times", "Array(double)", "{0, 1}")]
def figures(results, deck):
    return [{"quantity": "max |T - exact| [K]", "kiln": VALUE, "tolerance": "<= 1e-6",
             "passed": VALUE <= 1e-6, "golden": 2e-7, "exact": 0.0}]
'''


def main():
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        decks, checks = tmp / "truchas", tmp / "checks"
        checks.mkdir()
        # No folder, then an empty folder: no rows, the section says so, the check passes.
        for folder in (decks, decks):
            rows = truchas_section.run_all(folder, checks, fake_run)
            text = "\n".join(truchas_section.section("inputs/truchas/", rows))
            expect(rows == [] and "No deck in" in text, f"zero decks: {rows}, {text}")
            expect(check_report.check_truchas(text, folder) == [],
                   "zero decks: the check fails")
            decks.mkdir(exist_ok=True)
        expect(check_report.check_truchas("# no section\n", decks) != [],
               "a quick report without the section passes")
        # A deck without its module: an error naming it.
        (decks / "fake.xml").write_text("<ParameterList/>\n")
        try:
            truchas_section.run_all(decks, checks, fake_run)
            FAILURES.append("a deck without a check module was accepted")
        except truchas_section.SidecarError as error:
            expect("fake.xml" in str(error), f"the error does not name the deck: {error}")
        # The empty-deck report fails once the folder has a deck.
        empty = "\n".join(truchas_section.section("inputs/truchas/", []))
        expect(check_report.check_truchas(empty, decks) != [],
               "a report without the deck's row passes")
        # The module plugs in: within tolerance, then out of it.
        for value, passes in ((1e-7, True), (1e-3, False)):
            (checks / "fake.py").write_text(SIDECAR.replace("VALUE", repr(value)))
            rows = truchas_section.run_all(decks, checks, fake_run)
            text = "\n".join(truchas_section.section("inputs/truchas/", rows)) + "\n"
            expect(len(rows) == 1 and rows[0][1] == "heat_conduction/fake", f"rows {rows}")
            failures = check_report.check_truchas(text, decks)
            expect((failures == []) == passes, f"value {value}: check {failures}")
    for failure in FAILURES:
        print(f"test_truchas_section.py: FAILED: {failure}")
    if not FAILURES:
        print("test_truchas_section.py: every check passed")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
