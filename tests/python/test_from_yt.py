"""amrstream.from_yt against amrstream.load on the same real files, cell for cell.

The requirement: `from_yt` on the real Enzo and AMReX datasets gives the same leaf cells and
values as `amrstream.load` on the same files. Both Datasets are compared after sorting their
cells by (physical lower corner, cell width), since yt hands out cells grid by grid and the
project's readers in their own order. Traces through both, from the same seeds, must then be
identical point for point.

Real data come from $AMRSTREAM_SHARED_DATA (the folder holding enzo-moving7/,
amrex-pelelmex-3d/ and flash-2d-nanowire/; CTest sets it), else ../shared/data/real next to the
repository; tests that need it skip when it is absent. Everything skips when yt is missing.
"""


import numpy as np
import pytest

import yt  # noqa: E402  (Debian's python3-yt; amrstream.from_yt needs it)
yt.set_log_level(40)
yt.config.ytcfg["yt", "suppress_stream_logging"] = True

import amrstream  # noqa: E402

from shared_data import real_data

ENZO = "enzo-moving7/DD0010/moving7_0010"
AMREX = "amrex-pelelmex-3d/example_plt_3d"
FLASH_2D = "flash-2d-nanowire/nanowire_arrayhdf5_plt_cnt_0100"

ENZO_VECTOR = ("x-velocity", "y-velocity", "z-velocity")
AMREX_VECTOR = ("x_velocity", "y_velocity", "z_velocity")
# Every cell field Enzo writes in this file (the README lists them), by their on-disk names.
ENZO_FIELDS = ("x-velocity", "y-velocity", "z-velocity",
               "Dark_Matter_Density", "Density", "Temperature", "TotalEnergy")


# ------------------------------------------------------------------ the two Datasets per file

class Pair:
    """A file read by amrstream.load and by amrstream.from_yt, with every field on both."""

    def __init__(self, relative, vector):
        path = real_data(relative)
        self.loaded = amrstream.load(str(path))
        self.yt_ds = yt.load(str(path))
        extra = [name for name in self.loaded.field_names if name not in vector]
        self.vector = vector
        self.from_yt = amrstream.from_yt(self.yt_ds, vector=vector, fields=extra)
        self.order_loaded = cell_order(self.loaded)
        self.order_from_yt = cell_order(self.from_yt)


def cell_widths(dataset):
    """(N, 3) physical cell widths: a cell of level l spans 2**(finest level - l) finest cells."""
    levels = np.asarray(dataset.levels, dtype=np.int64)
    span = np.ldexp(1.0, (levels.max() - levels))  # exact powers of two
    return span[:, None] * np.asarray(dataset.finest_width, dtype=np.float64)[None, :]


def physical_corners(dataset):
    return (np.asarray(dataset.origin, dtype=np.float64)
            + np.asarray(dataset.corners, dtype=np.float64) * np.asarray(dataset.finest_width))


def cell_order(dataset):
    """Indices sorting the cells by (physical lower corner x, y, z, then width)."""
    corners, widths = physical_corners(dataset), cell_widths(dataset)
    return np.lexsort((widths[:, 0], corners[:, 2], corners[:, 1], corners[:, 0]))


@pytest.fixture(scope="module")
def enzo():
    return Pair(ENZO, ENZO_VECTOR)


@pytest.fixture(scope="module")
def amrex():
    return Pair(AMREX, AMREX_VECTOR)


@pytest.fixture(params=["enzo", "amrex"])
def pair(request):
    return request.getfixturevalue(request.param)


# ------------------------------------------------------------------ geometry

def test_same_cell_count_and_domain(pair):
    loaded, ours = pair.loaded, pair.from_yt
    assert ours.cell_count == loaded.cell_count
    assert len(ours.corners) == len(loaded.corners) == loaded.cell_count
    # Positions in code_length on both sides: Enzo's domain is [0, 1]^3, AMReX's [0, 0.016]^3.
    np.testing.assert_allclose(ours.origin, loaded.origin, rtol=1e-12, atol=0)
    np.testing.assert_allclose(ours.finest_width, loaded.finest_width, rtol=1e-12, atol=0)
    np.testing.assert_allclose(ours.domain_left_edge, loaded.domain_left_edge, rtol=1e-12, atol=0)
    np.testing.assert_allclose(ours.domain_right_edge, loaded.domain_right_edge, rtol=1e-12,
                               atol=0)
    assert ours.corners.dtype == np.int32 and ours.corners.shape == (ours.cell_count, 3)
    assert ours.levels.dtype == np.int32 and ours.levels.shape == (ours.cell_count,)


def test_a_path_is_opened_with_yt_load(enzo):
    by_path = amrstream.from_yt(str(real_data(ENZO)), vector=ENZO_VECTOR)
    assert by_path.cell_count == enzo.from_yt.cell_count
    np.testing.assert_array_equal(by_path.finest_width, enzo.from_yt.finest_width)


def test_time_unit_as_load_says_and_the_fields_units_from_yt(enzo):
    assert enzo.from_yt.time_unit == enzo.loaded.time_unit
    assert enzo.from_yt.units["x-velocity"] == "code_velocity"


def test_enzo_finest_cell_is_1_over_2048(enzo):
    # 16^3 root grid, 7 refinements by 2: code units, not cm or Mpc.
    np.testing.assert_array_equal(enzo.loaded.finest_width, [1 / 2048] * 3)
    np.testing.assert_array_equal(enzo.from_yt.finest_width, [1 / 2048] * 3)
    np.testing.assert_array_equal(enzo.loaded.domain_right_edge, [1.0] * 3)


def test_same_leaf_cells_cell_for_cell(pair):
    """Physical lower corners and widths agree cell for cell once both are sorted by them."""
    a, b = pair.order_loaded, pair.order_from_yt
    np.testing.assert_allclose(physical_corners(pair.from_yt)[b],
                               physical_corners(pair.loaded)[a], rtol=1e-9, atol=0)
    np.testing.assert_allclose(cell_widths(pair.from_yt)[b], cell_widths(pair.loaded)[a],
                               rtol=1e-9, atol=0)
    # With the same origin and finest width the integer corners agree exactly too.
    np.testing.assert_array_equal(pair.from_yt.corners[b], pair.loaded.corners[a])
    # No two cells share a corner (the sort key is then a bijection between the two sets).
    corners = pair.loaded.corners[a]
    assert not np.any(np.all(corners[1:] == corners[:-1], axis=1))


def test_levels_numbered_alike(pair):
    """Both number levels with 0 = the root (coarsest) level, so they agree cell for cell."""
    a, b = pair.order_loaded, pair.order_from_yt
    np.testing.assert_array_equal(pair.from_yt.levels[b], pair.loaded.levels[a])
    assert "0 =" in pair.loaded.level_name and "0 =" in pair.from_yt.level_name
    assert "root" in pair.loaded.level_name or "coarsest" in pair.loaded.level_name
    assert "coarsest" in pair.from_yt.level_name


def test_enzo_levels_0_to_7(enzo):
    counts = np.bincount(enzo.from_yt.levels, minlength=8)
    np.testing.assert_array_equal(counts, np.bincount(enzo.loaded.levels, minlength=8))
    assert len(counts) == 8 and np.all(counts > 0)


def test_amrex_leaves_all_on_level_2(amrex):
    # Every AMReX level tiles the domain (README), so every leaf is a level-2 cell of 0.0005.
    assert amrex.loaded.cell_count == 32 ** 3
    assert set(np.unique(amrex.loaded.levels)) == {2} == set(np.unique(amrex.from_yt.levels))


# ------------------------------------------------------------------ values

def test_same_field_names(pair):
    # from_yt was asked for the vector, then every other field load() found.
    assert set(pair.from_yt.field_names) == set(pair.loaded.field_names)
    assert list(pair.from_yt.field_names[:3]) == list(pair.vector)


def assert_same_values(pair, name):
    got = pair.from_yt.field(name)[pair.order_from_yt]
    want = pair.loaded.field(name)[pair.order_loaded]
    assert got.dtype == want.dtype == np.float32
    differ = np.flatnonzero(got != want)
    assert differ.size == 0, (
        f"{name}: {differ.size} of {len(got)} cells differ; first at sorted cell {differ[0]}: "
        f"from_yt {got[differ[0]]!r}, load {want[differ[0]]!r} "
        f"(ratio {got[differ[0]] / want[differ[0]]!r})")


@pytest.mark.parametrize("name", ENZO_FIELDS)
def test_enzo_field_values_cell_for_cell(enzo, name):
    """Exact float32 equality: both read the same big-endian float32 in code units (TotalEnergy
    too: its code unit, code_velocity**2, is not length**2/time**2 in this comoving run, so a
    conversion to code base units would scale it by 0.998)."""
    assert_same_values(enzo, name)


def test_amrex_field_values_cell_for_cell(amrex):
    """All 38 plotfile components (float64 on disk, float32 in both Datasets) agree exactly."""
    assert len(amrex.loaded.field_names) == 38
    for name in amrex.loaded.field_names:
        assert_same_values(amrex, name)


@pytest.mark.parametrize("which, disk_vector, disk_density", [
    ("enzo", ENZO_VECTOR, "Density"), ("amrex", AMREX_VECTOR, "density")])
def test_default_yt_names_read_the_disk_fields(request, which, disk_vector, disk_density):
    """from_yt's default vector (gas velocity_x/y/z, yt aliases in cm/s) and ('gas', 'density')
    read the on-disk fields, so their values are the file's, in code units."""
    pair = request.getfixturevalue(which)
    ours = amrstream.from_yt(pair.yt_ds, fields=[("gas", "density")])
    assert list(ours.field_names) == ["velocity_x", "velocity_y", "velocity_z", "density"]
    order = cell_order(ours)
    np.testing.assert_array_equal(ours.corners[order], pair.loaded.corners[pair.order_loaded])
    for yt_name, disk_name in zip(ours.field_names, disk_vector + (disk_density,)):
        np.testing.assert_array_equal(ours.field(yt_name)[order],
                                      pair.loaded.field(disk_name)[pair.order_loaded],
                                      err_msg=f"{yt_name} vs {disk_name}")


def test_same_time_and_periodicity(enzo, amrex):
    for pair in (enzo, amrex):
        assert pair.from_yt.time == pytest.approx(pair.loaded.time, rel=1e-12)
    assert enzo.loaded.periodic == enzo.from_yt.periodic == (True, True, True)
    # An AMReX plotfile does not declare its periodicity: load() says None (unknown, traced as
    # non-periodic), yt assumes non-periodic.
    assert amrex.loaded.periodic is None
    assert amrex.from_yt.periodic == (False, False, False)


def test_densest_seeds_come_from_the_same_cells(enzo):
    """seeds_densest picks among cells in storage order, so its seeds differ between the two
    Datasets; but every seed of either lies in a cell at or above the same 90th percentile."""
    threshold = np.sort(enzo.loaded.field("Density"))[int(0.9 * enzo.loaded.cell_count)]
    for dataset in (enzo.loaded, enzo.from_yt):
        seeds = amrstream.seeds_densest(dataset, "Density", 32, seed=11)
        density = density_at(dataset, seeds)
        assert np.all(density >= threshold)


def density_at(dataset, points):
    """Density of the leaf cell holding each point (brute force over cells)."""
    lower = physical_corners(dataset)
    upper = lower + cell_widths(dataset)
    inside = np.all((points[:, None, :] >= lower[None]) & (points[:, None, :] < upper[None]),
                    axis=2)
    assert np.all(inside.sum(axis=1) == 1), "a point is not in exactly one leaf cell"
    return dataset.field("Density")[np.argmax(inside, axis=1)]


# ------------------------------------------------------------------ traces

TRACE_CASES = [
    ("enzo", "Density", "cell"),
    ("enzo", "Density", "arc"),
    ("amrex", "density", "cell"),
]


@pytest.mark.parametrize("which, density, step_mode", TRACE_CASES)
def test_traces_identical(request, which, density, step_mode):
    """Same seeds, cpu backend, 300 steps both ways: every point of every line is equal."""
    pair = request.getfixturevalue(which)
    seeds = amrstream.seeds_densest(pair.loaded, density, 32, seed=3)
    settings = dict(vector=pair.vector, point_data=[density], steps=300, direction="both",
                    step_mode=step_mode, backend="cpu")
    want = amrstream.trace(pair.loaded, seeds, **settings)
    got = amrstream.trace(pair.from_yt, seeds, **settings)

    assert len(want) == len(got) == 2 * len(seeds)
    assert want.points.shape[0] > 2 * len(seeds) * 10, "lines are too short to mean anything"
    np.testing.assert_array_equal(got.offsets, want.offsets)
    np.testing.assert_array_equal(got.points, want.points)
    np.testing.assert_array_equal(got.seed_ids, want.seed_ids)
    np.testing.assert_array_equal(got.directions, want.directions)
    np.testing.assert_array_equal(got.steps, want.steps)
    np.testing.assert_array_equal(got.reasons, want.reasons)
    np.testing.assert_array_equal(got.integration_time, want.integration_time)
    np.testing.assert_array_equal(got.vectors, want.vectors)
    np.testing.assert_array_equal(got.point_data[density], want.point_data[density])
    for i in (0, len(want) - 1):
        np.testing.assert_array_equal(got[i], want[i])


# ------------------------------------------------------------------ bad input

def test_unknown_field_is_named(enzo):
    with pytest.raises(ValueError, match="no_such_field"):
        amrstream.from_yt(enzo.yt_ds, vector=ENZO_VECTOR, fields=["no_such_field"])
    with pytest.raises(ValueError, match="bogus_vz"):
        amrstream.from_yt(enzo.yt_ds, vector=("x-velocity", "y-velocity", "bogus_vz"))


def test_amrex_has_no_enzo_names(amrex):
    with pytest.raises(ValueError, match="x-velocity"):
        amrstream.from_yt(amrex.yt_ds, vector=ENZO_VECTOR)


def test_particle_only_dataset_is_refused_with_advice():
    rng = np.random.default_rng(4)
    count = 16
    data = {("io", f"particle_position_{axis}"): rng.random(count) for axis in "xyz"}
    data["io", "particle_mass"] = np.ones(count)
    particles = yt.load_particles(data, length_unit=1.0, bbox=np.array([[0.0, 1.0]] * 3))
    with pytest.raises((TypeError, ValueError)) as caught:
        amrstream.from_yt(particles)
    message = str(caught.value)
    assert "grid" in message
    # It says what to do: resample onto a grid.
    assert "covering_grid" in message or "arbitrary_grid" in message


def test_2d_flash_file_gives_the_slab_load_gives():
    """yt's 2D FLASH file becomes the same one-cell-thick slab as load(), cell for cell."""
    path = real_data(FLASH_2D)
    ds = yt.load(str(path))
    assert ds.dimensionality == 2
    loaded = amrstream.load(str(path))
    ours = amrstream.from_yt(ds, vector=("dens", "tele", "tion"), fields=["pele"])
    assert ours.cell_count == loaded.cell_count == 65536
    a, b = cell_order(loaded), cell_order(ours)
    np.testing.assert_array_equal(ours.corners[b], loaded.corners[a])
    # load() numbers FLASH's levels as the file does (refine level 1 = root), yt from 0.
    assert "1 = root" in loaded.level_name
    np.testing.assert_array_equal(ours.levels[b] + 1, loaded.levels[a])
    # yt states the FLASH bounding box in float64, the file in float32 as load reads it.
    np.testing.assert_allclose(ours.finest_width, loaded.finest_width, rtol=1e-7)
    np.testing.assert_allclose(ours.origin, loaded.origin, rtol=1e-7)
    assert ours.periodic == loaded.periodic == (True, False, False)
    for name in ("dens", "tele", "tion", "pele"):
        np.testing.assert_array_equal(ours.field(name)[b], loaded.field(name)[a], err_msg=name)