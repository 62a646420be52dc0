#!/usr/bin/python3
"""SPHERIC Test 2 (cases/damBreak3D, dx = 0.025 m, to t = 1 s) with its walls switched to the
boundary-integral deficiency correction as a user switches them, one word per patch in
constant/boundaryProperties (the patches name `layers 1` and no offset: the generator lays them on
the wall surface): the run's figures are those doc/boundaryFindings.md's table gives in its row
`deficiencyCorrectionBoundaryIntegral`, to the digits it prints them with (the gauges' and the
probes' L2 against the experiment, the averaged wall sensors' L2 at P1-P5, the most fluid behind a
wall at any step). About 10 minutes on one thread: CTest label long. Run by CTest with SPHKIT_BIN
set to the build's binaries."""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "utilities", "answers"))
import checkAnswers  # noqa: E402

BIN = os.path.abspath(os.environ.get("SPHKIT_BIN", os.path.join(ROOT, "build", "bin")))
MODEL = "deficiencyCorrectionBoundaryIntegral"


def documented_row():
    """The row's cells: gauges, probes, wall sensors (each 'a / b / ...'), most behind."""
    with open(os.path.join(ROOT, "doc", "boundaryFindings.md")) as f:
        row = re.search(r"^\| %s \| ([^|]+) \| ([^|]+) \| ([^|]+) \| (\d+) \|" % MODEL, f.read(), re.M)
    return [cell.strip().split(" / ") for cell in row.groups()[:3]] + [row.group(4)]


class SphericOnTheCorrection(unittest.TestCase):
    def test_the_documented_row(self):
        gauges, probes, sensors, behind = documented_row()
        with tempfile.TemporaryDirectory() as work:
            case = os.path.join(work, "damBreak3D")
            shutil.copytree(os.path.join(ROOT, "cases", "damBreak3D"), case, ignore=checkAnswers.OUTPUTS)
            with open(os.path.join(case, "constant", "boundaryProperties"), "w") as f:
                f.write("tank { type %s; }\nbox { type %s; }\n" % (MODEL, MODEL))
            control = os.path.join(case, "system", "controlDict")
            with open(control) as f:
                text = f.read()
            with open(control, "w") as f:
                f.write(text.replace("functions\n{", "functions\n{\n    leaks { type wallPenetrations; }", 1))
            environment = dict(os.environ, OMP_NUM_THREADS="1")
            made = subprocess.run([os.path.join(BIN, "generateParticles"), "-case", case], capture_output=True, text=True, env=environment)
            self.assertEqual(made.returncode, 0, made.stderr)
            self.assertIn("note: wall patch 'tank': firstLayerOffset 0, the first layer on the wall surface", made.stdout)
            run = subprocess.run([os.path.join(BIN, "wcsph"), "-case", case], capture_output=True, text=True, env=environment)
            self.assertEqual(run.returncode, 0, run.stdout[-2000:] + run.stderr)
            with open(os.path.join(case, "postProcessing", "leaks", "0", "penetrations.dat")) as f:
                most = max(int(line.split()[1]) for line in f if not line.startswith("#"))
        self.assertEqual(str(most), behind)
        figures = [("height at gauge %d" % k, quoted) for k, quoted in enumerate(gauges)]
        figures += [("p at probe %d" % k, quoted) for k, quoted in enumerate(probes)]
        figures += [("averaged pressure at sensor %d" % k, quoted) for k, quoted in enumerate(sensors)]
        for quantity, quoted in figures:
            with self.subTest(quantity=quantity):
                printed = re.search(re.escape(quantity) + r": L1 \S+, L2 (\S+),", run.stdout).group(1)
                self.assertTrue(checkAnswers.agrees(printed, 1.0, quoted), "%s: the run prints L2 %s, the table %s" % (quantity, printed, quoted))


if __name__ == "__main__":
    unittest.main()
