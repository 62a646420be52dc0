#!/usr/bin/python3
"""Runs every boundary model on the same cases and writes the comparison to
doc/boundarySuite.md and doc/boundarySuite.csv:

- uniform-pressure tanks (rectangularTank2D, ellipticalTank2D; one right-hand-side
  evaluation, wcsph -rates): RMS and max residual |a| of the fluid within r_inf of the wall,
  over the uncorrected RMS of the same particles, split into straight walls and corners, or
  low- and high-curvature arcs;
- hydrostatic tank (hydrostaticTank2D, to t = 2): wall pressure error (the fluid's pressure
  interpolated along the floor against rho g H, L2 and max over rho g H) and the centre line's,
  bottom gap (mean and spread of the lowest particle's height per column), residual kinetic
  energy, penetrations;
- deforming tank (deformingTank2D's Allrun: virtual particles against the correction): pressure
  noise near the bulging floor, clumping, penetrations;
each with the wall time that produced it.

Usage: utilities/boundarySuite/boundarySuite.py [--quick]   (from the repository root; the
binaries are taken from $SPHKIT_BIN or build/bin; --quick runs the hydrostatic tank at dx = 0.05)
"""
import csv
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
WORK = os.path.join(ROOT, "build", "boundarySuite")
QUICK = "--quick" in sys.argv

CORRECTION = "repulsion { type monaghanKajtar; K 1e-9; }"
TANK_MODELS = [
    ("no correction (repulsion only)", "monaghanKajtar", "type monaghanKajtar; K 1e-9;", "surface"),
    ("deficiencyCorrection", "deficiencyCorrection", "type deficiencyCorrection; " + CORRECTION, "surface"),
    ("deficiencyCorrection, literal", "deficiencyCorrection", "type deficiencyCorrection; calibration literal; " + CORRECTION, "surface"),
    ("deficiencyCorrection, radial", "deficiencyCorrection", "type deficiencyCorrection; direction radial; " + CORRECTION, "surface"),
    ("deficiencyCorrectionBoundaryIntegral", "deficiencyCorrectionBoundaryIntegral",
     "type deficiencyCorrectionBoundaryIntegral; " + CORRECTION, "surface"),
    ("dummyParticles (10 layers)", "dummyParticles", "type dummyParticles;", "layers"),
]
PARTNER = "repulsion { type lennardJones; Dc 1; r0 %g; }"
HYDROSTATIC_MODELS = [
    ("dummyParticles", "type dummyParticles;", "layers"),
    ("dynamicBoundary", "type dynamicBoundary;", "layers"),
    ("deficiencyCorrection + lennardJones", "type deficiencyCorrection; " + PARTNER, "surface"),
    ("deficiencyCorrection + lennardJones, temporalSmoothing 0.1", "type deficiencyCorrection; temporalSmoothing 0.1; " + PARTNER, "surface"),
    ("deficiencyCorrection + lennardJones, temporalSmoothing 0.02", "type deficiencyCorrection; temporalSmoothing 0.02; " + PARTNER, "surface"),
    ("deficiencyCorrectionBoundaryIntegral + lennardJones", "type deficiencyCorrectionBoundaryIntegral; " + PARTNER, "surface"),
    ("deficiencyCorrectionBoundaryIntegral + lennardJones, temporalSmoothing 0.02",
     "type deficiencyCorrectionBoundaryIntegral; temporalSmoothing 0.02; " + PARTNER, "surface"),
    ("lennardJones alone", "type lennardJones; Dc 1; r0 %g;", "surface"),
    ("monaghanKajtar alone, K = g H", "type monaghanKajtar; K 0.9;", "surface"),
]


def prepare(case, name):
    directory = os.path.join(WORK, case + "-" + re.sub(r"[^A-Za-z0-9]+", "-", name).strip("-"))
    shutil.rmtree(directory, ignore_errors=True)
    os.makedirs(directory)
    for part in ("system", "constant"):
        shutil.copytree(os.path.join(ROOT, "cases", case, part), os.path.join(directory, part))
    return directory


def edit(path, pattern, replacement):
    with open(path) as f:
        text = f.read()
    new, count = re.subn(pattern, replacement, text, count=1)
    if count == 0:
        raise SystemExit("boundarySuite.py: '%s' not found in %s" % (pattern, path))
    with open(path, "w") as f:
        f.write(new)


def run(directory, *arguments):
    start = time.time()
    result = subprocess.run([os.path.join(BIN, "wcsph"), "-case", directory, *arguments], capture_output=True, text=True)
    elapsed = time.time() - start
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


def hydrostatic_rows():
    rows = []
    dx = 0.05 if QUICK else 0.02
    for name, patch, walls in HYDROSTATIC_MODELS:
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
        generate(directory)
        seconds, failure = run(directory)
        if failure:
            rows.append((name, dx, None, None, None, None, None, None, None, None, seconds, failure))
            continue
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
        penetrations = sum(1 for p in fluid if p["y"] < 0 or p["x"] < 0 or p["x"] > 2)
        rows.append((name, dx, float(wall[1]), float(wall[2]), float(last[1]), float(last[2]), gap / dx, spread / dx, kinetic, penetrations,
                     seconds, ""))
    return rows


def deforming_rows():
    """Runs deformingTank2D's Allrun (both variants) and reads its comparison."""
    case = os.path.join(ROOT, "cases", "deformingTank2D")
    start = time.time()
    subprocess.run([os.path.join(case, "Allrun")], check=True, capture_output=True, env=dict(os.environ, SPHKIT_BIN=BIN))
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
    subprocess.run([os.path.join(case, "Allclean")], check=True)
    return rows


def main():
    if not os.path.exists(os.path.join(BIN, "wcsph")):
        raise SystemExit("boundarySuite.py: %s/wcsph not found; build first (./Allwmake)" % BIN)
    tanks = tank_rows()
    hydrostatic = hydrostatic_rows()
    deforming = deforming_rows()
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
    lines += ["", "## Hydrostatic tank (setup A, t = 2)", "",
              "Wall pressure: the fluid's pressure interpolated (Shepard, fluid only) along the floor from x = 0.2 to 1.8 against "
              "rho g H, so even a perfect wall model shows the interpolation's offset of about dx/2 (1.1 %); centre line: along "
              "x = 1; both over rho g H. Bottom gap: mean height above the floor of the lowest "
              "particle of each dx-wide column, over dx (0.5 where the fluid started), and its spread; kinetic energy per unit mass over g H; penetrations: "
              "fluid particles outside the tank at t = 2. Wall models act on particles on the wall (correction, repulsion) or "
              "on 4 layers behind it (dummy, dynamic).", "",
              "| model | dx | L2 wall p error | max wall p error | L2 centre-line p error | max centre-line p error | gap / dx | gap spread / dx | KE / gH | penetrations | wall time [s] | outcome |",
              "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for name, dx, wl2, wmx, l2, mx, gap, spread, kinetic, penetrations, s, failure in hydrostatic:
        if failure:
            lines.append("| %s | %g | | | | | | | | | %.2f | %s |" % (name, dx, s, failure.replace("|", "/")))
        else:
            lines.append("| %s | %g | %.4f | %.4f | %.4f | %.4f | %.3f | %.3f | %.2e | %d | %.2f | ran to t = 2 |"
                         % (name, dx, wl2, wmx, l2, mx, gap, spread, kinetic, penetrations, s))
    lines += ["", "## Deforming tank (deformingTank2D, the floor bulges 5 dx in and out over 2 s)", "",
              "Near the bulge (|x - 1| < 0.3, within 2h of the floor), averaged over the 40 written times: pressure noise (RMS of "
              "p - rho g (H - y) about its mean; rho g dx = 196 Pa), the smallest nearest-neighbour distance, the fraction of "
              "particles closer than 0.75 dx to a neighbour, and the most fluid particles below the floor at any time.", "",
              "| model | pressure noise [Pa] | smallest neighbour distance / dx | fraction below 0.75 dx | penetrations | wall time [s] |",
              "|---|---|---|---|---|---|"]
    for name, noise, closest, clumped, penetrations, seconds in deforming:
        lines.append("| %s | %.1f | %.2f | %.4f | %d | %.1f |" % (name, noise, closest, clumped, penetrations, seconds))
    with open(os.path.join(ROOT, "doc", "boundarySuite.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


main()
