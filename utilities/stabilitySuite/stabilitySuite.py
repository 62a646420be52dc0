#!/usr/bin/python3
"""Largest stable step of every time integrator on stiff and extreme cases, with the error and
wall time at that step. Writes doc/stabilitySuite.md and doc/stabilitySuite.csv.

For each case x integrator, a bisection on the fixed step dt (geometric, in [1, 8] or [0.1, 1]
times dt_rule = min(h/c0, 0.125 h^2/nu), the step at acoustic Courant number 1 or the explicit
viscous limit) finds the largest dt at which the run reaches its end time. A run is unstable
when wcsph stops it: non-finite position or velocity, density outside [0.5, 2] rho0, a particle
faster than c0 or outside the domain (walls included), or the integrator failing its step. For the adaptive
SUNDIALS integrators dt caps the step. A run over the time limit counts as unstable (marked).

Usage: utilities/stabilitySuite/stabilitySuite.py [--quick] [--check] [--jobs N] [--work DIR]
(from the repository root; binaries from $SPHKIT_BIN or build/bin; --quick: two integrators on
two cases; --check: every case prepared, its edits applied and evaluated once, and every
integrator's dictionary evaluated once, in seconds and without writing doc/ (a test runs it, so
that a change to a shipped case that the suite edits stops a test, not the next suite run);
runs in build/stabilitySuite or --work DIR)
"""
import argparse
import concurrent.futures
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.environ.get("SPHKIT_BIN", os.path.join(ROOT, "build", "bin"))
# An unknown or incomplete option stops here: a mistyped --check would otherwise run the suite
# and rewrite doc/.
_parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
_parser.add_argument("--quick", action="store_true")
_parser.add_argument("--check", action="store_true")
_parser.add_argument("--jobs", type=int, default=2)
_parser.add_argument("--work", default=os.path.join(ROOT, "build", "stabilitySuite"))
_options = _parser.parse_args()
if _options.jobs < 1:
    _parser.error("argument --jobs: at least 1, not %d" % _options.jobs)
WORK = _options.work
QUICK = _options.quick
CHECK = _options.check
JOBS = _options.jobs
TIME_LIMIT = 120  # seconds per run
BISECTIONS = 3    # within the bracket [1, 8] or [0.1, 1]: the step known to within a factor of 1.3

INTEGRATORS = [
    ("symplectic", "type symplectic;"),
    ("verlet (eulerEvery 40)", "type verlet; eulerEvery 40;"),
    ("leapfrog", "type leapfrog;"),
    ("predictorCorrector", "type predictorCorrector;"),
    ("arkodeERK BS3, fixed", "type arkodeERK; table ARKODE_BOGACKI_SHAMPINE_4_2_3;"),
    ("arkodeERK BS3, adaptive 1e-4", "type arkodeERK; table ARKODE_BOGACKI_SHAMPINE_4_2_3; adaptive yes;"),
    ("arkodeIMEX ARK324, fixed", "type arkodeIMEX; table ARK324L2SA;"),
    ("cvode, 1e-4", "type cvode;"),
]


def hydrostatic(coefficient):
    return ("hydrostatic tank, c0 = %d sqrt(gH)" % coefficient, "hydrostaticTank2D",
            {"system/generateParticlesDict": [("spacing     0.02;", "spacing     0.05;")],
             "constant/fluidProperties": [("coefficient 10;", "coefficient %d;" % coefficient), ("gravityRampTime 1;", "gravityRampTime 0.2;")],
             "system/controlDict": [("endTime         2;", "endTime         1;"), ("writeInterval   0.25;", "writeInterval   1;"),
                                    ("executeInterval      0.25;", "executeInterval      1;")]},
            "pressure L2 / rho g H at t = 1", r"hydrostatic p: L1 [0-9.e+-]+, L2 ([0-9.e+-]+)", None)


def poiseuille(factor):
    replacements = {"system/controlDict": [("endTime         0.5;", "endTime         0.1125;"), ("writeInterval   0.0225;", "writeInterval   0.1125;")]}
    if factor != 1:
        replacements["constant/fluidProperties"] = [("nu          1e-6;", "nu          %ge-6;" % factor)]
    return ("Poiseuille, Re 0.0125" if factor == 1 else "Poiseuille, nu x %d" % factor, "poiseuille2D", replacements,
            "velocity L2 / u_max at t = 0.1125" if factor == 1 else "", r"L2 \|u - u_exact\| / u_max = ([0-9.]+)" if factor == 1 else None,
            "comparePoiseuille.py" if factor == 1 else None)


def freeBody(ratio):
    mass = 1000 * ratio * math.pi * 0.01
    return ("free cylinder, density ratio %g" % ratio, "sinkingCylinder2D",
            {"system/caseParameters": [("dx          0.01;", "dx          0.02;")],  # the repulsion's reach r0 = dx/2 follows
             "constant/boundaryProperties": [("mass 62.832; momentOfInertia 0.31416;", "mass %.6g; momentOfInertia %.6g;" % (mass, mass * 0.005))],
             "system/controlDict": [("endTime         0.3;", "endTime         0.2;")]},
            "", None, None)


CASES = [
    hydrostatic(10), hydrostatic(40), hydrostatic(160), poiseuille(1), poiseuille(10),
    ("dam break, impact on the far wall", "damBreak2D",
     {"system/generateParticlesDict": [("spacing     0.00142875;", "spacing     0.0028575;")]},
     "front RMS |Z - Z_exp|", r"RMS \|Z - Z_exp\| = ([0-9.]+)", "compareFront.py"),
    ("deforming floor, bulge 0.1 m (half its width)", "deformingTank2D",
     {"system/generateParticlesDict": [("spacing     0.02;", "spacing     0.04;")], "system/controlDict": [("endTime         2;", "endTime         1;")]},
     "", None, None),
    freeBody(0.1), freeBody(10),
]
if QUICK:
    INTEGRATORS = INTEGRATORS[:1] + INTEGRATORS[4:5]
    CASES = CASES[:1] + CASES[3:4]


def edit(path, pairs):
    with open(path) as f:
        text = f.read()
    for old, new in pairs:
        if old not in text:
            sys.exit("stabilitySuite.py: '%s' not found in %s (the shipped case changed)" % (old, path))
        text = text.replace(old, new, 1)
    with open(path, "w") as f:
        f.write(text)


def prepare(index, case):
    """Copies and generates the case once; returns its directory and dt_rule."""
    name, source, replacements = case[0], case[1], case[2]
    directory = os.path.join(WORK, "case%d" % index)
    shutil.rmtree(directory, ignore_errors=True)
    # The case's dictionaries and scripts, not what an earlier Allrun left in it.
    shutil.copytree(os.path.join(ROOT, "cases", source), directory,
                    ignore=shutil.ignore_patterns("[0-9]*", "postProcessing", "variants", "log.*", "*.pvd"))
    for path, pairs in replacements.items():
        edit(os.path.join(directory, path), pairs)
    generated = subprocess.run([os.path.join(BIN, "generateParticles"), "-case", directory], capture_output=True, text=True)
    if generated.returncode != 0:
        sys.exit("stabilitySuite.py: generateParticles failed for %s:\n%s" % (name, generated.stdout + generated.stderr))
    log = evaluate_once(directory, name)
    h = float(re.search(r"Selecting kernel .* h ([0-9.e+-]+),", log).group(1))
    c0 = float(re.search(r"c0 ([0-9.e+-]+)", log).group(1))
    nu = float(re.search(r"nu ([0-9.e+-]+)", log).group(1)) if "Selecting viscosity laminar" in log else 0.0
    shutil.rmtree(os.path.join(directory, "postProcessing"), ignore_errors=True)
    return directory, min(h / c0, 0.125 * h * h / nu if nu > 0 else math.inf)


def evaluate_once(directory, name):
    """wcsph -rates on the directory: its log, or the suite stopped with wcsph's message."""
    result = subprocess.run([os.path.join(BIN, "wcsph"), "-case", directory, "-rates"], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("stabilitySuite.py: wcsph -rates failed for %s:\n%s" % (name, result.stdout + result.stderr))
    return result.stdout


def write_integrator(directory, integrator, dt):
    with open(os.path.join(directory, "system/timeIntegration"), "w") as f:
        f.write("integrator { %s }\ncourant 0.2;\nfixedDeltaT %.9g;\n" % (integrator, dt))


def check(prepared):
    """Every integrator's dictionary, evaluated once in the first case."""
    directory, dtRule = prepared[0]
    for label, integrator in INTEGRATORS:
        write_integrator(directory, integrator, dtRule)
        evaluate_once(directory, "%s with %s" % (CASES[0][0], label))
    print("Checked %d cases and %d integrators" % (len(CASES), len(INTEGRATORS)))


def run(case, directory, integrator, dt, tag):
    """One run at the fixed step dt: (status, wall seconds, error or None)."""
    target = directory + "_" + tag
    shutil.rmtree(target, ignore_errors=True)
    shutil.copytree(directory, target)
    write_integrator(target, integrator, dt)
    environment = dict(os.environ, OMP_NUM_THREADS="1")
    start = time.time()
    try:
        result = subprocess.run([os.path.join(BIN, "wcsph"), "-case", target], capture_output=True, text=True, timeout=TIME_LIMIT, env=environment)
    except subprocess.TimeoutExpired:
        shutil.rmtree(target, ignore_errors=True)
        return "timeout", TIME_LIMIT, None
    wall = time.time() - start
    output = result.stdout + result.stderr
    match = re.search(r"Wall time ([0-9.]+) s", output)
    wall = float(match.group(1)) if match else wall
    if result.returncode != 0:
        status = "unsupported" if "only the symplectic integrator" in output else "unstable" if "blew up" in output else "error: " + output.strip().splitlines()[-1]
        shutil.rmtree(target, ignore_errors=True)
        return status, wall, None
    error = None
    if case[5]:
        output += subprocess.run(["/usr/bin/python3", os.path.join(target, case[5])], cwd=target, capture_output=True, text=True).stdout
    if case[4]:
        found = re.findall(case[4], output)
        error = float(found[-1]) if found else None
    shutil.rmtree(target, ignore_errors=True)
    return "stable", wall, error


def bisect(case, directory, dtRule, label, integrator, tag):
    """Largest stable multiple of dt_rule in [0.1, 8]: (multiple or None, bound text, wall, error).
    Tries 8, then 1, then 0.1 only if 1 fails: a slow integrator is not run at tiny steps it need not take."""
    status, wall, error = run(case, directory, integrator, 8.0 * dtRule, tag)
    if status == "unsupported" or status.startswith("error"):
        return None, status, None, None
    if status == "stable":
        return 8.0, ">= 8", wall, error
    low, high = 1.0, 8.0
    status, wall, error = run(case, directory, integrator, dtRule, tag)
    if status != "stable":
        low, high = 0.1, 1.0
        status, wall, error = run(case, directory, integrator, low * dtRule, tag)
        if status != "stable":
            return None, "< 0.1 (" + status + ")", None, None
    best = (low, wall, error)
    for _ in range(BISECTIONS):
        middle = math.sqrt(low * high)
        status, w, e = run(case, directory, integrator, middle * dtRule, tag)
        if status == "stable":
            low, best = middle, (middle, w, e)
        else:
            high = middle
    return best[0], "%.2g (unstable at %.2g)" % (best[0], high), best[1], best[2]


def main():
    os.makedirs(WORK, exist_ok=True)
    started = time.time()
    prepared = [prepare(i, case) for i, case in enumerate(CASES)]
    print("Prepared %d cases in %.0f s" % (len(CASES), time.time() - started), flush=True)
    if CHECK:
        check(prepared)
        return
    jobs = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=JOBS) as pool:
        for i, case in enumerate(CASES):
            for j, (label, integrator) in enumerate(INTEGRATORS):
                jobs.append((i, j, pool.submit(bisect, case, prepared[i][0], prepared[i][1], label, integrator, "i%d" % j)))
        rows = []
        for done, (i, j, future) in enumerate(jobs, 1):
            multiple, bound, wall, error = future.result()
            rows.append((CASES[i][0], INTEGRATORS[j][0], prepared[i][1], multiple, bound, wall, error, CASES[i][3]))
            print("[%d/%d, %.0f s] %s | %s: %s%s" % (done, len(jobs), time.time() - started, CASES[i][0], INTEGRATORS[j][0], bound,
                                                   "" if wall is None else ", wall %.2f s" % wall), flush=True)
    if QUICK:
        return
    with open(os.path.join(ROOT, "doc", "stabilitySuite.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["case", "integrator", "dt_rule_s", "largest_stable_dt_over_dt_rule", "bracket", "wall_s_at_that_dt", "error", "error_measure"])
        for row in rows:
            writer.writerow([row[0], row[1], "%.4g" % row[2], "" if row[3] is None else "%.3g" % row[3], row[4],
                             "" if row[5] is None else "%.2f" % row[5], "" if row[6] is None else "%.4g" % row[6], row[7]])
    with open(os.path.join(ROOT, "doc", "stabilitySuite.md"), "w") as f:
        f.write("# Stability suite: largest stable step of each integrator\n\n"
                "Generated by `utilities/stabilitySuite/stabilitySuite.py` (%.0f min on 2 cores, one thread per run). "
                "Each cell: the largest stable fixed step as a multiple of dt_rule = min(h/c0, 0.125 h^2/nu) "
                "(geometric bisection in [1, 8], or in [0.1, 1] when 1 fails; in brackets the first unstable multiple), the wall time of the run at that step "
                "and its error where the case has a reference. `>= 8`: stable at the largest step tried. "
                "`unsupported`: free bodies are advanced by the symplectic integrator only.\n\n" % ((time.time() - started) / 60))
        for case in CASES:
            case_rows = [r for r in rows if r[0] == case[0]]
            f.write("## %s\n\ndt_rule = %.3g s. %s\n\n" % (case[0], case_rows[0][2], ("Error: " + case[3] + ".") if case[3] else "No reference: stability only."))
            f.write("| integrator | largest stable dt / dt_rule | wall time at that step (s) | error |\n|---|---|---|---|\n")
            for r in case_rows:
                f.write("| %s | %s | %s | %s |\n" % (r[1], r[4], "" if r[5] is None else "%.2f" % r[5], "" if r[6] is None else "%.3g" % r[6]))
            f.write("\n")
    print("Wrote doc/stabilitySuite.md and doc/stabilitySuite.csv")


if __name__ == "__main__":
    main()
