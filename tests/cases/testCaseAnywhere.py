#!/usr/bin/python3
"""A case runs wherever it is copied, and scales by its one parameter. rectangularTank2D's
Allrun, copied out of the repository, finds its tools and its plotting script through
SPHKIT_BIN; without SPHKIT_BIN, away from the repository, it stops with a message saying what
to set. damBreak3D at twice its spacing (system/caseParameters' dx, nothing else edited) keeps
the experiment's tank, column and box. Run by CTest with SPHKIT_BIN set to the build's binaries."""
import os
import re
import shutil
import subprocess
import tempfile
import unittest

import vtk
from vtk.util.numpy_support import vtk_to_numpy

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.path.abspath(os.environ.get("SPHKIT_BIN", os.path.join(ROOT, "build", "bin")))


def points(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetPoints().GetData())


class CaseAnywhere(unittest.TestCase):
    def setUp(self):
        self.work = tempfile.TemporaryDirectory()
        self.addCleanup(self.work.cleanup)

    def copy(self, name):
        case = os.path.join(self.work.name, "copied", name)
        shutil.copytree(os.path.join(ROOT, "cases", name), case, ignore=shutil.ignore_patterns("[0-9]*", "postProcessing", "log.*", "*.png", "*.pvd"))
        return case

    def test_a_copied_case_finds_its_tools_and_scripts_through_sphkit_bin(self):
        case = self.copy("rectangularTank2D")
        env = dict(os.environ, SPHKIT_BIN=BIN, OMP_NUM_THREADS="1")
        run = subprocess.run([os.path.join(case, "Allrun")], capture_output=True, text=True, env=env)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("fluid within r_inf of the wall", run.stdout)  # plotTankCorrection.py ran
        self.assertTrue(os.path.isfile(os.path.join(case, "tankCorrection.png")))

    def test_a_copied_case_without_sphkit_bin_says_what_to_set(self):
        case = self.copy("rectangularTank2D")
        env = {k: v for k, v in os.environ.items() if k != "SPHKIT_BIN"}
        run = subprocess.run([os.path.join(case, "Allrun")], capture_output=True, text=True, env=env)
        self.assertEqual(run.returncode, 1)
        self.assertIn("../../build/bin/wcsph not found; build sphkit first (./Allwmake) or set SPHKIT_BIN", run.stderr)
        self.assertFalse(os.path.exists(os.path.join(case, "0")))

    def test_dam_break_3d_scales_by_its_spacing_alone(self):
        case = self.copy("damBreak3D")
        parameters = os.path.join(case, "system", "caseParameters")
        with open(parameters) as f:
            text = f.read()
        self.assertIn("dx          0.025;", text)
        with open(parameters, "w") as f:
            f.write(text.replace("dx          0.025;", "dx          0.05;"))
        run = subprocess.run([os.path.join(BIN, "generateParticles"), "-case", case], capture_output=True, text=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
        self.assertEqual(run.returncode, 0, run.stderr)
        # Hand count: the column 1.228 x 1 x 0.55 m is 24.56 x 20 x 11 spacings: 25 x 20 x 11.
        self.assertIn("5500 fluid particles", run.stdout)
        fluid, walls = points(os.path.join(case, "0", "fluid.vtu")), points(os.path.join(case, "0", "walls.vtu"))
        # The experiment's sizes at any spacing: the column from x = 1.992 (first particle dx/2
        # inside) to 3.22 (last dx/2 inside), one layer of walls on the tank 3.22 x 1 x 1.
        self.assertAlmostEqual(fluid[:, 0].min(), 1.992 + 0.025, places=12)
        self.assertAlmostEqual(fluid[:, 0].max(), 3.22 - 0.025, places=12)
        self.assertAlmostEqual(fluid[:, 2].max(), 0.55 - 0.025, places=12)
        for axis, (low, high) in enumerate(((0.0, 3.22), (0.0, 1.0), (0.0, 1.0))):
            self.assertAlmostEqual(walls[:, axis].min(), low - 0.025, places=12)
            self.assertAlmostEqual(walls[:, axis].max(), high + 0.025, places=12)
        # The box's impact face x = 0.8245, whose particles the probes in front of it read.
        face = walls[(abs(walls[:, 0] - (0.8245 - 0.025)) < 1e-9) & (walls[:, 1] > 0.3) & (walls[:, 1] < 0.69) & (walls[:, 2] < 0.15)]
        self.assertGreater(len(face), 0)


if __name__ == "__main__":
    unittest.main()
