#!/usr/bin/python3
"""Compares the deforming-floor tank run with the deficiency correction (this case) and with
virtual particles (variants/virtualParticles), over time, near the bulge (|x - 1| < 0.3,
within 2h = 0.052 of the moving floor):
- pressure noise: RMS of p - rho0 g (H - y) - its mean, over those particles [Pa];
- clumping: the smallest nearest-neighbour distance among them, over dx, and the fraction
  closer than 0.75 dx;
- penetrations: fluid particles below the floor y_s(x, t) = 0.1 sin(pi t) exp(-(x - 1)^2/0.04).
Writes variantComparison.csv and variantComparison.png."""
import csv
import glob
import math
import os
import sys

DX, RHO, G, DEPTH, REACH = 0.02, 1000.0, 9.81, 0.6, 0.052


def floor(x, t):
    return 0.1 * math.sin(math.pi * t) * math.exp(-((x - 1.0) ** 2) / 0.04)


def measures(case):
    rows = []
    for directory in sorted(glob.glob(os.path.join(case, "[0-9]*")), key=lambda d: float(os.path.basename(d))):
        t = float(os.path.basename(directory))
        path = os.path.join(directory, "fluid.csv")
        if t == 0 or not os.path.exists(path):
            continue
        with open(path) as f:
            fluid = [(float(r["x"]), float(r["y"]), float(r["pressure"])) for r in csv.DictReader(f)]
        near = [p for p in fluid if abs(p[0] - 1.0) < 0.3 and p[1] < floor(p[0], t) + REACH]
        around = [p for p in fluid if abs(p[0] - 1.0) < 0.3 + DX * 2 and p[1] < floor(p[0], t) + REACH + 2 * DX]
        deviation = [p[2] - RHO * G * (DEPTH - p[1]) for p in near]
        mean = sum(deviation) / len(deviation)
        noise = math.sqrt(sum((d - mean) ** 2 for d in deviation) / len(deviation))
        nearest = []
        for a in near:
            nearest.append(min(math.hypot(a[0] - b[0], a[1] - b[1]) for b in around if b is not a) / DX)
        penetrations = sum(1 for p in fluid if p[1] < floor(p[0], t) - 1e-9 and 0.0 < p[0] < 2.0)
        rows.append((t, noise, min(nearest), sum(1 for d in nearest if d < 0.75) / len(nearest), penetrations))
    return rows


variants = [("deficiencyCorrection", "."), ("virtualParticles", "variants/virtualParticles")]
results = {name: measures(path) for name, path in variants}
with open("variantComparison.csv", "w") as f:
    f.write("variant,t,pressure_noise_Pa,min_neighbour_over_dx,fraction_below_0.75dx,penetrations\n")
    for name, rows in results.items():
        for row in rows:
            f.write("%s,%g,%.4g,%.4g,%.4g,%d\n" % ((name,) + row))
for name, rows in results.items():
    if rows:
        print("%-22s mean pressure noise %.1f Pa (rho g dx = %.0f Pa), smallest neighbour distance %.2f dx, mean fraction below 0.75 dx %.3f, "
              "max penetrations %d" % (name, sum(r[1] for r in rows) / len(rows), RHO * G * DX, min(r[2] for r in rows),
                                       sum(r[3] for r in rows) / len(rows), max(r[4] for r in rows)))
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("compareVariants.py: matplotlib not found (apt-get install python3-matplotlib)")
fig, axes = plt.subplots(1, 3, figsize=(14, 4))
for name, rows in results.items():
    t = [r[0] for r in rows]
    axes[0].plot(t, [r[1] for r in rows], label=name)
    axes[1].plot(t, [r[2] for r in rows], label=name)
    axes[2].plot(t, [r[4] for r in rows], label=name)
axes[0].set_ylabel("pressure noise near the bulge [Pa]")
axes[1].set_ylabel("smallest neighbour distance / dx")
axes[2].set_ylabel("penetrations")
for ax in axes:
    ax.set_xlabel("t [s] (convex to t = 1, concave after)")
    ax.grid(True, alpha=0.3)
    ax.legend()
fig.tight_layout()
fig.savefig("variantComparison.png", dpi=110)
