"""amrstream.slice against the reconstruction and the command line: the background holds what
Field.resample samples at the pixel centres, the figure is the one `amrstream slice` writes, the
lines stay in the window, and quantities convert."""
import os
import subprocess

import numpy as np
import pytest

import amrstream

SMALL = dict(levels=3, root_blocks=2, target_cells=20000)


@pytest.fixture(scope="module")
def cloud():
    return amrstream.load("builtin:cloud", length_unit="m", **SMALL)


def test_the_background_is_the_reconstruction_at_the_pixel_centres(cloud):
    field = amrstream.prepare(cloud)
    result = amrstream.slice(field, normal="z", point=(0.5, 0.5, 0.3), width=24, progress=None)
    assert result["background_name"] == "dens"
    assert result["axes"] == ("x", "y")
    grid = field.resample((24, 24, 1), box=(0.0, 0.0, 0.29, 1.0, 1.0, 0.31))
    # resample's arrays are [i, j, k]; the slice's [row from the lower edge, column].
    expected = grid["dens"][:, :, 0].T
    # The slice computes its pixel centres in float (as the device's grid probe does), resample
    # in double: the same points within a float's rounding.
    np.testing.assert_allclose(result["background"], expected, rtol=1e-5, atol=0)
    assert not np.array_equal(result["background"], np.roll(expected, 1, axis=1))
    assert result["lic"] is None
    for line in result["lines"]:
        assert line.shape[1] == 2
        assert np.all(line >= -1e-12) and np.all(line <= 1.0 + 1e-12)


def test_the_figure_is_the_command_lines(cloud, tmp_path):
    cli = os.environ.get("AMRSTREAM_CLI")
    if not cli:
        pytest.skip("AMRSTREAM_CLI is not set: run through ctest")
    import matplotlib.image

    options = ["--normal", "y", "--width", "48", "--lic", "--colour-scale", "log"]
    subprocess.run([cli, "slice", "builtin:cloud", "--levels", "3", "--root-blocks", "2",
                    "--target-cells", "20000", *options, "--out", str(tmp_path / "s.png")],
                   check=True, capture_output=True)
    written = np.round(matplotlib.image.imread(tmp_path / "s.png") * 255).astype(np.uint8)
    ds = amrstream.load("builtin:cloud", **SMALL)
    image = amrstream.slice(ds, normal="y", width=48, lic=True, colour_scale="log",
                            progress=None)["image"]
    assert image.shape == written.shape
    assert np.array_equal(image, written)


def test_quantities_and_bad_keywords(cloud):
    unyt = pytest.importorskip("unyt")
    plain = amrstream.slice(cloud, width=16, point=(0.5, 0.5, 0.25), window=(0.2, 0.2, 0.6, 0.6),
                            line_separation=0.05, progress=None)
    units = amrstream.slice(cloud, width=16, point=unyt.unyt_array([50, 50, 25], "cm"),
                            window=unyt.unyt_array([20, 20, 60, 60], "cm"),
                            line_separation=unyt.unyt_quantity(5, "cm"), progress=None)
    assert np.array_equal(plain["background"], units["background"])
    assert len(plain["lines"]) == len(units["lines"])
    with pytest.raises(TypeError, match=r"slice\(\) got an unexpected keyword argument 'widht' "
                                        r"\(did you mean 'width'\?\)"):
        amrstream.slice(cloud, widht=3)
    with pytest.raises(ValueError, match="normal: 'q' is neither x, y, z"):
        amrstream.slice(cloud, normal="q", progress=None)
    with pytest.raises(ValueError, match="were chosen when the Field was prepared"):
        amrstream.slice(amrstream.prepare(cloud), vector="magx,magy,magz")


def test_line_values_are_the_reconstruction_along_the_lines():
    rotation = amrstream.load("builtin:rotation", **SMALL)
    result = amrstream.slice(rotation, interpolant="linear", point=(0.5, 0.5, 0.45), width=64,
                             background="none", line_colour_by="magnitude",
                             line_width_by="magnitude", progress=None)
    assert result["line_colour_values"] is not None
    assert len(result["line_colour_values"]) == len(result["lines"]) > 3
    for line, speeds, widths in zip(result["lines"], result["line_colour_values"],
                                    result["line_width_values"]):
        assert speeds.shape == (len(line),)
        # The solid-body rotation's speed, 2 pi times the distance from the axis through (0.5,
        # 0.5), which the linear interpolant reconstructs exactly.
        expected = 2.0 * np.pi * np.hypot(line[:, 0] - 0.5, line[:, 1] - 0.5)
        known = ~np.isnan(speeds)
        assert known.mean() > 0.9
        np.testing.assert_allclose(speeds[known], expected[known], rtol=1e-4, atol=1e-4)
        np.testing.assert_array_equal(widths, speeds)
    plain = amrstream.slice(rotation, width=64, background="none", progress=None)
    assert plain["line_colour_values"] is None and plain["line_width_values"] is None


def test_an_oblique_planes_vti_lies_on_the_plane_with_the_reconstruction(tmp_path):
    cli = os.environ.get("AMRSTREAM_CLI")
    if not cli:
        pytest.skip("AMRSTREAM_CLI is not set: run through ctest")
    vtk_xml = pytest.importorskip("vtkmodules.vtkIOXML")
    from vtkmodules.util.numpy_support import vtk_to_numpy

    normal, point = np.array([1.0, 2.0, 3.0]), np.array([0.45, 0.5, 0.55])
    vti = tmp_path / "oblique.vti"
    subprocess.run([cli, "slice", "builtin:cloud", "--levels", "3", "--root-blocks", "2",
                    "--target-cells", "20000", "--normal", "1,2,3", "--point", "0.45,0.5,0.55",
                    "--width", "40", "--lic", "--vti", str(vti), "--out",
                    str(tmp_path / "oblique.png")], check=True, capture_output=True)
    reader = vtk_xml.vtkXMLImageDataReader()
    reader.SetFileName(str(vti))
    reader.Update()
    image = reader.GetOutput()
    width, height, depth = image.GetDimensions()
    assert width == 40 and depth == 1
    unit = normal / np.linalg.norm(normal)
    dens = vtk_to_numpy(image.GetPointData().GetArray("dens"))
    assert image.GetPointData().GetArray("LIC") is not None
    field = amrstream.prepare(amrstream.load("builtin:cloud", **SMALL))
    checked = 0
    for i, j in ((0, 0), (39, 0), (0, height - 1), (20, height // 2), (7, 31), (33, 9)):
        physical = [0.0, 0.0, 0.0]
        image.TransformIndexToPhysicalPoint(i, j, 0, physical)
        p = np.array(physical)
        assert abs(np.dot(p - point, unit)) < 1e-9, "the image's point is off the plane"
        n = i + width * j
        if np.isnan(dens[n]):
            continue
        # The reconstruction at p: the centre of a one-point resample box around it.
        box = tuple(p - 1e-7) + tuple(p + 1e-7)
        expected = field.resample((1, 1, 1), box=box)["dens"][0, 0, 0]
        np.testing.assert_allclose(dens[n], expected, rtol=1e-5)
        checked += 1
    assert checked >= 4
