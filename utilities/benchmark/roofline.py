"""Where each stage of a benchmark run sits under the roofline of one core (Williams, Waterman &
Patterson, "Roofline", CACM 52(4), 2009): attained = work / time, intensity = work / traffic,
roof = min(peak flops, intensity x memory bandwidth), position = attained / roof.

Work and traffic are counted per stage from a model of what it does for the benchmark cases'
schemes (Verlet, continuity with Tait's equation, artificial viscosity, Fourtakas diffusion,
dynamic-boundary walls), with the pairs counted in the run's final state:
- forces, per right-hand-side evaluation: 80 flops per pair within the support, fluid-fluid and
  fluid-wall (doc/performance.md, "The floor": distance 5, kernel gradient 6, pressure 8,
  continuity 8, viscosity 12, Fourtakas 40; a square root or a division counts one). Traffic:
  each particle's fields read once (position, velocity, density, pressure, mass) and its rates
  written once (acceleration, density rate): the compulsory traffic; the neighbours' fields
  come from the caches.
- density + pressure, per evaluation: Tait's equation on every particle, 7 flops; the density
  read and the pressure written.
- integrator, per step (Verlet): a fluid particle reads position, velocity, the previous
  velocity, acceleration, density, the previous density and the density rate, writes position,
  both velocities and both densities; 6 D + 6 flops. A wall particle, its density alone: reads
  three values, writes two, 4 flops.
The other stages (the neighbour search's sorts, the walls' pass, output) are left unmodelled:
their counts of calls are not in the log. A run that selected other schemes is refused
(`unmodelled` names them from its log).

The roofs of one core: the peak as 16 double flops a cycle (two 256-bit FMA units, the width the
build uses) at the clock /proc/cpuinfo reports, and the bandwidth of one thread copying, with
numpy, as many bytes as the integrator moves in a step (read and write counted; the best of
five): the benchmark cases' particle arrays (3-15 MB) live in the caches, where a copy of main
memory's size would put the roof too low by half. Both can be given instead (--peak-gflops,
--bandwidth). The model is for runs with one thread.
"""
import re

import numpy as np

FLOPS_PER_PAIR = 80
TAIT_FLOPS = 7
# The schemes the model counts, as the solver log names them ("Selecting <model> <choice>").
MODELLED = {"equationOfState": "tait", "density": "continuity", "viscosity": "artificial", "densityDiffusion": "fourtakas",
            "time integrator": "verlet"}


def unmodelled(log):
    """What the run selected that the model does not count: ['<model> <choice>', ...]."""
    found = [f"{model} {choice}" for model, choice in re.findall(r"^Selecting (time integrator|\w+) (\w+)", log, re.M)
             if model in MODELLED and choice != MODELLED[model]]
    found += [f"walls {model}" for model in re.findall(r"^Selecting boundary model for patch .*: (\w+)", log, re.M) if model != "dynamicBoundary"]
    return found


def count_pairs(points, radius, others=None):
    """Pairs closer than `radius`: within `points` each pair once, or between `points` and
    `others`. Cells of the radius's size, each of the 3^D neighbouring offsets in turn."""
    points = np.asarray(points, dtype=float)
    others_given = others is not None
    others = np.asarray(others, dtype=float) if others_given else points
    if len(points) == 0 or len(others) == 0:
        return 0
    dimension = points.shape[1]
    origin = np.minimum(points.min(axis=0), others.min(axis=0))
    cell_of = lambda x: np.floor((x - origin) / radius).astype(np.int64)
    cells_a, cells_b = cell_of(points), cell_of(others)
    extent = np.maximum(cells_a.max(axis=0), cells_b.max(axis=0)) + 3
    key = lambda cells: np.ravel_multi_index(tuple((cells + 1).T), extent)
    order = np.argsort(key(cells_b), kind="stable")
    sorted_keys, sorted_points = key(cells_b)[order], others[order]
    count = 0
    for offset in np.ndindex(*(3,) * dimension):
        keys = key(cells_a + np.array(offset) - 1)
        start, end = np.searchsorted(sorted_keys, keys, "left"), np.searchsorted(sorted_keys, keys, "right")
        lengths = end - start
        owner = np.repeat(np.arange(len(points)), lengths)
        candidate = np.repeat(start - np.cumsum(lengths) + lengths, lengths) + np.arange(lengths.sum())
        distance2 = np.sum((points[owner] - sorted_points[candidate]) ** 2, axis=1)
        close = distance2 < radius * radius
        if not others_given:
            close &= owner != order[candidate]  # not the particle itself
        count += int(np.count_nonzero(close))
    return count if others_given else count // 2


def core_peak_gflops():
    """16 double flops a cycle at the clock the kernel reports (None where it reports none)."""
    try:
        with open("/proc/cpuinfo") as f:
            clock = re.search(r"^cpu MHz\s*:\s*([0-9.]+)", f.read(), re.M)
    except OSError:
        return None
    return 16 * float(clock.group(1)) / 1e3 if clock else None


def copy_bandwidth_gbs(moved_bytes, tries=5):
    """One thread's bandwidth in GB/s copying arrays that move `moved_bytes` a copy (read and
    written), each try copying again for at least 0.1 s."""
    import time
    source = np.ones(max(1, int(moved_bytes) // 16))
    target = np.empty_like(source)
    best = 0.0
    for _ in range(tries):
        copies, start = 0, time.perf_counter()
        while copies == 0 or time.perf_counter() - start < 0.1:
            np.copyto(target, source)
            copies += 1
        best = max(best, copies * 2 * source.nbytes / (time.perf_counter() - start) / 1e9)
    return best


def integrator_bytes_per_step(dimension, fluid, walls):
    """What the Verlet update reads and writes in a step, fluid and walls."""
    return 8 * ((4 * dimension + 3) + (3 * dimension + 2)) * fluid + 8 * 5 * walls


def stage_models(dimension, fluid, walls, fluid_pairs, wall_pairs, steps, evaluations):
    """{stage: (flops, bytes)} over the run, for the stages modelled."""
    double = 8
    forces_flops = FLOPS_PER_PAIR * (fluid_pairs + wall_pairs) * evaluations
    forces_bytes = double * ((2 * dimension + 3) + (dimension + 1)) * (fluid + walls) * evaluations
    return {
        "forces": (forces_flops, forces_bytes),
        "density + pressure": (TAIT_FLOPS * (fluid + walls) * evaluations, 2 * double * (fluid + walls) * evaluations),
        "integrator": ((6 * dimension + 6) * fluid * steps + 4 * walls * steps, integrator_bytes_per_step(dimension, fluid, walls) * steps),
    }


def rows(seconds, models, peak_gflops, bandwidth_gbs):
    """One row per modelled stage: (stage, seconds, GFlop/s, GB/s, flops per byte, roof GFlop/s, position)."""
    table = []
    for stage, (flops, traffic) in models.items():
        time = seconds.get(stage)
        if not time:
            continue
        intensity = flops / traffic
        roof = min(peak_gflops, intensity * bandwidth_gbs)
        attained = flops / time / 1e9
        table.append((stage, time, attained, traffic / time / 1e9, intensity, roof, attained / roof))
    return table


def stage_seconds(log):
    """The solver log's 'Time per part' block: {stage: seconds} (on several ranks, the largest)."""
    block = re.split(r"Time per part[^:\n]*:", log, maxsplit=1)[1]
    return {name.strip(): float(value) for name, value in re.findall(r"^\s{4}(\S[^\n]*?)\s+([0-9.]+) s\s", block, re.M)}
