#!/usr/bin/python3
"""Throughput benchmark: runs a benchmark case with wcsph at 1 and 2 threads (and, with
--scaling, at other particle counts) and prints particles, steps, wall time, particle-steps per
second and peak memory (also per particle: the difference between the largest and the smallest
run over their particle counts), as a Markdown table. The time loop is timed by the solver
itself, without start-up; the case writes only at its end time, and that write (the solver's
"output" part) is left out of the rate.

Usage: utilities/benchmark/benchmark.py [--case damBreak2D] [--boundary MODEL] [--threads 1 2] [--ranks 2] [--scaling]
                                         [--factors 2 1 0.5] [--end-time T] [--repeat N] [--busy]
                                         [--roofline [--peak-gflops G] [--bandwidth B]] [--work DIR]
                                         [--dualsphysics DIR --dualsphysics-case XML]
(from the repository root; binaries from $SPHKIT_BIN or build/bin; work in build/benchmark/ or --work).
Cases: utilities/benchmark/<case>/: damBreak2D (DualSPHysics' standard 2D dam break, 20,000
fluid particles, 0.25 s) and damBreak3D (DualSPHysics' CaseDambreak, 47,600 fluid + 22,440
wall particles, 0.1 s). --boundary puts every wall patch on another model (its name in
constant/boundaryProperties; the patches laid out as it asks: one layer on the wall for a wall-force
model such as deficiencyCorrectionBoundaryIntegral). --factors scales the spacing (0.5: 4x the particles in 2D, 8x in 3D);
box extents are rounded to whole spacings. --end-time shortens the run (for the large ones).
--repeat runs each configuration N times, the thread counts taking turns so that a slow spell of
a shared machine falls on all of them, and reports the median time loop with the fastest and
the slowest. Every run sets its thread count with wcsph -threads, so the solver's own rule (one
thread per 3,000 particles, 800 in 3D) does not apply; the last column divides each time by the 1-thread
time of the same case, and gives the efficiency of a run on several threads or ranks against it
(the 1-thread time over the thread or rank count times the run's). --ranks adds runs of
`mpirun -np N --bind-to core wcsph -parallel -threads 1` (builds with MPI; where N passes the
cores, --oversubscribe --bind-to none), taking turns with the others; their peak memory is the
largest rank's. --busy runs everything beside a busy process pinned on the last core, as
a shared machine has one: the last column is then the slowdown that the solver's threads suffer
from waiting for one another there (the target of doc/performance.md: 1.3 at most).
--roofline adds, for each case's median 1-thread run, where its stages sit under the roofline of
one core (roofline.py: the model, and the roofs measured or given by --peak-gflops, --bandwidth).
--dualsphysics DIR --dualsphysics-case XML adds, for each thread count, runs of DualSPHysics' CPU
solver on the same thread count, taking turns with sphkit's: DIR holds DualSPHysics' GenCase and
DualSPHysics*CPU* executables, XML is DualSPHysics' definition of the same case at the same spacing
(CaseDambreak_Def.xml of its examples/main/01_DamBreak for damBreak3D), which GenCase turns into its
case once; the solver runs it to the same end time, writing no particle files (-sv:none). A table
after the first compares the whole processes' wall times (start-up included for both, as nothing
else is timed the same way in both) and gives sphkit's time over DualSPHysics'. Never needed by the
tests, which run a stand-in.
"""
import argparse
import glob
import os
import re
import shutil
import statistics
import subprocess
import sys
import time

import numpy as np

import roofline

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.environ.get("SPHKIT_BIN", os.path.join(ROOT, "build", "bin"))
MPIEXEC = os.environ.get("MPIEXEC", "mpirun")
WORK = os.path.join(ROOT, "build", "benchmark")


def prepare(case, spacing_factor, work, boundary=None):
    directory = os.path.join(work, "%s-x%g%s" % (case, spacing_factor, "-" + boundary if boundary else ""))
    shutil.rmtree(directory, ignore_errors=True)
    shutil.copytree(os.path.join(ROOT, "utilities", "benchmark", case), directory)
    generate = os.path.join(directory, "system/generateParticlesDict")
    with open(generate) as f:
        text = f.read()
    if boundary:  # every patch on the model, laid out as it asks (the patches' `layers` left out)
        properties = os.path.join(directory, "constant/boundaryProperties")
        with open(properties) as f:
            models = f.read()
        with open(properties, "w") as f:
            f.write(re.sub(r"type\s+\w+;", "type %s;" % boundary, models))
        boundaries = re.search(r"(?m)^boundaries\b", text).start()
        text = text[:boundaries] + re.sub(r"\s*layers\s+\d+;", "", text[boundaries:])
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


def run(directory, threads, end_time=None, ranks=None):
    """One run of wcsph on `threads` threads, or on `ranks` MPI ranks of one thread each: its
    particles, steps, time loop, peak memory, stages and what the roofline reads."""
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
    command = [os.path.join(BIN, "wcsph"), "-case", directory, "-threads", str(threads)]
    environment = None
    if ranks:
        placement = ["--oversubscribe", "--bind-to", "none"] if ranks > len(os.sched_getaffinity(0)) else ["--bind-to", "core"]
        command = [MPIEXEC, "-np", str(ranks), *placement, command[0], "-parallel", *command[1:]]
        environment = dict(os.environ, OMP_NUM_THREADS="1")
        if os.geteuid() == 0:  # OpenMPI refuses root unless told
            environment.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    log_path = os.path.join(directory, "log.wcsph.%s" % ("%dranks" % ranks if ranks else threads))
    with open(log_path, "w") as log:
        started = time.perf_counter()
        try:
            process = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT, env=environment)
        except FileNotFoundError:
            raise SystemExit("benchmark: --ranks needs %s (OpenMPI's mpirun; $MPIEXEC names another)" % MPIEXEC)
        _, status, usage = os.wait4(process.pid, 0)
        process_seconds = time.perf_counter() - started
    with open(log_path) as f:
        log = f.read()
    if status != 0:
        raise SystemExit("benchmark: wcsph failed on %s, see %s" % (directory, log_path))
    end = re.search(r"End at t = [0-9.e+-]+: (\d+) steps, (\d+) fluid (?:\+ (\d+) wall particles|particles on \d+ ranks)", log)
    steps, fluid, walls = int(end.group(1)), int(end.group(2)), int(end.group(3) or 0)
    wall = float(re.search(r"Wall time ([0-9.]+) s", log).group(1))
    output = float(re.search(r"^\s+output\s+([0-9.]+) s", log, re.M).group(1))  # on several ranks, the slowest rank's
    timed = wall - output
    peak = usage.ru_maxrss * 1024  # bytes (Linux reports kB)
    if ranks:  # mpirun's own usage is not the ranks'
        peak = float(re.search(r"Peak memory of a rank: largest ([0-9.]+) MiB", log).group(1)) * 2**20
    evaluations = int(re.search(r"right-hand-side evaluations\s+(\d+)", log).group(1))
    radius = float(re.search(r"support radius ([0-9.e+-]+)", log).group(1))
    return {"fluid": fluid, "walls": walls, "steps": steps, "wall": timed, "process": process_seconds, "peak": peak, "evaluations": evaluations,
            "radius": radius, "stages": roofline.stage_seconds(log), "unmodelled": roofline.unmodelled(log)}


def dualsphysics_executables(directory):
    """GenCase and the CPU solver in DualSPHysics' binary folder (the linux64 builds where there are several)."""
    def executable(pattern):
        found = sorted(path for path in glob.glob(os.path.join(directory, pattern)) if os.path.isfile(path) and os.access(path, os.X_OK))
        preferred = [path for path in found if "linux64" in os.path.basename(path)]
        return (preferred or found or [None])[0]
    gencase, solver = executable("GenCase*"), executable("DualSPHysics*CPU*")
    if not gencase or not solver:
        raise SystemExit("benchmark: --dualsphysics %s: no executable GenCase* and DualSPHysics*CPU* there (DualSPHysics' bin/linux folder)"
                         % directory)
    return gencase, solver


def dualsphysics_environment(directory):
    """DualSPHysics' executables load their libraries from their own folder."""
    libraries = os.environ.get("LD_LIBRARY_PATH")
    return dict(os.environ, LD_LIBRARY_PATH=directory + (":" + libraries if libraries else ""))


def prepare_dualsphysics(args, work):
    """DualSPHysics' case made by GenCase from the XML: the solver's input, as a path without extension."""
    definition = os.path.abspath(args.dualsphysics_case)
    if not definition.endswith(".xml") or not os.path.isfile(definition):
        raise SystemExit("benchmark: --dualsphysics-case %s: not an XML file (DualSPHysics' case definition, NAME_Def.xml)" % args.dualsphysics_case)
    gencase, _ = dualsphysics_executables(args.dualsphysics)
    out = os.path.join(work, "dualsphysics")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    name = os.path.join(out, re.sub(r"_Def$", "", os.path.basename(definition)[:-4]))
    log_path = os.path.join(out, "log.GenCase")
    with open(log_path, "w") as log:
        status = subprocess.run([gencase, definition[:-4], name, "-save:none"], stdout=log, stderr=subprocess.STDOUT,
                                env=dualsphysics_environment(args.dualsphysics)).returncode
    if status != 0:
        raise SystemExit("benchmark: GenCase failed on %s, see %s" % (definition, log_path))
    return name


def run_dualsphysics(args, name, threads, end_time):
    """One run of DualSPHysics' CPU solver on `threads` threads to `end_time`, writing no particles: its wall time."""
    _, solver = dualsphysics_executables(args.dualsphysics)
    out = os.path.dirname(name)
    log_path = os.path.join(out, "log.DualSPHysics.%d" % threads)
    command = [solver, "-cpu", "-ompthreads:%d" % threads, name, out, "-dirdataout", "data", "-sv:none", "-svres:0",
               "-tmax:%g" % end_time, "-tout:%g" % end_time]
    with open(log_path, "w") as log:
        started = time.perf_counter()
        status = subprocess.run(command, stdout=log, stderr=subprocess.STDOUT, env=dualsphysics_environment(args.dualsphysics)).returncode
        seconds = time.perf_counter() - started
    if status != 0:
        raise SystemExit("benchmark: DualSPHysics failed, see %s" % log_path)
    return seconds


def end_time_of(directory, end_time):
    """The simulated time a run of the case covers: --end-time, or its controlDict's."""
    if end_time is not None:
        return end_time
    with open(os.path.join(directory, "system/controlDict")) as f:
        return float(re.search(r"(?m)^endTime\s+([^;\s]+)\s*;", f.read()).group(1))


def start_busy_process():
    """A process that spins on the last core until killed."""
    core = max(os.sched_getaffinity(0))
    return subprocess.Popen([sys.executable, "-c", "import os\nos.sched_setaffinity(0, {%d})\nwhile True: pass" % core])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--case", default="damBreak2D")
    parser.add_argument("--boundary", help="every wall patch on this boundary model (default: the case's dynamicBoundary)")
    parser.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--ranks", type=int, nargs="+", default=[], help="MPI rank counts to run, one thread a rank (builds with MPI)")
    parser.add_argument("--scaling", action="store_true", help="also at 4x fewer and 4x more particles (2D: spacing x2, x0.5)")
    parser.add_argument("--factors", type=float, nargs="+", help="spacing factors to run (default 1, or 2 1 0.5 with --scaling)")
    parser.add_argument("--end-time", type=float, help="simulated time of each run (default: the case's endTime)")
    parser.add_argument("--repeat", type=int, default=1, help="runs per configuration; the table gives the median (default 1)")
    parser.add_argument("--busy", action="store_true", help="run beside a busy process pinned on the last core")
    parser.add_argument("--work", default=WORK, help="where the runs are written (default build/benchmark)")
    parser.add_argument("--roofline", action="store_true", help="where each stage of the 1-thread runs sits under one core's roofline")
    parser.add_argument("--peak-gflops", type=float, help="one core's peak double GFlop/s (default: 16 flops a cycle at /proc/cpuinfo's clock)")
    parser.add_argument("--bandwidth", type=float, help="one core's memory bandwidth in GB/s (default: measured, a numpy copy)")
    parser.add_argument("--dualsphysics", metavar="DIR", help="DualSPHysics' folder of executables (GenCase, DualSPHysics*CPU*): runs it beside")
    parser.add_argument("--dualsphysics-case", metavar="XML", help="DualSPHysics' definition of the same case (with --dualsphysics)")
    args = parser.parse_args()
    if args.repeat < 1:
        raise SystemExit("benchmark: --repeat must be at least 1, not %d" % args.repeat)
    if args.ranks and (1 not in args.threads or min(args.ranks) < 1):
        raise SystemExit("benchmark: --ranks compares with the 1-thread run: --threads must include 1, and a rank count is at least 1")
    if args.roofline and 1 not in args.threads:
        raise SystemExit("benchmark: --roofline models the 1-thread runs: --threads must include 1")
    if args.roofline and args.peak_gflops is None and roofline.core_peak_gflops() is None:
        raise SystemExit("benchmark: --roofline: /proc/cpuinfo gives no clock; give --peak-gflops")
    factors = args.factors or ([2.0, 1.0, 0.5] if args.scaling else [1.0])
    if bool(args.dualsphysics) != bool(args.dualsphysics_case):
        raise SystemExit("benchmark: --dualsphysics and --dualsphysics-case go together (its executables' folder and its definition of the case)")
    if args.dualsphysics and len(factors) > 1:
        raise SystemExit("benchmark: --dualsphysics compares one spacing, its case's: give one --factors, not %d" % len(factors))
    busy = start_busy_process() if args.busy else None
    try:
        peaks, medians = measure(args, factors)
    finally:
        if busy:
            busy.kill()
    if args.roofline:
        print_roofline(args, medians)
    if len(peaks) > 1 and max(peaks)[0] > min(peaks)[0]:
        # The peak includes the libraries and buffers any run has: the difference isolates what a particle costs.
        (small, peakSmall), (large, peakLarge) = min(peaks), max(peaks)
        print("\nmemory per particle (largest minus smallest run): %.0f bytes" % ((peakLarge - peakSmall) / (large - small)))


def print_roofline(args, medians):
    """The roofline table of each case's median 1-thread run, from its final state's pairs."""
    peak = args.peak_gflops or roofline.core_peak_gflops()
    print("\nroofline of one core: peak %.1f GFlop/s%s" % (peak, "" if args.peak_gflops else " (16 flops a cycle at /proc/cpuinfo's clock)"))
    print("\n| case | stage | time [s] | GFlop/s | GB/s | flops a byte | roof [GFlop/s] | share of the roof |")
    print("|---|---|---|---|---|---|---|---|")
    notes = []
    for label, directory, r in medians:
        if r["unmodelled"]:
            raise SystemExit("benchmark: --roofline models the benchmark cases' schemes; %s selected %s (see utilities/benchmark/roofline.py)"
                             % (directory, ", ".join(r["unmodelled"])))
        written = [name for name in os.listdir(directory) if re.fullmatch(r"[0-9.e+-]+", name) and name != "0"]
        state = os.path.join(directory, max(written, key=float))
        fluid, walls = (points(os.path.join(state, part + ".vtu")) for part in ("fluid", "walls"))
        dimension = fluid.shape[1]
        models = roofline.stage_models(dimension, r["fluid"], r["walls"], roofline.count_pairs(fluid, r["radius"]),
                                       roofline.count_pairs(fluid, r["radius"], walls), r["steps"], r["evaluations"])
        moved = roofline.integrator_bytes_per_step(dimension, r["fluid"], r["walls"])
        bandwidth = args.bandwidth or roofline.copy_bandwidth_gbs(moved)
        notes.append("%s: bandwidth %.1f GB/s%s, ridge at %.2f flops a byte" % (
            label, bandwidth, "" if args.bandwidth else " (one thread's numpy copy of %.1f MB, what a step's update moves)" % (moved / 1e6),
            peak / bandwidth))
        for stage, time, attained, traffic, intensity, roof, share in roofline.rows(r["stages"], models, peak, bandwidth):
            print("| %s | %s | %.3g | %.3g | %.3g | %.3g | %.3g | %.0f %% |" % (label, stage, time, attained, traffic, intensity, roof, 100 * share))
    print("\n" + "\n".join(notes))


def points(path):
    """A state file's particle positions in the case's dimension (a 2D state's z is 0)."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    xyz = vtk_to_numpy(reader.GetOutput().GetPoints().GetData())
    return xyz[:, :2] if np.all(xyz[:, 2] == 0) else xyz


def measure(args, factors):
    """Runs every configuration and prints its row; returns (particles, peak memory) per row and
    (label, directory, median 1-thread run) per case (the last run's state is on disk)."""
    print("| case | fluid + wall particles | threads | steps | time loop [s] | runs [s] | fluid particle-steps/s | all particle-steps/s | peak memory | bytes per particle | time / 1-thread time%s |"
          % (" (busy core)" if args.busy else ""))
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    peaks, medians, against = [], [], []
    configurations = [(threads, None) for threads in args.threads] + [(1, ranks) for ranks in args.ranks]
    for factor in factors:
        directory = prepare(args.case, factor, args.work, args.boundary)
        dualsphysics_case = prepare_dualsphysics(args, args.work) if args.dualsphysics else None
        runs = {configuration: [] for configuration in configurations}
        dualsphysics_runs = {threads: [] for threads in args.threads}
        for _ in range(args.repeat):
            for threads, ranks in configurations:
                runs[threads, ranks].append(run(directory, threads, args.end_time, ranks))
                if dualsphysics_case and not ranks:
                    dualsphysics_runs[threads].append(run_dualsphysics(args, dualsphysics_case, threads, end_time_of(directory, args.end_time)))
        one_thread = statistics.median(r["wall"] for r in runs[1, None]) if (1, None) in runs else None
        for threads, ranks in configurations:
            times = sorted(r["wall"] for r in runs[threads, ranks])
            median = statistics.median(times)
            peak = max(r["peak"] for r in runs[threads, ranks])
            r = runs[threads, ranks][0]  # particles and steps are the same in every run
            fluid, walls = r["fluid"], runs[1, None][0]["walls"] if ranks else r["walls"]  # a parallel log counts the fluid only
            if not ranks:  # a rank's peak is its share's
                peaks.append((fluid + walls, peak))
            workers = ranks or threads
            ratio = "-" if not one_thread else "%.2f" % (median / one_thread) + (
                " (efficiency %.0f %%)" % (100 * one_thread / (workers * median)) if workers > 1 else "")
            print("| %s dx x%g | %d + %d | %s | %d | %.3g | %.3g-%.3g | %.3g | %.3g | %.0f MB%s | %s | %s |" % (
                args.case, factor, fluid, walls, "%d ranks x 1" % ranks if ranks else threads, r["steps"], median, times[0], times[-1],
                r["steps"] * fluid / median, r["steps"] * (fluid + walls) / median, peak / 1e6, " (a rank)" if ranks else "",
                "-" if ranks else "%.0f" % (peak / (fluid + walls)), ratio), flush=True)
        if (1, None) in runs:
            ones = runs[1, None]
            medians.append(("%s dx x%g" % (args.case, factor), directory, sorted(ones, key=lambda r: r["wall"])[(len(ones) - 1) // 2]))
        if dualsphysics_case:
            against += [("%s dx x%g" % (args.case, factor), threads, sorted(r["process"] for r in runs[threads, None]), sorted(dualsphysics_runs[threads]))
                        for threads in args.threads]
    if against:
        print("\n| case | threads | sphkit, whole process [s] (runs) | DualSPHysics, whole process [s] (runs) | sphkit / DualSPHysics |")
        print("|---|---|---|---|---|")
        for label, threads, ours, theirs in against:
            print("| %s | %d | %.3g (%.3g-%.3g) | %.3g (%.3g-%.3g) | %.2f |" % (
                label, threads, statistics.median(ours), ours[0], ours[-1], statistics.median(theirs), theirs[0], theirs[-1],
                statistics.median(ours) / statistics.median(theirs)))
    return peaks, medians


if __name__ == "__main__":
    main()
