#!/usr/bin/python3
"""Plots the 1D uniform-pressure fluid's acceleration against position with and without the
deficiency correction (paper Fig. 3), from wcsph -rates; writes deficiency1D.csv and .png."""
import csv
import glob
import re
import sys


def entry(path, pattern):
    """A number from the case's dictionaries, so the title follows the case as it is set."""
    with open(path) as f:
        return float(re.search(pattern, f.read(), re.M).group(1))


# The cubic spline's influence radius is 2h, h = hdx dx.
influence = 2.0 * entry("system/sphSchemes", r"hdx\s+([^;\s]+)") * entry("system/generateParticlesDict", r"^spacing\s+([^;\s]+)")

directory = sorted(glob.glob("postProcessing/rates/*"))[-1]
rows = sorted(csv.DictReader(open(directory + "/fluid.csv")), key=lambda r: float(r["x"]))
x = [float(r["x"]) for r in rows]
before = [float(r["uncorrectedAcceleration_x"]) for r in rows]
after = [float(r["uncorrectedAcceleration_x"]) + float(r["boundaryCorrection_x"]) for r in rows]
with open("deficiency1D.csv", "w") as f:
    f.write("x,a_uncorrected,a_corrected\n")
    for row in zip(x, before, after):
        f.write("%.6g,%.6g,%.6g\n" % row)
print("max |a|: %.4g uncorrected, %.4g corrected; nearest particle: %.3g -> %.3g"
      % (max(map(abs, before)), max(map(abs, after)), before[0], after[0]))
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("plotDeficiency1D.py: matplotlib not found (apt-get install python3-matplotlib)")
fig, ax = plt.subplots(figsize=(8, 4))
ax.plot(x, before, "o-", ms=3, label="uncorrected")
ax.plot(x, after, "s-", ms=3, label="with deficiency correction")
ax.set_xlabel("x")
ax.set_ylabel("acceleration")
ax.set_title("1D fluid at uniform pressure 1, r_inf = %g" % influence)
ax.legend()
ax.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig("deficiency1D.png", dpi=120)
