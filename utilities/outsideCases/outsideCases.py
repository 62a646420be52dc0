#!/usr/bin/python3
"""Twenty-three cases the project does not ship, written as a user would (the shipped cases' schemes:
Wendland C2, hdx 1.3, continuity, artificial viscosity 0.02, Fourtakas diffusion, symplectic,
Courant 0.2, c0 = 10 sqrt(g H)), each run with the boundary-integral deficiency correction,
free-slip dummy particles and dynamic boundary particles; every patch's layout is the one its
model asks for (no `layers`), so that a model is one word:

- wedge2D: a 0.5 m column breaking onto a triangular wedge (a convex apex of 69 degrees) in a tank 1.5 m
  high (its splash passed a 1 m wall);
- piston2D: a piston wave maker, 0.1 m at 1 Hz into water 0.4 m deep (breaking waves);
- vTank2D: still water in a V-shaped tank whose bottom corner is 53 degrees;
- paddle2D: a paddle 0.3 x 0.04 m spinning at 3 rad/s in a tank (moving convex corners);
- slosh3D: a 3D tank surged near its first natural frequency (A = 0.02 m, 1 Hz);
- fastBulge2D: a narrow floor bulge, 0.12 m high and 0.06 m wide, rising in 0.3 s;
- baffle2D: a tank with a baffle 2 dx thick rising from its floor, surged near resonance;
- sluiceGate2D: a reservoir 0.5 m deep draining under a gate 0.03 m thick, 0.05 m (5 dx) above the floor;
- acuteV2D: still water in a V tank whose bottom corner is 30 degrees;
- spinningTank2D: a closed square tank, half full, turning about its centre at 1 rad/s;
- impulsivePiston2D: a piston started at 2 m/s from rest into water 0.4 m deep (c0 = 19.8 m/s; the jet it throws
  up its face passes 1 m in 0.16 s);
- fineStillWater2D: still water 0.5 m deep at H/dx = 100;
- obstacle3D: a 3D dam break onto a block 4 x 4 x 6 dx (convex edges and corners);
- wedgeEntry2D: a wedge of 20-degree deadrise driven into still water 0.6 m deep at 2 m/s (slamming at a
  convex apex);
- rollingTank2D: a tank rolling 0.1 rad at 0.75 Hz about its still-water line, near its first natural frequency,
  started at full rate;
- cylinder2D: a dam break onto a cylinder of radius 0.1 m, 0.1 m above the floor (a curved convex obstacle), in a tank
  1 m high, with `outOfDomain remove` (the run-up sheet on the far wall throws a few particles past 1.6 m);
- piston3D: a piston (a box 4 dx thick spanning the channel) at 1 Hz, 0.05 m, in a 3D channel 0.25 m deep;
- floatingBox2D: a box 0.3 x 0.1 m of half the water's density released 0.014 m above where it floats, a free
  body always on the correction (the row's model on the tank): where it comes to rest against Archimedes;
- sphere3D: a 3D dam break onto a sphere of radius 0.08 m (4 dx), 0.06 m above the floor, given as a
  triangulated surface (an OBJ file of 5,120 triangles, as from a CAD export: a curved convex obstacle in
  3D), with `outOfDomain remove` (its splash leaves the open tank);
- oscillatingSphere3D: a sphere of radius 0.06 m (3 dx) from an OBJ of 1,280 triangles, submerged at
  mid-depth in still water 0.3 m deep, oscillating 0.05 m along the tank at 1 Hz (a curved wall moving
  through the fluid in 3D): its in-line force against potential flow's added mass;
- slot2D: a reservoir 0.3 m deep on a shelf 0.04 m thick draining through a slot 3 dx wide into the basin below
  (fluid between walls a support apart, the slot's convex edges, the jet striking the basin's floor);
- slotStillWater2D: still water 0.3 m deep in a slot 4 dx wide (every particle within a support of both walls);
- mixedCorners2D: a dam break in a tank of three patches, the floor on the row's model and the side walls always on
  the correction (two models meeting at the corners, as a user mixes them by patch), with `outOfDomain remove`.

Reports per run: the outcome (the blow-up's message), the most fluid particles behind a wall
at any step (wallPenetrations), the wall time (one thread, two runs at a time), for the
still-water cases the pressure's error against hydrostatic at the end (L2 and max over rho g H,
below the top 0.1 m) and the fluid's RMS speed then, the floating box's rest, the oscillating
sphere's in-line force, and the particles removed as they left the domain. Usage: utilities/outsideCases/outsideCases.py [--markdown FILE] [--check FILE] [--work DIR] [--cases NAME ...] [--models NAME ...]
(from the repository root; binaries from $SPHKIT_BIN or build/bin; about 40 minutes on 2 cores).
--models runs the named models only; --markdown writes the table, keeping the rows not run; --check compares the runs'
outcomes, counts and figures with a table's (not the wall times) and exits 1 where one differs
(CTest's DocumentedFigures.outsideCases, label long).
"""
import argparse
import concurrent.futures
import glob
import os
import re
import subprocess
import sys
import time

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.environ.get("SPHKIT_BIN", os.path.join(ROOT, "build", "bin"))
MODELS = {"deficiencyCorrectionBoundaryIntegral": "correction", "dummyParticles": "dummy", "dynamicBoundary": "dynamic"}

# name: (dimension, dx, domain, fluid regions, wall patches, {patch: motion}, end time, depth H)
# The oscillating sphere: its radius, the motion's amplitude and frequency.
SPHERE_RADIUS, SPHERE_AMPLITUDE, SPHERE_FREQUENCY = 0.06, 0.05, 1.0
CASES = {
    "wedge2D": (2, 0.01, "{ min (-0.1 -0.1); max (2.1 1.6); }", "column { type box; min (0 0); max (0.5 0.5); }",
                "tank { type boxWalls; min (0 0); max (2 1.5); open (yMax); }\n"
                "wedge { type polygon; points ((1.2 0) (1.5 0) (1.35 0.22)); side right; }", {"tank": "", "wedge": ""}, 2.0, 0.5),
    "piston2D": (2, 0.01, "{ min (-0.3 -0.1); max (2.1 1.1); }", "water { type box; min (0 0); max (2 0.4); }",
                 "tank { type polyline; points ((-0.25 0) (2 0) (2 1)); }\npiston { type polyline; points ((0 1) (0 0)); side left; }",
                 {"tank": "", "piston": "motion { type oscillation; amplitude (0.1 0); frequency 1; rampTime 0.5; }"}, 4.0, 0.4),
    "vTank2D": (2, 0.01, "{ min (-0.7 -0.1); max (0.7 1.2); }", "water { type polygon; points ((0 0) (0.4 0.8) (-0.4 0.8)); }",
                "tank { type polyline; points ((-0.5 1) (0 0) (0.5 1)); side left; }", {"tank": ""}, 3.0, 0.8),
    "paddle2D": (2, 0.01, "{ min (-0.1 -0.1); max (1.1 1.1); }", "water { type box; min (0 0); max (1 0.7); }",
                 "tank { type boxWalls; min (0 0); max (1 1); open (yMax); }\n"
                 "paddle { type polygon; points ((0.35 0.33) (0.65 0.33) (0.65 0.37) (0.35 0.37)); side right; }",
                 {"tank": "", "paddle": "motion { type rotation; centre (0.5 0.35); omega 3; }"}, 3.0, 0.7),
    "slosh3D": (3, 0.02, "{ min (-0.1 -0.1 -0.1); max (0.7 0.4 0.6); }", "water { type box; min (0 0 0); max (0.6 0.3 0.2); }",
                "tank { type boxWalls; min (0 0 0); max (0.6 0.3 0.5); open (zMax); }",
                {"tank": "motion { type oscillation; amplitude (0.02 0 0); frequency 1.0; rampTime 0.5; }"}, 4.0, 0.2),
    "fastBulge2D": (2, 0.01, "{ min (-0.1 -0.2); max (1.1 1.1); }", "water { type box; min (0 0); max (1 0.4); }",
                    "tank { type polyline; points ((0 1) (0 0) (1 0) (1 1)); }",
                    {"tank": "motion { type gaussianBulge; centre (0.5 0); amplitude 0.12; width 0.06; period 1.2; }"}, 2.4, 0.4),
    "baffle2D": (2, 0.01, "{ min (-0.1 -0.1); max (1.1 1.1); }", "water { type box; min (0 0); max (1 0.3); }",
                 "tank { type boxWalls; min (0 0); max (1 0.8); open (yMax); }\n"
                 "baffle { type polygon; points ((0.49 0) (0.51 0) (0.51 0.2) (0.49 0.2)); side right; }",
                 {patch: "motion { type oscillation; amplitude (0.03 0); frequency 0.85; rampTime 0.5; }" for patch in ("tank", "baffle")}, 4.0, 0.3),
    "sluiceGate2D": (2, 0.01, "{ min (-0.1 -0.1); max (2.1 1.1); }", "reservoir { type box; min (0 0); max (0.5 0.5); }",
                     "tank { type boxWalls; min (0 0); max (2 1); open (yMax); }\n"
                     "gate { type polygon; points ((0.5 0.05) (0.53 0.05) (0.53 1) (0.5 1)); side right; }", {"tank": "", "gate": ""}, 2.0, 0.5),
    "acuteV2D": (2, 0.01, "{ min (-0.4 -0.1); max (0.4 1.2); }", "water { type polygon; points ((0 0) (0.216 0.8) (-0.216 0.8)); }",
                 "tank { type polyline; points ((-0.27 1) (0 0) (0.27 1)); side left; }", {"tank": ""}, 3.0, 0.8),
    "spinningTank2D": (2, 0.01, "{ min (-0.4 -0.4); max (1.4 1.4); }", "water { type box; min (0 0); max (1 0.5); }",
                       "tank { type boxWalls; min (0 0); max (1 1); }", {"tank": "motion { type rotation; centre (0.5 0.5); omega 1; }"}, 3.0, 0.5),
    "impulsivePiston2D": (2, 0.01, "{ min (-0.1 -0.1); max (2.1 2.1); }", "water { type box; min (0 0); max (2 0.4); }",
                          "tank { type polyline; points ((-0.1 0) (2 0) (2 2)); }\npiston { type polyline; points ((0 2) (0 0)); side left; }",
                          {"tank": "", "piston": "motion { type translation; velocity (2 0); }"}, 0.4, 0.4),
    "fineStillWater2D": (2, 0.005, "{ min (-0.1 -0.1); max (0.6 0.7); }", "water { type box; min (0 0); max (0.5 0.5); }",
                         "tank { type boxWalls; min (0 0); max (0.5 0.6); open (yMax); }", {"tank": ""}, 1.0, 0.5),
    "obstacle3D": (3, 0.025, "{ min (-0.1 -0.1 -0.1); max (1.1 0.5 1.5); }", "column { type box; min (0 0 0); max (0.3 0.4 0.4); }",
                   "tank { type boxWalls; min (0 0 0); max (1 0.4 0.6); open (zMax); }\nblock { type box; min (0.6 0.15 0); max (0.7 0.25 0.15); }",
                   {"tank": "", "block": ""}, 1.0, 0.4),
    "wedgeEntry2D": (2, 0.01, "{ min (-0.1 -0.1); max (2.1 1.3); }", "water { type box; min (0 0); max (2 0.6); }",
                     "tank { type boxWalls; min (0 0); max (2 1.2); open (yMax); }\n"
                     "wedge { type polygon; points ((1 0.62) (1.25 0.711) (1.25 0.9) (0.75 0.9) (0.75 0.711)); side right; }",
                     {"tank": "", "wedge": "motion { type translation; velocity (0 -2); }"}, 0.2, 0.6),
    "rollingTank2D": (2, 0.01, "{ min (-0.3 -0.3); max (1.3 1.1); }", "water { type box; min (0 0); max (1 0.3); }",
                      "tank { type boxWalls; min (0 0); max (1 0.8); open (yMax); }",
                      {"tank": "motion { type rotation; centre (0.5 0.3); amplitude 0.1; frequency 0.75; }"}, 4.0, 0.3),
    "cylinder2D": (2, 0.01, "{ min (-0.1 -0.1); max (2.1 1.1); }", "column { type box; min (0 0); max (0.5 0.5); }",
                   "tank { type boxWalls; min (0 0); max (2 1); open (yMax); }\n"
                   "cylinder { type circle; centre (1.2 0.2); radius 0.1; fluidInside no; }", {"tank": "", "cylinder": ""}, 2.0, 0.5),
    "piston3D": (3, 0.025, "{ min (-0.3 -0.1 -0.1); max (1.6 0.4 0.6); }", "water { type box; min (0 0 0); max (1.5 0.3 0.25); }",
                 "tank { type boxWalls; min (-0.2 0 0); max (1.5 0.3 0.5); open (zMax); }\n"
                 "piston { type box; min (-0.1 0 0); max (0 0.3 0.5); }",
                 {"tank": "", "piston": "motion { type oscillation; amplitude (0.05 0 0); frequency 1; rampTime 0.5; }"}, 3.0, 0.25),
    "floatingBox2D": (2, 0.01, "{ min (-0.1 -0.1); max (1.1 1.1); }", "water { type box; min (0 0); max (1 0.5); }",
                      "tank { type boxWalls; min (0 0); max (1 1); open (yMax); }\n"
                      "box { type polygon; points ((0.35 0.47) (0.65 0.47) (0.65 0.57) (0.35 0.57)); side right; }",
                      {"tank": "", "box": "motion { type freeBody; mass 15; momentOfInertia 0.125; centreOfMass (0.5 0.52); }"}, 4.0, 0.5),
    "sphere3D": (3, 0.02, "{ min (-0.1 -0.1 -0.1); max (0.9 0.5 0.9); }", "column { type box; min (0 0 0); max (0.24 0.4 0.3); }",
                 "tank { type boxWalls; min (0 0 0); max (0.8 0.4 0.6); open (zMax); }\n"
                 "sphere { type surface; file \"constant/geometry/sphere.obj\"; fluidInside no; }", {"tank": "", "sphere": ""}, 1.0, 0.3),
    "oscillatingSphere3D": (3, 0.02, "{ min (-0.1 -0.1 -0.1); max (0.7 0.4 0.6); }", "water { type box; min (0 0 0); max (0.6 0.3 0.3); }",
                            "tank { type boxWalls; min (0 0 0); max (0.6 0.3 0.5); open (zMax); }\n"
                            "sphere { type surface; file \"constant/geometry/sphere.obj\"; fluidInside no; }",
                            {"tank": "", "sphere": "motion { type oscillation; amplitude (%g 0 0); frequency %g; rampTime 0.5; }" % (
                                SPHERE_AMPLITUDE, SPHERE_FREQUENCY)}, 3.0, 0.3),
    "slot2D": (2, 0.01, "{ min (-0.1 -0.1); max (1.1 1.1); }", "reservoir { type box; min (0 0.34); max (1 0.64); }",
               "tank { type boxWalls; min (0 0); max (1 1); open (yMax); }\n"
               "shelfLeft { type polygon; points ((0 0.3) (0.485 0.3) (0.485 0.34) (0 0.34)); side right; }\n"
               "shelfRight { type polygon; points ((0.515 0.3) (1 0.3) (1 0.34) (0.515 0.34)); side right; }",
               {"tank": "", "shelfLeft": "", "shelfRight": ""}, 1.5, 0.64),
    "slotStillWater2D": (2, 0.01, "{ min (-0.1 -0.1); max (0.14 0.5); }", "water { type box; min (0 0); max (0.04 0.3); }",
                         "tank { type boxWalls; min (0 0); max (0.04 0.4); open (yMax); }", {"tank": ""}, 2.0, 0.3),
    "mixedCorners2D": (2, 0.01, "{ min (-0.1 -0.1); max (2.1 1.1); }", "column { type box; min (0 0); max (0.5 0.5); }",
                       "floor { type polyline; points ((0 0) (2 0)); }\nleft { type polyline; points ((0 1) (0 0)); }\n"
                       "right { type polyline; points ((2 0) (2 1)); }", {"floor": "", "left": "", "right": ""}, 2.0, 0.5),
}
STILL_WATER = ("vTank2D", "acuteV2D", "fineStillWater2D", "slotStillWater2D")
# controlDict entries beyond the common ones: the cylinder's run-up sheet climbs the far wall past 1.6 m
# in a few particles (the mixed corners' past 1.1 m), and the sphere's splash leaves its open tank, which
# DualSPHysics would exclude; the count removed is reported.
CONTROL = {"cylinder2D": "outOfDomain remove;\n", "sphere3D": "outOfDomain remove;\n", "mixedCorners2D": "outOfDomain remove;\n"}
# Function objects beyond wallPenetrations, and patches on a model of their own whatever the row's: a free
# body's loads come from a wall-force model, so the floating box is always on the correction.
FUNCTIONS = {"floatingBox2D": "    box { type bodyMotion; patch box; executeInterval 0.01; }\n",
             "oscillatingSphere3D": "    sphere { type forces; patches (sphere); executeInterval 0.005; }\n"}
# The mixed corners: the side walls always on the correction, the floor on the row's model.
MODEL_OF = {"floatingBox2D": {"box": "deficiencyCorrectionBoundaryIntegral"},
            "mixedCorners2D": {"left": "deficiencyCorrectionBoundaryIntegral", "right": "deficiencyCorrectionBoundaryIntegral"}}
# Files a case reads beyond its dictionaries, written by a function of none.
FILES = {"sphere3D": {"constant/geometry/sphere.obj": lambda: icosphere((0.5, 0.2, 0.14), 0.08, 4)},
         "oscillatingSphere3D": {"constant/geometry/sphere.obj": lambda: icosphere((0.3, 0.15, 0.15), SPHERE_RADIUS, 3)}}
# The floating box: its mass per unit length and width, and the fluid's density.
BOX_MASS, BOX_WIDTH, RHO = 15.0, 0.3, 1000.0


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def icosphere(centre, radius, subdivisions):
    """An OBJ text of a sphere: an icosahedron whose triangles are split in four, the new vertices
    pushed out to the sphere, `subdivisions` times (4: 2,562 vertices, 5,120 triangles)."""
    t = (1 + 5 ** 0.5) / 2
    vertices = [np.array(v, float) for v in ((-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
                                             (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1))]
    vertices = [v / np.linalg.norm(v) for v in vertices]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8),
             (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        middles = {}

        def middle(a, b):
            key = (min(a, b), max(a, b))
            if key not in middles:
                v = vertices[a] + vertices[b]
                vertices.append(v / np.linalg.norm(v))
                middles[key] = len(vertices) - 1
            return middles[key]
        faces = [f for a, b, c in faces for f in ((a, middle(a, b), middle(c, a)), (b, middle(b, c), middle(a, b)),
                                                  (c, middle(c, a), middle(b, c)), (middle(a, b), middle(b, c), middle(c, a)))]
    lines = ["v %.9g %.9g %.9g" % tuple(np.asarray(centre) + radius * v) for v in vertices]
    return "\n".join(lines + ["f %d %d %d" % (a + 1, b + 1, c + 1) for a, b, c in faces]) + "\n"


def prepare(work, name, model):
    dimension, dx, domain, fluid, walls, motions, end, depth = CASES[name]
    directory = os.path.join(work, f"{name}-{MODELS[model]}")
    subprocess.run(["rm", "-rf", directory], check=True)
    write(f"{directory}/system/controlDict", f"application wcsph;\nendTime {end};\nwriteInterval 0.1;\n{CONTROL.get(name, '')}"
          f"functions\n{{\n    leaks {{ type wallPenetrations; }}\n{FUNCTIONS.get(name, '')}}}\n")
    write(f"{directory}/system/generateParticlesDict", f"dimension {dimension};\nspacing {dx};\ndomain {domain};\n"
          f"initialPressure hydrostatic;\nfluid\n{{\n    {fluid}\n}}\nboundaries\n{{\n{walls}\n}}\n")
    write(f"{directory}/system/sphSchemes", "kernel { type wendlandC2; hdx 1.3; }\ndensity { type continuity; }\n"
          "viscosity { type artificial; alpha 0.02; }\ndensityDiffusion { type fourtakas; delta 0.1; }\n")
    write(f"{directory}/system/timeIntegration", "integrator { type symplectic; }\ncourant 0.2;\n")
    for path, text in FILES.get(name, {}).items():
        write(os.path.join(directory, path), text())
    gravity = "(0 -9.81)" if dimension == 2 else "(0 0 -9.81)"
    write(f"{directory}/constant/fluidProperties",
          f"rho0 1000;\ngravity {gravity};\nequationOfState {{ type tait; gamma 7; c0FromHeight {{ coefficient 10; height {depth}; }} }}\n")
    models = {patch: MODEL_OF.get(name, {}).get(patch, model) for patch in motions}
    write(f"{directory}/constant/boundaryProperties", "".join(f"{patch} {{ type {models[patch]}; {motion} }}\n" for patch, motion in motions.items()))
    subprocess.run([os.path.join(BIN, "generateParticles"), "-case", directory], check=True, capture_output=True)
    return directory


def read(path):
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    data = grid.GetPointData()
    return vtk_to_numpy(grid.GetPoints().GetData()), {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i)) for i in range(data.GetNumberOfArrays())}


def hydrostatic_error(name, directory, end):
    """A still-water case's pressure against rho g (surface - y) at the end, below the top 0.1 m: L2 and
    max over rho g H (the surface the mean height of the 20 highest particles, or of one row's
    in a narrower tank); and the fluid's
    RMS speed, what is left of the start's disturbance (the lattice meets the slanted walls in
    steps), whose acoustic breathing swings the pressure by a few per cent of rho g H."""
    x, fields = read(os.path.join(directory, f"{end:g}", "fluid.vtu"))
    y = x[:, 1]
    columns = int(round(np.ptp(x[:, 0]) / CASES[name][1])) + 1
    surface = np.sort(y)[-min(20, columns):].mean()
    below = y < surface - 0.1
    error = fields["pressure"][below] - 1000 * 9.81 * (surface - y[below])
    scale = 1000 * 9.81 * CASES[name][7]
    speed = np.sqrt(np.mean(np.sum(fields["velocity"] ** 2, axis=1)))
    return np.sqrt(np.mean(error ** 2)) / scale, np.abs(error).max() / scale, speed


def floating_error(directory, end):
    """The floating box's heave over the last second against Archimedes: its centre's mean height
    and that of its rest, where it displaces its mass (draft M / (rho b)) and the water, of the area
    its particles hold (N dx^2), stands level across the 1 m tank: the level is (N dx^2 + M / rho) / 1 m
    and the box's centre, half its 0.1 m height above its bottom, sits at level - draft + 0.05 m.
    Also its mean angle and the heave's standard deviation over that second."""
    body = np.loadtxt(glob.glob(os.path.join(directory, "postProcessing", "box", "*", "body.dat"))[0])
    last = body[body[:, 0] >= end - 1.0]
    x, _ = read(os.path.join(directory, "0", "fluid.vtu"))
    dx = CASES["floatingBox2D"][1]
    level = (len(x) * dx * dx + BOX_MASS / RHO) / 1.0
    rest = level - BOX_MASS / (RHO * BOX_WIDTH) + 0.05
    return last[:, 2].mean(), rest, (last[:, 2].mean() - rest) / dx, last[:, 2].std(), last[:, 3].mean()


def oscillating_force(directory, end):
    """The oscillating sphere's in-line force over the last second: the amplitude of its first
    harmonic at the motion's frequency (a least-squares fit of a + b sin + c cos), against the added-mass
    force of potential flow about a sphere far from walls, C_a rho V A omega^2 with C_a = 1/2 (the
    tank's walls, the free surface 1.5 radii above and the drag at KC = 2.6 add to it)."""
    forces = np.loadtxt(glob.glob(os.path.join(directory, "postProcessing", "sphere", "*", "forces.dat"))[0])
    last = forces[forces[:, 0] >= end - 1.0]
    omega = 2 * np.pi * SPHERE_FREQUENCY
    basis = np.column_stack([np.ones(len(last)), np.sin(omega * last[:, 0]), np.cos(omega * last[:, 0])])
    (_, b, c), *_ = np.linalg.lstsq(basis, last[:, 1], rcond=None)
    added = 0.5 * RHO * 4 / 3 * np.pi * SPHERE_RADIUS ** 3 * SPHERE_AMPLITUDE * omega ** 2
    return np.hypot(b, c), added


def run(work, name, model):
    directory = prepare(work, name, model)
    start = time.time()
    result = subprocess.run([os.path.join(BIN, "wcsph"), "-case", directory], capture_output=True, text=True,
                            env=dict(os.environ, OMP_NUM_THREADS="1"))
    seconds = time.time() - start
    counts = [int(line.split()[1]) for path in glob.glob(os.path.join(directory, "postProcessing", "leaks", "*", "penetrations.dat"))
              for line in open(path) if not line.startswith("#")]
    outcome = "ran to the end" if result.returncode == 0 else result.stderr.strip().splitlines()[0].replace("|", "/").replace(directory, "<case>")
    figure = ""
    removed = re.findall(r"left the domain and (?:was|were) removed \((\d+) so far\)", result.stdout)
    if removed:
        figure = f"{removed[-1]} fluid particles left the domain (removed)"
    if name == "floatingBox2D" and result.returncode == 0:
        figure = "box centre over the last 1 s: %.4f m against %.4f m at rest (%+.2f dx), heave std %.4f m, angle %.4f rad" % floating_error(directory, CASES[name][6])
    if name == "oscillatingSphere3D" and result.returncode == 0:
        figure = "in-line force over the last 1 s, first harmonic: %.3f N (added mass of potential flow, far from walls: %.3f N)" % \
            oscillating_force(directory, CASES[name][6])
    if name in STILL_WATER and result.returncode == 0:
        end = CASES[name][6]
        figure = f"at t = {end:g} s: pressure error L2 %.4f, max %.4f rho g H; RMS speed %.4f m/s" % hydrostatic_error(name, directory, end)
    return name, model, outcome, max(counts, default=0), seconds, figure


def documented_rows(path):
    """The table rows of a document this utility wrote, by (case, model): [outcome, behind, wall time, figure]."""
    rows = {}
    for line in open(path):
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if line.startswith("| ") and len(cells) == 6 and cells[0] in CASES:
            rows[(cells[0], cells[1])] = cells[2:]
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--markdown", help="write the table to FILE (the rows of cases not run are kept from it)")
    parser.add_argument("--check", metavar="FILE", help="compare each run's outcome, count and figure with FILE's row; exit 1 if any differs")
    parser.add_argument("--work", default=os.path.join(ROOT, "build", "outsideCases"))
    parser.add_argument("--cases", nargs="+", choices=list(CASES), default=list(CASES), help="run these only")
    parser.add_argument("--models", nargs="+", choices=list(MODELS), default=list(MODELS), help="on these models only")
    options = parser.parse_args()
    jobs = [(options.work, name, model) for name in options.cases for model in options.models]
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        runs = {(name, model): ["%s" % outcome, "%d" % behind, "%.1f" % seconds, figure]
                for name, model, outcome, behind, seconds, figure in pool.map(lambda job: run(*job), jobs)}
    heading = ["| case | model | outcome | most fluid behind a wall at any step | wall time [s] | figure |", "|---|---|---|---|---|---|"]
    print("\n".join(heading + ["| %s | %s | %s |" % (name, model, " | ".join(cells)) for (name, model), cells in runs.items()]))
    if options.check:
        documented = documented_rows(options.check)
        differing = [(key, cells) for key, cells in runs.items()
                     if key not in documented or [documented[key][i] for i in (0, 1, 3)] != [cells[i] for i in (0, 1, 3)]]
        for (name, model), cells in differing:
            print("differs from %s: %s on %s: %s, %s behind, '%s' (documented: %s)" %
                  (options.check, name, model, cells[0], cells[1], cells[3], documented.get((name, model), "no row")))
        if differing:
            return 1
    if options.markdown:
        rows = documented_rows(options.markdown) if os.path.exists(options.markdown) else {}
        rows.update(runs)
        lines = ["| %s | %s | %s |" % (name, model, " | ".join(rows[(name, model)])) for name in CASES for model in MODELS if (name, model) in rows]
        header = ["# Cases written outside the project", "", "Written by `utilities/outsideCases/outsideCases.py --markdown`. " + __doc__.strip(), ""]
        write(options.markdown, "\n".join(header + heading + lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
