#!/usr/bin/python3
"""Compares what each run of slopedTank2D leaves of still water at its last time: the pressure
error on the line x = 0.5 against rho0 g (H - z) (postProcessing/pressure), the most fluid
particles ever behind a wall (postProcessing/leaks, counted every step) and the kinetic energy
per unit mass over g H (postProcessing/totals). Writes stillWaterComparison.csv.
Usage: compareStillWater.py CASE [CASE ...]"""
import glob
import os
import sys

G, H = 1.0, 0.4


def last_row(case, name, pattern):
    files = glob.glob(os.path.join(case, "postProcessing", name, "*", pattern))
    if not files:
        sys.exit("compareStillWater.py: no postProcessing/%s/*/%s in %s; run the solver first" % (name, pattern, case))
    with open(sorted(files)[-1]) as f:
        return [float(v) for v in [line for line in f if not line.startswith("#")][-1].split()]


def boundary_model(case):
    with open(os.path.join(case, "constant", "boundaryProperties")) as f:
        return f.read().split("type")[1].split(";")[0].strip()


rows = []
for case in sys.argv[1:]:
    t, l2, linf = last_row(case, "pressure", "error.dat")
    _, behind, most = last_row(case, "leaks", "penetrations.dat")
    totals = last_row(case, "totals", "*.dat")
    kinetic = totals[2] / totals[1] / (G * H)  # time, mass, kinetic energy, momentum...
    rows.append((boundary_model(case), t, l2, linf, int(most), kinetic))
    print("%-38s t = %g: pressure error L2 %.4f, max %.4f (of rho0 g H); most behind a wall %d; kinetic energy %.2e g H"
          % rows[-1])
with open("stillWaterComparison.csv", "w") as f:
    f.write("model,t,pressure_L2,pressure_max,most_behind_wall,kinetic_energy_over_gH\n")
    for row in rows:
        f.write("%s,%g,%.6g,%.6g,%d,%.6g\n" % row)
