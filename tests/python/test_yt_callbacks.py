"""yt's annotate_amrstream_lines and annotate_amrstream_lic draw amrstream.slice's own lines and
LIC over the plot's window, on its axes in its units.

Oracles: amrstream.slice called here for the window the plot shows, worked out from the plot's
centre and width (axis-aligned) or yt's own image axes (off-axis), with the coordinates converted
to the plot's units by unyt (ds.quan(1, "code_length")); yt's own image of the density over that
window, which amrstream's reconstruction of it must match better than over a window a few pixels
off; yt's velocity at the lines, which they must follow.

Real data come from $AMRSTREAM_SHARED_DATA (CTest sets it), else ../shared/data/real next to the
repository; the tests skip when it is absent.
"""

import numpy as np
import pytest

import yt  # noqa: E402  (Debian's python3-yt; the callbacks are yt's)
yt.set_log_level(40)
yt.config.ytcfg["yt", "suppress_stream_logging"] = True

import amrstream  # noqa: E402
from amrstream import yt_callbacks  # noqa: E402

from shared_data import real_data

ENZO = "enzo-moving7/DD0010/moving7_0010"
AMREX = "amrex-pelelmex-3d/example_plt_3d"
FLASH_2D = "flash-2d-nanowire/nanowire_arrayhdf5_plt_cnt_0100"
VECTOR = ("x-velocity", "y-velocity", "z-velocity")
DENSITY = ("enzo", "Density")
CENTRE = (0.75, 0.72, 0.74)  # code_length, beside the collapsing core
WIDTH = 0.2                  # code_length
PIXELS = 128
IMAGE_AXES = {"x": (1, 2), "y": (2, 0), "z": (0, 1)}  # yt's (horizontal, vertical) per normal


@pytest.fixture(scope="module")
def enzo():
    return yt.load(str(real_data(ENZO)))


@pytest.fixture(scope="module")
def dataset(enzo):
    """The test's own Dataset of the same file (not the callbacks' cached one)."""
    return amrstream.from_yt(enzo, vector=VECTOR)


def slice_plot(ds, normal, unit=None, centre=CENTRE, field=DENSITY):
    plot = yt.SlicePlot(ds, normal, field, center=list(centre), width=(WIDTH, "code_length"),
                        buff_size=(PIXELS, PIXELS))
    if unit:
        plot.set_axes_unit(unit)
    return plot


def drawn(plot, gid, field=DENSITY):
    """The artists of one kind (gid) on the plot's axes, after yt has drawn it."""
    plot.render()
    return [a for a in plot.plots[field].axes.get_children() if a.get_gid() == gid]


def drawn_lines(plot, field=DENSITY):
    (collection,) = drawn(plot, "amrstream_lines", field)
    return [np.asarray(s, dtype=np.float64) for s in collection.get_segments()]


def window_of(normal, centre=CENTRE, width=WIDTH):
    """(a0, b0, a1, b1): the part of the plane an axis-aligned plot shows."""
    a, b = IMAGE_AXES[normal]
    return (centre[a] - width / 2, centre[b] - width / 2, centre[a] + width / 2,
            centre[b] + width / 2)


def code_length_in(ds, unit):
    return float(ds.quan(1.0, "code_length").to_value(unit))


def in_plot_units(lines, origin, scale):
    """Lines of the plane as the plot draws them: from its centre (yt's default origin,
    'center-window'), in its unit."""
    return [(np.asarray(line, dtype=np.float64) - np.asarray(origin)) * scale for line in lines]


def assert_same_lines(drawn_lines, expected, atol):
    assert len(expected) > 5
    assert len(drawn_lines) == len(expected)
    for ours, theirs in zip(drawn_lines, expected):
        np.testing.assert_allclose(ours, theirs, rtol=0, atol=atol)


def bounding_box(lines):
    points = np.concatenate(lines)
    return np.concatenate([points.min(axis=0), points.max(axis=0)])


@pytest.mark.parametrize("normal", ["x", "z"])
def test_the_lines_are_the_slices_lines_in_the_plots_units(enzo, dataset, normal):
    plot = slice_plot(enzo, normal, unit="kpc")
    plot.annotate_amrstream_lines(vector=VECTOR)
    window = window_of(normal)
    point = list(CENTRE)
    expected = amrstream.slice(dataset, vector=VECTOR, normal=normal, point=point,
                               window=window, width=PIXELS, background="none",
                               line_separation=WIDTH / 30, progress=None)
    assert expected["axes"] == tuple("xyz"[i] for i in IMAGE_AXES[normal])
    kpc = code_length_in(enzo, "kpc")
    origin = [(window[0] + window[2]) / 2, (window[1] + window[3]) / 2]
    lines = drawn_lines(plot)
    assert_same_lines(lines, in_plot_units(expected["lines"], origin, kpc), 1e-9 * kpc)
    # ... inside the plot's window, which the callback leaves as it was.
    axes = plot.plots[DENSITY].axes
    half = WIDTH / 2 * kpc
    np.testing.assert_allclose(axes.get_xlim(), (-half, half), rtol=1e-12)
    np.testing.assert_allclose(axes.get_ylim(), (-half, half), rtol=1e-12)
    box = bounding_box(lines)
    assert np.all(box >= -half * (1 + 1e-9)) and np.all(box <= half * (1 + 1e-9))


def test_other_axes_units_scale_the_same_lines(enzo):
    drawn_in = {}
    for unit in ("code_length", "kpc"):
        plot = slice_plot(enzo, "y", unit=unit)
        plot.annotate_amrstream_lines(vector=VECTOR, arrowsize=0)
        drawn_in[unit] = drawn_lines(plot)
    assert not drawn(plot, "amrstream_arrow")
    kpc = code_length_in(enzo, "kpc")
    assert abs(kpc - 181.97) < 0.01  # the file's comoving code length, about 182 kpc
    assert_same_lines(drawn_in["kpc"], [line * kpc for line in drawn_in["code_length"]],
                      1e-9 * kpc)


def test_the_lic_is_the_slices_lic_over_the_plots_window(enzo, dataset):
    plot = slice_plot(enzo, "x", unit="Mpc")
    plot.annotate_amrstream_lic(vector=VECTOR)
    (image,) = drawn(plot, "amrstream_lic")
    expected = amrstream.slice(dataset, vector=VECTOR, normal="x", point=list(CENTRE),
                               window=window_of("x"), width=PIXELS, background="none",
                               lines=False, lic=True, progress=None)["lic"]
    assert expected.shape == (PIXELS, PIXELS) and np.isfinite(expected).all()
    np.testing.assert_array_equal(np.ma.getdata(image.get_array()), expected)
    half = WIDTH / 2 * code_length_in(enzo, "Mpc")
    axes = plot.plots[DENSITY].axes
    np.testing.assert_allclose(image.get_extent(), (-half, half, -half, half), rtol=1e-12)
    np.testing.assert_allclose((*axes.get_xlim(), *axes.get_ylim()), image.get_extent(),
                               rtol=1e-12)
    assert image.origin == "lower"
    # The default opacity: 0 up to the 2nd percentile, 0.8 from the 98th, linear between.
    low, high = np.percentile(expected, (2, 98))
    assert image.norm.vmin == pytest.approx(low) and image.norm.vmax == pytest.approx(high)
    np.testing.assert_allclose(image.get_alpha(),
                               0.8 * np.clip((expected - low) / (high - low), 0, 1), atol=1e-6)


def test_swapped_axes_swap_the_lines_and_the_lic(enzo):
    plots = [slice_plot(enzo, "z"), slice_plot(enzo, "z").swap_axes()]
    for plot in plots:
        plot.annotate_amrstream_lic(vector=VECTOR, const_alpha=True, lim=(0.4, 0.6))
        plot.annotate_amrstream_lines(vector=VECTOR)
    straight, swapped = (drawn_lines(plot) for plot in plots)
    assert_same_lines(swapped, [line[:, ::-1] for line in straight], 1e-12)
    (straight_lic,), (swapped_lic,) = (drawn(plot, "amrstream_lic") for plot in plots)
    np.testing.assert_array_equal(swapped_lic.get_array(), straight_lic.get_array().T)
    assert swapped_lic.get_alpha() == straight_lic.get_alpha() == 0.8
    assert (swapped_lic.norm.vmin, swapped_lic.norm.vmax) == (0.4, 0.6)


def test_the_lines_follow_zoom_and_pan(enzo):
    plot = slice_plot(enzo, "x", unit="code_length")
    plot.set_origin("native")  # the axes read y and z themselves
    plot.annotate_amrstream_lines(vector=VECTOR)
    before = bounding_box(drawn_lines(plot))
    for change in (lambda: plot.zoom(2), lambda: plot.set_center((0.70, 0.70))):
        change()
        lines = drawn_lines(plot)
        axes = plot.plots[DENSITY].axes
        (x0, x1), (y0, y1) = axes.get_xlim(), axes.get_ylim()
        box = bounding_box(lines)
        slack = 1e-9 * (x1 - x0)
        assert x0 - slack <= box[0] and box[2] <= x1 + slack
        assert y0 - slack <= box[1] and box[3] <= y1 + slack
        assert not np.allclose(box, before)
        before = box
    # After both, the plot shows 0.1 wide around (y, z) = (0.70, 0.70): the slice's lines there.
    expected = amrstream.slice(amrstream.from_yt(enzo, vector=VECTOR), vector=VECTOR,
                               normal="x", point=[0.75, 0.70, 0.70],
                               window=(0.65, 0.65, 0.75, 0.75), width=PIXELS,
                               background="none", line_separation=0.1 / 30, progress=None)
    assert_same_lines(lines, expected["lines"], 1e-9)


def median_misfit(ours, theirs):
    """The median |log| of the ratio of two positive images, over pixels both have."""
    both = np.isfinite(ours) & np.isfinite(theirs) & (ours > 0) & (theirs > 0)
    assert both.mean() > 0.99
    return float(np.median(np.abs(np.log(ours[both] / theirs[both]))))


def assert_shows_the_plots_place(plot, dataset_with_density, normal, window):
    """amrstream's density over `window` is yt's image of it, closer than a window 6 pixels
    off either way (measured: 0.045-0.056 against 0.13-0.19)."""
    ours = amrstream.slice(dataset_with_density, vector=VECTOR, normal=normal,
                           point=list(CENTRE), window=window, width=PIXELS,
                           background="Density", lines=False, progress=None)["background"]
    theirs = np.asarray(plot.frb[DENSITY].to_value("code_mass/code_length**3"))
    right = median_misfit(ours, theirs)
    assert right < 0.1
    for shifted in ((ours[:, 6:], theirs[:, :-6]), (ours[6:], theirs[:-6]),
                    (ours[:, :-6], theirs[:, 6:]), (ours[:-6], theirs[6:])):
        assert right < 0.5 * median_misfit(*shifted)


def test_the_window_is_the_place_the_plot_shows(enzo):
    with_density = amrstream.from_yt(enzo, vector=VECTOR, fields=["Density"])
    for normal in "xyz":
        assert_shows_the_plots_place(slice_plot(enzo, normal), with_density, normal,
                                     window_of(normal))


def test_off_axis_slice_plots_with_amrstreams_north(enzo):
    normal, north = (1.0, 0.4, 0.3), (0.0, 0.0, 1.0)
    plot = yt.OffAxisSlicePlot(enzo, normal, DENSITY, center=list(CENTRE),
                               width=(WIDTH, "code_length"), north_vector=north,
                               buff_size=(PIXELS, PIXELS))
    plot.annotate_amrstream_lines(vector=VECTOR)
    # yt's image axes: its cutting plane's east and north, counted from the centre.
    east, up = (np.asarray(v) for v in plot.data_source.orienter.unit_vectors[:2])
    origin = (float(np.dot(CENTRE, east)), float(np.dot(CENTRE, up)))
    window = (origin[0] - WIDTH / 2, origin[1] - WIDTH / 2, origin[0] + WIDTH / 2,
              origin[1] + WIDTH / 2)
    text = ",".join(str(c) for c in normal)
    with_density = amrstream.from_yt(enzo, vector=VECTOR, fields=["Density"])
    assert_shows_the_plots_place(plot, with_density, text, window)
    expected = amrstream.slice(with_density, vector=VECTOR, normal=text, point=list(CENTRE),
                               window=window, width=PIXELS, background="none",
                               line_separation=WIDTH / 30, progress=None)
    assert_same_lines(drawn_lines(plot), in_plot_units(expected["lines"], origin, 1.0), 1e-9)


def test_the_lines_run_along_yts_velocity_with_an_arrow_each(enzo):
    plot = slice_plot(enzo, "x", unit="code_length")
    plot.annotate_amrstream_lines(vector=VECTOR)
    lines = drawn_lines(plot)
    assert len(drawn(plot, "amrstream_arrow")) == len(lines)
    across, up = (np.asarray(plot.frb["enzo", name].to_value("code_velocity"))
                  for name in ("y-velocity", "z-velocity"))
    pixel = WIDTH / PIXELS
    along = []
    for line in lines:
        steps = np.diff(line, axis=0)
        middles = (line[1:] + line[:-1]) / 2
        column, row = (np.clip(((middles + WIDTH / 2) / pixel).astype(int), 0, PIXELS - 1).T)
        along.append(np.sum(steps[:, 0] * across[row, column] + steps[:, 1] * up[row, column]
                            > 0) / len(steps))
    assert np.mean(along) > 0.99


def test_a_dataset_is_read_once_per_vector(monkeypatch):
    ds = yt.load(str(real_data(ENZO)))
    calls = []

    def counted(*args, **kwargs):
        calls.append(kwargs.get("vector"))
        return amrstream.from_yt(*args, **kwargs)

    monkeypatch.setattr(yt_callbacks, "from_yt", counted)
    plot = slice_plot(ds, "z")
    plot.annotate_amrstream_lic(vector=VECTOR, width=32)
    plot.annotate_amrstream_lines(vector=VECTOR, width=32)
    plot.render()
    plot.zoom(2)
    plot.render()
    assert calls == [VECTOR]
    other = slice_plot(ds, "x")
    other.annotate_amrstream_lines(vector=("y-velocity", "z-velocity", "x-velocity"), width=32)
    other.render()
    assert len(calls) == 2
    assert yt_callbacks.dataset_for(ds, VECTOR) is yt_callbacks.dataset_for(ds, list(VECTOR))
    assert len(calls) == 2


def test_bad_plots_and_fields_raise_at_once_naming_them(enzo):
    plot = slice_plot(enzo, "z")
    with pytest.raises(ValueError, match="no field 'no-such-velocity'"):
        plot.annotate_amrstream_lines(vector=("x-velocity", "no-such-velocity", "z-velocity"))
    with pytest.raises(ValueError, match="no field 'no-such-velocity'"):
        plot.annotate_amrstream_lic(vector=("x-velocity", "no-such-velocity", "z-velocity"))
    assert plot._callbacks == []  # nothing left to fail when the plot is drawn
    with pytest.raises(ValueError, match="three fields"):
        plot.annotate_amrstream_lines(vector=("x-velocity", "y-velocity"))
    with pytest.raises(ValueError, match="width must be a count of pixels"):
        plot.annotate_amrstream_lic(vector=VECTOR, width=12.5)
    projection = yt.ProjectionPlot(enzo, "z", DENSITY)
    with pytest.raises(ValueError, match="on a SlicePlot.*Projection"):
        projection.annotate_amrstream_lines(vector=VECTOR)
    # yt's own choice of north for this normal is not amrstream's: the message says what is.
    off_axis = yt.OffAxisSlicePlot(enzo, (1.0, 0.4, 0.3), DENSITY)
    with pytest.raises(ValueError, match=r"north_vector=\(0, 0, 1\)"):
        off_axis.annotate_amrstream_lic(vector=VECTOR)


def test_2d_flash_z_slice_draws_its_slabs_lines_and_refuses_other_slices():
    ds = yt.load(str(real_data(FLASH_2D)))
    vector = ("dens", "tele", "tion")  # the file has no vector: three scalars stand in for one
    plot = yt.SlicePlot(ds, "z", ("flash", "dens"), buff_size=(32, 32))
    plot.annotate_amrstream_lines(vector=vector)
    lines = drawn_lines(plot, ("flash", "dens"))
    slab = amrstream.from_yt(ds, vector=vector)
    low, high = np.asarray(slab.domain_left_edge), np.asarray(slab.domain_right_edge)
    window = (low[0], low[1], high[0], high[1])  # the whole domain, as the plot shows it
    expected = amrstream.slice(slab, vector=vector, normal="z", point=(low + high) / 2,
                               window=window, width=32, background="none",
                               line_separation=(high[0] - low[0]) / 30, progress=None)
    micrometres = code_length_in(ds, "um")  # the plot's unit for the 20 um high domain
    origin = (low + high)[:2] / 2
    assert_same_lines(lines, in_plot_units(expected["lines"], origin, micrometres), 1e-6)
    with pytest.raises(ValueError, match="2D.*only its z slice"):
        yt.SlicePlot(ds, "x", ("flash", "dens")).annotate_amrstream_lines(vector=vector)


def test_amrex_plotfile_lines():
    ds = yt.load(str(real_data(AMREX)))
    vector = ("x_velocity", "y_velocity", "z_velocity")
    field = ("boxlib", "density")
    plot = yt.SlicePlot(ds, "y", field, buff_size=(64, 64))
    plot.set_axes_unit("cm")
    plot.annotate_amrstream_lines(vector=vector)
    lines = drawn_lines(plot, field)
    low, high = (np.asarray(e.to_value("code_length")) for e in (ds.domain_left_edge,
                                                                  ds.domain_right_edge))
    window = (low[2], low[0], high[2], high[0])  # across y the image is (z, x)
    expected = amrstream.slice(amrstream.from_yt(ds, vector=vector), vector=vector,
                               normal="y", window=window, width=64, background="none",
                               line_separation=(high[2] - low[2]) / 30, progress=None)
    origin = ((low[2] + high[2]) / 2, (low[0] + high[0]) / 2)
    assert_same_lines(lines, in_plot_units(expected["lines"], origin,
                                           code_length_in(ds, "cm")), 1e-9)


@pytest.mark.parametrize("order", ["amrstream first", "yt first"])
def test_the_callbacks_are_registered_whichever_comes_first_and_yt_is_not_imported_for_them(order):
    """A fresh interpreter: importing amrstream alone leaves yt unimported (it takes 0.6 s);
    yt's plots get both callbacks once yt is imported, before or after amrstream."""
    import subprocess
    import sys
    imports = "import amrstream\nimport yt" if order == "amrstream first" else \
        "import yt\nimport amrstream"
    script = f"""
import sys
{imports.splitlines()[0]}
before = "yt" in sys.modules
{imports.splitlines()[1]}
from yt.visualization.plot_window import PWViewerMPL
print(before, all(hasattr(PWViewerMPL, name)
                  for name in ("annotate_amrstream_lines", "annotate_amrstream_lic")))
"""
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                         check=True).stdout.split()
    assert out == (["False", "True"] if order == "amrstream first" else ["True", "True"])
