"""Runs one gold-file regression case, or rebaselines its gold.

Registered by kiln_add_regression_test (tests/cmake/KilnRegression.cmake),
which writes the case's arguments to build/tests/regression-cases/NAME.args
(one per line; read here with @FILE). Two modes:

  test:        run kiln on --np ranks in --dir and compare the result with
               the gold by kiln-diff (with the case's fields and tolerances).
               Exit 0 if they agree, 1 otherwise. With --expect-differences-in
               (a WILL_FAIL case) exit 1 only if kiln-diff finds differences in
               exactly those fields, and 0 (which CTest reports as a failure of
               the WILL_FAIL test) for any other outcome, so that the test cannot
               pass because kiln crashed or the files could not be compared.
  --rebaseline: run the case on every rank count of --nps, make the new gold
               from the first run, check that the other runs match it within the
               tolerances, print the differences from the old gold, and only
               then replace it (with --yes, or after asking on a terminal).

Called by CTest and tests/rebaseline.sh; see doc/testing.md.
"""

import argparse
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree


def parse_arguments(argv):
    parser = argparse.ArgumentParser(prog="kiln_regression.py", fromfile_prefix_chars="@")
    parser.add_argument("--name", required=True)
    parser.add_argument("--requirement", default="")
    parser.add_argument("--input", required=True, help="the input deck")
    parser.add_argument("--gold", required=True, help="the gold file (in the source tree)")
    parser.add_argument("--kiln", required=True)
    parser.add_argument("--kiln-diff", required=True)
    parser.add_argument("--python", default=sys.executable,
                        help="the Python that runs kiln-diff")
    parser.add_argument("--mpiexec", required=True)
    parser.add_argument("--mpi-flag", action="append", default=[])
    parser.add_argument("--kiln-arg", action="append", default=[],
                        help="an argument given to kiln before the input")
    parser.add_argument("--set", action="append", default=[], metavar="PATH=VALUE",
                        help="change a parameter of the deck, e.g. Mesh/Box/Cells={8, 8, 8}")
    parser.add_argument("--field", action="append", default=[],
                        help="a field to compare (and to store in the gold)")
    parser.add_argument("--tolerance", action="append", default=[], metavar="NAME:ABS:REL")
    parser.add_argument("--perturb", action="append", default=[], metavar="FIELD:EPS",
                        help="rebaseline: multiply FIELD by 1+EPS in the new gold "
                             "(the deliberately wrong gold of a WILL_FAIL case)")
    parser.add_argument("--expect-differences-in", action="append", default=[],
                        metavar="FIELD")
    parser.add_argument("--nps", nargs="+", type=int, default=[1])
    parser.add_argument("--np", type=int, help="test mode: the number of ranks")
    parser.add_argument("--dir", required=True, help="the folder to run in (emptied first)")
    parser.add_argument("--rebaseline", action="store_true")
    parser.add_argument("--yes", action="store_true", help="rebaseline without asking")
    return parser.parse_args(argv)


def deck_name(args):
    return os.path.splitext(os.path.basename(args.input))[0]


def find_parameter(root, path, where):
    """The <Parameter> element at PATH (sublists separated by /) below the root list."""
    *lists, name = path.split("/")
    node = root
    for sublist in lists:
        found = [e for e in node if e.tag == "ParameterList" and e.get("name") == sublist]
        if not found:
            sys.exit(f"kiln_regression.py: {where}: no ParameterList \"{sublist}\" on the "
                     f"way to {path}")
        node = found[0]
    found = [e for e in node if e.tag == "Parameter" and e.get("name") == name]
    return found[0] if found else None


def prepare_input(args, folder):
    """The deck to run: the input itself, or a copy in FOLDER with --set applied."""
    if not args.set:
        return os.path.abspath(args.input)
    tree = ElementTree.parse(args.input)
    for assignment in args.set:
        path, sep, value = assignment.partition("=")
        if not sep:
            sys.exit(f"kiln_regression.py: --set {assignment}: expected PATH=VALUE")
        parameter = find_parameter(tree.getroot(), path, args.input)
        if parameter is None:
            sys.exit(f"kiln_regression.py: {args.input} has no parameter {path} to set")
        parameter.set("value", value)
    copy = os.path.join(folder, deck_name(args) + ".xml")
    tree.write(copy, encoding="unicode")
    return copy


def result_file(args, deck, folder):
    """Where kiln writes the results of DECK when run in FOLDER (Output/"File Base")."""
    parameter = find_parameter(ElementTree.parse(deck).getroot(), "Output/File Base", deck)
    base = parameter.get("value") if parameter is not None else ""
    if not base:
        base = os.path.join("results", deck_name(args))
    return os.path.join(folder, base + ".h5")


def run_kiln(args, np_, folder):
    """Runs the case on np_ ranks in FOLDER; returns the result file or None."""
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    deck = prepare_input(args, folder)
    command = ([args.mpiexec, "-np", str(np_)] + args.mpi_flag + [args.kiln] +
               args.kiln_arg + [deck])
    print("run:", " ".join(command), f"(in {folder})", flush=True)
    log = os.path.join(folder, "log.txt")
    with open(log, "w", encoding="utf-8") as stream:
        status = subprocess.call(command, cwd=folder, stdout=stream, stderr=subprocess.STDOUT)
    result = result_file(args, deck, folder)
    if status != 0 or not os.path.exists(result):
        with open(log, encoding="utf-8", errors="replace") as stream:
            lines = stream.readlines()
        sys.stdout.write("".join(lines[-40:]))
        print(f"kiln_regression.py: kiln failed on {args.input} at np {np_} (status {status}); "
              f"the log is {log}")
        return None
    return result


def kiln_diff(args, a, b, extra=()):
    command = [args.python, args.kiln_diff, a, b]
    if args.field:
        command += ["--fields", ",".join(args.field)]
    command += [f"--field={t}" for t in args.tolerance] + list(extra)
    completed = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               text=True, check=False)
    return completed.returncode, completed.stdout


def differing_fields(output):
    """The fields kiln-diff reported as differing (its last line)."""
    marker = "beyond the tolerance in "
    for line in output.splitlines():
        if line.startswith("kiln-diff: the files differ:") and marker in line:
            return sorted(line.split(marker, 1)[1].split(", "))
    return []


def test(args):
    if args.requirement:
        print(f"requirement: {args.requirement}")
    np_ = args.np or args.nps[0]
    expect = sorted(args.expect_differences_in)
    result = run_kiln(args, np_, args.dir)
    if result is None:
        if expect:
            print("kiln_regression.py: a WILL_FAIL case must fail in the comparison, not in "
                  "the run: reported as a failure")
            return 0
        return 1
    status, output = kiln_diff(args, result, args.gold)
    print(output, end="")
    if not expect:
        if status != 0:
            print(f"kiln_regression.py: {args.name} at np {np_} does not match "
                  f"{args.gold}; if the change is intended: tests/rebaseline.sh {args.name}")
        return 0 if status == 0 else 1
    found = differing_fields(output)
    if status == 1 and found == expect:
        print(f"kiln_regression.py: as intended, the deliberately wrong gold differs in "
              f"{', '.join(found)} (this WILL_FAIL test passes)")
        return 1
    print(f"kiln_regression.py: the deliberately wrong gold should differ in "
          f"{', '.join(expect)} only, but kiln-diff exited {status} with differences in "
          f"{', '.join(found) or 'nothing'}: reported as a failure (after an intended "
          f"change of the results: tests/rebaseline.sh {args.name})")
    return 0


def perturb(path, perturbations):
    import h5py  # the Python that runs kiln-diff has it

    with h5py.File(path, "r+") as f:
        for item in perturbations:
            field, _, eps = item.partition(":")
            for step in f["/steps"].values():
                if field not in step:
                    sys.exit(f"kiln_regression.py: --perturb {item}: no field {field}")
                step[field][...] = step[field][...] * (1.0 + float(eps))
            print(f"perturbed: {field} multiplied by 1 + {eps} at every step")


def confirm(args):
    if args.yes:
        return True
    if not sys.stdin.isatty():
        print("kiln_regression.py: not replacing the gold: rerun with --yes")
        return False
    answer = input(f"replace {args.gold}? [y/N] ")
    return answer.strip().lower() in ("y", "yes")


def rebaseline(args):
    top = args.dir
    runs = {}
    for np_ in args.nps:
        result = run_kiln(args, np_, os.path.join(top, f"np{np_}"))
        if result is None:
            return 1
        runs[np_] = result
    first = args.nps[0]
    candidate = os.path.join(top, "candidate.h5")
    command = [args.python, args.kiln_diff, "--extract", runs[first], candidate]
    if args.field:
        command += ["--fields", ",".join(args.field)]
    if subprocess.call(command) != 0:
        return 1
    for np_ in args.nps[1:]:
        status, output = kiln_diff(args, runs[np_], candidate)
        if status != 0:
            print(output, end="")
            print(f"kiln_regression.py: the run on {np_} ranks does not match the run on "
                  f"{first} within the case's tolerances; the new gold would fail. Not "
                  "replacing it.")
            return 1
        print(f"np {np_} matches the new gold (np {first}) within the tolerances")
    if args.perturb:
        perturb(candidate, args.perturb)
    if os.path.exists(args.gold):
        print(f"differences between the new gold (A) and the current one (B), {args.gold}:")
        status, output = kiln_diff(args, candidate, args.gold)
        print(output, end="")
        if status == 0:
            print("(no difference beyond the tolerances)")
    else:
        print(f"no gold yet at {args.gold}")
    if not confirm(args):
        return 1
    os.makedirs(os.path.dirname(os.path.abspath(args.gold)), exist_ok=True)
    shutil.copyfile(candidate, args.gold)
    print(f"replaced {args.gold} ({os.path.getsize(args.gold)} bytes); commit it with the "
          "physical reason for the change")
    return 0


def main(argv):
    args = parse_arguments(argv)
    return rebaseline(args) if args.rebaseline else test(args)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
