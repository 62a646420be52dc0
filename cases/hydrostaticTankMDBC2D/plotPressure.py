#!/usr/bin/python3
"""Plots the pressure along the tank's centre line at the last sampled time against
rho0 g (H - z), and the normalised L2 error over time, from postProcessing/pressure/; prints
the gap between the floor and the fluid's lowest row (each column's lowest particle, mean over
the columns, in dx; 0.5 where the fluid fills the lattice down to the wall) and the most fluid
particles behind the wall at any step."""
import csv
import glob
import os
import sys

directories = glob.glob("postProcessing/pressure/*")
if not directories:
    sys.exit("plotPressure.py: no postProcessing/pressure/; run the solver first")
base = sorted(directories, key=lambda d: float(os.path.basename(d)))[-1]
times = sorted((d for d in os.listdir(base) if os.path.isdir(os.path.join(base, d))), key=float)
with open(os.path.join(base, times[-1], "line.csv")) as f:
    header = f.readline().strip().split(",")
    rows = [dict(zip(header, map(float, line.split(",")))) for line in f]
with open(os.path.join(base, "error.dat")) as f:
    errors = [tuple(map(float, line.split())) for line in f if not line.startswith("#")]
print("hydrostatic pressure error at t = %g: L2 %.3e, max %.3e (normalised by rho0 g H)" % errors[-1])
dx = 0.02
last = max((d for d in glob.glob("[0-9]*") if os.path.exists(os.path.join(d, "fluid.csv"))), key=lambda d: float(d))
lowest = {}
with open(os.path.join(last, "fluid.csv")) as f:
    for row in csv.DictReader(f):
        column = int(float(row["x"]) // dx)
        lowest[column] = min(lowest.get(column, float(row["y"])), float(row["y"]))
inner = [y for column, y in lowest.items() if 5 <= column < 95]  # away from the side walls' corners
penetrations = max(int(line.split()[1]) for name in glob.glob("postProcessing/leaks/*/penetrations.dat")
                   for line in open(name) if not line.startswith("#"))
print("floor gap at t = %s: %.3f dx (mean of the lowest particle of each column, x = 0.1-1.9); penetrations %d"
      % (last, sum(inner) / len(inner) / dx, penetrations))
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("plotPressure.py: matplotlib not found (apt-get install python3-matplotlib)")
fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
left.plot([r["p"] for r in rows], [r["y"] for r in rows], "o", ms=3, label="sphkit t = %s" % times[-1])
left.plot([r["p_ref"] for r in rows], [r["y"] for r in rows], "-", label=r"$\rho_0 g (H - z)$")
left.set_xlabel("p [Pa]")
left.set_ylabel("z [m]")
left.legend()
left.grid(True, alpha=0.3)
right.semilogy([e[0] for e in errors[1:]], [e[1] for e in errors[1:]], "o-", label="L2")
right.semilogy([e[0] for e in errors[1:]], [e[2] for e in errors[1:]], "s-", label="max")
right.set_xlabel("t [s]")
right.set_ylabel(r"error / $\rho_0 g H$")
right.legend()
right.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig("pressureProfile.png", dpi=120)
