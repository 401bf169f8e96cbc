"""2D data traced and sliced as 2D: a planar rotation made with from_arrays(dimensions=2) is
traced in its plane (z = 0, the vector's third component zero) along circles; the FLASH 2D
sample takes a vector of two channels (a third is left out), its slab is centred on z = 0, it is
sliced across z only, and a channel alone is sliced without any vector."""
import numpy as np
import pytest

import amrstream
from shared_data import real_data

N = 32


def planar_rotation():
    """A 32 x 32 grid of unit cells on one level, the slab one cell thick across z = 0, holding
    the rotation (-(y - 16), x - 16) about the grid's centre."""
    i, j = np.meshgrid(np.arange(N), np.arange(N), indexing="ij")
    corners = np.stack([i.ravel(), j.ravel(), np.zeros(N * N, dtype=int)], axis=1)
    x, y = corners[:, 0] + 0.5, corners[:, 1] + 0.5
    fields = {"vx": -(y - N / 2), "vy": x - N / 2}
    return amrstream.from_arrays(corners, np.zeros(N * N, dtype=int), fields,
                                 origin=(0.0, 0.0, -0.5), dimensions=2)


def test_a_planar_rotation_is_traced_along_circles_in_its_plane():
    seeds = np.array([[16.0 + r, 16.0, 0.37] for r in (3.0, 6.0, 9.0)])
    traces = amrstream.trace(planar_rotation(), seeds, vector="vx,vy", interpolant="linear",
                             steps=400, step_size=0.2)
    assert traces.vector_name == "v"
    assert np.all(traces.points[:, 2] == 0.0)  # seeds moved onto the plane, lines stay there
    assert np.all(traces.vectors[:, 2] == 0.0)
    for line in range(len(traces)):
        points = traces[line]
        radius = np.hypot(points[:, 0] - 16.0, points[:, 1] - 16.0)
        np.testing.assert_allclose(radius, radius[0], rtol=1e-3)


def test_a_seed_grid_on_2d_data_has_one_layer():
    """Its NZ layers would all land on the plane: each point once, on the plane."""
    field = amrstream.prepare(planar_rotation(), vector="vx,vy")
    seeds = amrstream.seeds_grid(field, (4, 5, 3))
    assert seeds.shape == (20, 3)
    assert len(np.unique(seeds, axis=0)) == 20
    assert np.all(seeds[:, 2] == 0.0)


def test_a_three_dimensional_vector_needs_three_channels():
    i = np.arange(8)
    corners = np.stack(np.meshgrid(i, i, i, indexing="ij"), axis=-1).reshape(-1, 3)
    ones = np.ones(len(corners))
    ds = amrstream.from_arrays(corners, np.zeros(len(corners), dtype=int),
                               {"vx": ones, "vy": ones, "vz": ones})
    with pytest.raises(ValueError, match="must name exactly three channels"):
        amrstream.prepare(ds, vector="vx,vy")
    with pytest.raises(ValueError, match="dimensions must be 2 or 3"):
        amrstream.from_arrays(corners, np.zeros(len(corners), dtype=int), {"vx": ones},
                              dimensions=1)


def test_the_flash_2d_sample_is_2d():
    path = real_data("flash-2d-nanowire/nanowire_arrayhdf5_plt_cnt_0100")
    ds = amrstream.load(str(path))
    two = amrstream.prepare(ds, vector="tele,tion")
    three = amrstream.prepare(ds, vector="tele,tion,trad")  # the third is left out
    rng = np.random.default_rng(3)
    lower, upper = np.array([-1e-4, 0.0]), np.array([1e-4, 2e-3])
    seeds = np.column_stack([lower + rng.random((8, 2)) * (upper - lower), np.full(8, 1e-7)])
    a = amrstream.trace(two, seeds, steps=50)
    b = amrstream.trace(three, seeds, steps=50)
    assert np.all(a.points[:, 2] == 0.0) and np.all(a.vectors[:, 2] == 0.0)
    np.testing.assert_array_equal(a.points, b.points)
    with pytest.raises(ValueError, match="2D data are sliced across z only"):
        amrstream.slice(two, normal="x", lines=False, progress=None)
    alone = amrstream.slice(ds, vector="none", lines=False, background="dens", width=40,
                            colour_scale="log", progress=None)
    assert alone["background_name"] == "dens"
    assert np.isfinite(alone["background"]).all()
