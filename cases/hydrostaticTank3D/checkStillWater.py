#!/usr/bin/python3
"""What still water in a 3D tank should show, for hydrostaticTank3D, cylinderTank3D and their
variants, at the last written time: the kinetic energy per unit mass over g H (fieldTotals),
the near-floor pressure error (RMS of p - rho0 g (H - z) over rho0 g H, fluid within 2h of the
floor), the mean floor gap (the lowest particle of each dx x dx column, over dx; 0.5 where the
fluid started) and its spread, the centre-line pressure error (lineSample, L2 over rho0 g H)
and the most fluid particles behind the wall at any step (wallPenetrations). Spacing, depth
(the lineSample's freeSurfaceHeight), smoothing length, rho0 and g are read from the case's
dictionaries. Writes stillWaterComparison.csv into the first case given and prints one row
per case.
Usage: checkStillWater.py [case ...]
"""
import csv
import glob
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def number(case, path, pattern):
    with open(os.path.join(case, path)) as f:
        found = re.search(pattern, f.read())
    if not found:
        sys.exit("checkStillWater.py: '%s' not found in %s/%s" % (pattern, case, path))
    return [float(v) for v in found.groups()]


def last_rows(path):
    with open(path) as f:
        return [[float(v) for v in line.split()] for line in f if not line.startswith("#")]


def check(case):
    dx, = number(case, "system/generateParticlesDict", r"spacing\s+([0-9.eE+-]+);")
    depth, = number(case, "system/controlDict", r"freeSurfaceHeight\s+([0-9.eE+-]+);")
    hdx, = number(case, "system/sphSchemes", r"hdx\s+([0-9.eE+-]+);")
    rho0, = number(case, "constant/fluidProperties", r"rho0\s+([0-9.eE+-]+);")
    g, = number(case, "constant/fluidProperties", r"gravity\s+\(\S+ \S+ -?([0-9.eE+-]+)\);")
    times = [d for d in glob.glob(os.path.join(case, "[0-9]*")) if os.path.exists(os.path.join(d, "fluid.csv"))]
    if not times:
        sys.exit("checkStillWater.py: no %s/<time>/fluid.csv; run the solver first" % case)
    last = max(times, key=lambda d: float(os.path.basename(d)))
    with open(os.path.join(last, "fluid.csv")) as f:
        fluid = [(float(r["x"]), float(r["y"]), float(r["z"]), float(r["pressure"])) for r in csv.DictReader(f)]
    scale = rho0 * g * depth
    near = [(p - rho0 * g * (depth - z)) / scale for _, _, z, p in fluid if z < 2.0 * hdx * dx]
    lowest = {}
    for x, y, z, _ in fluid:
        column = (math.floor(x / dx), math.floor(y / dx))
        lowest[column] = min(lowest.get(column, z), z)
    gap = sum(lowest.values()) / len(lowest)
    spread = math.sqrt(sum((z - gap) ** 2 for z in lowest.values()) / len(lowest))
    totals = last_rows(glob.glob(os.path.join(case, "postProcessing", "totals", "*", "totals.dat"))[0])[-1]
    centre = last_rows(glob.glob(os.path.join(case, "postProcessing", "pressure", "*", "error.dat"))[0])[-1]
    leaks = [int(row[1]) for name in glob.glob(os.path.join(case, "postProcessing", "leaks", "*", "penetrations.dat")) for row in last_rows(name)]
    return (os.path.basename(os.path.abspath(case)), float(os.path.basename(last)), totals[2] / totals[1] / (g * depth),
            math.sqrt(sum(e * e for e in near) / len(near)), gap / dx, spread / dx, centre[1], max(leaks) if leaks else 0)


def main():
    cases = sys.argv[1:] or [HERE]
    header = "case,time,kinetic_over_gH,near_floor_p_rms,floor_gap_over_dx,gap_spread_over_dx,centre_line_L2,penetrations"
    rows = [check(case) for case in cases]
    with open(os.path.join(cases[0], "stillWaterComparison.csv"), "w") as f:
        f.write(header + "\n" + "".join("%s,%g,%.3e,%.4f,%.3f,%.3f,%.4f,%d\n" % row for row in rows))
    print("# " + header.replace(",", " "))
    for row in rows:
        print("%s %g %.3e %.4f %.3f %.3f %.4f %d" % row)


main()
