#!/usr/bin/python3
"""Plots the cylinder's depth and speed against time with the start of its motion in
potential flow (buoyancy and added mass, no drag): a0 = (s - 1)/(s + 1) g for density ratio
s = 2, the reference for early times. Writes bodyMotion.png and prints the comparison."""
import glob
import sys

G, RATIO, Y0 = 9.81, 2.0, 0.3
rows = []
for name in sorted(glob.glob("postProcessing/cylinder/*/body.dat")):
    rows += [list(map(float, line.split())) for line in open(name) if not line.startswith("#")]
a0 = (RATIO - 1) / (RATIO + 1) * G
for t_check in (0.02, 0.05, 0.1, 0.3):
    row = min(rows, key=lambda r: abs(r[0] - t_check))
    print("t = %.3f: depth travelled %.4f (potential flow %.4f), speed %.3f (potential flow %.3f)"
          % (row[0], Y0 - row[2], 0.5 * a0 * row[0] ** 2, -row[5], a0 * row[0]))
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("plotBody.py: matplotlib not found (apt-get install python3-matplotlib)")
fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
t = [r[0] for r in rows]
left.plot(t, [Y0 - r[2] for r in rows], label="sphkit")
left.plot(t, [0.5 * a0 * x * x for x in t], "--", label="potential flow, no drag")
left.set_ylabel("depth travelled [m]")
right.plot(t, [-r[5] for r in rows], label="sphkit")
right.plot(t, [a0 * x for x in t], "--", label="potential flow, no drag")
right.set_ylabel("sinking speed [m/s]")
for ax in (left, right):
    ax.set_xlabel("t [s]")
    ax.grid(True, alpha=0.3)
    ax.legend()
fig.tight_layout()
fig.savefig("bodyMotion.png", dpi=110)
