#!/usr/bin/python3
"""utilities/weakScalingModel: the halo share of an interior box against hand-computed values,
how the predicted efficiency depends on the rank count (through the one reduction per step
only), and the table of doc/performance.md is what the model prints."""
import os
import sys
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "utilities", "weakScalingModel"))
import weakScalingModel as model  # noqa: E402


class WeakScalingModel(unittest.TestCase):
    def test_the_halo_share_of_an_interior_box(self):
        # A 20 x 20 square with a halo 10 wide (r_c = 10 / 1.2 dx): 40^2 - 20^2 copies for 400.
        self.assertAlmostEqual(model.halo_share(2, 400, 10 / 1.2), 3.0, places=12)
        # A cube of 10^9 particles, side 1000 dx: about 2 D w / L for a thin halo.
        width = 1.2 * 3.464
        self.assertAlmostEqual(model.halo_share(3, 1e9, 3.464) / (6 * width / 1000), 1.0, delta=0.01)

    def test_only_the_reduction_grows_with_the_rank_count(self):
        for dimension in (2, 3):
            _, _, at8 = model.step_times(dimension, 1e5, 8)
            _, _, at1000 = model.step_times(dimension, 1e5, 1000)
            for part in ("work", "waits", "builds", "refreshes"):
                self.assertEqual(at8[part], at1000[part])
            self.assertAlmostEqual(at1000["agreement"] - at8["agreement"], 2 * model.ASSUMED["latency"] * (10 - 3), places=15)
            self.assertGreater(model.efficiency(dimension, 1e5, 8), model.efficiency(dimension, 1e5, 1000))
            # More particles per rank: a thinner halo, a higher efficiency.
            self.assertGreater(model.efficiency(dimension, 1e6, 1000), model.efficiency(dimension, 1e5, 1000))

    def test_the_documented_table_is_the_models(self):
        with open(os.path.join(ROOT, "doc", "performance.md")) as f:
            doc = f.read()
        self.assertIn(model.table(markdown=True), doc)


if __name__ == "__main__":
    unittest.main()
