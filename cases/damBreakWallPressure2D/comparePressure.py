#!/usr/bin/python3
"""Compares the downstream-wall pressure of damBreakWallPressure2D (and its variants) with the
delta-SPH curves of De Courcy et al. (2024) at sensors P1-P4, with Buchner's (2002) experiment
at y = 0.2 H (sensor B; the jax-sph digitisation, and the PySPH one in a block of its own) and
with Lobovsky et al.'s (2014) experiment at P1, P3 and P4 (a third block).

Reads <case>/postProcessing/sensors/<t0>/p.dat (the probes dx/2 in front of the wall) for each
case directory given (default: this one), or with --wall the wallPressure sensors on the wall
(postProcessing/wallSensors/<t0>/pressure.dat, their raw signal), normalises as the reference (T = t sqrt(g/H), P = p/(rho g H)), averages both over
windows of Delta T = 0.1 from T = 2 to 7 (the raw impact peaks are acoustic and resolution
dependent; the references are digitised and step back in time, so they are sorted first; a
window without a digitised point is left out) and writes pressureError.txt (RMS of the
window-mean difference per sensor, and the most fluid particles behind the wall at any step) and pressureComparison.png into the first case given.
Usage: comparePressure.py [--wall] [case ...]
"""
import glob
import math
import os
import sys

H, G, RHO = 0.6, 9.81, 1000.0
# Sensor name and reference file, in the order of the probes' columns.
SENSORS = (("P1", "deCourcy2024P1.csv"), ("P2", "deCourcy2024P2.csv"), ("P3", "deCourcy2024P3.csv"), ("P4", "deCourcy2024P4.csv"),
           ("B", "buchner2002JaxSPH.csv"))
SECOND_DIGITISATION = "buchner2002PySPH.csv"  # of sensor B
# Lobovsky et al.'s (2014) experiment: the same dam break at H = 0.3 m, its sensors 1, 3 and 4 at
# this case's P1, P3 and P4 (in units of H).
EXPERIMENT = (("P1", "lobovsky2014Sensor1.csv"), ("P3", "lobovsky2014Sensor3.csv"), ("P4", "lobovsky2014Sensor4.csv"))
WINDOWS = [(2.0 + 0.1 * k, 2.1 + 0.1 * k) for k in range(50)]
HERE = os.path.dirname(os.path.abspath(__file__))


def read_reference(name):
    with open(os.path.join(HERE, name)) as f:
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
    return [t * math.sqrt(G / H) for t, *_ in rows], [[r[1 + k] / (RHO * G * H) for r in rows] for k in range(len(SENSORS))]


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


def means_of(rows):
    return window_means([t for t, _ in rows], [p for _, p in rows])


def rms_against(times, values, reference_means):
    means = window_means(times, values)
    pairs = [(m, r) for m, r in zip(means, reference_means) if m is not None and r is not None]
    return math.sqrt(sum((m - r) ** 2 for m, r in pairs) / len(pairs))


def main():
    wall = "--wall" in sys.argv
    cases = [a for a in sys.argv[1:] if a != "--wall"] or [HERE]
    references = {name: read_reference(source) for name, source in SENSORS}
    second = read_reference(SECOND_DIGITISATION)
    reference_means = {name: means_of(rows) for name, rows in references.items()}
    second_means = means_of(second)
    lines = ["# case, RMS of the Delta T = 0.1 window means against De Courcy et al. (2024) at P1 P2 P3 P4 and Buchner (2002, "
             "jax-sph's digitisation) at B, most fluid particles behind the wall at any step"]
    lines_second = ["# case, the same at B against PySPH's digitisation of Buchner (2002)"]
    experiment = {name: read_reference(source) for name, source in EXPERIMENT}
    experiment_means = {name: means_of(rows) for name, rows in experiment.items()}
    lines_experiment = ["# case, the same at P1 P3 P4 against Lobovsky et al.'s (2014) experiment (the median of its repeated runs)"]
    column = {name: k for k, (name, _) in enumerate(SENSORS)}
    curves = {}
    for case in cases:
        times, values = read_sensors(case, wall)
        errors = [rms_against(times, values[k], reference_means[name]) for k, (name, _) in enumerate(SENSORS)]
        name = os.path.basename(os.path.abspath(case))
        curves[name] = (times, values)
        lines.append("%s %s %d" % (name, " ".join("%.3f" % e for e in errors), most_behind_wall(case)))
        lines_second.append("%s %.3f" % (name, rms_against(times, values[column["B"]], second_means)))
        lines_experiment.append("%s %s" % (name, " ".join("%.3f" % rms_against(times, values[column[sensor]], experiment_means[sensor])
                                                          for sensor, _ in EXPERIMENT)))
    lines += lines_second + lines_experiment
    with open(os.path.join(cases[0], "wallPressureError.txt" if wall else "pressureError.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    figure, axes = plt.subplots(len(SENSORS), 1, figsize=(8, 12), sharex=True)
    for k, (sensor, _) in enumerate(SENSORS):
        rows = references[sensor]
        if sensor == "B":  # an experiment digitised as scatter: points
            axes[k].plot([t for t, _ in rows], [p for _, p in rows], "k.", ms=3, label="Buchner 2002 (jax-sph digitisation)")
            axes[k].plot([t for t, _ in second], [p for _, p in second], "kx", ms=3, label="Buchner 2002 (PySPH digitisation)")
        else:
            axes[k].plot([t for t, _ in rows], [p for _, p in rows], "k-", lw=0.8, label="De Courcy et al. 2024")
            if sensor in experiment:
                measured = experiment[sensor]
                axes[k].plot([t for t, _ in measured], [p for _, p in measured], "k:", lw=0.8, label="Lobovsky et al. 2014 (experiment)")
        for name, (times, values) in curves.items():
            axes[k].plot(times, values[k], lw=0.6, label=name)
        axes[k].set_ylabel("%s: p / (rho g H)" % sensor)
        axes[k].set_xlim(2, 8)
        axes[k].set_ylim(-0.5, 3)
    axes[0].legend(fontsize=7)
    axes[-1].legend(fontsize=7)
    axes[-1].set_xlabel("t sqrt(g / H)")
    figure.tight_layout()
    figure.savefig(os.path.join(cases[0], "wallPressureComparison.png" if wall else "pressureComparison.png"), dpi=120)


main()
