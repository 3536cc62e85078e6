"""benchmarks/scaling.py on the smallest meshes: it runs, alternates the variants of a mesh,
keeps the median run of each and writes its tables and plots.

usage: scaling_smoke_test.py PATH/TO/kiln

The contact box and the elastic cube at 4 cells per edge, on 1 and 2 ranks and as two
one-rank copies at once, three rounds. A round runs every variant of a mesh in turn (np 1,
np 2, the copies), so that the machine's drift falls on all of them alike: the printed
progress must show them interleaved, not each variant's three rounds together.
"""

import csv
import pathlib
import re
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
SCALING = HERE.parent.parent / "benchmarks" / "scaling.py"


def main():
    kiln = str(pathlib.Path(sys.argv[1]).resolve())
    with tempfile.TemporaryDirectory() as tmp:
        out = pathlib.Path(tmp) / "study"
        result = subprocess.run(
            [sys.executable, str(SCALING), "--kiln", kiln, "--box", "4", "--cube", "4",
             "--np", "1", "2", "--repeat", "3", "--end-time", "11", "--out", str(out)],
            capture_output=True, text=True, timeout=600)
        assert result.returncode == 0, result.stdout + result.stderr
        # The progress lines, in the order the runs were made.
        runs = re.findall(r"^  (\w+) N=(\d+) np=(\d) copies=(\d) round (\d): ", result.stdout,
                          re.MULTILINE)
        variants = [("1", "1"), ("2", "1"), ("1", "2")]
        expected = [(case, "4", np, copies, str(r))
                    for case in ("box", "cube") for r in (1, 2, 3) for np, copies in variants]
        assert runs == expected, f"runs made in this order: {runs}"

        with open(out / "runs.csv") as f:
            rows = list(csv.DictReader(f))
        assert [(r["case"], r["np"], r["copies"]) for r in rows] == [
            (case, np, copies) for case in ("box", "cube") for np, copies in variants], rows
        # The median run of each variant: its wall time is the middle of the three printed.
        printed = re.findall(r"^  (\w+) N=4 np=(\d) copies=(\d) round \d: ([0-9.]+) s",
                             result.stdout, re.MULTILINE)
        for r in rows:
            walls = sorted(float(w) for c, np, k, w in printed
                           if (c, np, k) == (r["case"], r["np"], r["copies"]))
            assert abs(float(r["wall_s"]) - walls[1]) < 0.006, (r, walls)
        for case in ("box", "cube"):
            mine = [r for r in rows if r["case"] == case]
            assert len({r["unknowns"] for r in mine}) == 1, mine
            assert all(int(r["newton"]) >= 1 and int(r["linear"]) >= 1 for r in mine), mine

        readme = (out / "README.md").read_text()
        assert "medians of 3 runs per case, the variants of a mesh run in turn" in readme
        assert "efficiency vs two copies" in readme
        for png in ("box.png", "box-split.png", "cube.png", "cube-split.png"):
            assert (out / png).stat().st_size > 1000, png
    print("scaling.py: 18 runs alternated, medians kept, tables and plots written")


if __name__ == "__main__":
    main()
