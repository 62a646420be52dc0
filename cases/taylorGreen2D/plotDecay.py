#!/usr/bin/python3
"""Plots the Taylor-Green run against the exact solution: the velocity error norms over time
(postProcessing/velocityError/0/error.dat) and the kinetic energy against
KE0 exp(-16 pi^2 nu t / L^2) (postProcessing/totals/0/totals.dat). Writes taylorGreenDecay.png.
Also prints the decay rate fitted to ln KE over the run, against the exact 16 pi^2 nu / L^2.
    plotDecay.py [CASE]     the case directory, . by default"""
import math
import os
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

NU, L = 0.01, 1.0

CASE = sys.argv[1] if len(sys.argv) > 1 else "."


def rows(name):
    with open(os.path.join(CASE, name)) as f:
        return [list(map(float, line.split())) for line in f if not line.startswith("#")]

error = rows("postProcessing/velocityError/0/error.dat")
totals = rows("postProcessing/totals/0/totals.dat")
t = [r[0] for r in totals]
energy = [r[2] / totals[0][2] for r in totals]
exact = [math.exp(-16 * math.pi ** 2 * NU * s / L ** 2) for s in t]
fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
left.plot([r[0] for r in error], [r[1] for r in error], "o-", label="L1")
left.plot([r[0] for r in error], [r[2] for r in error], "s-", label="L2")
left.plot([r[0] for r in error], [r[3] for r in error], "^-", label="Linf")
left.set(xlabel="t [s]", ylabel="|u - u_exact| / U", title="velocity error")
left.legend()
right.plot(t, exact, "k-", label="exact")
right.plot(t, energy, "o", label="sphkit")
right.set(xlabel="t [s]", ylabel="KE / KE0", title="kinetic energy")
right.legend()
fig.tight_layout()
fig.savefig(os.path.join(CASE, "taylorGreenDecay.png"), dpi=100)
worst = max(abs(e - x) for e, x in zip(energy, exact))
print("at t = %g: velocity error L1 %.3e, L2 %.3e, Linf %.3e (of U); KE/KE0 %.5f (exact %.5f); largest KE deviation %.2e"
      % (error[-1][0], error[-1][1], error[-1][2], error[-1][3], energy[-1], exact[-1], worst))
rate = -np.polyfit(t, np.log(energy), 1)[0]
exactRate = 16 * math.pi ** 2 * NU / L ** 2
print("decay rate over t = %g to %g: %.4f, exact %.4f (%+.2f %%)" % (t[0], t[-1], rate, exactRate, 100 * (rate / exactRate - 1)))
