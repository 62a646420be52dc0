#!/usr/bin/python3
"""Linear modal theory of the sloshing tank, and the gauges of runs against it.

A 2D rectangular tank of breadth L holding water of depth h is forced in surge,
x_T(t) = A (cos(omega t) - 1), from rest. In the tank's frame, with x from the left wall,
linear potential flow gives the elevation as a sum of the antisymmetric natural modes
(Faltinsen & Timokha, Sloshing, 2009, ch. 5; derived again here):

    eta(x, t) = sum over odd n of a_n(t) cos(k_n x),  k_n = n pi / L,
    omega_n^2 = g k_n tanh(k_n h),
    a_n'' + omega_n^2 a_n = -(omega_n^2 / g) c_n x_T''(t),  c_n = -4 L / (n pi)^2,

c_n being the n-th cosine coefficient of x on [0, L] (the fictitious force's potential x_T'' x
projected on the modes). From rest, with x_T'' = -A omega^2 cos(omega t):

    a_n(t) = (omega_n^2 c_n A omega^2 / g) (cos(omega t) - cos(omega_n t)) / (omega_n^2 - omega^2).

No damping: the free modes started at t = 0 beat with the forced response for ever; a run's
viscosity damps them, so the comparison is for the first periods. The theory holds while the
elevation is small against the depth and the wave length (here k_1 eta < 0.05).

    linearSloshing.py --write FILE [--amplitude A] [--end T]   the theory's series at the probe, CSV
    linearSloshing.py CASE ...                                  each run's gauge against it

A run's elevation is its gauge's depth less the depth it read at t = 0 (the still level of the
particle lattice, which differs from h by a fraction of dx). Writes linearSloshingError.txt
(RMS and max |eta - eta_linear| over the run, both over the theory's largest |eta|, and the
run's own first natural period) and linearSloshing.png into the first case. The natural period
is fitted: the least-squares fit of eta = a cos(omega t) + b sin(omega t) + e^(-zeta omega_1 t)
(c cos(omega_1 t) + d sin(omega_1 t)) + m (the forced response and the damped first free mode)
over omega_1 within 20 % of the theory's and zeta in [0, 0.1]; on the theory's own series it
returns the theory's period to 0.001 s.
"""
import argparse
import glob
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compareSloshing  # noqa: E402  (the gauge's reader, beside this script)

G = 9.81
BREADTH = 1.72      # the tank as sloshingTank2D generates it (86 dx at dx = 0.02)
DEPTH = 0.6
PERIOD = 1.3        # the forcing of Faltinsen et al. (2000), off the first mode (1.661 s)
PROBE = 0.05        # from the left wall
AMPLITUDE = 0.004   # linear: the largest elevation 0.020 m, k_1 eta = 0.037
MODES = 199         # odd modes to n = 199: the sum's tail is below 1e-6 of its value


def modes():
    """(k_n, omega_n^2, c_n) of the odd modes."""
    for n in range(1, MODES + 1, 2):
        k = n * math.pi / BREADTH
        yield k, G * k * math.tanh(k * DEPTH), -4.0 * BREADTH / (n * math.pi) ** 2


def elevation(t, amplitude=AMPLITUDE, x=PROBE):
    omega = 2.0 * math.pi / PERIOD
    eta = 0.0
    for k, omega_n2, c_n in modes():
        forcing = omega_n2 * c_n * amplitude * omega ** 2 / G
        eta += forcing * (math.cos(omega * t) - math.cos(math.sqrt(omega_n2) * t)) / (omega_n2 - omega ** 2) * math.cos(k * x)
    return eta


def read_gauge(case):
    """The run's elevation about the level its gauge read at t = 0."""
    series = compareSloshing.read_case(case)
    still = series[0][1]
    return [(t, eta - still) for t, eta in series]


def fitted_natural_period(series):
    """The first natural period of a run's elevation series, fitted as the module's doc says."""
    t = np.array([row[0] for row in series])
    eta = np.array([row[1] for row in series])
    omega = 2.0 * math.pi / PERIOD
    omega_1 = math.sqrt(next(modes())[1])
    best = (math.inf, omega_1)
    for candidate in np.linspace(0.8 * omega_1, 1.2 * omega_1, 161):
        for zeta in np.linspace(0.0, 0.1, 21):
            decay = np.exp(-zeta * candidate * t)
            basis = np.column_stack([np.cos(omega * t), np.sin(omega * t), decay * np.cos(candidate * t), decay * np.sin(candidate * t),
                                     np.ones_like(t)])
            coefficients = np.linalg.lstsq(basis, eta, rcond=None)[0]
            residual = float(np.sum((basis @ coefficients - eta) ** 2))
            if residual < best[0]:
                best = (residual, candidate)
    return 2.0 * math.pi / best[1]


def amplitude_of(case):
    """The surge amplitude the case's boundaryProperties give the tank."""
    with open(os.path.join(case, "constant", "boundaryProperties")) as f:
        text = f.read()
    start = text.index("amplitude (") + len("amplitude (")
    return float(text[start:].split()[0])


def compare(cases):
    lines = ["# case, RMS and max |eta - eta_linear| [m] over the run, the same over the theory's largest |eta|, the run's fitted "
             "first natural period [s] (linear theory: %.3f), the most fluid particles behind the wall at any step"
             % (2.0 * math.pi / math.sqrt(next(modes())[1]))]
    curves = {}
    for case in cases:
        amplitude = amplitude_of(case)
        series = read_gauge(case)
        theory = [elevation(t, amplitude) for t, _ in series]
        errors = [eta - linear for (_, eta), linear in zip(series, theory)]
        scale = max(abs(v) for v in theory)
        rms = math.sqrt(sum(e * e for e in errors) / len(errors))
        worst = max(abs(e) for e in errors)
        leaks = [int(line.split()[1]) for name in glob.glob(os.path.join(case, "postProcessing", "leaks", "*", "penetrations.dat"))
                 for line in open(name) if not line.startswith("#")]
        name = os.path.basename(os.path.abspath(case))
        curves[name] = series
        lines.append("%s %.5f %.5f %.3f %.3f %.3f %d" % (name, rms, worst, rms / scale, worst / scale, fitted_natural_period(series),
                                                       max(leaks) if leaks else 0))
    with open(os.path.join(cases[0], "linearSloshingError.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    end = max(series[-1][0] for series in curves.values())
    times = [end * i / 2000 for i in range(2001)]
    fig, ax = plt.subplots(figsize=(9, 4))
    ax.plot(times, [elevation(t, amplitude_of(cases[0])) for t in times], "k-", lw=2, label="linear modal theory")
    for name, series in curves.items():
        ax.plot([t for t, _ in series], [e for _, e in series], lw=1, label=name)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("eta at x = %g m [m]" % PROBE)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(cases[0], "linearSloshing.png"), dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("cases", nargs="*")
    parser.add_argument("--write", metavar="FILE")
    parser.add_argument("--amplitude", type=float, default=AMPLITUDE)
    parser.add_argument("--end", type=float, default=10.0)
    args = parser.parse_args()
    if args.write:
        with open(args.write, "w") as f:
            f.write("# Linear modal theory (linearSloshing.py): tank %g m broad, %g m deep, surge A (cos(2 pi t / %g) - 1), "
                    "A = %g m, elevation %g m from the left wall\nt_s,eta_m\n" % (BREADTH, DEPTH, PERIOD, args.amplitude, PROBE))
            steps = int(round(args.end / 0.01))
            for i in range(steps + 1):
                t = i * 0.01
                f.write("%.2f,%.6e\n" % (t, elevation(t, args.amplitude)))
    if args.cases:
        compare(args.cases)
    if not args.write and not args.cases:
        parser.error("give --write FILE or a case")


if __name__ == "__main__":
    main()
