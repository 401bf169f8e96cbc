import os
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

try:
    import numpy as np

    import amr_blocks
except ImportError:  # numpy comes from Debian's python3-numpy, for /usr/bin/python3
    np = None


def two_root_blocks_one_refined():
    """Root blocks of width-2 cells at x = 0 and x = 16 finest cells; the first is refined."""
    cells = []
    for bx in (0, 8):
        for by in (0, 8):
            for bz in (0, 8):
                cells += [(bx + x, by + y, bz + z, 0)
                          for z in range(8) for y in range(8) for x in range(8)]
    cells += [(16 + 2 * x, 2 * y, 2 * z, 1) for z in range(8) for y in range(8) for x in range(8)]
    return np.array(cells, dtype=np.int64)


def write_dataset(directory, cells, values=None, origin="0 0 0", spacing="0.5 0.5 0.5"):
    directory = Path(directory)
    cells.astype("<i4").tofile(directory / "d.cells")
    centre = cells[:, 0] + 0.5 * (1 << cells[:, 3])
    (centre if values is None else values).astype("<f4").tofile(directory / "d.cx.scalars")
    (directory / "d.exa").write_text(
        f"# test\ncells d.cells\nscalar cx d.cx.scalars\norigin {origin}\nspacing {spacing}\n")
    return directory / "d.exa"


@unittest.skipIf(np is None, "needs numpy")
class AmrBlocksTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.addCleanup(self.dir.cleanup)

    def load(self, cells, **kwargs):
        return amr_blocks.load(write_dataset(self.dir.name, cells, **kwargs))

    def test_hierarchy_and_restriction(self):
        cells = two_root_blocks_one_refined()
        blocks = self.load(cells[np.random.default_rng(1).permutation(len(cells))],
                           origin="1 2 3")
        self.assertEqual(blocks.cell_count, 8 * 512 + 512)
        self.assertEqual([len(level.corners) for level in blocks.levels], [8, 2])
        self.assertEqual(blocks.levels[1].refined.tolist(), [True, False])
        lower, upper = blocks.domain
        np.testing.assert_allclose(lower, [1, 2, 3])
        np.testing.assert_allclose(upper, [17, 10, 11])
        coarse = blocks.levels[1].values["cx"]
        expected_x = 2 * np.arange(8) + 1.0
        np.testing.assert_allclose(coarse[0], np.broadcast_to(expected_x[:, None, None], (8,) * 3))
        np.testing.assert_allclose(coarse[1], 16 + coarse[0])
        fine = blocks.levels[0]
        corner = fine.corners.tolist().index([8, 0, 8])
        np.testing.assert_allclose(fine.values["cx"][corner][:, 3, 5], 8.5 + np.arange(8))

    def test_truncated_cells(self):
        path = write_dataset(self.dir.name, two_root_blocks_one_refined())
        cells = path.parent / "d.cells"
        cells.write_bytes(cells.read_bytes()[:-4])
        with self.assertRaisesRegex(amr_blocks.DatasetError, "d.cells.*multiple of 16"):
            amr_blocks.load(path)

    def test_truncated_scalars(self):
        path = write_dataset(self.dir.name, two_root_blocks_one_refined())
        scalars = path.parent / "d.cx.scalars"
        scalars.write_bytes(scalars.read_bytes()[:-4])
        with self.assertRaisesRegex(amr_blocks.DatasetError, "d.cx.scalars"):
            amr_blocks.load(path)

    def test_incomplete_block(self):
        with self.assertRaisesRegex(amr_blocks.DatasetError, "d.cells.*complete aligned"):
            self.load(two_root_blocks_one_refined()[1:])

    def test_partly_refined_block(self):
        with self.assertRaisesRegex(amr_blocks.DatasetError, "d.cells.*partly refined"):
            self.load(two_root_blocks_one_refined()[512:])

    def test_misaligned_cell(self):
        cells = two_root_blocks_one_refined()
        cells[-1, 0] += 1
        with self.assertRaisesRegex(amr_blocks.DatasetError, "d.cells.*aligned"):
            self.load(cells)

    def test_overlap(self):
        cells = two_root_blocks_one_refined()
        coarse_copy = cells[-512:].copy()
        coarse_copy[:, 0] -= 16
        with self.assertRaisesRegex(amr_blocks.DatasetError, "d.cells.*overlap"):
            self.load(np.concatenate([cells, coarse_copy]))

    def test_bad_directive(self):
        path = write_dataset(self.dir.name, two_root_blocks_one_refined())
        path.write_text(path.read_text() + "colour red\n")
        with self.assertRaisesRegex(amr_blocks.DatasetError, r"d.exa:6"):
            amr_blocks.load(path)


if __name__ == "__main__":
    unittest.main()
