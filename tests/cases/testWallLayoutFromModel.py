#!/usr/bin/python3
"""A wall patch that names no layers takes the layout its wall model needs, so switching the
model is one word in constant/boundaryProperties and a rerun of generateParticles -overwrite.
On hydrostaticTank2D (quintic kernel, hdx 1.2: support 3.6 dx): dummy particles and dynamic
boundary get the 4 layers the case names, bit for bit; the deficiency correction gets the one
layer on the wall that the docs advise (layers 1; firstLayerOffset 0;), bit for bit, and the
solver accepts it and runs. Run by CTest with SPHKIT_BIN set to the build's binaries."""
import os
import re
import shutil
import subprocess
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CASE = os.path.join(ROOT, "cases", "hydrostaticTank2D")
BIN = os.path.abspath(os.environ.get("SPHKIT_BIN", os.path.join(ROOT, "build", "bin")))
ENV = dict(os.environ, OMP_NUM_THREADS="1")


def edit(path, old, new):
    with open(path) as f:
        text = f.read()
    assert old in text, (path, old)
    with open(path, "w") as f:
        f.write(text.replace(old, new))


def generate(case):
    return subprocess.run([os.path.join(BIN, "generateParticles"), "-case", case, "-overwrite"], capture_output=True, text=True, env=ENV)


def walls(case):
    with open(os.path.join(case, "0", "walls.vtu"), "rb") as f:
        return f.read()


class WallLayoutFromModel(unittest.TestCase):
    def setUp(self):
        self.work = tempfile.TemporaryDirectory()
        self.case = os.path.join(self.work.name, "tank")
        shutil.copytree(CASE, self.case, ignore=shutil.ignore_patterns("0", "[1-9]*", "postProcessing", "log.*"))
        self.particles = os.path.join(self.case, "system", "generateParticlesDict")
        self.models = os.path.join(self.case, "constant", "boundaryProperties")

    def tearDown(self):
        self.work.cleanup()

    def explicit(self, layout):
        """The walls generated with the layout written in the patch."""
        edit(self.particles, "layers 4;", layout)
        self.assertEqual(generate(self.case).returncode, 0)
        written = walls(self.case)
        edit(self.particles, layout, "")
        return written

    def test_wall_particle_models_get_the_layers_that_fill_the_support(self):
        shipped = self.explicit("layers 4;")
        for model in ("dummyParticles", "dynamicBoundary"):
            with self.subTest(model=model):
                edit(self.models, "dummyParticles", model)
                run = generate(self.case)
                self.assertEqual(run.returncode, 0, run.stderr)
                self.assertIn(f"note: wall patch 'tank': 4 layers from dx/2 behind the wall, for {model} with a kernel support of 3.6 dx", run.stdout)
                self.assertEqual(walls(self.case), shipped)
                edit(self.models, model, "dummyParticles")

    def test_a_wall_force_model_gets_one_layer_on_the_wall_and_runs(self):
        advised = self.explicit("layers 1; firstLayerOffset 0;")
        edit(self.models, "dummyParticles", "deficiencyCorrectionBoundaryIntegral")
        run = generate(self.case)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("1 layer on the wall surface, for the wall-force model deficiencyCorrectionBoundaryIntegral", run.stdout)
        self.assertEqual(walls(self.case), advised)
        edit(os.path.join(self.case, "system", "controlDict"), "endTime         2;", "endTime         0.01;")
        solved = subprocess.run([os.path.join(BIN, "wcsph"), "-case", self.case], capture_output=True, text=True, env=ENV)
        self.assertEqual(solved.returncode, 0, solved.stdout[-2000:] + solved.stderr)
        self.assertTrue(os.path.exists(os.path.join(self.case, "0.01", "walls.vtu")))

    def test_without_a_model_the_generator_says_what_to_write(self):
        os.remove(self.models)
        edit(self.particles, "layers 4;", "")
        run = generate(self.case)
        self.assertEqual(run.returncode, 1)
        self.assertRegex(run.stderr, re.escape("generateParticlesDict:15:13: error: wall patch 'tank' names no layers") + ".*" +
                         re.escape("tank { type dummyParticles; }"))


if __name__ == "__main__":
    unittest.main()
