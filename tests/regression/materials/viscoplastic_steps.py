#!/usr/bin/env python3
"""Viscoplastic flow in the time stepping (issue 31), on tests/regression/materials/
viscoplastic-step-control.xml (a bar under a constant traction, power-law flow at a plastic
strain rate of about sqrt(2) 1e-4 1/s; see the deck).

usage: viscoplastic_steps.py CASE KILN DECK WORKDIR NP MPIEXEC
  step_control  the first step (1 s, increment 1.3e-4) is cut by "Maximum Plastic Strain
                Increment" = 1e-4 (the log says so, once), every accepted step's increment of
                the equivalent plastic strain (outputs every step) is at most 1e-4, and the
                plastic strain at 3 s is just below 3 s times the initial rate.
  newton        the Jacobian with flow is not reused (a viscoplastic model makes the mechanics
                block change with every iterate): no Jacobian kept in the run, and Newton
                converges quadratically in 1 to 3 iterations per step (the NOX log's |F|:
                |F_k+1|/|F_0| <= max(10 (|F_k|/|F_0|)^2, 1e-11)); with MTS (Truchas' ring aluminium, the
                bar at a von Mises stress of 85 MPa) likewise.
  elastic       the same bar, linear elastic (no Model), under a traction growing in time:
                the Jacobian is constant and kept in every step after the first.
  reuse         the power-law bar of `newton` (MueLu and the Direct preconditioner), with
                Solver/"Keep Preconditioner Within Solve" and "Adaptive Linear Tolerance Rate"
                at their defaults against both off: one preconditioner per Newton solve (kept
                for its later iterations) against one per iteration, the same Newton
                iterations in every step, Newton still quadratic, and the displacements and
                plastic strains at the end equal to 1e-9 relative.
  across        the same bar with the Solver's defaults against Solver/"Keep Preconditioner
                Across Steps" (fewer preconditioners built: the first solve's serves the
                later steps until a repeated step changes dt; the same Newton iterations),
                Time Stepping/"Extrapolated Newton Start" (no more Newton iterations in any
                step, fewer in all) and both; Newton still quadratic, the displacements and
                plastic strains at the end equal to 1e-9 relative, MueLu and Direct. The bar
                linear elastic (a constant Jacobian) with both: the same counts and
                displacements to the last bit. Both options are on by default; "default"
                here is both off.
  restart       the bar from 0 to 5 s in one run against 0 to 2 s restarted from its
                checkpoint to 5 s, with Kiln's defaults and with both options given: the
                restarted results equal the complete ones to the last bit (kiln-diff with no
                tolerance), with fewer preconditioners built than steps (kept across steps).
"""
import re
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "support"))
import kiln_deck as kd  # noqa: E402  (tests/support/kiln_deck.py)

case, kiln, deck, work, n_ranks, mpiexec = sys.argv[1:7]
work = Path(work) / case
work.mkdir(parents=True, exist_ok=True)
text = Path(deck).read_text()
RATE = 1e-7 * np.sqrt(2e6)  # A sigma_vM^n [1/s]
TOLERANCE = 1e-4


def fail(message, log=""):
    print(log)
    print(f"viscoplastic_steps.py {case}: {message}")
    sys.exit(1)


def run(body, name):
    (work / f"{name}.xml").write_text(body)
    done = kd.run_kiln(kiln, f"{name}.xml", n_ranks, mpiexec, cwd=work, expect=None,
                       log=work / f"{name}.log")
    if done.returncode != 0:
        fail(f"kiln {name}.xml failed ({done.returncode})", done.log)
    return done.log


def replace(body, old, new):
    if old not in body:
        fail(f"the deck lacks {old}")
    return body.replace(old, new)


def summary(log, what):
    m = re.search(rf"^{what}: (\d+)$", log, re.M)
    if not m:
        fail(f"the summary has no '{what}'", log)
    return int(m.group(1))


def quadratic(log, floor=0.0):
    """The NOX log's |F| of every Newton solve; fails unless each |F_k+1| / |F_0| is at most
    max(10 (|F_k| / |F_0|)^2, 1e-11) from the first iteration on (quadratic convergence, down to
    round-off), or |F_k+1| <= floor (a solve that starts from a predictor begins far below the
    |F| its round-off is relative to). Returns the norms of each solve."""
    solves = []
    for m in re.finditer(r"^\|\|F\|\| = ([0-9.e+-]+)\s+step = ([0-9.e+-]+)", log, re.M):
        if float(m.group(2)) == 0.0:
            solves.append([])
        solves[-1].append(float(m.group(1)))
    for norms in solves:
        r = [f / norms[0] for f in norms] if norms[0] > 0 else []
        for k in range(1, len(r) - 1):
            if r[k + 1] > max(10 * r[k] ** 2, 1e-11) and norms[k + 1] > floor:
                fail(f"Newton does not converge quadratically: |F| {norms}", log)
    return solves


def newton_per_step(log):
    return [int(n) for n in re.findall(r"^step \d+:.*Newton (\d+) \(", log, re.M)]


def verbose_deck(body, solver=""):
    return replace(body, '<ParameterList name="Time Stepping">',
                   '<ParameterList name="Solver">' + solver +
                   '<ParameterList name="Nonlinear Solver">'
                   '<ParameterList name="Printing"><Parameter name="Output Information" '
                   'type="int" value="3"/></ParameterList></ParameterList></ParameterList>'
                   '<ParameterList name="Time Stepping">')


# Solver/"Keep Preconditioner Across Steps" and Time Stepping/"Extrapolated Newton Start", on
# by default.
ACROSS_ON = '<Parameter name="Keep Preconditioner Across Steps" type="bool" value="true"/>'
ACROSS_OFF = ACROSS_ON.replace('"true"', '"false"')
PREDICTOR_ON = '<Parameter name="Extrapolated Newton Start" type="bool" value="true"/>'
PREDICTOR_OFF = PREDICTOR_ON.replace('"true"', '"false"')


def with_stepping(body, stepping):
    """The deck with `stepping` (parameters) added to its Time Stepping."""
    if not stepping:
        return body
    method = '<Parameter name="Method" type="string" value="Backward Euler"/>'
    return replace(body, method, method + stepping)


def elastic_body(body=None):
    """The bar without the model (linear elastic) under a traction 4e6 t Pa, steps of 0.5 s."""
    body = text if body is None else body
    body = body[:body.index('    <ParameterList name="Model">')] + \
        body[body.index('    </ParameterList>\n  </ParameterList>\n  <ParameterList name="Mechanics">')
             + len('    </ParameterList>\n'):]
    body = replace(body, '<Parameter name="Traction" type="Array(double)" value="{4e6, 0, 0}"/>',
                   '<Parameter name="Traction Expressions" type="Array(string)" '
                   'value="{4e6*t, 0, 0}"/>')
    body = replace(body, '<Parameter name="Initial Step" type="double" value="1"/>',
                   '<Parameter name="Initial Step" type="double" value="0.5"/>')
    body = replace(body, '<Parameter name="Maximum Step" type="double" value="1"/>',
                   '<Parameter name="Maximum Step" type="double" value="0.5"/>'
                   '<Parameter name="Growth Factor" type="double" value="1"/>')
    if "Power Law" in body:
        fail("the elastic deck still has the model")
    return body


if case == "step_control":
    log = run(text, "steps")
    cuts = re.findall(r"plastic strain increment ([0-9.e+-]+) > \"Maximum Plastic Strain "
                      r"Increment\" = 0.0001; retrying with dt = ([0-9.e+-]+) s", log)
    if len(cuts) != 1 or not TOLERANCE < float(cuts[0][0]) <= RATE:
        fail(f"not one cut of the 1 s step by the plastic strain increment: {cuts}", log)
    with h5py.File(work / "results" / "steps.h5", "r") as h5:
        names = sorted(h5["steps"].keys())
        times = [float(h5["steps"][n].attrs["time"]) for n in names]
        plastic = [float(np.max(h5["steps"][n]["plastic_strain"][...])) for n in names]
    increments = np.diff(plastic)
    if times[-1] != 3.0 or len(increments) < 4:
        fail(f"outputs at {times}")
    if increments.max() > TOLERANCE * (1 + 1e-12):
        fail(f"a step's plastic strain increment {increments.max():.6g} > {TOLERANCE}")
    # At most 3 s times the initial rate; the flow relaxes the von Mises stress slowly (the
    # rollers hold the lateral faces), by a few per cent over the 3 s.
    if not 0.8 * 3.0 * RATE < plastic[-1] <= 3.0 * RATE:
        fail(f"plastic strain at 3 s {plastic[-1]:.9g}, expected just below {3 * RATE:.9g}")
    print(f"{len(names) - 1} steps, one cut (1 s -> {cuts[0][1]} s), largest increment "
          f"{increments.max():.4g} <= {TOLERANCE}, plastic strain at 3 s {plastic[-1]:.4g}")
elif case == "reuse":
    off = ('<Parameter name="Keep Preconditioner Within Solve" type="bool" value="false"/>'
           '<Parameter name="Adaptive Linear Tolerance Rate" type="double" value="0"/>')
    for preconditioner in ("MueLu", "Direct"):
        linear = ('<ParameterList name="Linear Solver"><Parameter name="Preconditioner Type" '
                  f'type="string" value="{preconditioner}"/></ParameterList>')
        fields = {}
        counts = {}
        for variant, solver in (("default", linear), ("off", linear + off)):
            name = f"reuse-{preconditioner}-{variant}"
            log = run(with_stepping(verbose_deck(text, solver + ACROSS_OFF), PREDICTOR_OFF), name)
            quadratic(log)
            counts[variant] = (newton_per_step(log), summary(log, "Newton iterations"),
                               summary(log, "preconditioners built in this run"),
                               summary(log, "preconditioners kept in this run"),
                               summary(log, "linear iterations"))
            with h5py.File(work / "results" / f"{name}.h5", "r") as h5:
                last = sorted(h5["steps"].keys())[-1]
                fields[variant] = [h5["steps"][last][f][...] for f in
                                   ("displacement", "plastic_strain")]
        steps, newton, built, kept, linear_its = counts["default"]
        solves = sum(1 for n in steps if n > 0) + 1  # and the equilibrium at t = 0
        if counts["off"][0] != steps:
            fail(f"{preconditioner}: Newton iterations per step {steps} against "
                 f"{counts['off'][0]} with both off")
        if built > solves or built + kept != newton or kept < newton - solves:
            fail(f"{preconditioner}: {built} preconditioners built, {kept} kept for {newton} "
                 f"Newton iterations in {solves} solves")
        if counts["off"][2] != counts["off"][1] or counts["off"][3] != 0:
            fail(f"{preconditioner}, both off: {counts['off'][2]} built, {counts['off'][3]} "
                 f"kept for {counts['off'][1]} Newton iterations")
        for a, b, what in zip(fields["default"], fields["off"], ("displacement", "plastic strain")):
            error = np.max(np.abs(a - b)) / np.max(np.abs(b))
            if not error <= 1e-9:
                fail(f"{preconditioner}: {what} differs by {error:.3g} relative")
        print(f"{preconditioner}: Newton {steps}; preconditioners built {built}, kept {kept} "
              f"(off: built {counts['off'][2]}); linear iterations {linear_its} (off: "
              f"{counts['off'][4]})")
elif case == "across":
    for preconditioner in ("MueLu", "Direct"):
        linear = ('<ParameterList name="Linear Solver"><Parameter name="Preconditioner Type" '
                  f'type="string" value="{preconditioner}"/></ParameterList>')
        runs = {}
        # "default" has both options off (the reference); "both" is Kiln's default.
        for variant, solver, stepping in (("default", linear + ACROSS_OFF, PREDICTOR_OFF),
                                          ("across", linear + ACROSS_ON, PREDICTOR_OFF),
                                          ("predictor", linear + ACROSS_OFF, PREDICTOR_ON),
                                          ("both", linear + ACROSS_ON, PREDICTOR_ON)):
            name = f"across-{preconditioner}-{variant}"
            log = run(with_stepping(verbose_deck(text, solver), stepping), name)
            # Round-off: a tenth of the Newton target (Absolute Tolerance 1e-8).
            quadratic(log, 1e-9)
            with h5py.File(work / "results" / f"{name}.h5", "r") as h5:
                last = sorted(h5["steps"].keys())[-1]
                fields = [h5["steps"][last][f][...] for f in ("displacement", "plastic_strain")]
            runs[variant] = dict(steps=newton_per_step(log),
                                 newton=summary(log, "Newton iterations"),
                                 built=summary(log, "preconditioners built in this run"),
                                 linear=summary(log, "linear iterations"), fields=fields)
        ref = runs["default"]
        for variant, got in runs.items():
            for a, b, what in zip(got["fields"], ref["fields"], ("displacement", "plastic strain")):
                error = np.max(np.abs(a - b)) / np.max(np.abs(b))
                if not error <= 1e-9:
                    fail(f"{preconditioner} {variant}: {what} differs by {error:.3g} relative")
            print(f"{preconditioner} {variant}: Newton {got['steps']} ({got['newton']}), "
                  f"preconditioners built {got['built']}, linear iterations {got['linear']}")
        for variant in ("across", "both"):
            if not runs[variant]["built"] < ref["built"]:
                fail(f"{preconditioner} {variant}: {runs[variant]['built']} preconditioners "
                     f"built, not fewer than {ref['built']}")
        if runs["across"]["steps"] != ref["steps"]:
            fail(f"{preconditioner}: Newton iterations per step {runs['across']['steps']} "
                 f"with the preconditioner kept across steps, {ref['steps']} without")
        # A constant (elastic) Jacobian: neither option applies; the same counts, the same
        # results to the last bit.
        elastic = {}
        for variant, solver, stepping in (("default", linear + ACROSS_OFF, PREDICTOR_OFF),
                                          ("both", linear, "")):
            name = f"across-{preconditioner}-elastic-{variant}"
            log = run(with_stepping(verbose_deck(elastic_body(), solver), stepping), name)
            with h5py.File(work / "results" / f"{name}.h5", "r") as h5:
                last = sorted(h5["steps"].keys())[-1]
                fields = [h5["steps"][last]["displacement"][...]]
            elastic[variant] = ([summary(log, what) for what in (
                "Newton iterations", "linear iterations", "Jacobians assembled in this run",
                "Jacobians kept in this run", "preconditioners built in this run",
                "preconditioners kept in this run")], newton_per_step(log), fields)
        if elastic["both"][:2] != elastic["default"][:2] or \
                not np.array_equal(elastic["both"][2][0], elastic["default"][2][0]):
            fail(f"{preconditioner}, elastic: counts {elastic['both'][0]} with both options, "
                 f"{elastic['default'][0]} without, or other displacements")
        print(f"{preconditioner} elastic: the same counts with both options "
              f"{elastic['both'][0]} and displacements")
        for variant in ("predictor", "both"):
            steps = runs[variant]["steps"]
            if len(steps) != len(ref["steps"]) or \
                    any(a > b for a, b in zip(steps, ref["steps"])) or \
                    not runs[variant]["newton"] < ref["newton"]:
                fail(f"{preconditioner} {variant}: Newton iterations per step {steps}, "
                     f"without the predictor {ref['steps']}")
elif case == "restart":
    # 0 -> 5 s in one run (outputs at 0, 2 and 5 s) against 0 -> 2 s (its checkpoint at its
    # end) restarted to 5 s, with Kiln's defaults (both options on) and with them explicitly.
    KILN_DIFF = Path(__file__).resolve().parents[3] / "tools" / "kiln-diff"
    body = replace(text, '<Parameter name="Times" type="Array(double)" value="{0, 3}"/>',
                   '<Parameter name="Times" type="Array(double)" value="{0, 2, 5}"/>')
    for variant, solver, stepping in (("default", "", ""), ("both", ACROSS_ON, PREDICTOR_ON)):
        deck = with_stepping(verbose_deck(body, solver), stepping)
        complete = replace(deck, '<ParameterList name="Output">', '<ParameterList name="Output">'
                           f'<Parameter name="File Base" type="string" value="results/{variant}-complete"/>')
        restarted = replace(deck, '<ParameterList name="Output">', '<ParameterList name="Output">'
                            f'<Parameter name="File Base" type="string" value="results/{variant}-restarted"/>')
        part1 = replace(restarted, 'value="{0, 2, 5}"', 'value="{0, 2}"')
        log = run(complete, f"{variant}-complete")
        run(part1, f"{variant}-part1")
        (work / f"{variant}-restarted.xml").write_text(restarted)
        done = kd.run_kiln(kiln, f"{variant}-restarted.xml", n_ranks, mpiexec,
                           ["--restart", f"results/{variant}-restarted.checkpoint.h5"], cwd=work,
                           expect=None, log=work / f"{variant}-restarted.log")
        if done.returncode != 0 or "t = 2 s" not in done.log:
            fail(f"{variant}: the restart from 2 s failed ({done.returncode})", done.log)
        built = summary(log, "preconditioners built in this run")
        steps = newton_per_step(log)
        if variant == "both" and not built < len(steps):
            fail(f"{variant}: {built} preconditioners built in {len(steps)} steps: none kept "
                 "across steps", log)
        diff = subprocess.run([str(KILN_DIFF), "--abs", "0", "--rel", "0",
                               f"results/{variant}-complete.h5", f"results/{variant}-restarted.h5"],
                              cwd=work, capture_output=True, text=True)
        if diff.returncode != 0:
            fail(f"{variant}: the restarted run is not bit-identical to the complete one",
                 diff.stdout + diff.stderr)
        print(f"{variant}: 0 -> 5 s equals 0 -> 2 s + restart to 5 s, bit for bit (Newton "
              f"{steps}, {built} preconditioners built)")
elif case == "newton":
    verbose = verbose_deck(text)
    mts = replace(verbose, '''      <Parameter name="Type" type="string" value="Power Law"/>
      <Parameter name="Power Law A" type="double" value="1e-7"/>
      <Parameter name="Power Law n" type="double" value="0.5"/>
      <Parameter name="Power Law Q" type="double" value="0"/>
      <Parameter name="Power Law R" type="double" value="1"/>''',
                  '''      <Parameter name="Type" type="string" value="MTS"/>''')
    # MTS at 400 K with the defaults (Truchas' ring aluminium): the traction 150e6 Pa gives a
    # von Mises stress of 75 MPa, between sigma_a = 10 MPa and sigma_a + sigma_hat = 99 MPa,
    # where the law flows (3 Newton iterations per step).
    mts = replace(mts, '<Parameter name="Reference Temperature" type="double" value="100"/>',
                  '<Parameter name="Reference Temperature" type="double" value="400"/>')
    mts = replace(mts, '{4e6, 0, 0}', '{150e6, 0, 0}')
    # The load is there from t = 0 (the equilibrium at t = 0 is elastic): this is about Newton,
    # not the step size.
    mts = replace(mts, '<Parameter name="Maximum Plastic Strain Increment" type="double" '
                  'value="1e-4"/>', '<Parameter name="Maximum Plastic Strain Increment" '
                  'type="double" value="1"/>')
    for name, body in (("power-law", verbose), ("mts", mts)):
        log = run(body, name)
        kept = summary(log, "Jacobians kept in this run")
        iterations = newton_per_step(log)
        if kept != 0:
            fail(f"{name}: {kept} Jacobians kept with plastic flow", log)
        if not iterations or max(iterations) > 3 or min(iterations) < 1:
            fail(f"{name}: Newton iterations per step {iterations}", log)
        # Round-off: a tenth of the Newton target (the later steps start at the predictor).
        solves = quadratic(log, 1e-9)
        print(f"{name}: Newton iterations per step {iterations}, no Jacobian kept; |F| of each "
              "solve: " + "; ".join(" ".join(f"{f:.3g}" for f in n) for n in solves))
else:  # elastic
    log = run(elastic_body(), "elastic")
    kept = summary(log, "Jacobians kept in this run")
    assembled = summary(log, "Jacobians assembled in this run")
    steps = len(newton_per_step(log))
    if kept < steps - 1 or assembled > 2:
        fail(f"a constant elastic Jacobian: {assembled} assembled, {kept} kept in {steps} steps",
             log)
    print(f"elastic: {assembled} Jacobians assembled, {kept} kept in {steps} steps")
