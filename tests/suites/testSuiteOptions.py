#!/usr/bin/python3
"""The stability and boundary suites refuse an unknown or incomplete option before they run
anything: a mistyped --check would otherwise start the long suite and rewrite doc/. And the
boundary suite reads a comparison script's first block, where the script prints several."""
import importlib.util
import os
import subprocess
import sys
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SUITES = {name: os.path.join(ROOT, "utilities", name, name + ".py") for name in ("stabilitySuite", "boundarySuite")}


class SuiteOptions(unittest.TestCase):
    def refused(self, suite, *arguments):
        run = subprocess.run(["/usr/bin/python3", SUITES[suite], *arguments], capture_output=True, text=True, timeout=60)
        self.assertEqual(run.returncode, 2, run.stdout + run.stderr)
        self.assertEqual(run.stdout, "")  # nothing prepared or run
        return run.stderr

    def test_unknown_and_incomplete_options_stop_first(self):
        for suite in SUITES:
            with self.subTest(suite=suite):
                self.assertIn("unrecognized arguments: --chek", self.refused(suite, "--chek"))
                self.assertIn("argument --work: expected one argument", self.refused(suite, "--check", "--work"))

    def test_the_boundary_suite_reads_the_first_block_of_a_comparison(self):
        # comparePressure.py's output for one case: De Courcy P1-P4, B and the count; Buchner's
        # second digitisation; Lobovsky at P1, P3, P4. The suite read the last line until 2026-12-07.
        printed = ("# case, RMS ... at P1 P2 P3 P4 and Buchner (2002) at B, most behind\ndam 0.469 0.264 0.226 0.218 0.479 0\n"
                   "# case, the same at B against PySPH's digitisation\ndam 0.470\n"
                   "# case, the same at P1 P3 P4 against Lobovsky et al.\ndam 0.566 0.331 0.289\n")
        spec = importlib.util.spec_from_file_location("boundarySuite", SUITES["boundarySuite"])
        suite = importlib.util.module_from_spec(spec)
        arguments, sys.argv = sys.argv, [SUITES["boundarySuite"]]  # it reads its options as it loads
        try:
            spec.loader.exec_module(suite)
        finally:
            sys.argv = arguments
        self.assertEqual(suite.first_figures(printed), [0.469, 0.264, 0.226, 0.218, 0.479, 0.0])
        self.assertEqual(suite.first_figures("# case, RMS and max\nslosh 0.0243 0.0604 0\n"), [0.0243, 0.0604, 0.0])

    def test_the_stability_suite_needs_a_job(self):
        self.assertIn("argument --jobs: at least 1, not 0", self.refused("stabilitySuite", "--jobs", "0"))


if __name__ == "__main__":
    unittest.main()
