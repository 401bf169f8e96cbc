"""Derived vectors from Python: vector="grad(NAME)" / "-grad(NAME)" and frame_velocity.

Leaf cells of three levels (refined off the middle) over [0, 1) x [0, 2) x [0, 1), cells twice
as tall in y as wide. Oracles: the lines of -grad(f) for f = x + 2y are straight along
-(1, 2, 0); solid-body rotation about the domain's axis plus a drift U is rotation alone in the
frame moving at U, so lines keep their distance from the axis; `auto` is the volume-weighted mean
over the domain's cells (exactly U: the domain is symmetric about the axis and the mean of a
linear field over whole cells tiling it is its value at the centre) or, for trace(), over the
cells that hold the seeds (computed here from the cells with numpy).
"""

import math

import numpy as np
import pytest

import amrstream

CENTRE = np.array([0.5, 1.0, 0.5])
DRIFT = (0.3, -0.2, 0.1)
OMEGA = 2.0 * math.pi
FINEST = np.array([1.0 / 32.0, 1.0 / 16.0, 1.0 / 32.0])


def drifting_rotation(p):
    return np.stack([-OMEGA * (p[:, 1] - CENTRE[1]) + DRIFT[0],
                     OMEGA * (p[:, 0] - CENTRE[0]) + DRIFT[1],
                     np.full(len(p), DRIFT[2])], axis=1)


def three_level_cells():
    """Corners (finest cells) and widths: width-4 cells over 32^3 finest cells, split into
    width 2 in [8, 24) x [4, 20) x [8, 28) and into width 1 in [10, 18) x [6, 12) x [14, 22)."""
    corners, widths = [], []

    def inside(c, lo, hi):
        return all(lo[a] <= c[a] < hi[a] for a in range(3))

    def add(c, w):
        if (w == 4 and inside(c, (8, 4, 8), (24, 20, 28))) or \
                (w == 2 and inside(c, (10, 6, 14), (18, 12, 22))):
            h = w // 2
            for i in range(8):
                add((c[0] + h * (i & 1), c[1] + h * ((i >> 1) & 1), c[2] + h * ((i >> 2) & 1)), h)
            return
        corners.append(c)
        widths.append(w)

    for z in range(0, 32, 4):
        for y in range(0, 32, 4):
            for x in range(0, 32, 4):
                add((x, y, z), 4)
    return np.array(corners, dtype=np.int64), np.array(widths)


@pytest.fixture(scope="module")
def cells():
    corners, widths = three_level_cells()
    centres = (corners + 0.5 * widths[:, None]) * FINEST
    v = drifting_rotation(centres)
    fields = {"f": centres[:, 0] + 2.0 * centres[:, 1],
              "velx": v[:, 0], "vely": v[:, 1], "velz": v[:, 2]}
    levels = {4: 0, 2: 1, 1: 2}
    ds = amrstream.from_arrays(corners, np.array([levels[w] for w in widths]), fields,
                               finest_width=tuple(FINEST), source="three-levels")
    return ds, corners, widths


def radius_changes(lines):
    """The largest change of a line's distance from the rotation axis (physical units)."""
    largest = 0.0
    for points in lines:
        r = np.hypot(points[:, 0] - CENTRE[0], points[:, 1] - CENTRE[1])
        largest = max(largest, float(np.max(np.abs(r - r[0]))))
    return largest


def test_minus_grad_lines_are_straight(cells):
    ds, _, _ = cells
    seeds = [[0.70, 1.45, 0.55], [0.58, 0.95, 0.60]]
    lines = amrstream.trace(ds, seeds, vector="-grad(f)", direction="forward", steps=400,
                            backend="cpu")
    assert lines.vector_name == "-grad(f)"
    assert "f" in lines.point_data
    down = -np.array([1.0, 2.0, 0.0]) / math.sqrt(5.0)
    for points in lines:
        assert len(points) > 20
        along = points.astype(np.float64) - points[0]
        off = along - np.outer(along @ down, down)
        assert np.max(np.linalg.norm(off, axis=1)) < 1e-4
        assert np.all(np.diff(points.astype(np.float64), axis=0) @ down > 0)
    np.testing.assert_allclose(lines.vectors[0], [-1.0, -2.0, 0.0], atol=1e-4)


def test_frame_velocity_turns_the_drifting_rotation_into_circles(cells):
    ds, _, _ = cells
    seeds = [[0.75, 1.0, 0.5], [0.5, 1.3, 0.6], [0.42, 0.9, 0.7]]
    # The linear interpolant is exact for the linear field across the level jumps; steps of a
    # twentieth of a finest cell (1/32 wide) keep RK4's error on the circles far below 1e-4.
    common = dict(direction="forward", steps=3000, step_size=0.05, interpolant="linear",
                  backend="cpu")
    moving = amrstream.trace(ds, seeds, frame_velocity=DRIFT, **common)
    assert moving.vector_name == "vel"
    assert radius_changes(moving) < 1e-4
    assert radius_changes(amrstream.trace(ds, seeds, **common)) > 0.02
    # numpy arrays and text are frame velocities too.
    same = amrstream.trace(ds, seeds, frame_velocity=np.array(DRIFT), **common)
    np.testing.assert_array_equal(same.points, moving.points)
    text = amrstream.trace(ds, seeds, frame_velocity="0.3,-0.2,0.1", **common)
    np.testing.assert_array_equal(text.points, moving.points)


def test_prepare_auto_is_the_mean_over_the_domain(cells):
    ds, _, _ = cells
    field = amrstream.prepare(ds, frame_velocity="auto")
    np.testing.assert_allclose(field.frame_velocity, DRIFT, atol=1e-6)
    assert amrstream.prepare(ds).frame_velocity == (0.0, 0.0, 0.0)
    assert amrstream.prepare(ds, frame_velocity=(0.5, 0, -1)).frame_velocity == (0.5, 0.0, -1.0)
    gradient = amrstream.prepare(ds, vector="grad(f)")
    assert gradient.vector_name == "grad(f)"
    assert gradient.vector == ["d(f)/dx", "d(f)/dy", "d(f)/dz"]


def test_trace_auto_is_the_mean_over_the_cells_that_hold_the_seeds(cells):
    ds, corners, widths = cells
    # Two seeds share a cell; the others lie in cells of other widths.
    seeds = np.array([[0.30, 0.70, 0.50], [0.301, 0.701, 0.501], [0.80, 1.60, 0.20],
                      [0.60, 1.10, 0.55]])
    held = set()
    for p in seeds / FINEST:
        inside = np.all((corners <= p) & (p < corners + widths[:, None]), axis=1)
        held.add(int(np.flatnonzero(inside)[0]))
    held = sorted(held)
    assert len(held) == 3 and len({int(widths[i]) for i in held}) > 1
    values = np.stack([ds.field(n)[held].astype(np.float64) for n in ("velx", "vely", "velz")],
                      axis=1)
    volumes = (widths[held].astype(np.float64)) ** 3
    expected = tuple(volumes @ values / volumes.sum())
    common = dict(direction="forward", steps=5, backend="cpu")
    auto = amrstream.trace(ds, seeds, frame_velocity="auto", **common)
    given = amrstream.trace(ds, seeds, frame_velocity=expected, **common)
    np.testing.assert_allclose(auto.vectors, given.vectors, atol=1e-6)
    domain = amrstream.trace(ds, seeds, frame_velocity=DRIFT, **common)
    assert np.max(np.abs(auto.vectors - domain.vectors)) > 0.1


@pytest.mark.parametrize("kwargs, exception, fragment", [
    (dict(frame_velocity=(1, 2)), ValueError, "frame_velocity must be 3 numbers, not 2"),
    (dict(frame_velocity=(math.nan, 0, 0)), ValueError, "frame_velocity: nan is not a finite"),
    (dict(frame_velocity="fast"), ValueError,
     "frame_velocity: 'fast' is not auto nor three numbers VX,VY,VZ"),
    (dict(frame_velocity=("a", 0, 0)), TypeError, "frame_velocity must be a real number"),
    (dict(vector="grad(g)"), ValueError,
     "vector: no channel 'g' in three-levels to take the gradient of (did you mean 'f'?); "
     "the channels are: f, velx, vely, velz"),
    (dict(vector="-grad(f"), ValueError, "vector: '-grad(f' is not grad(NAME) or -grad(NAME)"),
])
def test_bad_derived_vectors_are_refused_naming_the_keyword(cells, kwargs, exception, fragment):
    ds, _, _ = cells
    with pytest.raises(exception) as error:
        amrstream.trace(ds, [[0.5, 1.0, 0.5]], steps=2, backend="cpu", **kwargs)
    assert fragment in str(error.value)
    with pytest.raises(exception) as error:
        amrstream.prepare(ds, **kwargs)
    assert fragment in str(error.value)


def test_a_prepared_field_keeps_its_frame_and_pathlines_take_none(cells):
    ds, _, _ = cells
    field = amrstream.prepare(ds)
    with pytest.raises(ValueError, match="frame_velocity"):
        amrstream.trace(field, [[0.5, 1.0, 0.5]], frame_velocity=DRIFT)
    with pytest.raises(TypeError, match="frame_velocity"):
        amrstream.pathlines(["a", "b"], [[0.5, 1.0, 0.5]], frame_velocity=DRIFT)
