"""unyt and yt quantities where a length or a position is asked for: converted to the dataset's
coordinates (its length_unit, or the centimetres of its code unit), so a call given quantities
traces exactly what the same call given the converted numbers traces. The oracle of each
conversion is unyt's own."""
import numpy as np
import pytest

import amrstream
from shared_data import real_data

unyt = pytest.importorskip("unyt")

SEEDS = [[0.31, 0.42, 0.53], [0.62, 0.35, 0.48], [0.5, 0.5, 0.5]]


@pytest.fixture(scope="module")
def cloud_in_metres():
    return amrstream.load("builtin:cloud", levels=3, root_blocks=2, target_cells=20000, length_unit="m")


def test_seeds_in_another_unit_trace_the_same_lines(cloud_in_metres):
    plain = amrstream.trace(cloud_in_metres, SEEDS, steps=40, backend="cpu")
    quantities = amrstream.trace(cloud_in_metres, unyt.unyt_array(SEEDS, "m").to("cm"),
                                 steps=40, backend="cpu")
    assert np.array_equal(plain.points, quantities.points)
    assert np.array_equal(plain.offsets, quantities.offsets)


def test_max_length_as_a_quantity(cloud_in_metres):
    plain = amrstream.trace(cloud_in_metres, SEEDS, steps=400, max_length=0.125, backend="cpu")
    quantity = amrstream.trace(cloud_in_metres, SEEDS, steps=400, backend="cpu",
                               max_length=unyt.unyt_quantity(12.5, "cm"))
    assert "max length" in {amrstream.reason_name(r) for r in plain.reasons}
    assert np.array_equal(plain.points, quantity.points)


def test_seed_boxes_and_rakes(cloud_in_metres):
    box = [0.2, 0.3, 0.4, 0.6, 0.7, 0.8]
    in_mm = unyt.unyt_array(box, "m").to("mm")
    assert np.allclose(amrstream.seeds_random(cloud_in_metres, 16, box=in_mm),
                       amrstream.seeds_random(cloud_in_metres, 16, box=box), rtol=0, atol=1e-15)
    # A list mixing quantities and plain numbers (the numbers in the dataset's unit).
    mixed = [unyt.unyt_quantity(200, "mm"), 0.3, 0.4, 0.6, 0.7, unyt.unyt_quantity(80, "cm")]
    assert np.allclose(amrstream.seeds_grid(cloud_in_metres, (2, 3, 4), box=mixed),
                       amrstream.seeds_grid(cloud_in_metres, (2, 3, 4), box=box), atol=1e-15)
    rake = amrstream.seeds_line(unyt.unyt_array([10, 20, 30], "cm"),
                                unyt.unyt_array([0.5, 0.5, 0.5], "m"), 5)
    assert str(rake.units) == "cm"
    assert np.allclose(rake.d, amrstream.seeds_line([10, 20, 30], [50, 50, 50], 5))
    lines = amrstream.trace(cloud_in_metres, rake, steps=5, backend="cpu")
    assert np.allclose(lines[0][0], [0.1, 0.2, 0.3])


def test_resample_box_as_a_quantity(cloud_in_metres):
    field = amrstream.prepare(cloud_in_metres)
    grid = field.resample(4, box=unyt.unyt_array([0, 0, 0, 50, 50, 50], "cm"))
    assert np.allclose(grid["origin"], (0.0625, 0.0625, 0.0625))
    assert np.allclose(grid["spacing"], (0.125, 0.125, 0.125))


def test_a_quantity_that_is_not_a_length_is_refused(cloud_in_metres):
    with pytest.raises(ValueError, match=r"seeds is given in s, which is not a length"):
        amrstream.trace(cloud_in_metres, unyt.unyt_array(SEEDS, "s"), backend="cpu")
    with pytest.raises(ValueError, match=r"max_length is given in K"):
        amrstream.trace(cloud_in_metres, SEEDS, max_length=unyt.unyt_quantity(1, "K"),
                        backend="cpu")


def test_a_quantity_needs_a_dataset_that_states_its_unit():
    unitless = amrstream.load("builtin:cloud", levels=3, root_blocks=2, target_cells=20000)
    with pytest.raises(ValueError, match=r"does not state the size of its length unit"):
        amrstream.trace(unitless, unyt.unyt_array(SEEDS, "cm"), backend="cpu")
    # Dimensionless quantities are numbers.
    lines = amrstream.trace(unitless, unyt.unyt_array(SEEDS, ""), steps=3, backend="cpu")
    assert np.allclose(lines[0][0], SEEDS[0])


def test_enzo_code_units_by_the_files_centimetres():
    path = real_data("enzo-moving7/DD0010/moving7_0010")
    ds = amrstream.load(str(path))
    assert ds.length_unit.startswith("code units (1 = 5.615e+23 cm")
    assert ds.length_unit_cm == pytest.approx(5.6149e23, rel=1e-4)
    in_kpc = unyt.unyt_array(SEEDS, "cm").to("kpc") * ds.length_unit_cm
    plain = amrstream.trace(ds, SEEDS, steps=30, backend="cpu")
    quantities = amrstream.trace(ds, in_kpc, steps=30, backend="cpu")
    assert np.allclose(plain.points, quantities.points, rtol=0, atol=1e-12)


def test_yt_code_length_on_the_enzo_sample():
    yt = pytest.importorskip("yt")
    path = real_data("enzo-moving7/DD0010/moving7_0010")
    yt_ds = yt.load(str(path))
    ds = amrstream.from_yt(yt_ds)
    assert ds.length_unit_cm == pytest.approx(float(yt_ds.length_unit.to_value("cm")), rel=1e-15)
    seeds = yt_ds.arr(SEEDS, "code_length")
    plain = amrstream.trace(ds, SEEDS, steps=30, backend="cpu")
    assert np.allclose(amrstream.trace(ds, seeds, steps=30, backend="cpu").points, plain.points,
                       rtol=0, atol=1e-12)
    assert np.allclose(amrstream.trace(ds, seeds.to("Mpc"), steps=30, backend="cpu").points,
                       plain.points, rtol=0, atol=1e-12)


def test_the_cameras_lengths_as_quantities(cloud_in_metres):
    lines = amrstream.trace(cloud_in_metres, SEEDS, steps=20, backend="cpu")
    assert lines.length_unit == "m"
    look = dict(width=64, height=48, ao_samples=0)
    plain = lines.render(look_at=[0.5, 0.5, 0.5], view_box=[0.2, 0.2, 0.2, 0.8, 0.8, 0.8],
                         tube_radius_physical=0.01, **look)
    quantities = lines.render(look_at=unyt.unyt_array([50, 50, 50], "cm"),
                              view_box=unyt.unyt_array([0.2, 0.2, 0.2, 0.8, 0.8, 0.8], "m"),
                              tube_radius_physical=unyt.unyt_quantity(10, "mm"), **look)
    wider = lines.render(look_at=[0.5, 0.5, 0.5], view_box=[0.2, 0.2, 0.2, 0.8, 0.8, 0.8],
                         tube_radius_physical=0.02, **look)
    assert np.array_equal(plain, quantities)
    assert not np.array_equal(plain, wider)
