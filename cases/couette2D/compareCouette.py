#!/usr/bin/python3
"""Plots the sampled velocity profiles of couette2D (postProcessing/profile) against the series
solution of Morris, Fox & Zhu (1997) for the impulsively started upper plate:
  u(y,t) = V0 y/L + sum_n 2 V0/(n pi) (-1)^n sin(n pi y/L) exp(-n^2 pi^2 nu t/L^2)
and writes couetteProfiles.png. The error norms over every particle are the run's own
(postProcessing/velocityError/0/error.dat)."""
import csv
import glob
import math
import os
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

L, NU, V0 = 1e-3, 1e-6, 2.5e-5


def exact(y, t):
    return V0 * y / L + sum(2 * V0 / (n * math.pi) * (-1) ** n * math.sin(n * math.pi * y / L) * math.exp(-n * n * math.pi ** 2 * NU * t / L ** 2)
                            for n in range(1, 400))


base = sorted(glob.glob("postProcessing/profile/*"))[0]
fig, ax = plt.subplots(figsize=(6, 5))
fine = [L * k / 200 for k in range(201)]
for name in ("0.0225", "0.045", "0.1125", "0.225"):
    rows = list(csv.DictReader(open(os.path.join(base, name, "line.csv"))))
    t = float(name)
    line, = ax.plot([float(r["Ux"]) / V0 for r in rows], [float(r["y"]) / L for r in rows], "o", ms=4, label="sphkit t = %g s" % t)
    ax.plot([exact(y, t) / V0 for y in fine], [y / L for y in fine], "-", color=line.get_color())
ax.set(xlabel="u / V0", ylabel="y / L", title="Couette start-up (Morris et al. 1997): dots sphkit, lines series")
ax.legend(fontsize=8)
ax.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig("couetteProfiles.png", dpi=120)
with open("postProcessing/velocityError/0/error.dat") as f:
    for line in f:
        if not line.startswith("#"):
            t, l1, l2, linf = map(float, line.split())
            if t in (0.0225, 0.1125, 0.225):
                print("t = %-7g |u - u_exact| / V0 over the particles: L1 %.2e, L2 %.2e, Linf %.2e" % (t, l1, l2, linf))
