#!/usr/bin/python3
"""cases/sloshingTank2D/linearSloshing.py: the modal sum's coefficients and natural periods
against closed forms."""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "cases", "sloshingTank2D"))
import linearSloshing as linear  # noqa: E402


class LinearSloshing(unittest.TestCase):
    def test_first_natural_period_is_the_readmes(self):
        # omega_1^2 = g (pi / L) tanh(pi h / L), L = 1.72 m, h = 0.6 m: T_1 = 1.661 s.
        _, omega_12, _ = next(linear.modes())
        self.assertAlmostEqual(2 * math.pi / math.sqrt(omega_12), 1.661, places=3)

    def test_quasi_static_response_is_the_tilted_level(self):
        # A steady acceleration a tilts the level to eta = -(x - L/2) a / g: the modes' forced
        # amplitudes -c_n a / g summed must give that line (the cosine series of x).
        a = 0.7
        for x in (0.05, 0.4, 0.86, 1.5):
            tilt = sum(-c_n * a / linear.G * math.cos(k * x) for k, _, c_n in linear.modes())
            self.assertAlmostEqual(tilt, -(x - linear.BREADTH / 2) * a / linear.G, delta=2e-5)

    def test_starts_from_rest(self):
        self.assertEqual(linear.elevation(0.0), 0.0)
        self.assertLess(abs(linear.elevation(1e-3)), 1e-7)

    def test_fit_returns_the_theorys_own_natural_period(self):
        series = [(i * 0.01, linear.elevation(i * 0.01)) for i in range(1001)]
        self.assertAlmostEqual(linear.fitted_natural_period(series), 1.661, delta=0.002)


if __name__ == "__main__":
    unittest.main()
