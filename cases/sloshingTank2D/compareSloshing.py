#!/usr/bin/python3
"""Compares the free-surface elevation of sloshingTank2D (and its variants) with the
experiment of Faltinsen et al. (2000), Fig. 7: the probe 0.05 m from the left wall, in the
moving tank's frame.

Reads the case's `gauge` (a waveGauge function object at the probe's foot, moving with the
tank: the depth where the kernel-interpolated fluid volume fraction falls through 1/2, so one
splashed particle does not read as the level); eta = depth - 0.6 m. Writes sloshingError.txt
(RMS and max |eta - eta_exp| over the experiment's samples, per case) and
sloshingComparison.png into the first case given. Any spacing: nothing here depends on it.
Usage: compareSloshing.py [case ...]
"""
import glob
import math
import os
import sys

import numpy as np

DEPTH = 0.6
HERE = os.path.dirname(os.path.abspath(__file__))


def read_case(case):
    rows = {}
    for name in sorted(glob.glob(os.path.join(case, "postProcessing", "gauge", "*", "elevation.dat"))):
        with open(name) as f:
            for line in f:
                if not line.startswith("#"):
                    t, depth = (float(v) for v in line.split()[:2])
                    rows[t] = depth - DEPTH  # a restarted run repeats its start time: one row each
    if not rows:
        sys.exit("compareSloshing.py: no %s/postProcessing/gauge/<time>/elevation.dat; run the solver first" % case)
    return sorted(rows.items())


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


if __name__ == "__main__":
    main()
