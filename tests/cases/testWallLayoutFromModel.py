#!/usr/bin/python3
"""A wall patch that names no layers takes the layout its wall model needs, so switching the
model is one word in constant/boundaryProperties and a rerun of generateParticles -overwrite.
On hydrostaticTank2D (quintic kernel, hdx 1.2: support 3.6 dx): dummy particles and dynamic
boundary get the 4 layers the case names, bit for bit; the deficiency correction gets the one
layer on the wall that the docs advise (layers 1; firstLayerOffset 0;), bit for bit, and the
solver accepts it and runs; a patch that names `layers 1` and no offset gets the same. Run by CTest with SPHKIT_BIN set to the build's binaries."""
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

    def test_a_patch_that_names_its_layers_but_no_offset_takes_its_models_offset(self):
        # `layers 1;` alone under a wall-force model lies on the wall surface, as the model needs
        # (it lay dx/2 behind it, silently, before 2026-12-07); under dummy particles dx/2 behind.
        for model, offset in (("deficiencyCorrection", "0"), ("dummyParticles", "0.5")):
            with self.subTest(model=model):
                edit(self.particles, "layers 4;", f"layers 1; firstLayerOffset {offset};")
                self.assertEqual(generate(self.case).returncode, 0)
                written = walls(self.case)
                edit(self.particles, f"layers 1; firstLayerOffset {offset};", "layers 1;")
                edit(self.models, "dummyParticles", model)
                run = generate(self.case)
                self.assertEqual(run.returncode, 0, run.stderr)
                self.assertEqual(walls(self.case), written)
                note = f"note: wall patch 'tank': firstLayerOffset 0, the first layer on the wall surface, for the wall-force model {model}"
                if offset == "0":
                    self.assertIn(note, run.stdout)
                else:
                    self.assertNotIn("firstLayerOffset", run.stdout)
                edit(self.models, model, "dummyParticles")
                edit(self.particles, "layers 1;", "layers 4;")

    def test_a_solid_thinner_than_twice_its_layers_holds_them_from_both_faces(self):
        # Quintic kernel, hdx 1.2: dummy particles need 4 layers. A post 6 dx thick holds 3
        # behind each face by the field `layer`, but the fluid at either face finds all 6 rows:
        # the generator records 4 and the solver runs it, and continues from the state it wrote.
        # A plate 2 dx thick holds 1 behind its long
        # faces: the generator says the fluid on its sides reach each other through it, and the
        # solver stops.
        for width, runs in ((0.12, True), (0.04, False)):
            with self.subTest(width=width):
                shutil.copytree(CASE, self.case, dirs_exist_ok=True, ignore=shutil.ignore_patterns("0", "[1-9]*", "postProcessing", "log.*"))
                edit(os.path.join(self.case, "system", "controlDict"), "endTime         2;", "endTime         0.002;")
                post = f"post {{ type polygon; points ((1 0) ({1 + width:g} 0) ({1 + width:g} 0.5) (1 0.5)); side right; }}"
                edit(self.particles, "    tank    {", f"    {post}\n    tank    {{")
                with open(self.models, "a") as f:
                    f.write("post { type dummyParticles; }\n")
                made = generate(self.case)
                self.assertEqual(made.returncode, 0, made.stderr)
                note = "the layers from its faces meet inside it, where it is thinner than twice its 4 layers" if runs else "thinner than its 4 layers"
                self.assertIn("note: wall patch 'post': " + note, made.stdout)
                solved = subprocess.run([os.path.join(BIN, "wcsph"), "-case", self.case], capture_output=True, text=True, env=ENV)
                if runs:
                    self.assertEqual(solved.returncode, 0, solved.stdout[-2000:] + solved.stderr)
                    # The written state keeps the record: a run continues from it.
                    edit(os.path.join(self.case, "system", "controlDict"), "endTime         0.002;", "endTime         0.004;")
                    resumed = subprocess.run([os.path.join(BIN, "wcsph"), "-case", self.case], capture_output=True, text=True, env=ENV)
                    self.assertEqual(resumed.returncode, 0, resumed.stdout[-2000:] + resumed.stderr)
                    self.assertIn("Starting time loop at t = 0.002", resumed.stdout)
                else:
                    self.assertIn("'dummyParticles' needs at least 4 layers of wall particles to fill the kernel support", solved.stderr)
                    self.assertIn("a solid thinner than its layers holds fewer", solved.stderr)

    def test_without_a_model_the_generator_says_what_to_write(self):
        os.remove(self.models)
        edit(self.particles, "layers 4;", "")
        run = generate(self.case)
        self.assertEqual(run.returncode, 1)
        self.assertRegex(run.stderr, re.escape("generateParticlesDict:15:13: error: wall patch 'tank' names no layers") + ".*" +
                         re.escape("tank { type dummyParticles; }"))


if __name__ == "__main__":
    unittest.main()
