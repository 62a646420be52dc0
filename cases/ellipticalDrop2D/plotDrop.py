#!/usr/bin/python3
"""Plots the elliptical drop against Monaghan's (1994) ODE: the outermost particle along y
(postProcessing/majorAxis) against the semi-major axis b (ellipticalDropMonaghan1994.csv), and
the velocity error norms over time (postProcessing/velocityError). Writes ellipticalDrop.png."""
import csv
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def rows(name):
    with open(name) as f:
        return [list(map(float, line.split())) for line in f if not line.startswith("#")]


with open("ellipticalDropMonaghan1994.csv") as f:
    reference = list(csv.DictReader(line for line in f if not line.startswith("#")))
front = rows("postProcessing/majorAxis/0/surgeFront.dat")
error = rows("postProcessing/velocityError/0/error.dat")
fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
left.plot([float(r["t"]) for r in reference], [float(r["b_major"]) for r in reference], "k-", label="ODE semi-major axis b")
left.plot([r[0] for r in front], [r[1] for r in front], "o", ms=4, label="sphkit outermost particle")
left.set(xlabel="t [s]", ylabel="y [m]", title="major axis")
left.legend()
for column, label, marker in ((1, "L1", "o-"), (2, "L2", "s-"), (3, "Linf", "^-")):
    right.plot([r[0] for r in error], [r[column] for r in error], marker, label=label)
right.set(xlabel="t [s]", ylabel="|u - u_exact| / (A0 R0)", title="velocity error")
right.legend()
fig.tight_layout()
fig.savefig("ellipticalDrop.png", dpi=100)
print("at t = %g: outermost particle y = %.4f, velocity error L1 %.3e, Linf %.3e of A0 R0" % (front[-1][0], front[-1][1], error[-1][1], error[-1][3]))
