#!/usr/bin/python3
"""weakScalingModel: the predicted weak-scaling efficiency of `wcsph -parallel` to 1000 ranks and
beyond (issue 23), from what was measured on 1-8 ranks of the 2-core machine. A rank owns N
particles in a cube (square) of side L = N^(1/D) dx, inside the domain (neighbours on every side);
per step it spends, against c N for the serial step of its particles:

    work      I c N (1 + kappa h)         h = ((L + 2w)^D - L^D) / L^D halo copies per owned
                                          particle, w = 1.2 r_c (the models' reach r_c plus the
                                          skin); kappa: what a copy costs against an owned particle;
                                          I: the slowest rank's work over the mean
    waits     omega c N                   at the two exchanges of an evaluation, where one rank's
                                          stage before it took longer than the other's
    builds    g N (1 + h) / 10            a halo build (migration, serial order, lists) every 10 steps
    refreshes X (m alpha + h N b / B)     X exchanges per evaluation (one evaluation per step),
                                          m = 3^D - 1 neighbours, b bytes per copy, B bandwidth
    agreement 2 alpha ceil(log2 P)        the one max-reduction per step
    E(P) = c N / (the sum)

Measured here (doc/performance.md, "Several ranks: weak scaling"; the benchmark dam breaks of
utilities/benchmark, 1 thread per rank, serial and on 2 ranks, medians of 3 runs, 2026-12-04):
c, kappa, omega, g and I from the time per part of the logs, b and the halo share from
decompositionReport (the formula is an interior rank's; the measured ranks border walls or the
domain's edge on some sides). Assumed, as the design study did (a network, not this machine's
shared memory): alpha = 2 us, B = 10 GB/s.

    weakScalingModel.py                 the table of doc/performance.md
    weakScalingModel.py --markdown      the same as a Markdown table
"""
import argparse
import math

# Measured on this machine (see the module's docstring); the doc's section gives the runs.
MEASURED = {
    # r_c / dx (Wendland C2 at h = 1.4142 dx; cubic spline at h = 1.732 dx), c [s per particle-
    # step], kappa, omega, g [s per held particle and build], I, b [bytes per copy per
    # evaluation], X (exchanges per evaluation: dummy-particle walls' state and the rates in 2D,
    # the fluid's and the dynamic-boundary walls' rates in 3D)
    2: dict(rc_over_dx=2 * 1.4142, c=1.95e-7, kappa=0.90, omega=0.065, g=1.26e-7, imbalance=1.006, bytes_per_copy=23.5, exchanges=2),
    3: dict(rc_over_dx=2 * 1.732, c=1.48e-6, kappa=0.21, omega=0.011, g=1.18e-7, imbalance=1.034, bytes_per_copy=30.0, exchanges=2),
}
ASSUMED = dict(latency=2e-6, bandwidth=10e9)
SKIN = 0.2  # kernel supports past the reach (DistributedSystem::skinPerSupport)


def halo_share(dimension, particles_per_rank, rc_over_dx):
    """Copies per owned particle of an interior box of side L = N^(1/D) dx (lengths in dx)."""
    side = particles_per_rank ** (1.0 / dimension)
    width = (1.0 + SKIN) * rc_over_dx
    return ((side + 2 * width) ** dimension - side ** dimension) / side ** dimension


def step_times(dimension, particles_per_rank, ranks, measured=None, assumed=None):
    """The parts of one step on one rank [s], and the serial step of its particles."""
    m = dict(MEASURED[dimension], **(measured or {}))
    a = dict(ASSUMED, **(assumed or {}))
    n = particles_per_rank
    h = halo_share(dimension, n, m["rc_over_dx"])
    serial = m["c"] * n
    parts = {
        "work": m["imbalance"] * serial * (1 + m["kappa"] * h),
        "waits": m["omega"] * serial,
        "builds": m["g"] * n * (1 + h) / 10,
        "refreshes": m["exchanges"] * ((3 ** dimension - 1) * a["latency"] + h * n * m["bytes_per_copy"] / a["bandwidth"]),
        "agreement": 2 * a["latency"] * math.ceil(math.log2(ranks)) if ranks > 1 else 0.0,
    }
    return serial, h, parts


def efficiency(dimension, particles_per_rank, ranks, **changes):
    serial, _, parts = step_times(dimension, particles_per_rank, ranks, **changes)
    return serial / sum(parts.values())


def table(markdown):
    rows = []
    for dimension in (2, 3):
        for n in (1e5, 1e6):
            for ranks in (8, 1000):
                serial, h, parts = step_times(dimension, n, ranks)
                rows.append((f"{dimension}D", f"{n:.0e}", ranks, f"{100 * h:.1f} %", f"{1e3 * serial:.1f}",
                             f"{1e3 * parts['work']:.1f}", f"{1e3 * parts['waits']:.2f}", f"{1e3 * parts['builds']:.2f}",
                             f"{1e3 * parts['refreshes']:.3f}", f"{1e6 * parts['agreement']:.0f}", f"{100 * serial / sum(parts.values()):.0f} %"))
    header = ("D", "particles per rank", "ranks", "halo copies / owned", "serial step of them [ms]", "work [ms]", "waits [ms]",
              "halo builds [ms]", "halo refreshes [ms]", "agreement [us]", "efficiency")
    if markdown:
        lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
        lines += ["| " + " | ".join(str(v) for v in row) + " |" for row in rows]
    else:
        lines = ["  ".join(f"{h:>12}" for h in header)] + ["  ".join(f"{str(v):>12}" for v in row) for row in rows]
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--markdown", action="store_true", help="print the table as Markdown (as doc/performance.md holds it)")
    print(table(parser.parse_args().markdown))


if __name__ == "__main__":
    main()
