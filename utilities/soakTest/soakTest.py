#!/usr/bin/python3
"""Soak test: the hydrostatic tank (cases/hydrostaticTank2D) for 10^5 steps at a fixed step,
checking what a long run must keep: total mass (to round-off), total volume sum(m/rho),
energy bounded (kinetic, and kinetic + potential), no drift of the smallest fluid-wall gap or
of the hydrostatic pressure error. Prints a Markdown report and writes it, with the time
series as CSV, to build/soakTest/.

Usage: utilities/soakTest/soakTest.py [--steps N] [--spacing DX] [--threads T]
(from the repository root; binaries from $SPHKIT_BIN or build/bin). The shipped spacing 0.02
(4500 fluid particles) takes about 15 minutes on one core of this machine.
"""
import argparse
import csv
import os
import re
import shutil
import subprocess

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.environ.get("SPHKIT_BIN", os.path.join(ROOT, "build", "bin"))
WORK = os.path.join(ROOT, "build", "soakTest")
GRAVITY, DEPTH = 9.81, 0.9


def set_entry(path, keyword, value):
    with open(path) as f:
        text = f.read()
    text, count = re.subn(r"(?m)^(\s*)%s\s+[^;\n]*;" % keyword, r"\g<1>%s %s;" % (keyword, value), text, count=1)
    if count == 0:
        text += "%s %s;\n" % (keyword, value)
    with open(path, "w") as f:
        f.write(text)


def run(case, log, env):
    with open(log, "w") as out:
        subprocess.run([os.path.join(BIN, "wcsph"), "-case", case], stdout=out, stderr=subprocess.STDOUT, env=env, check=True)
    with open(log) as f:
        return f.read()


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {key: np.array([float(row[key]) for row in rows]) for key in rows[0]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=100000)
    parser.add_argument("--spacing", type=float, default=0.02)
    parser.add_argument("--threads", type=int, default=os.cpu_count())
    parser.add_argument("--analyse", action="store_true", help="only analyse the last run in build/soakTest/")
    args = parser.parse_args()
    if not args.analyse:
        soak(args)
    analyse(args)


def soak(args):
    env = dict(os.environ, OMP_NUM_THREADS=str(args.threads))
    case = os.path.join(WORK, "case")
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)
    for part in ("system", "constant"):
        shutil.copytree(os.path.join(ROOT, "cases", "hydrostaticTank2D", part), os.path.join(case, part))
    set_entry(os.path.join(case, "system/generateParticlesDict"), "spacing", "%g" % args.spacing)
    subprocess.run([os.path.join(BIN, "generateParticles"), "-case", case], stdout=subprocess.DEVNULL, check=True)

    # The step: the solver's own (Courant) step in still water, measured over 200 steps past the gravity ramp.
    controlDict = os.path.join(case, "system/controlDict")
    set_entry(controlDict, "endTime", "1.2")
    run(case, os.path.join(WORK, "log.ramp"), env)
    set_entry(controlDict, "endTime", "1.3")
    log = run(case, os.path.join(WORK, "log.calibrate"), env)
    end, steps = re.search(r"End at t = ([0-9.e+-]+): (\d+) steps", log).groups()
    dt = (float(end) - 1.2) / int(steps)
    for name in os.listdir(case):  # start the soak from the ramp's end state, at t = 1.2
        if re.fullmatch(r"[0-9.e+-]+", name) and float(name) > 1.2:
            shutil.rmtree(os.path.join(case, name))
    start, endTime = 1.2, 1.2 + args.steps * dt
    with open(os.path.join(case, "system/timeIntegration"), "a") as f:
        f.write("fixedDeltaT %.17g;\n" % dt)
    set_entry(controlDict, "endTime", "%.17g" % endTime)
    set_entry(controlDict, "writeInterval", "%.17g" % ((endTime - start) / 100))
    set_entry(controlDict, "writeCsv", "yes")
    set_entry(controlDict, "executeInterval", "%.17g" % ((endTime - start) / 100))
    print("soak: %d steps of dt = %.4g s from t = %g to %.4g, %d threads" % (args.steps, dt, start, endTime, args.threads), flush=True)
    run(case, os.path.join(WORK, "log.soak"), env)


def analyse(args):
    case = os.path.join(WORK, "case")
    start = 1.2
    with open(os.path.join(WORK, "log.soak")) as f:
        log = f.read()
    took = int(re.search(r"End at t = ([0-9.e+-]+): (\d+) steps", log).group(2))
    endTime = float(re.search(r"End at t = ([0-9.e+-]+):", log).group(1))
    wall = float(re.search(r"Wall time ([0-9.]+) s", log).group(1))
    dt = (endTime - start) / took

    series = []
    times = sorted((float(name), name) for name in os.listdir(case)
                   if re.fullmatch(r"[0-9.e+-]+", name) and float(name) >= start - 1e-9 and os.path.exists(os.path.join(case, name, "fluid.csv")))
    walls = read_csv(os.path.join(case, times[0][1], "walls.csv"))
    surface = np.stack([walls["x"][walls["layer"] == 0], walls["y"][walls["layer"] == 0]], axis=1)
    for t, name in times:
        fluid = read_csv(os.path.join(case, name, "fluid.csv"))
        m, rho = fluid["mass"], fluid["density"]
        points = np.stack([fluid["x"], fluid["y"]], axis=1)
        gap = min(np.sqrt(((surface[None, :, :] - points[i:i + 512, None, :]) ** 2).sum(axis=2)).min() for i in range(0, len(points), 512))
        kinetic = 0.5 * (m * (fluid["velocity_x"] ** 2 + fluid["velocity_y"] ** 2)).sum()
        potential = (m * GRAVITY * fluid["y"]).sum()
        series.append((t, m.sum(), (m / rho).sum(), kinetic, potential, gap))
    errors = {}
    with open(os.path.join(case, "postProcessing/pressure/1.2/error.dat")) as f:
        for line in f:
            if not line.startswith("#"):
                t, l2, _ = map(float, line.split())
                errors[t] = l2
    s = np.array(series)
    scale = s[0, 1] * GRAVITY * DEPTH  # M g H
    half = len(s) // 2
    # The error series is written to 9 digits: match each state to the nearest sample.
    samples = np.array(sorted(errors.items()))
    l2 = np.array([samples[np.abs(samples[:, 0] - t).argmin(), 1] for t in s[:, 0]])
    rows = [
        ("steps taken", "%d (dt = %.4g s, %.4g s simulated)" % (took, dt, endTime - start)),
        ("wall time", "%.0f s, %.3g particle-steps/s" % (wall, took * len(m) / wall)),
        ("total mass: largest relative change", "%.2e" % np.abs(s[:, 1] / s[0, 1] - 1).max()),
        ("total volume sum(m/rho): largest relative change", "%.2e" % np.abs(s[:, 2] / s[0, 2] - 1).max()),
        ("kinetic energy / (M g H): largest, last", "%.2e, %.2e" % (s[:, 3].max() / scale, s[-1, 3] / scale)),
        ("(kinetic + potential) energy change / (M g H): largest, last", "%.2e, %.2e" % (
            np.abs(s[:, 3] + s[:, 4] - s[0, 3] - s[0, 4]).max() / scale, (s[-1, 3] + s[-1, 4] - s[0, 3] - s[0, 4]) / scale)),
        ("smallest fluid-wall gap / dx: first half, second half", "%.3f, %.3f" % (s[:half, 5].min() / args.spacing, s[half:, 5].min() / args.spacing)),
        ("pressure L2 error / (rho g H): mean of first half, second half", "%.4f, %.4f" % (np.nanmean(l2[:half]), np.nanmean(l2[half:]))),
    ]
    report = "| quantity | value |\n|---|---|\n" + "".join("| %s | %s |\n" % row for row in rows)
    print(report)
    with open(os.path.join(WORK, "report.md"), "w") as f:
        f.write("Soak test: hydrostatic tank, dx = %g, %d threads\n\n" % (args.spacing, args.threads) + report)
    with open(os.path.join(WORK, "series.csv"), "w") as f:
        f.write("t,mass,volume,kinetic,potential,gap,pressureL2\n")
        for row, e in zip(series, l2):
            f.write(",".join("%.12g" % v for v in row) + ",%.6g\n" % e)


if __name__ == "__main__":
    main()
