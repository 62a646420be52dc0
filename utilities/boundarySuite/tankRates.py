"""Reads the right-hand side that `wcsph -rates` writes (postProcessing/rates/<t>/*.csv) and
measures the residual acceleration of the fluid near the walls of a uniform-pressure tank."""
import csv
import glob
import math
import os


def read_csv(path):
    with open(path) as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def read_rates(case):
    directories = sorted(glob.glob(os.path.join(case, "postProcessing", "rates", "*")), key=lambda d: float(os.path.basename(d)))
    if not directories:
        raise SystemExit("%s: no postProcessing/rates/; run wcsph -rates first" % case)
    return read_csv(os.path.join(directories[-1], "fluid.csv")), read_csv(os.path.join(directories[-1], "walls.csv"))


def residual(particle):
    """The acceleration without repulsion: uncorrected + correction, or the acceleration
    itself where the walls act through particles (dummy particles) or there is no correction."""
    if "uncorrectedAcceleration_x" in particle:
        ax = particle["uncorrectedAcceleration_x"] + particle.get("boundaryCorrection_x", 0.0)
        ay = particle["uncorrectedAcceleration_y"] + particle.get("boundaryCorrection_y", 0.0)
        return ax, ay
    return particle["acceleration_x"], particle["acceleration_y"]


def uncorrected(particle):
    if "uncorrectedAcceleration_x" in particle:
        return particle["uncorrectedAcceleration_x"], particle["uncorrectedAcceleration_y"]
    return particle["acceleration_x"], particle["acceleration_y"]


def near_wall(fluid, walls, reach):
    """Fluid particles within `reach` of a surface wall particle (layer 0), each with the
    index of its nearest one."""
    surface = [w for w in walls if w.get("layer", 0) == 0]
    result = []
    for p in fluid:
        best, nearest = None, None
        for w in surface:
            d = math.hypot(p["x"] - w["x"], p["y"] - w["y"])
            if best is None or d < best:
                best, nearest = d, w
        if best is not None and best < reach:
            result.append((p, nearest, best))
    return result


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values)) if values else float("nan")
