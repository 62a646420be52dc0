#!/usr/bin/python3
"""Compares the sampled velocity profiles of poiseuille2D with the series solution of
Morris, Fox & Zhu (1997):
  u(y,t) = F/(2 nu) y (L - y) - sum_n 4 F L^2/(nu pi^3 (2n+1)^3) sin((2n+1) pi y/L) exp(-(2n+1)^2 pi^2 nu t/L^2)
Writes poiseuilleError.csv (L2 and max |u - u_exact| over u_max at every sampled time) and
poiseuilleProfiles.png."""
import csv
import glob
import math
import os
import sys

L, NU, F = 1e-3, 1e-6, 2e-4
UMAX = F * L * L / (8 * NU)


def exact(y, t):
    u = F / (2 * NU) * y * (L - y)
    for n in range(200):
        k = 2 * n + 1
        u -= 4 * F * L * L / (NU * math.pi ** 3 * k ** 3) * math.sin(k * math.pi * y / L) * math.exp(-k * k * math.pi ** 2 * NU * t / (L * L))
    return u


base = sorted(glob.glob("postProcessing/profile/*"))[0]
times = sorted((d for d in os.listdir(base) if os.path.isdir(os.path.join(base, d))), key=float)
profiles, errors = {}, []
for name in times:
    t = float(name)
    rows = list(csv.DictReader(open(os.path.join(base, name, "line.csv"))))
    y = [float(r["y"]) for r in rows]
    u = [float(r["Ux"]) for r in rows]
    diff = [abs(a - exact(b, t)) / UMAX for a, b in zip(u, y)]
    errors.append((t, math.sqrt(sum(d * d for d in diff) / len(diff)), max(diff)))
    profiles[t] = (y, u)
with open("poiseuilleError.csv", "w") as f:
    f.write("t,L2_over_umax,max_over_umax\n")
    for e in errors:
        f.write("%g,%.4g,%.4g\n" % e)
for t, l2, mx in errors:
    if t in (0.0225, 0.045, 0.1125) or t == errors[-1][0]:
        print("t = %-7g L2 |u - u_exact| / u_max = %.4f, max %.4f" % (t, l2, mx))
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("comparePoiseuille.py: matplotlib not found (apt-get install python3-matplotlib)")
fig, ax = plt.subplots(figsize=(6, 5))
fine = [L * k / 200 for k in range(201)]
for t in (0.0225, 0.045, 0.1125, errors[-1][0]):
    if t not in profiles:
        continue
    line, = ax.plot([u / UMAX for u in profiles[t][1]], [y / L for y in profiles[t][0]], "o", ms=4, label="sphkit t = %g s" % t)
    ax.plot([exact(y, t) / UMAX for y in fine], [y / L for y in fine], "-", color=line.get_color())
ax.set_xlabel("u / u_max")
ax.set_ylabel("y / L")
ax.set_title("Poiseuille flow (Morris et al. 1997): dots sphkit, lines series")
ax.legend(fontsize=8)
ax.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig("poiseuilleProfiles.png", dpi=120)
