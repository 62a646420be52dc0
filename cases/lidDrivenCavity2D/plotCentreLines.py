#!/usr/bin/python3
"""Plots the cavity's centre-line velocities at the last sampled time against Ghia, Ghia & Shin
(1982): u along x = 0.5 (postProcessing/uCentreLine) and v along y = 0.5 (vCentreLine), for
the Reynolds number given as the argument (default 100). Writes centreLines.png."""
import csv
import glob
import os
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

RE = sys.argv[1] if len(sys.argv) > 1 else "100"


def last_profile(name):
    base = glob.glob("postProcessing/%s/0" % name)[0]
    latest = max((d for d in os.listdir(base) if os.path.isdir(os.path.join(base, d))), key=float)
    return latest, list(csv.DictReader(open(os.path.join(base, latest, "line.csv"))))


def ghia(name):
    with open(name) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


t, u = last_profile("uCentreLine")
_, v = last_profile("vCentreLine")
fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.5))
left.plot([float(r["u_Re" + RE]) for r in ghia("ghia1982U.csv")], [float(r["y"]) for r in ghia("ghia1982U.csv")], "ks", label="Ghia et al. 1982")
left.plot([float(r["Ux"]) for r in u], [float(r["y"]) for r in u], "-", label="sphkit t = %s" % t)
left.set(xlabel="u / U at x = 0.5", ylabel="y / L", title="Re %s: u on the vertical centre line" % RE)
left.legend()
right.plot([float(r["x"]) for r in ghia("ghia1982V.csv")], [float(r["v_Re" + RE]) for r in ghia("ghia1982V.csv")], "ks", label="Ghia et al. 1982")
right.plot([float(r["x"]) for r in v], [float(r["Uy"]) for r in v], "-", label="sphkit t = %s" % t)
right.set(xlabel="x / L", ylabel="v / U at y = 0.5", title="Re %s: v on the horizontal centre line" % RE)
right.legend()
fig.tight_layout()
fig.savefig("centreLines.png", dpi=100)
print("wrote centreLines.png (Re %s, t = %s)" % (RE, t))
