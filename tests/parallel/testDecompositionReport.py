#!/usr/bin/python3
"""decompositionReport on shipped cases, through mpirun: the ranks together own every particle
the generator wrote, once; one rank has no halo; more ranks share the weight within the RCB's
lattice granularity and exchange halos, across the periodic seam too; bad options stop with a
message; the table of doc/performance.md is what the report prints. Run by CTest with SPHKIT_BIN set to the build's binaries and MPIEXEC to mpirun."""
import os
import re
import shutil
import subprocess
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.path.abspath(os.environ.get("SPHKIT_BIN", os.path.join(ROOT, "build", "bin")))
MPIEXEC = os.environ.get("MPIEXEC", "mpirun")
ENV = dict(os.environ, OMP_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


class DecompositionReport(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.TemporaryDirectory()
        cls.generated = {}
        for name in ("damBreak2D", "taylorGreen2D", "damBreak3D"):
            case = os.path.join(cls.work.name, name)
            shutil.copytree(os.path.join(ROOT, "cases", name), case,
                            ignore=shutil.ignore_patterns("[0-9]*", "postProcessing", "log.*", "*.png", "*.pvd"))
            run = subprocess.run([os.path.join(BIN, "generateParticles"), "-case", case], capture_output=True, text=True, env=ENV, check=True)
            fluid, walls = map(int, re.search(r"(\d+) fluid particles, (\d+) wall particles", run.stdout).groups())
            cls.generated[name] = (case, fluid, walls)

    @classmethod
    def tearDownClass(cls):
        cls.work.cleanup()

    def report(self, name, ranks, *options):
        case = self.generated[name][0]
        run = subprocess.run([MPIEXEC, "-np", str(ranks), "--oversubscribe", os.path.join(BIN, "decompositionReport"), "-case", case, *options],
                             capture_output=True, text=True, env=ENV, timeout=120)
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        total = re.search(r"total: (\d+) fluid and (\d+) wall particles owned, (\d+) halo copies .*?, (\d+) messages", run.stdout)
        imbalance = float(re.search(r"load imbalance \(largest / mean weight\): ([\d.]+)", run.stdout).group(1))
        rows = re.findall(r"^ +\d+ +(\d+) +(\d+) +(\d+) +(\d+) ", run.stdout, re.M)
        return [int(g) for g in total.groups()], imbalance, rows

    def test_the_ranks_own_every_particle_once_and_share_the_weight(self):
        _, fluid, walls = self.generated["damBreak2D"]
        (owned_fluid, owned_walls, halos, messages), imbalance, rows = self.report("damBreak2D", 1)
        self.assertEqual((owned_fluid, owned_walls, halos, messages), (fluid, walls, 0, 0))
        self.assertEqual(len(rows), 1)
        (owned_fluid, owned_walls, halos, messages), imbalance, rows = self.report("damBreak2D", 3)
        self.assertEqual((owned_fluid, owned_walls), (fluid, walls))
        self.assertEqual(len(rows), 3)
        self.assertGreater(halos, 0)
        self.assertGreaterEqual(messages, 4)  # three boxes: each exchanges with one or two others
        # Cuts between lattice columns: a rank bordering two cuts is off by at most two columns of
        # 40 fluid particles from its share, at least 1,067 (3,200 fluid particles over 3, and a
        # tenth of each wall particle within the fluid's reach).
        self.assertLess(imbalance, 1.0 + 2 * 40 / 1067)

    def test_a_periodic_case_exchanges_across_its_seam(self):
        _, fluid, _ = self.generated["taylorGreen2D"]
        (owned_fluid, _, halos, messages), _, rows = self.report("taylorGreen2D", 2)
        self.assertEqual(owned_fluid, fluid)
        # Two boxes on a periodic square: each sees the other across the cut and across the
        # seam, so each owned column beside either face is sent: twice the single cut's halo.
        per_rank_halo = [int(r[2]) for r in rows]
        self.assertEqual(per_rank_halo[0], per_rank_halo[1])
        side = round(fluid ** 0.5)
        self.assertEqual(halos % (2 * side), 0, f"{halos} halo copies are no whole number of columns of {side}")
        self.assertEqual(messages, 2)

    def test_the_documented_figures_are_the_reports(self):
        with open(os.path.join(ROOT, "doc", "performance.md")) as f:
            doc = f.read()
        section = doc[doc.index("## Several ranks: the decomposition measured"):]
        section = section[:section.index("\n## ")]
        rows = re.findall(r"^\| (damBreak[23]D)(, walls weighing 1)? \| (\d+) \| ([\d.]+) % \| (\d+) \| ([\d,]+) \| ([\d.]+) \| ([\d.]+) / ([\d.]+) MiB \|$",
                          section, re.M)
        self.assertEqual(len(rows), 9)
        for name, heavy_walls, ranks, share, messages, size, imbalance, largest, mean in rows:
            case = self.generated[name][0]
            options = ["-wallWeight", "1"] if heavy_walls else []
            run = subprocess.run([MPIEXEC, "-np", ranks, "--oversubscribe", os.path.join(BIN, "decompositionReport"), "-case", case, *options],
                                 capture_output=True, text=True, env=ENV, timeout=120)
            self.assertEqual(run.returncode, 0, run.stderr)
            total = re.search(r"halo copies \(([\d.]+) % of the owned\), (\d+) messages and (\d+) bytes per evaluation", run.stdout)
            load = re.search(r"imbalance \(largest / mean weight\): ([\d.]+); memory per rank: largest ([\d.]+) MiB, mean ([\d.]+) MiB", run.stdout)
            printed = (f"{float(total.group(1)):.1f}", total.group(2), f"{int(total.group(3)):,}", f"{float(load.group(1)):.3f}", load.group(2), load.group(3))
            self.assertEqual(printed, (share, messages, size, imbalance, largest, mean), f"{name}{heavy_walls} on {ranks} ranks")

    def test_a_bad_option_stops_with_a_message(self):
        case = self.generated["damBreak2D"][0]
        run = subprocess.run([MPIEXEC, "-np", "2", "--oversubscribe", os.path.join(BIN, "decompositionReport"), "-case", case, "-wallWeight", "-1"],
                             capture_output=True, text=True, env=ENV, timeout=60)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("error: -wallWeight takes a positive number, found '-1'", run.stderr)


if __name__ == "__main__":
    unittest.main()
