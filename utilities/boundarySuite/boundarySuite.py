#!/usr/bin/python3
"""Runs every boundary model on the same cases and writes the comparison to
doc/boundarySuite.md and doc/boundarySuite.csv:

- uniform-pressure tanks (rectangularTank2D, ellipticalTank2D; one right-hand-side
  evaluation, wcsph -rates): RMS and max residual |a| of the fluid within r_inf of the wall,
  over the uncorrected RMS of the same particles, split into straight walls and corners, or
  low- and high-curvature arcs; and the boundary-integral weighting on 2:1 and 3:1 rectangles
  and ellipses at r_inf/10 and r_inf/20;
- hydrostatic tank (hydrostaticTank2D, to t = 2): wall pressure error (the fluid's pressure
  interpolated along the floor against rho g H, L2 and max over rho g H) and the centre line's,
  bottom gap (mean and spread of the lowest particle's height per column), residual kinetic
  energy, penetrations;
- deforming tank (deformingTank2D's Allrun: virtual particles against the correction): pressure
  noise near the bulging floor, clumping, penetrations;
- flows that hurt, every wall model on the same case: the standard 2D dam break
  (damBreakWallPressure2D at H/dx = 20, 40, 80: blow-up, wall-pressure error against De Courcy
  et al. 2024, penetrations at every step), sloshing (sloshingTank2D against Faltinsen et al.
  2000, and at a small amplitude against linear modal theory), a steep fast floor bulge (steepBulge2D, 50 % of the depth at 5x and 7.5x
  deformingTank2D's wall speed; steepBulge3D), 3D still water (hydrostaticTank3D), each flow at
  three resolutions;
each with the wall time that produced it (runs two at a time, one thread each). Penetrations
are counted at every step (the wallPenetrations function object).

Usage: utilities/boundarySuite/boundarySuite.py [--quick] [--check] [--models=NAME,...] [--work DIR]
(from the repository root; the binaries are taken from $SPHKIT_BIN or build/bin; the full suite
takes about an hour; --quick runs the static shapes and the hydrostatic tank at dx = 0.05 and
the flows that hurt at their coarsest resolution only; --models re-runs the deforming tank and
the flows of the named flow models only and replaces their rows in doc/boundarySuite.md, keeping
every other row; --check prepares every case as --quick would, with the suite's edits, and
evaluates each once (wcsph -rates) instead of running it, in about 20 s and without writing
doc/: a test runs it, so that a change to a shipped case that the suite edits stops a test, not
the next suite run (the deforming tank, which the suite runs as shipped, is left out); the runs
go to build/boundarySuite or --work DIR)
"""
import argparse
import concurrent.futures
import csv
import glob
import math
import os
import re
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import tankRates  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.environ.get("SPHKIT_BIN", os.path.join(ROOT, "build", "bin"))
# An unknown or incomplete option stops here: a mistyped --check would otherwise run the hour-long
# suite and rewrite doc/.
_parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
_parser.add_argument("--quick", action="store_true")
_parser.add_argument("--check", action="store_true")
_parser.add_argument("--models", type=lambda names: names.split(","), help="NAME,...: the flow models to re-run")
_parser.add_argument("--work", default=os.path.join(ROOT, "build", "boundarySuite"))
_options = _parser.parse_args()
WORK = _options.work
CHECK = _options.check
QUICK = _options.quick or CHECK
ONLY = _options.models
sys.path.insert(0, os.path.join(ROOT, "cases", "sloshingTank2D"))
from linearSloshing import AMPLITUDE as LINEAR_SLOSHING_AMPLITUDE  # noqa: E402

CORRECTION = "repulsion { type monaghanKajtar; K 1e-9; }"
TANK_MODELS = [
    ("no correction (repulsion only)", "monaghanKajtar", "type monaghanKajtar; K 1e-9;", "surface"),
    ("deficiencyCorrection, calibrated (the paper)", "deficiencyCorrection", "type deficiencyCorrection; calibration calibrated; " + CORRECTION, "surface"),
    ("deficiencyCorrection, literal", "deficiencyCorrection", "type deficiencyCorrection; calibration literal; " + CORRECTION, "surface"),
    ("deficiencyCorrection, calibrated, radial", "deficiencyCorrection",
     "type deficiencyCorrection; calibration calibrated; direction radial; " + CORRECTION, "surface"),
    ("deficiencyCorrection, wallPressure (default)", "deficiencyCorrection", "type deficiencyCorrection; " + CORRECTION, "surface"),
    ("deficiencyCorrectionBoundaryIntegral, calibrated", "deficiencyCorrectionBoundaryIntegral",
     "type deficiencyCorrectionBoundaryIntegral; calibration calibrated; " + CORRECTION, "surface"),
    ("deficiencyCorrectionBoundaryIntegral, wallPressure (default)", "deficiencyCorrectionBoundaryIntegral",
     "type deficiencyCorrectionBoundaryIntegral; " + CORRECTION, "surface"),
    ("dummyParticles (10 layers)", "dummyParticles", "type dummyParticles;", "layers"),
]
HYDROSTATIC_MODELS = [
    ("dummyParticles", "type dummyParticles;", "layers"),
    ("dynamicBoundary", "type dynamicBoundary;", "layers"),
    ("deficiencyCorrectionBoundaryIntegral (defaults)", "type deficiencyCorrectionBoundaryIntegral;", "surface"),
    ("deficiencyCorrection (defaults)", "type deficiencyCorrection;", "surface"),
    ("deficiencyCorrection, calibration calibrated + lennardJones, temporalSmoothing 0.02",
     "type deficiencyCorrection; calibration calibrated; temporalSmoothing 0.02; repulsion { type lennardJones; Dc 1; r0 %g; }", "surface"),
    ("lennardJones alone", "type lennardJones; Dc 1; r0 %g;", "surface"),
    ("monaghanKajtar alone, K = g H", "type monaghanKajtar; K 0.9;", "surface"),
]
# The wall models of the flows that hurt: name, patch entry, layout (surface: one layer on the
# wall; layers: enough behind it for the kernel's support).
FLOW_MODELS = [
    ("deficiencyCorrectionBoundaryIntegral", "type deficiencyCorrectionBoundaryIntegral;", "surface"),
    ("deficiencyCorrectionBoundaryIntegral (closingSpeed each)",
     "type deficiencyCorrectionBoundaryIntegral; repulsion { type wallDistance; closingSpeed each; }", "surface"),
    ("deficiencyCorrection", "type deficiencyCorrection;", "surface"),
    ("dummyParticles", "type dummyParticles;", "layers"),  # noSlip as the viscosity makes it: the correction's default too
    ("dynamicBoundary", "type dynamicBoundary;", "layers"),
    ("modifiedDynamicBoundary", "type modifiedDynamicBoundary;", "layers"),
]


def prepare(case, name):
    directory = os.path.join(WORK, case + "-" + re.sub(r"[^A-Za-z0-9]+", "-", name).strip("-"))
    shutil.rmtree(directory, ignore_errors=True)
    os.makedirs(directory)
    for part in ("system", "constant"):
        shutil.copytree(os.path.join(ROOT, "cases", case, part), os.path.join(directory, part))
    for data in glob.glob(os.path.join(ROOT, "cases", case, "*.csv")):  # reference data the case's function objects read
        shutil.copy(data, directory)
    return directory


def edit(path, pattern, replacement):
    with open(path) as f:
        text = f.read()
    new, count = re.subn(pattern, replacement, text, count=1)
    if count == 0:
        raise SystemExit("boundarySuite.py: '%s' not found in %s" % (pattern, path))
    with open(path, "w") as f:
        f.write(new)


class Prepared(Exception):
    """--check: the case was prepared and evaluated once; its row is not measured."""


def run(directory, *arguments):
    """wcsph on the directory: (wall seconds, the first line of its error or ""). With --check a
    run in time is one evaluation instead, and any failure stops the suite."""
    timed = not arguments
    if CHECK:
        arguments = ("-rates",)
    start = time.time()
    result = subprocess.run([os.path.join(BIN, "wcsph"), "-case", directory, *arguments], capture_output=True, text=True,
                            env=dict(os.environ, OMP_NUM_THREADS="1"))
    elapsed = time.time() - start
    if CHECK and result.returncode != 0:
        raise SystemExit("boundarySuite.py: wcsph -rates failed in %s:\n%s" % (directory, result.stdout + result.stderr))
    if CHECK and timed:
        raise Prepared()
    message = "" if result.returncode == 0 else result.stderr.strip().splitlines()[0]
    return elapsed, message


def generate(directory):
    subprocess.run([os.path.join(BIN, "generateParticles"), "-case", directory], check=True, capture_output=True)


def tank_rows():
    rows = []
    for case in ("rectangularTank2D", "ellipticalTank2D"):
        reference = {}
        for name, _, patch, walls in TANK_MODELS:
            directory = prepare(case, name)
            particles = os.path.join(directory, "system", "generateParticlesDict")
            if walls == "layers":
                if case == "rectangularTank2D":
                    edit(particles, r"tank\s*\{[^}]*\}", "tank { type boxWalls; min (0 0); max (4 2); layers 10; }")
                else:
                    edit(particles, r"layers 1; firstLayerOffset 0;", "layers 10; firstLayerOffset 0.5;")
                    edit(particles, r"domain\s*\{[^}]*\}", "domain { min (-3 -2); max (3 2); }")
            with open(os.path.join(directory, "constant", "boundaryProperties"), "w") as f:
                f.write("tank { %s }\n" % patch)
            generate(directory)
            seconds, failure = run(directory, "-rates")
            fluid, wall = tankRates.read_rates(directory)
            near = tankRates.near_wall(fluid, [w for w in wall if w.get("layer", 0) == 0] if walls == "surface" else
                                       [w for w in wall if w.get("layer", 0) == 0], 0.5)
            regions = {}
            for p, nearest, _ in near:
                if case == "rectangularTank2D":
                    corner = (p["x"] < 0.5 or p["x"] > 3.5) and (p["y"] < 0.5 or p["y"] > 1.5)
                    region = "corners" if corner else "straight walls"
                else:
                    t = math.atan2(nearest["y"] / 1.0, nearest["x"] / 2.0)
                    radius = (4 * math.sin(t) ** 2 + math.cos(t) ** 2) ** 1.5 / 2.0
                    region = "high-curvature arcs (R < 1)" if radius < 1.0 else "low-curvature arcs"
                regions.setdefault(region, []).append(p)
            for region, particles_in in sorted(regions.items()):
                residual = [math.hypot(*tankRates.residual(p)) for p in particles_in]
                if name.startswith("no correction"):
                    reference[region] = tankRates.rms(residual)
                scale = reference.get(region, float("nan"))
                rows.append((case, region, name, len(particles_in), tankRates.rms(residual) / scale, max(residual) / scale, seconds, failure))
    return rows


def in_parallel(function, jobs):
    """function(*job) for every job, two at a time (the machine's cores), results in job order
    (None for a job that --check only prepared)."""
    def row(job):
        try:
            return function(*job)
        except Prepared:
            return None

    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        return list(pool.map(row, jobs))


def most_behind_wall(directory):
    counts = [int(line.split()[1]) for name in glob.glob(os.path.join(directory, "postProcessing", "leaks", "*", "penetrations.dat"))
              for line in open(name) if not line.startswith("#")]
    return max(counts) if counts else 0


def add_leak_counter(directory):
    path = os.path.join(directory, "system", "controlDict")
    with open(path) as f:
        has_functions = re.search(r"functions\s*\{", f.read())
    if has_functions:
        edit(path, r"functions\s*\{", "functions\n{\n    leaks { type wallPenetrations; }\n")
    else:
        with open(path, "a") as f:
            f.write("\nfunctions\n{\n    leaks { type wallPenetrations; }\n}\n")


def static_row(shape, extent, spacing, model, patch):
    """The residual of one uniform-pressure evaluation in a rectangle or ellipse of the given
    extent (length and height, or semi-axes), r_inf = 0.5 kept as dx changes."""
    case = "rectangularTank2D" if shape == "rectangle" else "ellipticalTank2D"
    directory = prepare(case, "%s-%gx%g-%g-%s" % (shape, extent[0], extent[1], spacing, model))
    particles = os.path.join(directory, "system", "generateParticlesDict")
    edit(particles, r"spacing\s+[0-9.e-]+;", "spacing     %g;" % spacing)
    if shape == "rectangle":
        L, H = extent
        edit(particles, r"max \(4 2\)", "max (%g %g)" % (L, H))
        edit(particles, r"tank\s*\{[^}]*\}", "tank { type polygon; points ((0 0) (%g 0) (%g %g) (0 %g)); layers 1; firstLayerOffset 0; }" % (L, L, H, H))
        edit(particles, r"domain\s*\{[^}]*\}", "domain { min (-1 -1); max (%g %g); }" % (L + 1, H + 1))
    else:
        a, b = extent
        for _ in range(2):
            edit(particles, r"semiAxes \(2 1\)", "semiAxes (%g %g)" % (a, b))
        edit(particles, r"domain\s*\{[^}]*\}", "domain { min (%g %g); max (%g %g); }" % (-a - 1, -b - 1, a + 1, b + 1))
    edit(os.path.join(directory, "system", "sphSchemes"), r"hdx\s+[0-9.]+", "hdx %g" % (0.25 / spacing))
    with open(os.path.join(directory, "constant", "boundaryProperties"), "w") as f:
        f.write("tank { %s }\n" % patch)
    generate(directory)
    seconds, failure = run(directory, "-rates")
    fluid, wall = tankRates.read_rates(directory)
    residual = [math.hypot(*tankRates.residual(p)) for p, _, _ in tankRates.near_wall(fluid, wall, 0.5)]
    return tankRates.rms(residual), max(residual), seconds


def static_rows():
    """Residual over the uncorrected RMS, corners and ends included, on 2:1 and 3:1 shapes."""
    models = [("deficiencyCorrectionBoundaryIntegral, wallPressure", "type deficiencyCorrectionBoundaryIntegral; " + CORRECTION),
              ("deficiencyCorrectionBoundaryIntegral, calibrated", "type deficiencyCorrectionBoundaryIntegral; calibration calibrated; " + CORRECTION)]
    rows = []
    for shape, extent in (("rectangle", (4, 2)), ("rectangle", (6, 2)), ("ellipse", (2, 1)), ("ellipse", (3, 1))):
        for spacing in (0.05,) if QUICK else (0.05, 0.025):
            reference, _, _ = static_row(shape, extent, spacing, "none", "type monaghanKajtar; K 1e-9;")
            for name, patch in models:
                rms, largest, seconds = static_row(shape, extent, spacing, name, patch)
                rows.append(("%s %g:%g" % (shape, extent[0], extent[1]), round(0.5 / spacing), name, rms / reference, largest / reference, seconds))
    return rows


def hydrostatic_rows():
    dx = 0.05 if QUICK else 0.02
    return in_parallel(hydrostatic_row, [(name, patch, walls, dx) for name, patch, walls in HYDROSTATIC_MODELS])


def hydrostatic_row(name, patch, walls, dx):
    directory = prepare("hydrostaticTank2D", name)
    particles = os.path.join(directory, "system", "generateParticlesDict")
    edit(particles, r"spacing\s+[0-9.e-]+;", "spacing     %g;" % dx)
    if walls == "surface":
        edit(particles, r"tank\s*\{[^}]*\}", "tank { type polyline; points ((0 1) (0 0) (2 0) (2 1)); layers 1; firstLayerOffset 0; }")
    with open(os.path.join(directory, "constant", "boundaryProperties"), "w") as f:
        f.write("tank { %s }\n" % (patch % (0.5 * dx) if "%g" in patch else patch))
    # The wall pressure: the fluid's pressure along the floor, between the corners' reach.
    edit(os.path.join(directory, "system", "controlDict"), r"functions\s*\{",
         "functions\n{\n    floor { type lineSample; start (0.2 0); end (1.8 0); points 33; executeInterval 0.25; "
         "hydrostaticReference { freeSurfaceHeight 0.9; } }\n")
    add_leak_counter(directory)
    generate(directory)
    seconds, failure = run(directory)
    if failure:
        return (name, dx, None, None, None, None, None, None, None, None, seconds, failure)
    with open(os.path.join(directory, "postProcessing", "pressure", "0", "error.dat")) as f:
        last = [line.split() for line in f if not line.startswith("#")][-1]
    with open(os.path.join(directory, "postProcessing", "floor", "0", "error.dat")) as f:
        wall = [line.split() for line in f if not line.startswith("#")][-1]
    run(directory, "-rates")
    fluid, _ = tankRates.read_rates(directory)
    lowest = {}
    for p in fluid:  # the lowest particle of each column of width dx
        column = int(math.floor(p["x"] / dx))
        lowest[column] = min(lowest.get(column, p["y"]), p["y"])
    bottom = list(lowest.values())
    gap = sum(bottom) / len(bottom)
    spread = math.sqrt(sum((y - gap) ** 2 for y in bottom) / len(bottom))
    kinetic = sum(0.5 * (p["velocity_x"] ** 2 + p["velocity_y"] ** 2) for p in fluid) / len(fluid) / 0.9  # per unit mass, over g H
    return (name, dx, float(wall[1]), float(wall[2]), float(last[1]), float(last[2]), gap / dx, spread / dx, kinetic,
            most_behind_wall(directory), seconds, "")


def deforming_rows():
    """Runs deformingTank2D's Allrun (both variants) and reads its comparison."""
    case = os.path.join(ROOT, "cases", "deformingTank2D")
    start = time.time()
    subprocess.run([os.path.join(case, "Allrun")], check=True, capture_output=True, env=dict(os.environ, SPHKIT_BIN=os.path.abspath(BIN)))
    seconds = time.time() - start
    results = {}
    with open(os.path.join(case, "variantComparison.csv")) as f:
        for row in csv.DictReader(f):
            results.setdefault(row["variant"], []).append(row)
    rows = []
    for name, values in results.items():
        noise = sum(float(v["pressure_noise_Pa"]) for v in values) / len(values)
        closest = min(float(v["min_neighbour_over_dx"]) for v in values)
        clumped = sum(float(v["fraction_below_0.75dx"]) for v in values) / len(values)
        penetrations = max(int(v["penetrations"]) for v in values)
        rows.append((name, noise, closest, clumped, penetrations, seconds / 2))
    subprocess.run([os.path.join(case, "Allclean")], check=True, env=dict(os.environ, SPHKIT_BIN=os.path.abspath(BIN)))
    return rows


def flow_case(case, model, patch, layout, spacing=None, edits=(), layers=4):
    """A copy of `case` with the model on its tank patch; layered models get the layers their
    kernel needs, the correction one layer on the wall. Returns the directory."""
    directory = prepare(case, model + ("-%g" % spacing if spacing else "") + "".join("-" + tag for tag, _, _ in edits))
    particles = os.path.join(directory, "system", "generateParticlesDict")
    if spacing:
        edit(particles, r"spacing\s+[0-9.e-]+;", "spacing     %.12g;" % spacing)
    if layout == "layers":
        edit(particles, r"layers 1; firstLayerOffset 0;", "layers %d;" % layers)
    properties = os.path.join(directory, "constant", "boundaryProperties")
    with open(properties) as f:
        motion = re.search(r"motion\s*\{[^}]*\}", f.read())
    with open(properties, "w") as f:
        f.write("tank { %s %s }\n" % (patch, motion.group(0) if motion else ""))
    for _, path, (pattern, replacement) in edits:
        edit(os.path.join(directory, path), pattern, replacement)
    return directory


def first_figures(printed):
    """The numbers of a comparison script's first case line (the line after its first comment):
    a script may print further blocks after it (comparePressure.py: the second digitisation, the
    experiment at three sensors), whose lines are not the first block's columns."""
    lines = printed.strip().splitlines()
    first = next(k for k, line in enumerate(lines) if line.startswith("#"))
    return [float(v) for v in lines[first + 1].split()[1:]]


def compare(script, directory, *options):
    """Runs a case's comparison script on one directory; returns its first case line's numbers."""
    result = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "cases", script[0], script[1]), *options, directory], capture_output=True,
                            text=True, check=True)
    return first_figures(result.stdout)


def dam_break_row(model, patch, layout, resolution):
    directory = flow_case("damBreakWallPressure2D", model, patch, layout, 0.6 / resolution)
    generate(directory)
    seconds, failure = run(directory)
    script = ("damBreakWallPressure2D", "comparePressure.py")
    errors = compare(script, directory)[:4] + compare(script, directory, "--wall")[:4] if not failure else None
    return (model, resolution, errors, most_behind_wall(directory), seconds, failure)


def sloshing_row(model, patch, layout, resolution):
    """sloshingTank2D at dx = H/resolution (H = 0.6 m; 30 shipped)."""
    directory = flow_case("sloshingTank2D", model, patch, layout, 0.6 / resolution, layers=3)
    generate(directory)
    seconds, failure = run(directory)
    errors = compare(("sloshingTank2D", "compareSloshing.py"), directory) if not failure else None
    return (model, resolution, errors, most_behind_wall(directory), seconds, failure)


def linear_sloshing_row(model, patch, layout, resolution):
    """sloshingTank2D forced at linearSloshing.py's amplitude (0.004 m) against linear modal
    theory, at dx = H/resolution."""
    edits = [("linear", "constant/boundaryProperties", (r"amplitude \(0.032 0\)", "amplitude (%g 0)" % LINEAR_SLOSHING_AMPLITUDE))]
    directory = flow_case("sloshingTank2D", model, patch, layout, 0.6 / resolution, edits=edits, layers=3)
    generate(directory)
    seconds, failure = run(directory)
    errors = compare(("sloshingTank2D", "linearSloshing.py"), directory) if not failure else None
    return (model, resolution, errors, most_behind_wall(directory), seconds, failure)


def bulge_row(model, patch, layout, period, resolution):
    """steepBulge2D: the floor bulging by 0.3 (half the depth) over `period` (1.2 s shipped), at
    dx = H/resolution (H = 0.6 m; 30 shipped)."""
    edits = [("T%g" % period, "constant/boundaryProperties", (r"period [0-9.e-]+;", "period %g;" % period)),
             ("", "system/controlDict", (r"endTime\s+[0-9.e-]+;", "endTime %g;" % period))]
    directory = flow_case("steepBulge2D", model, patch, "surface", 0.6 / resolution, edits=edits)
    if layout == "layers":
        edit(os.path.join(directory, "system", "generateParticlesDict"), r"tank\s*\{[^}]*\}",
             "tank { type boxWalls; min (0 0); max (2 1); layers 3; open (yMax); }")
    generate(directory)
    seconds, failure = run(directory)
    noise, _, leaks = bulge_noise(directory)
    return (model, period, resolution, noise, int(leaks), seconds, failure)


def bulge3d_row(model, patch, layout, resolution):
    """steepBulge3D (half the depth in 0.3 s) at dx = H/resolution (H = 0.4 m; 10 shipped)."""
    directory = flow_case("steepBulge3D", model, patch, layout, 0.4 / resolution, layers=3)
    generate(directory)
    seconds, failure = run(directory)
    noise, last, leaks = bulge_noise(directory)
    return (model, resolution, noise, last, int(leaks), seconds, failure)


def bulge_noise(directory):
    """The bulgeNoise utility's figures (noise over the written times, last time, penetrations)."""
    result = subprocess.run([os.path.join(BIN, "bulgeNoise"), directory], capture_output=True, text=True, check=True)
    return [float(v) for v in result.stdout.strip().splitlines()[-1].split()[1:]]


def box_row(model, patch, layout, resolution):
    """hydrostaticTank3D (box 1 x 0.6 m, H = 0.4 m, to t = 4 s) at dx = H/resolution."""
    directory = flow_case("hydrostaticTank3D", model, patch, layout, 0.4 / resolution, layers=3)
    generate(directory)
    seconds, failure = run(directory)
    if failure:
        return (model, resolution, None, None, None, None, None, most_behind_wall(directory), seconds, failure)
    _, kinetic, pressure, gap, spread, centre, leaks = compare(("hydrostaticTank3D", "checkStillWater.py"), directory)
    return (model, resolution, kinetic, pressure, gap, spread, centre, int(leaks), seconds, "")


def flow_rows():
    """Every flow at three resolutions (the shipped one among them), the coarsest with --quick."""
    pick = lambda resolutions: resolutions[:1] if QUICK else resolutions  # noqa: E731
    models = [m for m in FLOW_MODELS if ONLY is None or m[0] in ONLY]
    dam = in_parallel(dam_break_row, [(m, p, l, r) for r in pick((20, 40, 80)) for m, p, l in models])
    slosh = in_parallel(sloshing_row, [(m, p, l, r) for r in pick((15, 30, 45)) for m, p, l in models])
    linear = in_parallel(linear_sloshing_row, [(m, p, l, r) for r in pick((15, 30, 45)) for m, p, l in models])
    bulge = in_parallel(bulge_row, [(m, p, l, period, r) for period, r in [(1.2, r) for r in pick((15, 30, 60))] + [(0.8, 30)]
                                    for m, p, l in models])
    bulge3d = in_parallel(bulge3d_row, [(m, p, l, r) for r in pick((8, 10, 12)) for m, p, l in models])
    box = in_parallel(box_row, [(m, p, l, r) for r in pick((6, 8, 10)) for m, p, l in models])
    return dam, slosh, linear, bulge, bulge3d, box


def outcome(failure):
    return failure.replace("|", "/") if failure else "ran to the end"


def dam_break_lines(dam):
    lines = ["### Standard 2D dam break (damBreakWallPressure2D, to T = t sqrt(g/H) = 8)", "",
             "Downstream-wall pressure at P1-P4 against De Courcy et al. (2024): RMS of the Delta T = 0.1 window means, T = 2-7, "
             "over rho g H, read two ways: probes, the fluid interpolated dx/2 from the wall for every model; and on the wall, the "
             "case's wallPressure sensors (0.009 m of wall each; comparePressure.py --wall): the wall particles' pressure where the "
             "model gives them one (the correction's and dummy particles' extrapolation; a dynamic boundary's is its repulsion, not "
             "the fluid's), else the fluid extrapolated to the wall.", "",
             "| model | H/dx | P1 | P2 | P3 | P4 | wall P1 | wall P2 | wall P3 | wall P4 | penetrations | wall time [s] | outcome |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for model, resolution, errors, leaks, seconds, failure in dam:
        values = " | ".join("%.3f" % e for e in errors) if errors else " | | | | | | | "
        lines.append("| %s | %d | %s | %d | %.1f | %s |" % (model, resolution, values, leaks, seconds, outcome(failure)))
    return lines


def flow_lines(dam, slosh, linear, bulge, bulge3d, box):
    lines = ["", "## Flows that hurt: every wall model on the same case", "",
             "Every run alone on one thread, two at a time; penetrations: the most fluid particles behind the wall's first layer of "
             "particles at any step (wallPenetrations). The correction runs with its defaults (calibration wallPressure, the "
             "wallDistance partner); dummy particles free-slip, 4 layers (3 in the sloshing tank, the bulge and the 3D tank), and so the dynamic boundary and mDBC (modifiedDynamicBoundary).", ""]
    lines += dam_break_lines(dam)
    if slosh:
        lines += ["", "### Sloshing (sloshingTank2D: Faltinsen et al. 2000, Fig. 7, to t = 10 s)", "",
                  "Free-surface elevation 0.05 m from the left wall, in the tank's frame (a waveGauge moving with the tank), against "
                  "the experiment; H = 0.6 m, dx = 0.02 shipped.", "",
                  "| model | H/dx | RMS error [m] | max error [m] | penetrations | wall time [s] | outcome |", "|---|---|---|---|---|---|---|"]
        for model, resolution, errors, leaks, seconds, failure in slosh:
            values = "%.4f | %.4f" % (errors[0], errors[1]) if errors else " | "
            lines.append("| %s | %d | %s | %d | %.1f | %s |" % (model, resolution, values, leaks, seconds, outcome(failure)))
    if linear:
        lines += ["", "### Linear sloshing (sloshingTank2D at surge amplitude 0.004 m, to t = 10 s, against linear modal theory)", "",
                  "The same gauge against linearSloshing.py's modal sum (largest elevation 0.020 m, k_1 eta = 0.037; undamped, so the "
                  "free modes started at t = 0 beat for ever where a run's viscosity damps them); the run's elevation is its depth less "
                  "the depth read at t = 0. Errors in m and over the theory's largest |eta|; T1: the run's first natural period, "
                  "fitted (linearSloshing.py; linear theory 1.661 s).", "",
                  "| model | H/dx | RMS error [m] | max error [m] | RMS / max eta | max / max eta | T1 [s] | penetrations | wall time [s] | outcome |",
                  "|---|---|---|---|---|---|---|---|---|---|"]
        for model, resolution, errors, leaks, seconds, failure in linear:
            values = "%.5f | %.5f | %.3f | %.3f | %.3f" % tuple(errors[:5]) if errors else " | | | | "
            lines.append("| %s | %d | %s | %d | %.1f | %s |" % (model, resolution, values, leaks, seconds, outcome(failure)))
    lines += ["", "### Steep fast floor bulge (steepBulge2D: amplitude 0.3 = half the depth, one period)", "",
              "Period 1.2 s (shipped): 5x deformingTank2D's peak wall speed (0.1 pi m/s), 0.8 s: 7.5x. Pressure noise: RMS of p about its "
              "neighbours' mean within 2.5 dx, over the fluid within 2h of the floor near the bulge, averaged over the written times "
              "(H = 0.6 m, dx = 0.02 shipped; the noise in Pa scales with rho g dx).", "",
              "| model | period [s] | H/dx | pressure noise [Pa] | penetrations | wall time [s] | outcome |", "|---|---|---|---|---|---|---|"]
    for model, period, resolution, noise, leaks, seconds, failure in bulge:
        lines.append("| %s | %g | %d | %s | %d | %.1f | %s |" % (model, period, resolution, "%.1f" % noise if noise is not None else "", leaks, seconds,
                                                            outcome(failure)))
    lines += ["", "### Steep fast floor bulge in 3D (steepBulge3D: amplitude 0.2 = half the depth, width 0.15, period 1.2 s)", "",
              "The same measures over the fluid within 1.5 widths of the bulge's axis (H = 0.4 m, H/dx = 10 shipped: rho g dx = 392 Pa); "
              "a run that blew up is measured over what it wrote (last time).", "",
              "| model | H/dx | pressure noise [Pa] | last written time [s] | penetrations | wall time [s] | outcome |", "|---|---|---|---|---|---|---|"]
    for model, resolution, noise, last, leaks, seconds, failure in bulge3d:
        lines.append("| %s | %d | %.1f | %g | %d | %.1f | %s |" % (model, resolution, noise, last, leaks, seconds, outcome(failure)))
    lines += ["", "### 3D still water (hydrostaticTank3D: box 1 x 0.6 m, H = 0.4 m, t = 4 s)", "",
              "At t = 4 (checkStillWater.py): kinetic energy per unit mass over g H; near-floor pressure: RMS of p - rho g (H - z) "
              "over rho g H within 2h of the floor; floor gap: mean height of the lowest particle of each dx x dx column over dx "
              "(0.5 at the start), and its spread; centre line: L2 pressure error over rho g H.", "",
              "| model | H/dx | KE / gH | near-floor p RMS | floor gap / dx | gap spread / dx | centre-line p error | penetrations | wall time [s] | outcome |",
              "|---|---|---|---|---|---|---|---|---|---|"]
    for model, resolution, kinetic, pressure, gap, spread, centre, leaks, seconds, failure in box:
        values = "%.2e | %.4f | %.3f | %.3f | %.4f" % (kinetic, pressure, gap, spread, centre) if kinetic is not None else " | | | | "
        lines.append("| %s | %d | %s | %d | %.1f | %s |" % (model, resolution, values, leaks, seconds, outcome(failure)))
    return lines


def deforming_lines(deforming):
    lines = ["## Deforming tank (deformingTank2D, the floor bulges 5 dx in and out over 2 s)", "",
             "Near the bulge (|x - 1| < 0.3, within 2h of the floor), averaged over the 40 written times: pressure noise (RMS of "
             "p - rho g (H - y) about its mean; rho g dx = 196 Pa), the smallest nearest-neighbour distance, the fraction of "
             "particles closer than 0.75 dx to a neighbour, and the most fluid particles below the floor at any written time.", "",
             "| model | pressure noise [Pa] | smallest neighbour distance / dx | fraction below 0.75 dx | penetrations | wall time [s] |",
             "|---|---|---|---|---|---|"]
    for name, noise, closest, clumped, penetrations, seconds in deforming:
        lines.append("| %s | %.1f | %.2f | %.4f | %d | %.1f |" % (name, noise, closest, clumped, penetrations, seconds))
    return lines


def table_rows(lines):
    """Each table row's index by its section and its key cells: the model and the resolution
    (and, in the 2D bulge's table, the period; in the deforming tank's, the model alone)."""
    rows, heading = {}, ""
    for index, line in enumerate(lines):
        if line.startswith("#"):
            heading = line
        elif line.startswith("| ") and not line.startswith("|---"):
            width = 1 if heading.startswith("## Deforming") else 3 if heading.startswith("### Steep fast floor bulge (steepBulge2D") else 2
            rows[(heading, tuple(cell.strip() for cell in line.strip("|").split("|")[:width]))] = index
    return rows


def replace_rows(new_lines):
    """--models: writes the re-run rows over their old ones in doc/boundarySuite.md, a new model's at the end of each table."""
    path = os.path.join(ROOT, "doc", "boundarySuite.md")
    with open(path) as f:
        lines = f.read().split("\n")
    for key, index in table_rows(new_lines).items():
        old = table_rows(lines)
        if key in old:
            lines[old[key]] = new_lines[index]
            continue
        section = [row for (heading, _), row in old.items() if heading == key[0]]
        if not section:
            raise SystemExit("boundarySuite.py: no table %s in %s; run the whole suite" % (key[0], path))
        lines.insert(max(section) + 1, new_lines[index])  # a model new to the suite: its row ends the table
    with open(path, "w") as f:
        f.write("\n".join(lines))
    print("\n".join(new_lines))


def main():
    if not os.path.exists(os.path.join(BIN, "wcsph")):
        raise SystemExit("boundarySuite.py: %s/wcsph not found; build first (./Allwmake)" % BIN)
    if ONLY is not None:
        unknown = [name for name in ONLY if name not in [m[0] for m in FLOW_MODELS]]
        if unknown:
            raise SystemExit("boundarySuite.py: --models: unknown %s; valid: %s" % (", ".join(unknown), ", ".join(m[0] for m in FLOW_MODELS)))
        if not CHECK:
            replace_rows(deforming_lines(deforming_rows()) + flow_lines(*flow_rows()))
            return
    if CHECK:
        started = time.time()
        for part in (tank_rows, static_rows, hydrostatic_rows, flow_rows):
            part()
        print("boundarySuite.py --check: every case prepared and evaluated once in %.0f s" % (time.time() - started))
        return
    tanks = tank_rows()
    statics = static_rows()
    hydrostatic = hydrostatic_rows()
    deforming = deforming_rows()
    flows = flow_rows()
    with open(os.path.join(ROOT, "doc", "boundarySuite.csv"), "w") as f:
        f.write("suite,case,region_or_dx,model,particles,rms_over_uncorrected,max_over_uncorrected_rms,L2_wall_pressure,max_wall_pressure,"
                "L2_centre_pressure,max_centre_pressure,gap_over_dx,gap_spread_over_dx,kinetic_over_gH,penetrations,wall_seconds,failure\n")
        for case, region, name, n, r, m, s, failure in tanks:
            f.write('tank,%s,%s,"%s",%d,%.4g,%.4g,,,,,,,,,%.2f,"%s"\n' % (case, region, name, n, r, m, s, failure))
        for name, dx, wl2, wmx, l2, mx, gap, spread, kinetic, penetrations, s, failure in hydrostatic:
            values = ",".join("" if v is None else "%.4g" % v for v in (wl2, wmx, l2, mx, gap, spread, kinetic, penetrations))
            f.write('hydrostatic,hydrostaticTank2D,%g,"%s",,,,%s,%.2f,"%s"\n' % (dx, name, values, s, failure))
    lines = ["# Boundary suite", "",
             "Generated by `utilities/boundarySuite/boundarySuite.py%s` (numbers also in `boundarySuite.csv`); "
             "wall times on this project's 2-core machine." % (" --quick" if QUICK else ""), "",
             "## Uniform-pressure tanks (one right-hand-side evaluation)", "",
             "Residual |a| of the fluid within r_inf = 0.5 of the wall (the correction included, the repulsion not), over the RMS "
             "without correction in the same region. Paper setup: pressure 1, density 1000, r_inf = 0.5, dx = 0.05.", "",
             "| case | region | model | particles | RMS / uncorrected RMS | max / uncorrected RMS | wall time [s] |",
             "|---|---|---|---|---|---|---|"]
    for case, region, name, n, r, m, s, failure in tanks:
        lines.append("| %s | %s | %s | %d | %.3f | %.3f | %.2f |" % (case, region, name, n, r, m, s))
    lines += ["", "Every near-wall particle (corners and ends included) on 2:1 and 3:1 shapes, at r_inf/10 and r_inf/20 (r_inf = 0.5 "
              "kept: hdx = 0.25/dx):", "",
              "| shape | r_inf/dx | model | RMS / uncorrected RMS | max / uncorrected RMS | wall time [s] |", "|---|---|---|---|---|---|"]
    for shape, resolution, name, r, m, seconds in statics:
        lines.append("| %s | %d | %s | %.4f | %.3f | %.2f |" % (shape, resolution, name, r, m, seconds))
    lines += ["", "## Hydrostatic tank (setup A, t = 2)", "",
              "Wall pressure: the fluid's pressure interpolated (Shepard, fluid only) along the floor from x = 0.2 to 1.8 against "
              "rho g H, so even a perfect wall model shows the interpolation's offset of about dx/2 (1.1 %); centre line: along "
              "x = 1; both over rho g H. Bottom gap: mean height above the floor of the lowest "
              "particle of each dx-wide column, over dx (0.5 where the fluid started), and its spread; kinetic energy per unit mass over g H; penetrations: "
              "the most fluid particles behind the wall at any step. Wall models act on particles on the wall (correction, repulsion) or "
              "on 4 layers behind it (dummy, dynamic).", "",
              "| model | dx | L2 wall p error | max wall p error | L2 centre-line p error | max centre-line p error | gap / dx | gap spread / dx | KE / gH | penetrations | wall time [s] | outcome |",
              "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for name, dx, wl2, wmx, l2, mx, gap, spread, kinetic, penetrations, s, failure in hydrostatic:
        if failure:
            lines.append("| %s | %g | | | | | | | | | %.2f | %s |" % (name, dx, s, failure.replace("|", "/")))
        else:
            lines.append("| %s | %g | %.4f | %.4f | %.4f | %.4f | %.3f | %.3f | %.2e | %d | %.2f | ran to t = 2 |"
                         % (name, dx, wl2, wmx, l2, mx, gap, spread, kinetic, penetrations, s))
    lines += [""] + deforming_lines(deforming) + flow_lines(*flows)
    with open(os.path.join(ROOT, "doc", "boundarySuite.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
