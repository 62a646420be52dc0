#!/usr/bin/python3
"""Compares the surge front of damBreak2D with Martin & Moyce (1952).

Reads postProcessing/front/<t0>/surgeFront.dat, normalises it as the experiment
(T = t sqrt(2g/a), Z = x/a), interpolates it at the experimental times and writes
frontComparison.csv, frontError.txt (RMS and max |Z - Z_exp|) and frontComparison.png.
"""
import csv
import glob
import math
import sys

A = 0.05715   # column width [m]
G = 9.81

def read_front():
    files = sorted(glob.glob("postProcessing/front/*/surgeFront.dat"))
    if not files:
        sys.exit("compareFront.py: no postProcessing/front/*/surgeFront.dat; run the solver first")
    rows = []
    for name in files:
        with open(name) as f:
            rows += [tuple(map(float, line.split())) for line in f if not line.startswith("#")]
    rows.sort()
    return [t * math.sqrt(2 * G / A) for t, _ in rows], [x / A for _, x in rows]

def read_experiment():
    with open("martinMoyce1952Front.csv") as f:
        lines = [line for line in f if not line.startswith("#")]
    reader = csv.DictReader(lines)
    return [(float(r["T"]), float(r["Z"])) for r in reader]

def interpolate(x, xs, ys):
    for k in range(1, len(xs)):
        if xs[k] >= x:
            w = (x - xs[k - 1]) / (xs[k] - xs[k - 1])
            return ys[k - 1] + w * (ys[k] - ys[k - 1])
    return None

T, Z = read_front()
rows = []
for t_exp, z_exp in read_experiment():
    z = interpolate(t_exp, T, Z)
    if z is not None:
        rows.append((t_exp, z_exp, z))
if not rows:
    sys.exit("compareFront.py: the run does not reach the first experimental time")
with open("frontComparison.csv", "w") as f:
    f.write("T,Z_experiment,Z_sph\n")
    for r in rows:
        f.write("%g,%g,%.6g\n" % r)
errors = [abs(z - ze) for _, ze, z in rows]
rms = math.sqrt(sum(e * e for e in errors) / len(errors))
summary = ("surge front vs Martin & Moyce (1952), %d points up to T = %.2f: RMS |Z - Z_exp| = %.3f, max = %.3f (Z = x/a)\n"
           % (len(rows), rows[-1][0], rms, max(errors)))
with open("frontError.txt", "w") as f:
    f.write(summary)
print(summary, end="")

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("compareFront.py: matplotlib not found (apt-get install python3-matplotlib); no plot written")
    sys.exit(0)
fig, ax = plt.subplots(figsize=(6, 4))
ax.plot(T, Z, "-", label="sphkit wcsph")
ax.plot([r[0] for r in read_experiment()], [r[1] for r in read_experiment()], "o", label="Martin & Moyce 1952")
ax.set_xlabel(r"$T = t\sqrt{2g/a}$")
ax.set_ylabel(r"$Z = x_{front}/a$")
ax.set_title("Dam break, column a x 2a")
ax.legend()
ax.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig("frontComparison.png", dpi=120)
