#!/usr/bin/python3
"""Plots the pressure along the tank's centre line at the last sampled time against
rho0 g (H - z), and the normalised L2 error over time, from postProcessing/pressure/."""
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
