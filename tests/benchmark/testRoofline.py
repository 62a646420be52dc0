#!/usr/bin/python3
"""The benchmark's roofline (utilities/benchmark/roofline.py): the pair count against a brute-force
one, the model's work and traffic and a row's arithmetic against hand-computed values, the solver
log's stages read, and benchmark.py --roofline end to end on a small run of the 2D case.
Run by CTest with SPHKIT_BIN set to the build's binaries."""
import os
import re
import subprocess
import sys
import tempfile
import unittest

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "utilities", "benchmark"))
import roofline  # noqa: E402


class Roofline(unittest.TestCase):
    def test_pairs_are_those_a_brute_force_search_finds(self):
        rng = np.random.default_rng(20261206)
        for dimension in (2, 3):
            points, others, radius = rng.random((300, dimension)), rng.random((120, dimension)) + 0.4, 0.17
            within = np.linalg.norm(points[:, None] - points[None], axis=2)
            between = np.linalg.norm(points[:, None] - others[None], axis=2)
            self.assertEqual(roofline.count_pairs(points, radius), (np.count_nonzero(within < radius) - len(points)) // 2)
            self.assertEqual(roofline.count_pairs(points, radius, others), np.count_nonzero(between < radius))
        # A lattice: each point of a 4 x 3 grid of spacing 1 and its neighbours within 1.5.
        lattice = np.array([(i, j) for i in range(4) for j in range(3)], dtype=float)
        self.assertEqual(roofline.count_pairs(lattice, 1.5), 3 * 3 + 4 * 2 + 2 * 3 * 2)  # rows, columns, diagonals

    def test_the_models_work_and_traffic(self):
        # 2D: 100 fluid and 20 wall particles, 900 + 50 pairs, 10 steps of 2 evaluations.
        models = roofline.stage_models(2, 100, 20, 900, 50, 10, 20)
        self.assertEqual(models["forces"], (80 * 950 * 20, 8 * (7 + 3) * 120 * 20))
        self.assertEqual(models["density + pressure"], (7 * 120 * 20, 16 * 120 * 20))
        self.assertEqual(models["integrator"], (18 * 100 * 10 + 4 * 20 * 10, 8 * (11 + 8) * 100 * 10 + 40 * 20 * 10))

    def test_a_row_is_bound_by_the_lower_roof(self):
        models = {"forces": (8e9, 4e9), "integrator": (1e8, 2e9)}
        rows = roofline.rows({"forces": 2.0, "integrator": 0.5, "output": 1.0}, models, 40.0, 10.0)
        self.assertEqual([r[0] for r in rows], ["forces", "integrator"])
        stage, time, attained, traffic, intensity, roof, share = rows[0]
        self.assertEqual((time, attained, traffic, intensity, roof, share), (2.0, 4.0, 2.0, 2.0, 20.0, 0.2))  # memory roof: 2 x 10
        self.assertAlmostEqual(rows[1][5], 0.5)  # 0.05 flops a byte x 10 GB/s
        self.assertAlmostEqual(rows[1][6], 0.4)  # 0.2 GFlop/s of 0.5

    def test_the_logs_stages(self):
        log = ("Wall time 0.61 s\nTime per part:\n    neighbour search        0.023 s    3.8 %\n"
               "    density + pressure      0.008 s    1.3 %\n    forces                  0.343 s   56.3 %\n    other                   0.151 s   24.8 %\n")
        self.assertEqual(roofline.stage_seconds(log), {"neighbour search": 0.023, "density + pressure": 0.008, "forces": 0.343, "other": 0.151})

    def test_schemes_the_model_does_not_count_are_named(self):
        log = ("Selecting equationOfState tait: rho0 1000\nSelecting density continuity\nSelecting viscosity laminar: nu 1e-6\n"
               "Selecting densityDiffusion fourtakas: delta 0.1\nSelecting boundary model for patch tank (10 particles): dynamicBoundary\n"
               "Selecting boundary model for patch lid (5 particles): dummyParticles\nSelecting time integrator symplectic: courant 0.2\n")
        self.assertEqual(roofline.unmodelled(log), ["viscosity laminar", "time integrator symplectic", "walls dummyParticles"])
        self.assertEqual(roofline.unmodelled(log.replace("laminar", "artificial").replace("symplectic", "verlet").replace("dummyParticles", "dynamicBoundary")), [])

    def test_the_benchmark_prints_the_stages_under_the_roofline(self):
        with tempfile.TemporaryDirectory() as work:
            run = subprocess.run([sys.executable, os.path.join(ROOT, "utilities", "benchmark", "benchmark.py"), "--case", "damBreak2D",
                                  "--threads", "1", "--factors", "4", "--end-time", "0.02", "--roofline", "--peak-gflops", "40",
                                  "--bandwidth", "10", "--work", work], capture_output=True, text=True, timeout=300)
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        self.assertIn("roofline of one core: peak 40.0 GFlop/s\n", run.stdout)
        self.assertIn("damBreak2D dx x4: bandwidth 10.0 GB/s, ridge at 4.00 flops a byte", run.stdout)
        rows = {m.group(1): [float(v) for v in m.group(2, 3, 4)] for m in re.finditer(
            r"^\| damBreak2D dx x4 \| ([a-z +]+) \| \S+ \| (\S+) \| \S+ \| (\S+) \| (\S+) \| \d+ % \|$", run.stdout, re.M)}
        self.assertIn("forces", rows)
        attained, intensity, roof = rows["forces"]
        self.assertGreater(intensity, 4.0)  # the pair terms sit right of the ridge: bound by the peak
        self.assertEqual(roof, 40.0)
        self.assertTrue(0 < attained < roof)

    def test_a_roofline_without_one_thread_stops_first(self):
        run = subprocess.run([sys.executable, os.path.join(ROOT, "utilities", "benchmark", "benchmark.py"), "--threads", "2", "--roofline"],
                             capture_output=True, text=True)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("--roofline models the 1-thread runs: --threads must include 1", run.stderr)


if __name__ == "__main__":
    unittest.main()
