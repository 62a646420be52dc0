#!/usr/bin/python3
"""Vertical acceleration along the middle of the water column against height, for each kernel
run by Allrun (kernels/<name>/), with the kernel's own shape W(z)/W(0) scaled to the bottom
particle's deficiency (the paper's observation: the deficiency has the kernel's shape).
Writes columnDeficiency.csv and columnDeficiency.png, and prints the correlation."""
import csv
import glob
import math
import os
import sys

G = 1.0


def kernel_shape(name, q):  # W(q h)/W(0), q = r/h
    if name == "cubicSpline":
        return (1 - 1.5 * q * q + 0.75 * q ** 3) if q < 1 else (0.25 * (2 - q) ** 3 if q < 2 else 0.0)
    if name == "quinticSpline":
        f = lambda q: sum(c * max(a - q, 0.0) ** 5 for a, c in ((3, 1), (2, -6), (1, 15)))
        return f(q) / f(0.0)
    s = q / 2
    return max(1 - s, 0.0) ** 4 * (1 + 4 * s)


results = {}
for directory in sorted(glob.glob("kernels/*")):
    name = os.path.basename(directory)
    rows = list(csv.DictReader(open(glob.glob(directory + "/postProcessing/rates/*/fluid.csv")[0])))
    column = sorted((float(r["y"]), float(r["uncorrectedAcceleration_y"]), float(r["uncorrectedAcceleration_y"]) + float(r["boundaryCorrection_y"]))
                    for r in rows if abs(float(r["x"]) - 4.05) < 1e-6)
    hdx = {"quinticSpline": 10.0 / 3.0}.get(name, 5.0)
    h = hdx * 0.1
    reach = (3 if name == "quinticSpline" else 2) * h
    bottom = column[0][1]
    near = [(y, a, c) for y, a, c in column if y < reach]
    shape = [bottom * kernel_shape(name, (y - column[0][0]) / h) for y, _, _ in near]
    mean_a = sum(a for _, a, _ in near) / len(near)
    mean_s = sum(shape) / len(shape)
    cov = sum((a - mean_a) * (s - mean_s) for (_, a, _), s in zip(near, shape))
    corr = cov / math.sqrt(sum((a - mean_a) ** 2 for _, a, _ in near) * sum((s - mean_s) ** 2 for s in shape))
    results[name] = (column, near, shape, corr)
    print("%-14s bottom deficiency %.4f g, correlation with the kernel's shape %.3f; after correction max |a| %.4f g over z < r_inf"
          % (name, bottom / G, corr, max(abs(c) for _, _, c in near) / G))
with open("columnDeficiency.csv", "w") as f:
    f.write("kernel,z,a_uncorrected,a_corrected\n")
    for name, (column, _, _, _) in results.items():
        for y, a, c in column:
            f.write("%s,%.4g,%.6g,%.6g\n" % (name, y, a, c))
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("plotColumn.py: matplotlib not found (apt-get install python3-matplotlib)")
fig, ax = plt.subplots(figsize=(7, 5))
for name, (column, near, shape, corr) in results.items():
    line, = ax.plot([a for _, a, _ in column], [y for y, _, _ in column], "o", ms=3, label="%s (uncorrected)" % name)
    ax.plot(shape, [y for y, _, _ in near], "-", color=line.get_color(), label="%s kernel shape, r = %.3f" % (name, corr))
ax.set_xlabel("vertical acceleration a_z / g")
ax.set_ylabel("height z")
ax.set_ylim(0, 2)
ax.legend(fontsize=8)
ax.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig("columnDeficiency.png", dpi=120)
