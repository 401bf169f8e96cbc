"""seeds_random on datasets with holes: every seed in a cell, checked against the cells' boxes.

Needs the module on PYTHONPATH (build/python); CTest sets it.
"""

import numpy as np
import pytest

import amrstream  # noqa: E402  (the package CTest names: tests/python/run_pytest.sh)

ORIGIN = np.array([1.0, 2.0, 3.0])
FINEST_WIDTH = np.array([0.5, 0.25, 0.5])


def blocks_with_a_hole(fields=("velx", "vely", "velz")):
    """Two blocks of equal volume with a hole between them: 4^3 fine cells (level 1) at
    x = 0..4 and 2^3 coarse cells (level 0, 2 wide) at x = 8..12, in finest cells. The domain's
    bounding box [0, 12) x [0, 4) x [0, 4) is a third hole."""
    fine = [(x, y, z) for z in range(4) for y in range(4) for x in range(4)]
    coarse = [(8 + 2 * x, 2 * y, 2 * z) for z in range(2) for y in range(2) for x in range(2)]
    corners = np.array(fine + coarse)
    levels = np.array([1] * len(fine) + [0] * len(coarse))
    values = {name: np.full(len(levels), 1.0) for name in fields}
    return amrstream.from_arrays(corners, levels, values, origin=tuple(ORIGIN),
                                 finest_width=tuple(FINEST_WIDTH))


def inside_some_cell(ds, points):
    """Per point, whether it lies in a cell's half-open box, from the dataset's own arrays."""
    levels = ds.levels.astype(np.int64)
    widths = (1 << (levels.max() - levels))[:, None] * FINEST_WIDTH  # physical, per cell
    lower = ORIGIN + ds.corners * FINEST_WIDTH
    upper = lower + widths
    inside = (points[:, None, :] >= lower[None]) & (points[:, None, :] < upper[None])
    return inside.all(axis=2).any(axis=1)


@pytest.fixture(scope="module")
def holed():
    return blocks_with_a_hole()


def test_random_seeds_of_a_dataset_land_in_cells_never_in_the_hole(holed):
    assert holed.domain_left_edge == (1, 2, 3) and holed.domain_right_edge == (7, 3, 5)
    seeds = amrstream.seeds_random(holed, 4000, seed=3)
    assert seeds.shape == (4000, 3)
    assert inside_some_cell(holed, seeds).all()
    # The blocks have equal volumes: about half the seeds in each (4.4 standard deviations).
    in_coarse_block = np.count_nonzero(seeds[:, 0] >= ORIGIN[0] + 8 * FINEST_WIDTH[0])
    assert abs(in_coarse_block / 4000 - 0.5) < 0.035
    amrstream.trace(holed, seeds, steps=1, backend="cpu")  # no seed "outside the domain"


def test_the_oracle_sees_the_hole(holed):
    hole = ORIGIN + np.array([6.0, 2.0, 2.0]) * FINEST_WIDTH
    cell = ORIGIN + np.array([2.0, 2.0, 2.0]) * FINEST_WIDTH
    assert list(inside_some_cell(holed, np.array([hole, cell]))) == [False, True]
    with pytest.raises(amrstream.InputError, match="outside the domain"):
        amrstream.trace(holed, [hole], steps=1, backend="cpu")


def test_dataset_and_its_field_draw_the_same_seeds(holed):
    field = amrstream.prepare(holed)
    for box in (None, (1.5, 2.0, 3.0, 6.5, 3.0, 5.0)):
        a = amrstream.seeds_random(holed, 500, box=box, seed=9)
        b = amrstream.seeds_random(field, 500, box=box, seed=9)
        assert np.array_equal(a, b)
        assert inside_some_cell(holed, a).all()


def test_a_box_around_the_hole_keeps_its_seeds_in_cells(holed):
    box = (2.5, 2.0, 3.0, 5.5, 3.0, 5.0)  # x = 3..9 finest cells: half hole
    seeds = amrstream.seeds_random(holed, 1000, box=box, seed=4)
    assert inside_some_cell(holed, seeds).all()
    assert (seeds >= box[:3]).all() and (seeds < box[3:]).all()


def test_a_box_all_hole_is_refused(holed):
    with pytest.raises(amrstream.InputError, match="nearly all holes"):
        amrstream.seeds_random(holed, 10, box=(3.2, 2.0, 3.0, 4.8, 3.0, 5.0), seed=1)


def test_a_dataset_without_a_vector_draws_in_cells_too():
    scalar_only = blocks_with_a_hole(fields=("dens",))
    seeds = amrstream.seeds_random(scalar_only, 1000, seed=2)
    assert inside_some_cell(scalar_only, seeds).all()
