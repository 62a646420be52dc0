#!/usr/bin/python3
"""A case's Allclean removes what the tools and the case's scripts wrote, and keeps what a user
put in the case (on c09449c it removed every folder named as a number and every log.*). Runs
damBreak2D's Allrun at a coarse spacing, adds a user's files beside and inside what it wrote,
and cleans. Run by CTest with SPHKIT_BIN set to the build's binaries."""
import os
import shutil
import subprocess
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CASE = os.path.join(ROOT, "cases", "damBreak2D")
BIN = os.path.abspath(os.environ.get("SPHKIT_BIN", os.path.join(ROOT, "build", "bin")))


def tree(top):
    found = set()
    for directory, _, files in os.walk(top):
        for name in files:
            found.add(os.path.relpath(os.path.join(directory, name), top))
    return found


def copy_as_shipped(shipped, case, files):
    """The case as in git, whatever an earlier Allrun left beside it (the README's first command
    runs damBreak2D): its dictionaries and the named files."""
    for part in ("system", "constant"):
        shutil.copytree(os.path.join(shipped, part), os.path.join(case, part))
    for name in files:
        shutil.copy2(os.path.join(shipped, name), case)


class CleanCase(unittest.TestCase):
    def test_allclean_keeps_what_the_user_wrote(self):
        with tempfile.TemporaryDirectory() as work:
            case = os.path.join(work, "damBreak")
            copy_as_shipped(CASE, case, ("Allrun", "Allclean", "README.md", "answers", "compareFront.py", "martinMoyce1952Front.csv",
                                          "koshizukaOka1996Front.csv"))
            particles = os.path.join(case, "system", "generateParticlesDict")
            with open(particles) as f:
                text = f.read()
            with open(particles, "w") as f:
                f.write(text.replace("spacing     0.00142875;", "spacing     0.0028575;"))
            control = os.path.join(case, "system", "controlDict")
            with open(control) as f:
                text = f.read()
            with open(control, "w") as f:
                f.write(text.replace("endTime         0.2;", "endTime         0.06;"))
            before = tree(case)
            env = dict(os.environ, SPHKIT_BIN=BIN, OMP_NUM_THREADS="1")
            subprocess.run([os.path.join(case, "Allrun")], check=True, capture_output=True, env=env)
            self.assertIn("0.06/fluid.vtu", tree(case))
            self.assertIn("postProcessing/front/0/surgeFront.dat", tree(case))
            mine = {"2024/notes.txt", "0.01/myPlot.png", "postProcessing/myAnalysis/notes.md", "log.mine", "other.pvd"}
            for name in mine:
                os.makedirs(os.path.dirname(os.path.join(case, name)) or case, exist_ok=True)
                with open(os.path.join(case, name), "w") as f:
                    f.write("the user's\n")
            cleaned = subprocess.run([os.path.join(case, "Allclean")], check=True, capture_output=True, text=True, env=env)
            left = tree(case)
            # What the user wrote stays, and with it the time folder it sits in (said on the console).
            self.assertEqual(left - before, mine | {"0.01/fluid.vtu", "0.01/walls.vtu"})
            self.assertIn("keeping 0.01/", cleaned.stdout)
            self.assertEqual(before - left, set())

    def test_allclean_removes_csv_states_profiles_and_variants(self):
        # hydrostaticTank3D writes fluid.csv beside fluid.vtu (writeCsv), lineSample profiles in
        # postProcessing/<name>/<t0>/<time>/ and variants/: Allclean leaves the case as shipped.
        with tempfile.TemporaryDirectory() as work:
            case = os.path.join(work, "tank")
            copy_as_shipped(os.path.join(ROOT, "cases", "hydrostaticTank3D"), case, ("Allrun", "Allclean", "checkStillWater.py", "README.md"))
            edits = [("system/generateParticlesDict", "spacing     0.04;", "spacing     0.05;"),
                     ("system/controlDict", "endTime         4;", "endTime         0.1;")]
            for path, old, new in edits:
                with open(os.path.join(case, path)) as f:
                    text = f.read()
                with open(os.path.join(case, path), "w") as f:
                    f.write(text.replace(old, new))
            before = tree(case)
            env = dict(os.environ, SPHKIT_BIN=BIN, OMP_NUM_THREADS="1")
            subprocess.run([os.path.join(case, "Allrun")], check=True, capture_output=True, env=env)
            self.assertIn("0.1/fluid.csv", tree(case))
            self.assertIn("postProcessing/pressure/0/0/line.csv", tree(case))
            self.assertIn("variants/dummyParticles/0.1/fluid.vtu", tree(case))
            cleaned = subprocess.run([os.path.join(case, "Allclean")], check=True, capture_output=True, text=True, env=env)
            self.assertEqual(tree(case), before, cleaned.stdout)


if __name__ == "__main__":
    unittest.main()
