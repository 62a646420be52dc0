#!/usr/bin/python3
"""benchmark.py --dualsphysics: a stand-in for DualSPHysics' GenCase and CPU solver (scripts that
record their command lines, the solver taking a known time) runs beside sphkit on the same thread
count and end time; the comparison table gives both whole processes' times and their ratio; a
missing half of the pair of options, a folder without the executables, and a failing GenCase stop
with a message. Run by CTest with SPHKIT_BIN set to the build's binaries."""
import os
import re
import stat
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BENCHMARK = os.path.join(ROOT, "utilities", "benchmark", "benchmark.py")

# GenCase NAME_Def OUT/NAME -save:none writes OUT/NAME.xml; the solver sleeps 0.4 s.
STAND_IN = {
    "GenCase_linux64": "import sys\nopen(sys.argv[2] + '.xml', 'w').write(open(sys.argv[1] + '.xml').read())\n"
                       "open(sys.argv[2] + '.gencase', 'w').write(' '.join(sys.argv[1:]))\n",
    "DualSPHysics5.4CPU_linux64": "import os, sys, time\ntime.sleep(0.4)\n"
                                  "open(os.path.join(sys.argv[4], 'argv.%s' % sys.argv[2]), 'w').write(' '.join(sys.argv[1:]))\n",
}


def stand_in(directory, failing_gencase=False):
    for name, body in STAND_IN.items():
        path = os.path.join(directory, name)
        with open(path, "w") as f:
            f.write("#!%s\n%s%s" % (sys.executable, "raise SystemExit(3)\n" if failing_gencase and name.startswith("GenCase") else "", body))
        os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)


def benchmark(work, *options):
    return subprocess.run([sys.executable, BENCHMARK, "--case", "damBreak2D", "--threads", "1", "2", "--factors", "4", "--end-time", "0.01",
                           "--work", work, *options], capture_output=True, text=True, timeout=300)


class BenchmarkDualSPHysics(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.TemporaryDirectory()
        self.bin = os.path.join(self.scratch.name, "bin")
        os.makedirs(self.bin)
        self.xml = os.path.join(self.scratch.name, "CaseDambreak_Def.xml")
        with open(self.xml, "w") as f:
            f.write("<case/>\n")
        self.work = os.path.join(self.scratch.name, "work")

    def tearDown(self):
        self.scratch.cleanup()

    def test_runs_beside_sphkit_and_gives_the_ratio(self):
        stand_in(self.bin)
        run = benchmark(self.work, "--dualsphysics", self.bin, "--dualsphysics-case", self.xml)
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        out = os.path.join(self.work, "dualsphysics")
        with open(os.path.join(out, "CaseDambreak.gencase")) as f:
            self.assertEqual(f.read(), "%s %s -save:none" % (self.xml[:-4], os.path.join(out, "CaseDambreak")))
        for threads in (1, 2):
            with open(os.path.join(out, "argv.-ompthreads:%d" % threads)) as f:
                self.assertEqual(f.read(), "-cpu -ompthreads:%d %s %s -dirdataout data -sv:none -svres:0 -tmax:0.01 -tout:0.01"
                                 % (threads, os.path.join(out, "CaseDambreak"), out))
        rows = re.findall(r"^\| damBreak2D dx x4 \| (\d) \| (\S+) \(\S+-\S+\) \| (\S+) \(\S+-\S+\) \| (\S+) \|$", run.stdout, re.M)
        self.assertEqual([r[0] for r in rows], ["1", "2"], run.stdout)
        for _, ours, theirs, ratio in rows:
            self.assertGreaterEqual(float(theirs), 0.4)  # the stand-in's sleep, timed from outside
            self.assertAlmostEqual(float(ratio), float(ours) / float(theirs), delta=0.01 + 0.006 * float(ratio))

    def test_bad_options_stop_first(self):
        half = benchmark(self.work, "--dualsphysics", self.bin)
        self.assertNotEqual(half.returncode, 0)
        self.assertIn("--dualsphysics and --dualsphysics-case go together", half.stderr)
        empty = benchmark(self.work, "--dualsphysics", self.bin, "--dualsphysics-case", self.xml)
        self.assertNotEqual(empty.returncode, 0)
        self.assertIn("no executable GenCase* and DualSPHysics*CPU* there", empty.stderr)
        stand_in(self.bin, failing_gencase=True)
        failing = benchmark(self.work, "--dualsphysics", self.bin, "--dualsphysics-case", self.xml)
        self.assertNotEqual(failing.returncode, 0)
        self.assertIn("GenCase failed on %s, see %s" % (self.xml, os.path.join(self.work, "dualsphysics", "log.GenCase")), failing.stderr)


if __name__ == "__main__":
    unittest.main()
