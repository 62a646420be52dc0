#!/usr/bin/python3
"""Pressure noise and penetrations of steepBulge2D and its variants. For each written time
(fluid.csv, t > 0), over the fluid near the bulge (|x - x_c| < 1.5 w) and within 2h of the
moving floor y_s(x, t) = A sin(2 pi t / T) exp(-(x - x_c)^2 / w^2): the RMS of each particle's
pressure about the mean of its neighbours within 2.5 dx (noise, not the dynamic pressure),
averaged over the written times [Pa]; and the most fluid particles behind the wall at any step
(wallPenetrations). The bulge (x_c, A, w, T), dx and h are read from each case's dictionaries.
Writes bulgeComparison.csv into the first case given and prints one row per case.
Usage: compareBulge.py [case ...]
"""
import csv
import glob
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def numbers(case, path, pattern):
    with open(os.path.join(case, path)) as f:
        found = re.search(pattern, f.read())
    if not found:
        sys.exit("compareBulge.py: '%s' not found in %s/%s" % (pattern, case, path))
    return [float(v) for v in found.groups()]


def compare(case):
    value = r"([0-9.eE+-]+)"
    centre, amplitude, width, period = numbers(case, "constant/boundaryProperties",
                                               r"centre \(%s \S+\); amplitude %s; width %s; period %s;" % (value, value, value, value))
    dx, = numbers(case, "system/generateParticlesDict", r"spacing\s+%s;" % value)
    hdx, = numbers(case, "system/sphSchemes", r"hdx\s+%s;" % value)
    reach, radius = 2.0 * hdx * dx, 2.5 * dx
    noise = []
    for state in glob.glob(os.path.join(case, "[0-9]*", "fluid.csv")):
        t = float(os.path.basename(os.path.dirname(state)))
        if t == 0:
            continue
        with open(state) as f:
            fluid = [(float(r["x"]), float(r["y"]), float(r["pressure"])) for r in csv.DictReader(f)]
        lift = amplitude * math.sin(2.0 * math.pi * t / period)
        near = [p for p in fluid if abs(p[0] - centre) < 1.5 * width and p[1] < lift * math.exp(-((p[0] - centre) / width) ** 2) + reach]
        deviations = []
        for a in near:
            around = [b[2] for b in fluid if (a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2 < radius ** 2]
            deviations.append(a[2] - sum(around) / len(around))
        if deviations:
            noise.append(math.sqrt(sum(d * d for d in deviations) / len(deviations)))
    if not noise:
        sys.exit("compareBulge.py: no %s/<time>/fluid.csv after t = 0; run the solver first" % case)
    leaks = [int(line.split()[1]) for name in glob.glob(os.path.join(case, "postProcessing", "leaks", "*", "penetrations.dat"))
             for line in open(name) if not line.startswith("#")]
    return os.path.basename(os.path.abspath(case)), sum(noise) / len(noise), max(leaks) if leaks else 0


def main():
    cases = sys.argv[1:] or [HERE]
    rows = [compare(case) for case in cases]
    with open(os.path.join(cases[0], "bulgeComparison.csv"), "w") as f:
        f.write("case,pressure_noise_Pa,penetrations\n" + "".join("%s,%.1f,%d\n" % row for row in rows))
    print("# case, pressure noise [Pa], the most fluid particles behind the wall at any step")
    for row in rows:
        print("%s %.1f %d" % row)


main()
