#!/usr/bin/python3
"""Colours each point on the fluid side by the weights of the three wall particles (blue,
green, red), for the concave and the convex wall: weightBlending.png (paper Fig. 6)."""
import csv
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("plotWeights.py: matplotlib not found (apt-get install python3-matplotlib)")
fig, axes = plt.subplots(1, 2, figsize=(12, 5))
for ax, name in zip(axes, ("concave", "convex")):
    rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(name + ".csv"))]
    colours = [(r["wn_2"], r["wn_1"], r["wn_0"]) for r in rows]
    ax.scatter([r["x"] for r in rows], [r["y"] for r in rows], c=colours, s=4, marker="s", linewidths=0)
    ax.set_aspect("equal")
    ax.set_title("%s wall: R = 1, spacing 0.25, r_inf = 0.775" % name)
    middle = [r for r in rows if abs(r["x"]) < 1e-9]
    print("%s: %d points; on the middle particle's normal, its weight runs from %.3f to %.3f" %
          (name, len(rows), min(r["wn_1"] for r in middle), max(r["wn_1"] for r in middle)))
fig.tight_layout()
fig.savefig("weightBlending.png", dpi=110)
