#!/usr/bin/python3
"""Throughput benchmark: runs a benchmark case with wcsph at 1 and 2 threads (and, with
--scaling, at other particle counts) and prints particles, steps, wall time, particle-steps per
second and peak memory (also per particle: the difference between the largest and the smallest
run over their particle counts), as a Markdown table. The time loop is timed by the solver
itself, without start-up; the case writes only at its end time, and that write (the solver's
"output" part) is left out of the rate.

Usage: utilities/benchmark/benchmark.py [--case damBreak2D] [--threads 1 2] [--scaling]
                                         [--factors 2 1 0.5] [--end-time T] [--repeat N] [--busy]
(from the repository root; binaries from $SPHKIT_BIN or build/bin; work in build/benchmark/).
Cases: utilities/benchmark/<case>/: damBreak2D (DualSPHysics' standard 2D dam break, 20,000
fluid particles, 0.25 s) and damBreak3D (DualSPHysics' CaseDambreak, 47,600 fluid + 22,440
wall particles, 0.1 s). --factors scales the spacing (0.5: 4x the particles in 2D, 8x in 3D);
box extents are rounded to whole spacings. --end-time shortens the run (for the large ones).
--repeat runs each configuration N times, the thread counts taking turns so that a slow spell of
a shared machine falls on all of them, and reports the median time loop with the fastest and
the slowest. Every run sets its thread count with wcsph -threads, so the solver's own rule (one
thread per 3,000 particles, 800 in 3D) does not apply; the last column divides each time by the 1-thread
time of the same case. --busy runs everything beside a busy process pinned on the last core, as
a shared machine has one: the last column is then the slowdown that the solver's threads suffer
from waiting for one another there (the target of doc/performance.md: 1.3 at most).
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.environ.get("SPHKIT_BIN", os.path.join(ROOT, "build", "bin"))
WORK = os.path.join(ROOT, "build", "benchmark")


def prepare(case, spacing_factor):
    directory = os.path.join(WORK, "%s-x%g" % (case, spacing_factor))
    shutil.rmtree(directory, ignore_errors=True)
    shutil.copytree(os.path.join(ROOT, "utilities", "benchmark", case), directory)
    generate = os.path.join(directory, "system/generateParticlesDict")
    with open(generate) as f:
        text = f.read()
    spacing = float(re.search(r"(?m)^spacing\s+([0-9.e+-]+);", text).group(1)) * spacing_factor
    text = re.sub(r"(?m)^spacing\s+[0-9.e+-]+;", "spacing     %.10g;" % spacing, text)
    # Boxes need whole numbers of spacings: each max moves to the nearest one from its min.
    def whole(match):
        lo = [float(v) for v in match.group(1).split()]
        hi = [float(v) for v in match.group(2).split()]
        hi = [a + max(1, round((b - a) / spacing)) * spacing for a, b in zip(lo, hi)]
        return "min (%s); max (%s);" % (match.group(1), " ".join("%.10g" % v for v in hi))
    regions = re.search(r"(?m)^fluid\b", text).start()  # the domain, before, keeps its bounds
    text = text[:regions] + re.sub(r"min \(([^)]*)\); max \(([^)]*)\);", whole, text[regions:])
    with open(generate, "w") as f:
        f.write(text)
    subprocess.run([os.path.join(BIN, "generateParticles"), "-case", directory], check=True, stdout=subprocess.DEVNULL)
    return directory


def run(directory, threads, end_time=None):
    for name in os.listdir(directory):
        if re.fullmatch(r"[0-9.e+-]+", name) and name != "0":
            shutil.rmtree(os.path.join(directory, name))
    if end_time is not None:
        control = os.path.join(directory, "system/controlDict")
        with open(control) as f:
            text = f.read()
        text = re.sub(r"(?m)^endTime\s+[^;]+;", "endTime %g;" % end_time, text)
        text = re.sub(r"(?m)^writeInterval\s+[^;]+;", "writeInterval %g;" % end_time, text)
        with open(control, "w") as f:
            f.write(text)
    log_path = os.path.join(directory, "log.wcsph.%d" % threads)
    with open(log_path, "w") as log:
        process = subprocess.Popen([os.path.join(BIN, "wcsph"), "-case", directory, "-threads", str(threads)], stdout=log,
                                   stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(process.pid, 0)
    with open(log_path) as f:
        log = f.read()
    if status != 0:
        raise SystemExit("benchmark: wcsph failed on %s, see %s" % (directory, log_path))
    steps, fluid, walls = map(int, re.search(r"End at t = [0-9.e+-]+: (\d+) steps, (\d+) fluid \+ (\d+) wall particles", log).groups())
    wall = float(re.search(r"Wall time ([0-9.]+) s", log).group(1))
    output = float(re.search(r"^\s+output\s+([0-9.]+) s", log, re.M).group(1))
    timed = wall - output
    peak = usage.ru_maxrss * 1024  # bytes (Linux reports kB)
    return {"fluid": fluid, "walls": walls, "steps": steps, "wall": timed, "peak": peak}


def start_busy_process():
    """A process that spins on the last core until killed."""
    core = max(os.sched_getaffinity(0))
    return subprocess.Popen([sys.executable, "-c", "import os\nos.sched_setaffinity(0, {%d})\nwhile True: pass" % core])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--case", default="damBreak2D")
    parser.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--scaling", action="store_true", help="also at 4x fewer and 4x more particles (2D: spacing x2, x0.5)")
    parser.add_argument("--factors", type=float, nargs="+", help="spacing factors to run (default 1, or 2 1 0.5 with --scaling)")
    parser.add_argument("--end-time", type=float, help="simulated time of each run (default: the case's endTime)")
    parser.add_argument("--repeat", type=int, default=1, help="runs per configuration; the table gives the median (default 1)")
    parser.add_argument("--busy", action="store_true", help="run beside a busy process pinned on the last core")
    args = parser.parse_args()
    if args.repeat < 1:
        raise SystemExit("benchmark: --repeat must be at least 1, not %d" % args.repeat)
    factors = args.factors or ([2.0, 1.0, 0.5] if args.scaling else [1.0])
    busy = start_busy_process() if args.busy else None
    try:
        peaks = measure(args, factors)
    finally:
        if busy:
            busy.kill()
    if len(peaks) > 1 and max(peaks)[0] > min(peaks)[0]:
        # The peak includes the libraries and buffers any run has: the difference isolates what a particle costs.
        (small, peakSmall), (large, peakLarge) = min(peaks), max(peaks)
        print("\nmemory per particle (largest minus smallest run): %.0f bytes" % ((peakLarge - peakSmall) / (large - small)))


def measure(args, factors):
    """Runs every configuration and prints its row; returns (particles, peak memory) per row."""
    print("| case | fluid + wall particles | threads | steps | time loop [s] | runs [s] | fluid particle-steps/s | all particle-steps/s | peak memory | bytes per particle | time / 1-thread time%s |"
          % (" (busy core)" if args.busy else ""))
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    peaks = []
    for factor in factors:
        directory = prepare(args.case, factor)
        runs = {threads: [] for threads in args.threads}
        for _ in range(args.repeat):
            for threads in args.threads:
                runs[threads].append(run(directory, threads, args.end_time))
        one_thread = statistics.median(r["wall"] for r in runs[1]) if 1 in runs else None
        for threads in args.threads:
            times = sorted(r["wall"] for r in runs[threads])
            median = statistics.median(times)
            peak = max(r["peak"] for r in runs[threads])
            r = runs[threads][0]  # particles and steps are the same in every run
            peaks.append((r["fluid"] + r["walls"], peak))
            print("| %s dx x%g | %d + %d | %d | %d | %.3g | %.3g-%.3g | %.3g | %.3g | %.0f MB | %.0f | %s |" % (
                args.case, factor, r["fluid"], r["walls"], threads, r["steps"], median, times[0], times[-1], r["steps"] * r["fluid"] / median,
                r["steps"] * (r["fluid"] + r["walls"]) / median, peak / 1e6, peak / (r["fluid"] + r["walls"]),
                "%.2f" % (median / one_thread) if one_thread else "-"), flush=True)
    return peaks


if __name__ == "__main__":
    main()
