#!/usr/bin/python3
"""The stability and boundary suites refuse an unknown or incomplete option before they run
anything: a mistyped --check would otherwise start the long suite and rewrite doc/."""
import os
import subprocess
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

    def test_the_stability_suite_needs_a_job(self):
        self.assertIn("argument --jobs: at least 1, not 0", self.refused("stabilitySuite", "--jobs", "0"))


if __name__ == "__main__":
    unittest.main()
