#!/usr/bin/python3
"""Plots a uniform-pressure tank's acceleration field before and after the deficiency
correction, and the normalised correction C_j per boundary particle index (Jones, Yang &
McCue-Weil 2010, Figs. 7 and 8). Run in a case directory after `wcsph -rates`; writes
correctionByIndex.csv and tankCorrection.png, and prints the residual near the walls."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import tankRates  # noqa: E402

INFLUENCE_RADIUS = float(sys.argv[1]) if len(sys.argv) > 1 else 0.5

fluid, walls = tankRates.read_rates(".")
surface = [w for w in walls if w.get("layer", 0) == 0]
surface.sort(key=lambda w: w["id"])
largest = max(abs(w["correctionCoefficient"]) for w in surface) or 1.0
with open("correctionByIndex.csv", "w") as f:
    f.write("index,x,y,C,C_normalised\n")
    for k, w in enumerate(surface):
        f.write("%d,%.6g,%.6g,%.6g,%.6g\n" % (k, w["x"], w["y"], w["correctionCoefficient"], abs(w["correctionCoefficient"]) / largest))

near = tankRates.near_wall(fluid, walls, INFLUENCE_RADIUS)
before = [math.hypot(*tankRates.uncorrected(p)) for p, _, _ in near]
after = [math.hypot(*tankRates.residual(p)) for p, _, _ in near]
print("fluid within r_inf of the wall: %d particles; RMS |a| %.4g before, %.4g after the correction (ratio %.3f); max %.4g before, %.4g after"
      % (len(near), tankRates.rms(before), tankRates.rms(after), tankRates.rms(after) / tankRates.rms(before), max(before), max(after)))

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("plotTankCorrection.py: matplotlib not found (apt-get install python3-matplotlib)")
fig = plt.figure(figsize=(13, 8))
scale = max(before)
for position, (title, field) in enumerate((("before correction", tankRates.uncorrected), ("after correction", tankRates.residual))):
    ax = fig.add_subplot(2, 2, position + 1)
    ax.plot([w["x"] for w in surface], [w["y"] for w in surface], "k.", ms=3)
    vectors = [field(p) for p in fluid]
    ax.quiver([p["x"] for p in fluid], [p["y"] for p in fluid], [v[0] for v in vectors], [v[1] for v in vectors],
              [math.hypot(*v) for v in vectors], angles="xy", scale_units="xy", scale=scale / 0.2, width=0.002, cmap="viridis",
              clim=(0, scale))
    ax.set_aspect("equal")
    ax.set_title("acceleration %s (max %.3g)" % (title, max(math.hypot(*v) for v in vectors)))
ax = fig.add_subplot(2, 1, 2)
ax.plot(range(len(surface)), [abs(w["correctionCoefficient"]) / largest for w in surface], "b.-", ms=3)
ax.set_xlabel("boundary particle index")
ax.set_ylabel("|C_j| / max |C_j|")
ax.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig("tankCorrection.png", dpi=110)
