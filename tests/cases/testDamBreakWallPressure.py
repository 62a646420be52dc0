#!/usr/bin/python3
"""damBreakWallPressure2D at H/dx = 20 to T = 8 with the correction's defaults, compared by the
case's own comparePressure.py: pins the figures doc/boundarySuite.md reports for this row
(RMS of the Delta T = 0.1 window means against De Courcy et al. 2024, P1-P4, read by probes dx/2
in front of the wall and by the wallPressure sensors on it) and the count of fluid behind the
wall at every step. Run by CTest with SPHKIT_BIN set to the build's binaries."""
import os
import shutil
import subprocess
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CASE = os.path.join(ROOT, "cases", "damBreakWallPressure2D")
BIN = os.environ.get("SPHKIT_BIN", os.path.join(ROOT, "build", "bin"))


def first_row(printed):
    """The figures of the first case in comparePressure.py's first block: P1-P4, B, the count behind the wall."""
    return [float(v) for v in printed.strip().splitlines()[1].split()[1:]]


class DamBreakWallPressure(unittest.TestCase):
    def test_documented_figures_at_h_over_dx_20(self):
        with tempfile.TemporaryDirectory() as work:
            case = os.path.join(work, "damBreak")
            os.makedirs(case)
            for part in ("system", "constant"):
                shutil.copytree(os.path.join(CASE, part), os.path.join(case, part))
            particles = os.path.join(case, "system", "generateParticlesDict")
            with open(particles) as f:
                text = f.read()
            with open(particles, "w") as f:
                f.write(text.replace("spacing     0.015;", "spacing     0.03;"))
            subprocess.run([os.path.join(BIN, "generateParticles"), "-case", case], check=True, capture_output=True)
            subprocess.run([os.path.join(BIN, "wcsph"), "-case", case], check=True, capture_output=True)
            result = subprocess.run(["/usr/bin/python3", os.path.join(CASE, "comparePressure.py"), case], check=True, capture_output=True,
                                    text=True)
            values = first_row(result.stdout)
            # doc/boundarySuite.md, deficiencyCorrectionBoundaryIntegral, H/dx = 20.
            for measured, documented in zip(values[:4], (0.469, 0.263, 0.226, 0.217)):
                self.assertAlmostEqual(measured, documented, delta=0.02)
            self.assertEqual(values[5], 0, "fluid behind the wall at some step")
            # The wallPressure sensors on the wall (the model's p_j), as the case's README reports them.
            result = subprocess.run(["/usr/bin/python3", os.path.join(CASE, "comparePressure.py"), "--wall", case], check=True,
                                    capture_output=True, text=True)
            values = first_row(result.stdout)
            for measured, documented in zip(values[:4], (0.527, 0.392, 0.306, 0.118)):
                self.assertAlmostEqual(measured, documented, delta=0.02)
            self.assertTrue(os.path.exists(os.path.join(case, "pressureError.txt")), "the comparison writes into the case it reads")


if __name__ == "__main__":
    unittest.main()
