import math
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from distance import compare_traces, curve_distances  # noqa: E402


def straight(n, start=(0.0, 0.0, 0.0), direction=(1.0, 0.0, 0.0), step=0.1):
    return [[s + k * step * d for s, d in zip(start, direction)] for k in range(n)]


def arc(n, turns=0.75, radius=1.0):
    return [[radius * math.cos(2 * math.pi * turns * k / (n - 1)),
             radius * math.sin(2 * math.pi * turns * k / (n - 1)), 0.5] for k in range(n)]


class CurveDistanceTest(unittest.TestCase):
    def test_identical_lines_are_zero_apart(self):
        line = straight(50)
        distances, common = curve_distances(line, line, 0.05)
        self.assertEqual(len(distances), 99)
        self.assertAlmostEqual(common, 4.9)
        self.assertTrue(all(d == 0.0 for d in distances))

    def test_shifted_copy_is_d_apart_everywhere(self):
        d = 0.3
        line = straight(20, direction=(0.6, 0.8, 0.0))
        shifted = [[x, y, z + d] for x, y, z in line]
        distances, _ = curve_distances(line, shifted, 0.02)
        self.assertGreater(len(distances), 50)
        for distance in distances:
            self.assertAlmostEqual(distance, d, places=12)

    def test_different_samplings_of_a_circle_agree(self):
        distances, common = curve_distances(arc(1000), arc(1537), 0.01)
        self.assertAlmostEqual(common, 1.5 * math.pi, places=4)
        self.assertLess(max(distances), 1e-4)

    def test_comparison_stops_at_the_shorter_line(self):
        distances, common = curve_distances(straight(11), straight(31), 0.1)
        self.assertAlmostEqual(common, 1.0)
        self.assertEqual(len(distances), 11)

    def test_diverging_lines_grow_apart_linearly(self):
        a = straight(11, direction=(1.0, 0.0, 0.0))
        b = straight(11, direction=(0.0, 1.0, 0.0))
        distances, _ = curve_distances(a, b, 0.25)
        for k, distance in enumerate(distances):
            self.assertAlmostEqual(distance, math.sqrt(2) * 0.25 * k)

    def test_summary_over_seeds(self):
        ours = {0: straight(11), 1: straight(11), 2: straight(3)}
        theirs = {0: straight(11), 1: [[x, y + 0.5, z] for x, y, z in straight(21)]}
        summary = compare_traces(ours, theirs, 0.5)
        self.assertEqual(summary["compared_seeds"], 2)
        self.assertEqual(summary["missing_seeds"], 1)
        self.assertEqual(summary["samples"], 6)
        self.assertAlmostEqual(summary["max_distance"], 0.5)
        self.assertAlmostEqual(summary["max_distance_cells"], 1.0)
        self.assertAlmostEqual(summary["median_distance"], 0.25)
        self.assertAlmostEqual(summary["mean_common_length"], 1.0)


if __name__ == "__main__":
    unittest.main()
