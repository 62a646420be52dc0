#!/usr/bin/python3
"""Compares the flux through the square array of cylinders of cylinderArray2D (and its variants)
with Sangani & Acrivos (1982), Table 1: at a solid fraction Phi = 0.2 the drag per unit length of
a cylinder over mu and the superficial velocity, K = F / (mu (1 - Phi) U), is 51.53 (their
multipole series, converged; Int. J. Multiphase Flow 8 (1982) 193-206). Here F = rho g L^2
(the body force on the fluid of one cell, which stands for the mean pressure gradient rho g),
and U is the mean velocity in the fluid, the fluid's x momentum over its mass (fieldTotals).

Reads <case>/postProcessing/totals/<t0>/totals.dat for each case directory given (default: this
one), averages U over t = 1-2 s (steady from about 0.2 s; the average takes out the acoustic
ripple) and prints, per case, U, K = g L^2 / (nu (1 - Phi) U), its error against 51.53, and the
most fluid particles behind the wall at any step.
Usage: compareFlux.py [case ...]
"""
import glob
import os
import sys

L, PHI, G, NU = 0.1, 0.2, 0.4, 0.01  # as system/ and constant/ give them
K_SANGANI_ACRIVOS = 51.53
WINDOW = (1.0, 2.0)
HERE = os.path.dirname(os.path.abspath(__file__))


def rows(case, name, pattern):
    files = sorted(glob.glob(os.path.join(case, "postProcessing", name, "*", pattern)))
    return [list(map(float, line.split())) for path in files for line in open(path) if not line.startswith("#")]


def main():
    cases = sys.argv[1:] or [HERE]
    exact = G * L * L / (NU * (1.0 - PHI) * K_SANGANI_ACRIVOS)
    print(f"Sangani & Acrivos (1982), Phi = {PHI}: K = {K_SANGANI_ACRIVOS}, mean velocity in the fluid {exact:.4e} m/s")
    for case in cases:
        totals = rows(case, "totals", "totals.dat")
        if not totals:
            sys.exit(f"compareFlux.py: no {case}/postProcessing/totals/*/totals.dat; run the solver first")
        inside = [momentum / mass for t, mass, _, momentum, *_ in totals if WINDOW[0] <= t <= WINDOW[1]]
        if not inside:
            sys.exit(f"compareFlux.py: {case} did not reach t = {WINDOW[0]} s")
        mean = sum(inside) / len(inside)
        k = G * L * L / (NU * (1.0 - PHI) * mean)
        behind = max((int(r[1]) for r in rows(case, "leaks", "penetrations.dat")), default=0)
        name = os.path.basename(os.path.abspath(case))
        print(f"{name} U {mean:.4e} m/s K {k:.2f} error {100.0 * (k / K_SANGANI_ACRIVOS - 1.0):+.1f} % behind the wall {behind}")


if __name__ == "__main__":
    main()
