#!/usr/bin/python3
"""Compares the free-surface elevation of sloshingTank2D (and its variants) with the
experiment of Faltinsen et al. (2000), Fig. 7: the probe 0.05 m from the left wall, in the
moving tank's frame.

For each written time (fluid.csv) the elevation is where the kernel-interpolated fluid volume
fraction sum_k V_k W(|x - x_k|) falls through 1/2 along the vertical through the probe (one
splashed particle does not read as the level); eta = that height - 0.6 m. Writes
sloshingError.txt (RMS and max |eta - eta_exp| over the experiment's samples, per case) and
sloshingComparison.png into the first case given.
Usage: compareSloshing.py [case ...]
"""
import csv
import glob
import math
import os
import sys

import numpy as np

DX, DEPTH, PROBE = 0.02, 0.6, 0.05
AMPLITUDE, PERIOD = 0.032, 1.3
H = 1.3 * DX  # the case's Wendland C2 smoothing length
HERE = os.path.dirname(os.path.abspath(__file__))


def wendland(r):
    q = np.minimum(r / H, 2.0)
    return 7.0 / (4.0 * math.pi * H * H) * (1.0 - q / 2.0) ** 4 * (2.0 * q + 1.0)


def elevation(x, y, t):
    probe = PROBE + AMPLITUDE * (math.cos(2.0 * math.pi * t / PERIOD) - 1.0)  # the tank frame moves
    near = np.abs(x - probe) < 2.0 * H
    heights = np.arange(0.0, 1.2, 0.002)
    fraction = [np.sum(DX * DX * wendland(np.hypot(x[near] - probe, y[near] - z))) for z in heights]
    wet = [z for z, f in zip(heights, fraction) if f >= 0.5]
    return (max(wet) if wet else 0.0) - DEPTH


def read_case(case):
    rows = []
    for directory in glob.glob(os.path.join(case, "[0-9]*")):
        path = os.path.join(directory, "fluid.csv")
        if not os.path.exists(path):
            continue
        with open(path) as f:
            points = [(float(r["x"]), float(r["y"])) for r in csv.DictReader(f)]
        t = float(os.path.basename(directory))
        x, y = np.array([p[0] for p in points]), np.array([p[1] for p in points])
        rows.append((t, elevation(x, y, t)))
    if not rows:
        sys.exit("compareSloshing.py: no %s/<time>/fluid.csv; run the solver first" % case)
    return sorted(rows)


def read_experiment():
    with open(os.path.join(HERE, "faltinsen2000Fig7.csv")) as f:
        rows = [line.split(",") for line in f if line[0].isdigit()]
    return sorted((float(t), float(eta)) for t, eta in rows)


def main():
    cases = sys.argv[1:] or [HERE]
    experiment = read_experiment()
    lines = ["# case, RMS and max |eta - eta_exp| [m] over the experiment's samples, the most fluid particles behind the wall at any step"]
    curves = {}
    for case in cases:
        series = read_case(case)
        times, etas = [t for t, _ in series], [e for _, e in series]
        errors = [np.interp(t, times, etas) - e for t, e in experiment if t <= times[-1]]
        leaks = [int(line.split()[1]) for name in glob.glob(os.path.join(case, "postProcessing", "leaks", "*", "penetrations.dat"))
                 for line in open(name) if not line.startswith("#")]
        name = os.path.basename(os.path.abspath(case))
        curves[name] = (times, etas)
        lines.append("%s %.4f %.4f %d" % (name, math.sqrt(sum(e * e for e in errors) / len(errors)), max(abs(e) for e in errors),
                                         max(leaks) if leaks else 0))
    with open(os.path.join(cases[0], "sloshingError.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axis = plt.subplots(figsize=(9, 4))
    axis.plot([t for t, _ in experiment], [e for _, e in experiment], "ko", ms=3, label="Faltinsen et al. 2000 (experiment)")
    for name, (times, etas) in curves.items():
        axis.plot(times, etas, lw=0.8, label=name)
    axis.set_xlabel("t [s]")
    axis.set_ylabel("eta [m], 0.05 m from the left wall")
    axis.legend(fontsize=7)
    figure.tight_layout()
    figure.savefig(os.path.join(cases[0], "sloshingComparison.png"), dpi=120)


main()
