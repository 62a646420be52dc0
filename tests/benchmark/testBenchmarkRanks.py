#!/usr/bin/python3
"""benchmark.py --ranks: the MPI runs beside the 1-thread run of the same case, each row's
efficiency the 1-thread time over the rank count times the row's, the peak memory a rank's; and
--ranks without a 1-thread run stops first. Run by CTest (builds with MPI) with SPHKIT_BIN set to
the build's binaries and MPIEXEC to mpirun."""
import os
import re
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BENCHMARK = os.path.join(ROOT, "utilities", "benchmark", "benchmark.py")


class BenchmarkRanks(unittest.TestCase):
    def test_rank_rows_beside_the_one_thread_run(self):
        with tempfile.TemporaryDirectory() as work:
            run = subprocess.run([sys.executable, BENCHMARK, "--case", "damBreak2D", "--threads", "1", "--ranks", "2", "--factors", "4",
                                  "--end-time", "0.01", "--work", work], capture_output=True, text=True, timeout=300)
            self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
            self.assertTrue(os.path.exists(os.path.join(work, "damBreak2D-x4", "0.01", "fluid.pvtu")), "the 2-rank run wrote its pieces")
        # case | particles | threads | steps | time loop | runs | rates | peak | bytes per particle | ratio
        rows = [m.groups() for m in re.finditer(
            r"^\| damBreak2D dx x4 \| (\d+) \+ (\d+) \| ([^|]+?) \| (\d+) \| (\S+) \| \S+ \| \S+ \| \S+ \| \d+ MB( \(a rank\))? \| (\S+) \| (.+?) \|$",
            run.stdout, re.M)]
        self.assertEqual([r[2] for r in rows], ["1", "2 ranks x 1"], run.stdout)
        one, two = rows
        self.assertEqual(one[:2], two[:2], "the same particles")
        self.assertEqual(one[3], two[3], "the same steps (the parallel run is the serial one)")
        self.assertEqual((one[5], two[5]), (None, " (a rank)"))
        self.assertEqual(two[6], "-")  # a rank's peak is no cost per particle of the case
        ratio, efficiency = re.fullmatch(r"(\S+) \(efficiency (\d+) %\)", two[7]).groups()
        self.assertAlmostEqual(float(ratio), float(two[4]) / float(one[4]), delta=0.01 + 0.006 * float(ratio))
        self.assertAlmostEqual(int(efficiency), 100 * float(one[4]) / (2 * float(two[4])), delta=1.5)

    def test_ranks_without_a_one_thread_run_stop_first(self):
        run = subprocess.run([sys.executable, BENCHMARK, "--threads", "2", "--ranks", "2"], capture_output=True, text=True)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("--ranks compares with the 1-thread run: --threads must include 1", run.stderr)


if __name__ == "__main__":
    unittest.main()
