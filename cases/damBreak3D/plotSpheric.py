#!/usr/bin/python3
"""Plots damBreak3D against the SPHERIC Test 2 measurements (Kleefsman et al. 2005): the water
heights at the four gauges (postProcessing/heights, sphericTest2Heights.csv), and the pressure at
P1-P4 on the box's impact face and P5-P8 on its top (sphericTest2Pressures.csv, the impact
window only), as the fluid probes (postProcessing/boxPressure, P1-P4) and the wall sensors
(postProcessing/boxSensors, P1-P8: raw, and averaged over its timeWindow) read it. Writes
sphericTest2.png."""
import csv
import re
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def rows(name):
    with open(name) as f:
        return [list(map(float, line.split())) for line in f if not line.startswith("#")]


def measured(name):
    with open(name) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def spacing():
    """The case's one parameter, dx, from system/caseParameters."""
    with open("system/caseParameters") as f:
        return float(re.search(r"^dx\s+([^;\s]+)\s*;", f.read(), re.M).group(1))


heights = rows("postProcessing/heights/0/height.dat")
pressure = rows("postProcessing/boxPressure/0/p.dat")
sensors = rows("postProcessing/boxSensors/0/pressure.dat")
gauges = measured("sphericTest2Heights.csv")
probes = measured("sphericTest2Pressures.csv")
end = heights[-1][0]
fig, axes = plt.subplots(3, 4, figsize=(16, 10))
for k, (column, title) in enumerate((("H_x0.496_fileH3", "H at x = 0.496"), ("H2_x0.992", "H2, x = 0.992"), ("H_x1.488_fileH1", "H at x = 1.488"),
                                     ("H4_x2.638", "H4, x = 2.638"))):
    ax = axes[0][k]
    ax.plot([float(r["t_s"]) for r in gauges if float(r["t_s"]) <= end], [float(r[column]) for r in gauges if float(r["t_s"]) <= end], "k-",
            label="experiment")
    ax.plot([r[0] for r in heights], [r[k + 1] for r in heights], "-", label="sphkit")
    ax.set(title=title, xlabel="t [s]", ylabel="height [m]")
    ax.legend(fontsize=8)
for k in range(8):
    ax = axes[1 + k // 4][k % 4]
    ax.plot([float(r["t_s"]) for r in probes], [float(r["P%d_Pa" % (k + 1)]) for r in probes], "k-", label="experiment")
    if k < 4:
        ax.plot([r[0] for r in pressure if 0.3 <= r[0] <= 0.65], [r[k + 1] for r in pressure if 0.3 <= r[0] <= 0.65], "-", color="C0", label="sphkit, fluid probe")
    window = [r for r in sensors if 0.3 <= r[0] <= 0.65]
    ax.plot([r[0] for r in window], [r[k + 1] for r in window], "-", color="C1", lw=0.6, label="sphkit, wall sensor")
    ax.plot([r[0] for r in window], [r[k + 9] for r in window], "-", color="C2", label="sphkit, wall sensor, averaged")
    ax.set(title="P%d" % (k + 1), xlabel="t [s]", ylabel="p [Pa]")
    ax.legend(fontsize=8)
fig.suptitle("SPHERIC Test 2 (Kleefsman et al. 2005): sphkit dx = %g m against the measurements" % spacing())
fig.tight_layout()
fig.savefig("sphericTest2.png", dpi=90)
peak = [max(r[k + 1] for r in pressure if 0.35 <= r[0] <= 0.65) for k in range(4)]
peak_measured = [max(float(r["P%d_Pa" % (k + 1)]) for r in probes) for k in range(8)]
print("impact peak pressure P1-P4 [Pa]: sphkit %s, experiment %s" % (" ".join("%.0f" % p for p in peak), " ".join("%.0f" % p for p in peak_measured[:4])))
for label, first in (("wall sensors", 1), ("wall sensors averaged", 9)):
    peak_sensors = [max(r[first + k] for r in sensors if 0.35 <= r[0] <= 0.65) for k in range(8)]
    print("impact peak pressure P1-P8 [Pa], %s: sphkit %s, experiment %s" % (label, " ".join("%.0f" % p for p in peak_sensors),
                                                                            " ".join("%.0f" % p for p in peak_measured)))
