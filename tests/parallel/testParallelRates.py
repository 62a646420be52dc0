#!/usr/bin/python3
"""wcsph -parallel -rates on 1-4 ranks (mpirun, oversubscribed, one thread each) against the
serial -rates of the same build: every particle's every array (acceleration, density rate,
pressure, ...) equal bit for bit, and the .csv files the same text, on a periodic case without walls (taylorGreen2D), the 2D dam
break as shipped (dummy particles, no-slip: the walls' extrapolated state crosses ranks), the 2D
dam break on dynamic-boundary walls, the periodic channel with summation density (the summed
density crosses ranks), the deficiency correction in a tank, mDBC in a tank and the 3D dam break (SPHERIC Test 2, dynamic boundary, pairs in vector
lanes). Each from a state the serial solver wrote after some steps: particles off
the lattice (on it, a halo too narrow by a fifth of the support can go unseen: the particles it
leaves out lie at exactly the support) and stored in the order the cell sorts left. Also mDBC,
whose ghost nodes read the fluid twice a wall particle's depth in front of it. Run by CTest with SPHKIT_BIN set to the build's binaries and MPIEXEC to mpirun."""
import os
import re
import shutil
import subprocess
import tempfile
import unittest

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.path.abspath(os.environ.get("SPHKIT_BIN", os.path.join(ROOT, "build", "bin")))
MPIEXEC = os.environ.get("MPIEXEC", "mpirun")
ENV = dict(os.environ, OMP_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
# Under the sanitizers each case is compared on one rank count, the smallest above one (a rank
# boundary, halos, every exchange); the release build compares every count.
SANITIZED = os.environ.get("SPHKIT_SANITIZED") == "1"


def arrays(path):
    """Every point array of a .vtu or .pvtu, and the points, in the order of the particles' ids."""
    reader = vtk.vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu") else vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    data = grid.GetPointData()
    ids = vtk_to_numpy(data.GetArray("id"))
    order = np.argsort(ids, kind="stable")
    result = {"points": vtk_to_numpy(grid.GetPoints().GetData())[order]}
    for a in range(data.GetNumberOfArrays()):
        result[data.GetArrayName(a)] = vtk_to_numpy(data.GetArray(a))[order]
    return result


class ParallelRates(unittest.TestCase):
    def setUp(self):
        self.work = tempfile.TemporaryDirectory()
        self.addCleanup(self.work.cleanup)

    def case(self, name, end_time, boundary=None, density=None):
        case = os.path.join(self.work.name, name)
        shutil.copytree(os.path.join(ROOT, "cases", name), case,
                        ignore=shutil.ignore_patterns("[0-9]*", "postProcessing", "log.*", "*.png", "*.pvd"))
        if boundary:  # the walls' model, before the generator lays them out for it
            path = os.path.join(case, "constant", "boundaryProperties")
            with open(path) as f:
                text = f.read()
            with open(path, "w") as f:
                f.write(re.sub(r"type\s+\w+;(\s*noSlip\s+\w+;)?", f"type {boundary};", text))
        if density:
            path = os.path.join(case, "system", "sphSchemes")
            with open(path) as f:
                text = f.read()
            with open(path, "w") as f:
                f.write(re.sub(r"density\s+\{\s*type\s+\w+;\s*\}", f"density {{ type {density}; }}", text))
        subprocess.run([os.path.join(BIN, "generateParticles"), "-case", case], capture_output=True, env=ENV, check=True)
        path = os.path.join(case, "system", "controlDict")
        with open(path) as f:
            text = f.read()
        text = re.sub(r"^endTime\s+[^;]+;", f"endTime {end_time};", text, flags=re.M)
        text = re.sub(r"^writeInterval\s+[^;]+;", f"writeInterval {end_time};", text, flags=re.M)
        with open(path, "w") as f:
            f.write(text)
        run = subprocess.run([os.path.join(BIN, "wcsph"), "-case", case], capture_output=True, text=True, env=ENV)
        self.assertEqual(run.returncode, 0, run.stdout[-2000:] + run.stderr[-2000:])
        self.assertTrue(os.path.isdir(os.path.join(case, str(end_time))), os.listdir(case))
        return case

    def rates(self, case, ranks=None):
        command = [os.path.join(BIN, "wcsph"), "-rates", "-case", case]
        if ranks:
            command = [MPIEXEC, "-np", str(ranks), "--oversubscribe", command[0], "-parallel", *command[1:]]
        run = subprocess.run(command, capture_output=True, text=True, env=ENV, timeout=300)
        self.assertEqual(run.returncode, 0, run.stdout[-3000:] + run.stderr[-3000:])
        directory = os.path.join(case, "postProcessing", "rates", self.start)
        suffix = ".pvtu" if ranks else ".vtu"
        written = {}
        for part in ("fluid", "walls"):
            with open(os.path.join(directory, part + ".csv")) as f:
                written[part] = (arrays(os.path.join(directory, part + suffix)), f.read())
        return written

    def assert_equal_to_serial(self, case, ranks):
        serial_written = self.rates(case)
        serial = {part: arrays for part, (arrays, _) in serial_written.items()}
        if SANITIZED:
            ranks = (min(n for n in ranks if n > 1),)
        for n in ranks:
            parallel_written = self.rates(case, n)
            parallel = {part: arrays for part, (arrays, _) in parallel_written.items()}
            for part in ("fluid", "walls"):
                self.assertEqual(serial_written[part][1], parallel_written[part][1], f"{part}.csv on {n} ranks")
                # Pieces carry each particle's place in the serial order besides what the serial state holds.
                self.assertEqual(sorted([*serial[part], "orderCell", "orderRank"]), sorted(parallel[part]), f"{part} arrays on {n} ranks")
                for name, values in serial[part].items():
                    different = np.count_nonzero(np.any(np.atleast_2d(values.T).T != np.atleast_2d(parallel[part][name].T).T, axis=-1)
                                                 if values.ndim > 1 else values != parallel[part][name])
                    self.assertEqual(different, 0, f"{part} '{name}' differs at {different} of {len(values)} particles on {n} ranks")

    def test_a_periodic_case_on_one_to_four_ranks(self):
        self.start = "0.02"
        self.assert_equal_to_serial(self.case("taylorGreen2D", 0.02), (1, 2, 3, 4))

    def test_the_2d_dam_break_as_shipped_on_dummy_particles(self):
        self.start = "0.02"
        self.assert_equal_to_serial(self.case("damBreak2D", 0.02), (2, 3, 4))

    def test_the_periodic_channel_with_summation_density(self):
        self.start = "0.01"
        self.assert_equal_to_serial(self.case("poiseuille2D", 0.01, density="summation"), (2, 3))

    def test_the_2d_dam_break_on_dynamic_boundary_walls(self):
        self.start = "0.02"
        self.assert_equal_to_serial(self.case("damBreak2D", 0.02, "dynamicBoundary"), (2, 3, 4))

    def test_the_3d_dam_break(self):
        self.start = "0.005"
        self.assert_equal_to_serial(self.case("damBreak3D", 0.005), (2, 4))

    def test_the_deficiency_correction_calibrated_in_a_tank(self):
        # C_j from the 4 nearest fluid particles: the halo reaches 3 kernel supports.
        self.start = "0.3"
        self.assert_equal_to_serial(self.case("rectangularTank2D", 0.3), (2, 3))

    def test_mdbc_in_a_tank(self):
        # A wall particle's ghost node lies twice its depth in front of it: the halo reaches the
        # fluid around the deepest one (7 dx), beyond the support (3.6 dx).
        self.start = "0.05"
        self.assert_equal_to_serial(self.case("hydrostaticTankMDBC2D", 0.05), (2, 3, 4))

if __name__ == "__main__":
    unittest.main()
