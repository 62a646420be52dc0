#!/usr/bin/python3
"""Compares the downstream-wall pressure of damBreakWallPressure2D (and its variants) with the
delta-SPH curves of De Courcy et al. (2024) at sensors P1-P4.

Reads <case>/postProcessing/sensors/<t0>/p.dat (the probes dx/2 in front of the wall) for each
case directory given (default: this one), or with --wall the wallPressure sensors on the wall
(postProcessing/wallSensors/<t0>/pressure.dat, their raw signal), normalises as the reference (T = t sqrt(g/H), P = p/(rho g H)), averages both over
windows of Delta T = 0.1 from T = 2 to 7 (the raw impact peaks are acoustic and resolution
dependent; the reference is digitised and steps back in time, so it is sorted first) and
writes pressureError.txt (RMS of the window-mean difference per sensor, and the most fluid
particles behind the wall at any step) and pressureComparison.png into the first case given.
Usage: comparePressure.py [--wall] [case ...]
"""
import glob
import math
import os
import sys

H, G, RHO = 0.6, 9.81, 1000.0
SENSORS = ("P1", "P2", "P3", "P4")
WINDOWS = [(2.0 + 0.1 * k, 2.1 + 0.1 * k) for k in range(50)]
HERE = os.path.dirname(os.path.abspath(__file__))


def read_reference(sensor):
    with open(os.path.join(HERE, "deCourcy2024%s.csv" % sensor)) as f:
        rows = [line.split(",") for line in f if line[0].isdigit() or line[0] == "-"]
    return sorted((float(t), float(p)) for t, p in rows)


def read_sensors(case, wall):
    pattern = os.path.join(case, "postProcessing", *(("wallSensors", "*", "pressure.dat") if wall else ("sensors", "*", "p.dat")))
    files = sorted(glob.glob(pattern))
    if not files:
        sys.exit("comparePressure.py: no %s; run the solver first" % pattern)
    rows = []
    for name in files:
        with open(name) as f:
            rows += [list(map(float, line.split())) for line in f if not line.startswith("#")]
    rows.sort()
    return [t * math.sqrt(G / H) for t, *_ in rows], [[r[1 + k] / (RHO * G * H) for r in rows] for k in range(4)]


def window_means(times, values):
    means = []
    for lo, hi in WINDOWS:
        inside = [v for t, v in zip(times, values) if lo <= t < hi]
        means.append(sum(inside) / len(inside) if inside else None)
    return means


def most_behind_wall(case):
    files = glob.glob(os.path.join(case, "postProcessing", "leaks", "*", "penetrations.dat"))
    counts = [int(line.split()[1]) for name in files for line in open(name) if not line.startswith("#")]
    return max(counts) if counts else 0


def main():
    wall = "--wall" in sys.argv
    cases = [a for a in sys.argv[1:] if a != "--wall"] or [HERE]
    references = {s: read_reference(s) for s in SENSORS}
    reference_means = {s: window_means([t for t, _ in references[s]], [p for _, p in references[s]]) for s in SENSORS}
    lines = ["# case, RMS of the Delta T = 0.1 window means against De Courcy et al. (2024) at P1 P2 P3 P4, most fluid particles behind the wall at any step"]
    curves = {}
    for case in cases:
        times, values = read_sensors(case, wall)
        errors = []
        for k, sensor in enumerate(SENSORS):
            means = window_means(times, values[k])
            pairs = [(m, r) for m, r in zip(means, reference_means[sensor]) if m is not None and r is not None]
            errors.append(math.sqrt(sum((m - r) ** 2 for m, r in pairs) / len(pairs)))
        name = os.path.basename(os.path.abspath(case))
        curves[name] = (times, values)
        lines.append("%s %s %d" % (name, " ".join("%.3f" % e for e in errors), most_behind_wall(case)))
    with open(os.path.join(cases[0], "wallPressureError.txt" if wall else "pressureError.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    figure, axes = plt.subplots(4, 1, figsize=(8, 10), sharex=True)
    for k, sensor in enumerate(SENSORS):
        axes[k].plot([t for t, _ in references[sensor]], [p for _, p in references[sensor]], "k-", lw=0.8, label="De Courcy et al. 2024")
        for name, (times, values) in curves.items():
            axes[k].plot(times, values[k], lw=0.6, label=name)
        axes[k].set_ylabel("%s: p / (rho g H)" % sensor)
        axes[k].set_xlim(2, 8)
        axes[k].set_ylim(-0.5, 3)
    axes[0].legend(fontsize=7)
    axes[-1].set_xlabel("t sqrt(g / H)")
    figure.tight_layout()
    figure.savefig(os.path.join(cases[0], "wallPressureComparison.png" if wall else "pressureComparison.png"), dpi=120)


main()
