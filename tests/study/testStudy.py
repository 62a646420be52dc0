#!/usr/bin/python3
"""The study utility: the dictionary editing it relies on, a two-point sweep end to end (its
CSV, Markdown, plot and resumption), and the errors that must stop a sweep before any run.
Run by CTest with SPHKIT_BIN set to the build's binaries."""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "utilities", "study"))
import foamDictionary  # noqa: E402

STUDY = os.path.join(ROOT, "utilities", "study", "study.py")


class FoamDictionaryTest(unittest.TestCase):
    TEXT = "a 1; // one\nb { c (1 2); d { e f; } }\n/* g */ h \"x y\";\n"

    def test_parse_and_find(self):
        entries = foamDictionary.parse(self.TEXT)
        self.assertEqual(foamDictionary.find(entries, "a").value, ["1"])
        self.assertEqual(foamDictionary.words(foamDictionary.find(entries, "b/c")), ["1", "2"])
        self.assertEqual(foamDictionary.find(entries, "b/d/e").value, ["f"])
        self.assertIsNone(foamDictionary.find(entries, "b/x"))

    def test_set_entry_keeps_everything_else(self):
        self.assertEqual(foamDictionary.set_entry(self.TEXT, "b/d/e", "g"), "a 1; // one\nb { c (1 2); d { e g; } }\n/* g */ h \"x y\";\n")
        self.assertEqual(foamDictionary.set_entry(self.TEXT, "a", "{ k 2; }"), "a { k 2; } // one\nb { c (1 2); d { e f; } }\n/* g */ h \"x y\";\n")
        self.assertEqual(foamDictionary.set_entry(self.TEXT, "b", "3"), "a 1; // one\nb 3;\n/* g */ h \"x y\";\n")
        with self.assertRaises(foamDictionary.DictionaryError):
            foamDictionary.set_entry(self.TEXT, "b/q", "1")

    def test_malformed_text_names_the_line(self):
        with self.assertRaisesRegex(foamDictionary.DictionaryError, "dict:2: entry 'b' does not end with ';'"):
            foamDictionary.parse("a 1;\nb 2\n", "dict")


class StudyTest(unittest.TestCase):
    def setUp(self):
        self.work = tempfile.mkdtemp(prefix="sphkit-study-")
        self.case = os.path.join(self.work, "couette2D")
        source = os.path.join(ROOT, "cases", "couette2D")
        for part in ("system", "constant"):
            shutil.copytree(os.path.join(source, part), os.path.join(self.case, part))
        self.output = os.path.join(self.work, "results")

    def tearDown(self):
        shutil.rmtree(self.work)

    def study(self, kernels):
        path = os.path.join(self.case, "system", "studyDict")
        with open(path, "w") as f:
            f.write("error velocityError;\nresolution spacing;\nparameters\n{\n"
                    "    spacing { file system/generateParticlesDict; entry spacing; values (5e-5 2.5e-5); }\n"
                    "    kernel { file system/sphSchemes; entry kernel; values (%s); }\n}\n"
                    "set { endTime { file system/controlDict; entry endTime; value 0.0225; } }\n" % kernels)
        return subprocess.run([sys.executable, STUDY, path, "--output", self.output], capture_output=True, text=True)

    def test_sweep_writes_table_plot_and_resumes(self):
        result = self.study('"{ type quinticSpline; hdx 1; }"')
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        with open(os.path.join(self.output, "study.csv")) as f:
            rows = f.read().splitlines()
        self.assertEqual(len(rows), 3)
        self.assertTrue(all('"ok"' in row for row in rows[1:]), rows)
        with open(os.path.join(self.output, "study.md")) as f:
            table = f.read()
        self.assertIn("Pareto front", table)
        self.assertIn("Observed order in spacing", table)
        self.assertTrue(os.path.isfile(os.path.join(self.output, "study.png")))
        again = self.study('"{ type quinticSpline; hdx 1; }"')
        self.assertIn("2 points, 2 already in", again.stdout)

    def test_unknown_model_stops_before_any_run(self):
        result = self.study('"{ type quinticSpline; hdx 1; }" "{ type quintic; hdx 1; }"')
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("unknown kernel 'quintic'", result.stderr)
        self.assertIn("Nothing was run", result.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.output, "study.csv")))

    def test_missing_entry_names_the_study_line(self):
        path = os.path.join(self.case, "system", "studyDict")
        with open(path, "w") as f:
            f.write("error velocityError;\nparameters\n{\n    nu { file constant/fluidProperties; entry viscosity; values (1e-6); }\n}\n")
        result = subprocess.run([sys.executable, STUDY, path, "--output", self.output], capture_output=True, text=True)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("studyDict:4: 'nu': '%s' has no entry 'viscosity'" % os.path.join(self.case, "constant", "fluidProperties"), result.stderr)


if __name__ == "__main__":
    unittest.main()
