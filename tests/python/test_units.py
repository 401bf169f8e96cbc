"""Units a file does not state, declared at load() (or from_arrays), and their checks."""
import numpy as np
import pytest

import amrstream

SMALL = dict(levels=2, root_blocks=1)


def test_load_declares_the_length_unit_and_channel_units():
    ds = amrstream.load("builtin:rotation", length_unit="kpc",
                        units={"velx": "km/s", "vel": "km/s"}, **SMALL)
    assert ds.length_unit == "kpc"
    assert ds.units == {"velx": "km/s", "vel": "km/s"}


def test_a_name_that_is_no_channel_gets_the_closest():
    with pytest.raises(ValueError, match=r"unit: 'Velx' is no channel .*did you mean 'velx'"):
        amrstream.load("builtin:rotation", units={"Velx": "km/s"}, **SMALL)


def test_from_arrays_keeps_the_fields_units():
    corners = np.array([[0, 0, 0], [1, 0, 0]])
    ds = amrstream.from_arrays(corners, np.array([0, 0]),
                               {"T": np.array([1.0, 2.0], dtype=np.float32)},
                               length_unit="cm", units={"T": "K"})
    assert ds.units == {"T": "K"}
    assert ds.length_unit == "cm"
