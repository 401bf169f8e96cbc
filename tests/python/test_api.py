"""Tests of the amrstream Python module (python/amrstream, src/python) against the command line.

Needs the module on PYTHONPATH (build/python). The CLI comparisons read the `amrstream`
executable from $AMRSTREAM_CLI and the real data sets from $AMRSTREAM_SHARED_DATA; tests that
need either skip, saying so, when it is absent. CTest sets all three.
"""

import errno
import gc
import os
import subprocess
import sys
import textwrap
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import amrstream  # noqa: E402  (the package CTest names: tests/python/run_pytest.sh)
import vtk  # noqa: E402  (Debian's python3-paraview reads the .vtp files)
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

from shared_data import real_data

# Small builtin data sets: the same sizes on both sides of every CLI comparison.
SMALL = dict(levels=3, root_blocks=2, target_cells=50000)
SMALL_CLI = ["--levels", "3", "--root-blocks", "2", "--target-cells", "50000"]
GPU_BACKENDS = ["compute", "rayquery", "pipeline"]
REASON_PERIODIC_WRAP = 8


# ---------------------------------------------------------------- helpers

def cli_path():
    path = os.environ.get("AMRSTREAM_CLI")
    if not path:
        pytest.skip("AMRSTREAM_CLI is not set: it names the amrstream executable (CTest sets it)")
    if not Path(path).is_file():
        pytest.skip(f"AMRSTREAM_CLI={path} does not exist: build the amrstream target")
    return path


_backend_ok = {}


def require_backend(name):
    """Skips unless `name` can trace here (e.g. no Vulkan device on this machine)."""
    if name not in _backend_ok:
        ds = amrstream.load("builtin:rotation", levels=1, root_blocks=1, target_cells=1000)
        try:
            amrstream.trace(ds, [[0.5, 0.5, 0.5]], steps=2, backend=name)
            _backend_ok[name] = None
        except amrstream.BackendError as e:
            _backend_ok[name] = str(e)
    if _backend_ok[name] is not None:
        pytest.skip(f"backend {name} is not available here: {_backend_ok[name]}")


def write_seeds(path, seeds):
    # repr() of a Python float round-trips exactly, so the CLI gets the very same doubles.
    with open(path, "w") as f:
        for x, y, z in np.asarray(seeds, dtype=np.float64):
            f.write(f"{float(x)!r} {float(y)!r} {float(z)!r}\n")


def run_cli(*args):
    result = subprocess.run([cli_path(), *map(str, args)], capture_output=True, text=True,
                            timeout=120)
    assert result.returncode == 0, f"amrstream {' '.join(map(str, args))} failed:\n{result.stderr}"
    return result


def run_python(script):
    """Runs `script` in a fresh interpreter (for what may crash one)."""
    return subprocess.run([sys.executable, "-c", textwrap.dedent(script)], capture_output=True,
                          text=True, timeout=60, env=dict(os.environ))


class Vtp:
    """What vtkXMLPolyDataReader reads from a .vtp: points, polylines, arrays, field data."""

    def __init__(self, path):
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(str(path))
        reader.Update()
        poly = reader.GetOutput()
        assert poly.GetNumberOfPoints() > 0, f"VTK read no points from {path}"
        self.points = vtk_to_numpy(poly.GetPoints().GetData())
        lines = poly.GetLines()
        self.offsets = vtk_to_numpy(lines.GetOffsetsArray()).astype(np.int64)
        connectivity = vtk_to_numpy(lines.GetConnectivityArray())
        # The writer stores each polyline's points in order, one after the other.
        assert np.array_equal(connectivity, np.arange(len(self.points))), "connectivity"
        pd, cd, fd = poly.GetPointData(), poly.GetCellData(), poly.GetFieldData()
        self.point_arrays = {pd.GetArrayName(i): vtk_to_numpy(pd.GetArray(i))
                             for i in range(pd.GetNumberOfArrays())}
        self.cell_arrays = {cd.GetArrayName(i): vtk_to_numpy(cd.GetArray(i))
                            for i in range(cd.GetNumberOfArrays())}
        self.field_data = {}
        for i in range(fd.GetNumberOfArrays()):
            array = fd.GetAbstractArray(i)
            self.field_data[array.GetName()] = [array.GetVariantValue(j).ToString()
                                                for j in range(array.GetNumberOfValues())]

    @property
    def polyline_count(self):
        return len(self.offsets) - 1

    def lines(self):
        """The traced lines the file holds, as (point indices, seed id, reason): a degenerate
        2-point polyline (one point written twice) counts as 1 point, and split pieces (reason 8
        on all but the last) are joined."""
        times = self.point_arrays["IntegrationTime"]
        seeds = self.cell_arrays["SeedIds"]
        reasons = self.cell_arrays["ReasonForTermination"]
        lines, pieces = [], []
        for c in range(self.polyline_count):
            idx = np.arange(self.offsets[c], self.offsets[c + 1])
            assert len(idx) >= 2, f"polyline {c} has fewer than 2 points (VTK rejects it)"
            if len(idx) == 2 and times[idx[0]] == times[idx[1]]:
                for name, values in self.point_arrays.items():
                    assert np.array_equal(values[idx[0]], values[idx[1]]), \
                        f"degenerate polyline {c}: {name} differs between its 2 points"
                assert np.array_equal(self.points[idx[0]], self.points[idx[1]])
                idx = idx[:1]
            if pieces:
                assert seeds[c] == seeds[c - 1], f"piece {c} of a split line changes SeedIds"
            pieces.append(idx)
            if reasons[c] != REASON_PERIODIC_WRAP:
                lines.append((np.concatenate(pieces), int(seeds[c]), int(reasons[c])))
                pieces = []
        assert not pieces, "the file ends in a piece with ReasonForTermination 8"
        return lines


def assert_same_vtp(a, b, ignore_field_data=("Seeds",)):
    """Two .vtp files hold the same polylines and arrays, bit for bit."""
    assert a.polyline_count == b.polyline_count
    assert np.array_equal(a.offsets, b.offsets)
    assert a.points.dtype == b.points.dtype
    assert np.array_equal(a.points, b.points), "points differ"
    assert a.point_arrays.keys() == b.point_arrays.keys()
    for name in a.point_arrays:
        assert a.point_arrays[name].dtype == b.point_arrays[name].dtype, name
        assert np.array_equal(a.point_arrays[name], b.point_arrays[name]), f"point array {name}"
    assert a.cell_arrays.keys() == b.cell_arrays.keys()
    for name in a.cell_arrays:
        assert np.array_equal(a.cell_arrays[name], b.cell_arrays[name]), f"cell array {name}"
    assert a.field_data.keys() == b.field_data.keys()
    for name in a.field_data:
        if name not in ignore_field_data:
            assert a.field_data[name] == b.field_data[name], f"field data {name}"


def assert_traces_match_file(t, f, *, period=None):
    """The Traces' own arrays hold what the file holds. period: with unwrapped periodic lines,
    the file's points are the Traces' (wrapped) points plus whole periods."""
    lines = f.lines()
    assert len(lines) == len(t)
    counts = np.diff(t.offsets.astype(np.int64))
    assert [len(idx) for idx, _, _ in lines] == counts.tolist()
    assert [seed for _, seed, _ in lines] == t.seed_ids.tolist()
    assert [reason for _, _, reason in lines] == t.reasons.tolist()
    idx = np.concatenate([i for i, _, _ in lines]) if lines else np.zeros(0, np.int64)
    points = f.points[idx]
    if period is None:
        assert np.array_equal(points, t.points), "points differ"
    else:
        shift = np.round((points.astype(np.float64) - t.points) / period)
        unwrapped = t.points + shift * period
        tolerance = 4 * np.finfo(np.float32).eps * max(1.0, np.abs(points).max())
        assert np.abs(unwrapped - points).max() <= tolerance
    assert np.array_equal(f.point_arrays["IntegrationTime"][idx], t.integration_time)
    assert np.array_equal(f.point_arrays[t.vector_name][idx], t.vectors)
    speed = np.linalg.norm(t.vectors.astype(np.float64), axis=1)
    assert np.allclose(f.point_arrays["Speed"][idx], speed, rtol=1e-6, atol=0)
    for name, values in t.point_data.items():
        assert np.array_equal(f.point_arrays[name][idx], values), f"point data {name}"
    if t.vorticity is not None:
        assert np.array_equal(f.point_arrays["Vorticity"][idx], t.vorticity)
    expected = {t.vector_name, "IntegrationTime", "Speed", *t.point_data}
    if t.vorticity is not None:
        expected |= {"Vorticity", "Rotation", "AngularVelocity"}
    assert set(f.point_arrays) == expected
    assert set(f.cell_arrays) == {"SeedIds", "ReasonForTermination"}


def levels_zero_coarsest(ds):
    """Dataset.levels (the file's numbering) as from_arrays wants them: 0 = coarsest."""
    levels = ds.levels.astype(np.int64)
    if "0 = finest" in ds.level_name:
        return levels.max() - levels
    return levels - levels.min()


def assert_same_traces(a, b):
    assert len(a) == len(b)
    for name in ("offsets", "seed_ids", "directions", "steps", "reasons", "points",
                 "integration_time", "vectors"):
        assert np.array_equal(getattr(a, name), getattr(b, name)), name
    assert a.vector_name == b.vector_name
    assert a.point_data.keys() == b.point_data.keys()
    for name in a.point_data:
        assert np.array_equal(a.point_data[name], b.point_data[name]), name


# ---------------------------------------------------------------- data sets

@pytest.fixture(scope="module")
def cloud():
    return amrstream.load("builtin:cloud", **SMALL)


@pytest.fixture(scope="module")
def abc():
    return amrstream.load("builtin:abc", **SMALL)


@pytest.fixture(scope="module")
def cloud_seeds(cloud):
    # Random seeds plus seeds just inside faces that the field leaves through at once, so some
    # lines end at their seed (1 point: a degenerate 2-point polyline in the file).
    edge = [[0.999, 0.5, 0.5], [0.5, 0.0005, 0.5], [0.5, 0.5, 0.9999], [1e-6, 0.3, 0.7]]
    return np.vstack([amrstream.seeds_random(cloud, 24, seed=5), edge])


@pytest.fixture(scope="module")
def abc_seeds(abc):
    return amrstream.seeds_random(abc, 8, seed=7)


# ---------------------------------------------------------------- 1. Python equals the CLI

@pytest.mark.parametrize("backend", ["cpu", *GPU_BACKENDS])
def test_cloud_traces_equal_cli_vtp(backend, cloud, cloud_seeds, tmp_path):
    require_backend(backend)
    write_seeds(tmp_path / "seeds.txt", cloud_seeds)
    run_cli("trace", "builtin:cloud", *SMALL_CLI, "--seeds", tmp_path / "seeds.txt",
            "--steps", 300, "--direction", "both", "--point-data", "all", "--backend", backend,
            "--out", tmp_path / "cli.vtp")
    t = amrstream.trace(cloud, cloud_seeds, steps=300, direction="both", point_data="all",
                        backend=backend)
    assert t.backend.startswith(backend)
    counts = t.to_vtp(str(tmp_path / "py.vtp"))
    cli, py = Vtp(tmp_path / "cli.vtp"), Vtp(tmp_path / "py.vtp")

    assert counts == (py.polyline_count, len(py.points))
    assert py.polyline_count == len(t) == 2 * len(cloud_seeds)
    assert (np.diff(t.offsets.astype(np.int64)) == 1).any(), "no 1-point line: edge seeds moved?"
    assert set(t.point_data) == {"dens"} and t.vector_name == "mag"
    assert_same_vtp(cli, py)
    assert cli.field_data["Seeds"] == [f"{len(cloud_seeds)} from {tmp_path / 'seeds.txt'}"]
    assert py.field_data["Seeds"] == [f"{len(cloud_seeds)} from Python"]
    assert_traces_match_file(t, cli)


def test_cli_trace_of_an_exa_reads_channels_one_at_a_time_and_equals_the_whole_load(tmp_path):
    """`trace` reads an .exa's channels one at a time, after the layout (the density for the
    seeds, then each channel the volume takes): the seeds and the traces equal those of the
    whole dataset loaded at once (the builtin it was written from, and Python's load)."""
    run_cli("gen", "cloud", *SMALL_CLI, "--out", tmp_path / "c")
    common = ["--seed-density", "dens", "--count", 40, "--steps", 200, "--backend", "cpu"]
    run_cli("trace", tmp_path / "c.exa", *common, "--seeds-out", tmp_path / "exa_seeds.txt",
            "--out", tmp_path / "exa.vtp")
    run_cli("trace", "builtin:cloud", *SMALL_CLI, *common,
            "--seeds-out", tmp_path / "builtin_seeds.txt", "--out", tmp_path / "builtin.vtp")
    assert (tmp_path / "exa_seeds.txt").read_text() == (tmp_path / "builtin_seeds.txt").read_text()
    seeds = np.loadtxt(tmp_path / "exa_seeds.txt", ndmin=2)
    t = amrstream.trace(amrstream.load(str(tmp_path / "c.exa")), seeds, steps=200,
                        backend="cpu")
    exa = Vtp(tmp_path / "exa.vtp")
    assert_same_vtp(exa, Vtp(tmp_path / "builtin.vtp"),
                    ignore_field_data=("Seeds", "Input", "InputFormat", "SimulationTime"))
    assert_traces_match_file(t, exa)
    assert set(t.point_data) == {"dens"}


def test_field_resample_equals_the_cli_vti_and_indexes_x_first(tmp_path):
    """Field.resample gives the arrays `amrstream resample` writes, bit for bit, indexed
    [i, j, k] with x first; the ABC flow's x component depends on y and z only."""
    run_cli("resample", "builtin:abc", *SMALL_CLI, "--dims", "7,6,5", "--box",
            "0.1,0.2,0.0,0.9,0.8,1.0", "--out", tmp_path / "g.vti")
    field = amrstream.prepare(amrstream.load("builtin:abc", **SMALL))
    grid = field.resample((7, 6, 5), box=(0.1, 0.2, 0.0, 0.9, 0.8, 1.0))
    reader = vtk.vtkXMLImageDataReader()
    reader.SetFileName(str(tmp_path / "g.vti"))
    reader.Update()
    image = reader.GetOutput()
    assert image.GetDimensions() == grid["dims"] == (7, 6, 5)
    assert np.allclose(image.GetOrigin(), grid["origin"], rtol=1e-15, atol=0)
    assert np.allclose(image.GetSpacing(), grid["spacing"], rtol=1e-15, atol=0)
    vectors = vtk_to_numpy(image.GetPointData().GetArray("vel")).reshape(5, 6, 7, 3)
    assert np.array_equal(grid["vel"], vectors.transpose(2, 1, 0, 3))
    assert grid["valid"].all() and grid["vel"].flags.writeable is False
    x, y, z = (grid["origin"][a] + grid["spacing"][a] * np.arange(n)
               for a, n in enumerate(grid["dims"]))
    X, Y, Z = np.meshgrid(x, y, z, indexing="ij")
    exact = np.sqrt(3.0) * np.sin(2 * np.pi * Z) + np.cos(2 * np.pi * Y)
    assert np.abs(grid["vel"][..., 0] - exact).max() < 0.3  # coarse cells; transposed: ~2
    with pytest.raises(ValueError, match="^box: each upper bound"):
        field.resample(4, box=(1, 0, 0, 0, 1, 1))


def test_render_camera_and_colour_options_equal_cli_png(cloud, cloud_seeds, tmp_path):
    require_backend("compute")
    look = ["--width", 96, "--height", 64, "--frames", 2, "--view", "+x", "--up", "+y",
            "--projection", "orthographic", "--fov", 50, "--zoom", 1.2, "--colour-by", "dens",
            "--colour-scale", "log", "--colour-map", "inferno", "--tube-radius-view", 0.01,
            "--radius-by-colour", 0.3]
    write_seeds(tmp_path / "seeds.txt", cloud_seeds)
    run_cli("render", "builtin:cloud", *SMALL_CLI, "--seeds", tmp_path / "seeds.txt",
            "--steps", 300, "--direction", "both", "--backend", "compute", *look,
            "--out", tmp_path / "cli.png")
    t = amrstream.trace(cloud, cloud_seeds, steps=300, direction="both", backend="compute")
    image = t.render(width=96, height=64, frames=2, view="+x", up="+y",
                     projection="orthographic", fov=50, zoom=1.2, colour_by="dens",
                     colour_scale="log", colour_map="inferno", tube_radius_view=0.01,
                     radius_by_colour=0.3, backend="compute")
    reader = vtk.vtkPNGReader()
    reader.SetFileName(str(tmp_path / "cli.png"))
    reader.Update()
    png = reader.GetOutput()
    cli = vtk_to_numpy(png.GetPointData().GetScalars()).reshape(64, 96, -1)[::-1]
    assert image.shape == (64, 96, 4)
    assert np.array_equal(image[..., :cli.shape[2]], cli)
    with pytest.raises(ValueError, match="a log scale needs a positive minimum"):
        t.render(width=32, height=32, colour_scale="log", range=(-1, 1), backend="compute")
    with pytest.raises(ValueError, match="no view 'front'"):
        t.render(width=32, height=32, view="front", backend="compute")
    with pytest.raises(ValueError, match=r"^radius_by_colour: 0 is outside the range 1e-06 to 1"):
        t.render(width=32, height=32, radius_by_colour=0.0, backend="compute")


@pytest.mark.parametrize("backend", ["cpu", "compute"])
def test_linear_interpolant_traces_equal_cli_vtp(backend, cloud, cloud_seeds, tmp_path):
    require_backend(backend)
    write_seeds(tmp_path / "seeds.txt", cloud_seeds)
    run_cli("trace", "builtin:cloud", *SMALL_CLI, "--seeds", tmp_path / "seeds.txt",
            "--steps", 200, "--interpolant", "linear", "--vorticity", "--backend", backend,
            "--out", tmp_path / "cli.vtp")
    t = amrstream.trace(cloud, cloud_seeds, steps=200, interpolant="linear", vorticity=True,
                        backend=backend)
    t.to_vtp(str(tmp_path / "py.vtp"))
    cli, py = Vtp(tmp_path / "cli.vtp"), Vtp(tmp_path / "py.vtp")
    assert cli.field_data["Interpolant"] == ["linear"]
    assert_same_vtp(cli, py)
    assert_traces_match_file(t, cli)
    tent = amrstream.trace(cloud, cloud_seeds, steps=200, vorticity=True, backend=backend)
    # the interpolant changed the lines
    assert tent.points.shape != t.points.shape or not np.array_equal(tent.points, t.points)


@pytest.mark.parametrize("backend", ["cpu", *GPU_BACKENDS])
def test_periodic_abc_traces_equal_cli_vtp(backend, abc, abc_seeds, tmp_path):
    require_backend(backend)
    write_seeds(tmp_path / "seeds.txt", abc_seeds)
    common = ["--seeds", tmp_path / "seeds.txt", "--steps", 300, "--vorticity",
              "--backend", backend]
    run_cli("trace", "builtin:abc", *SMALL_CLI, *common, "--out", tmp_path / "cli_split.vtp")
    run_cli("trace", "builtin:abc", *SMALL_CLI, *common, "--periodic-lines", "unwrapped",
            "--compression", "none", "--out", tmp_path / "cli_unwrapped.vtp")
    t = amrstream.trace(abc, abc_seeds, steps=300, vorticity=True, backend=backend)
    split_counts = t.to_vtp(str(tmp_path / "py_split.vtp"))
    unwrapped_counts = t.to_vtp(str(tmp_path / "py_unwrapped.vtp"), compression="none",
                                periodic_lines="unwrapped")
    cli_split, py_split = Vtp(tmp_path / "cli_split.vtp"), Vtp(tmp_path / "py_split.vtp")
    cli_unwrapped = Vtp(tmp_path / "cli_unwrapped.vtp")
    py_unwrapped = Vtp(tmp_path / "py_unwrapped.vtp")

    assert abc.periodic == (True, True, True)
    assert t.vorticity is not None and t.vorticity.shape == t.points.shape
    assert split_counts == (py_split.polyline_count, len(py_split.points))
    assert unwrapped_counts == (py_unwrapped.polyline_count, len(py_unwrapped.points))
    assert py_split.polyline_count > len(t), "no line crossed a periodic face"
    assert py_unwrapped.polyline_count == len(t)
    assert_same_vtp(cli_split, py_split)
    assert_same_vtp(cli_unwrapped, py_unwrapped)
    assert_traces_match_file(t, cli_split)
    assert_traces_match_file(t, cli_unwrapped, period=1.0)
    # Split pieces stay in the domain and never jump; unwrapped lines never jump either.
    lower, upper = np.array(abc.domain_left_edge), np.array(abc.domain_right_edge)
    assert (cli_split.points >= lower).all() and (cli_split.points <= upper).all()
    for f in (cli_split, cli_unwrapped):
        for c in range(f.polyline_count):
            piece = f.points[f.offsets[c]:f.offsets[c + 1]]
            assert np.abs(np.diff(piece, axis=0)).max(initial=0) < 0.5, f"polyline {c} jumps"


def test_trace_of_prepared_field_equals_trace_of_dataset(cloud, cloud_seeds):
    field = amrstream.prepare(cloud, vector=("magx", "magy", "magz"), point_data=["dens"])
    assert field.vector_name == "mag" and list(field.point_data) == ["dens"]
    assert_same_traces(amrstream.trace(field, cloud_seeds, steps=300, backend="cpu"),
                       amrstream.trace(cloud, cloud_seeds, steps=300, backend="cpu"))


# ---------------------------------------------------------------- 2. from_arrays round trip

def _exa_from(ds, folder):
    """Writes ds as an ExaBricks .exa (levels 0 = finest, a non-zero origin) and loads it."""
    levels = ds.levels.astype(np.int64)
    cells = np.column_stack([ds.corners, levels.max() - levels]).astype("<i4")
    cells.tofile(folder / "c.cells")
    lines = ["cells c.cells", "origin 1 -2 0.5", "spacing 0.25 0.25 0.25"]
    for name in ds.field_names:
        ds.field(name).astype("<f4").tofile(folder / f"c.{name}.scalars")
        lines.append(f"scalar {name} c.{name}.scalars")
    (folder / "c.exa").write_text("\n".join(lines) + "\n")
    return amrstream.load(str(folder / "c.exa"))


ROUND_TRIP_SOURCES = {
    "builtin-abc-periodic": lambda tmp: amrstream.load("builtin:abc", **SMALL),
    "exa-0-finest": lambda tmp: _exa_from(amrstream.load("builtin:cloud", **SMALL), tmp),
    "gerris-levels-3-7": lambda tmp: amrstream.load(
        str(real_data("gerris-ring/ring-end.txt"))),
    "enzo-periodic-8-levels": lambda tmp: amrstream.load(
        str(real_data("enzo-moving7/DD0010/moving7_0010"))),
}


@pytest.mark.parametrize("source", ROUND_TRIP_SOURCES)
def test_from_arrays_round_trip_traces_like_the_original(source, tmp_path):
    ds = ROUND_TRIP_SOURCES[source](tmp_path)
    rebuilt = amrstream.from_arrays(ds.corners, levels_zero_coarsest(ds),
                                    {name: ds.field(name) for name in ds.field_names},
                                    origin=ds.origin, finest_width=ds.finest_width,
                                    periodic=ds.periodic)
    assert rebuilt.cell_count == ds.cell_count
    assert rebuilt.field_names == ds.field_names
    assert np.array_equal(rebuilt.corners, ds.corners)
    assert np.array_equal(rebuilt.levels, levels_zero_coarsest(ds))
    assert rebuilt.periodic == ds.periodic
    assert rebuilt.domain_left_edge == ds.domain_left_edge
    assert rebuilt.domain_right_edge == ds.domain_right_edge
    seeds = amrstream.seeds_random(ds, 48, seed=11)
    original = amrstream.trace(ds, seeds, steps=300, backend="cpu")
    assert (np.diff(original.offsets.astype(np.int64)) > 10).sum() > 10, "too few real lines"
    assert_same_traces(amrstream.trace(rebuilt, seeds, steps=300, backend="cpu"), original)


# ---------------------------------------------------------------- 3. zero copy and lifetime

def _base_owner(array):
    while isinstance(array, np.ndarray):
        array = array.base
    return array


def test_traces_arrays_are_views_that_outlive_the_traces(cloud, cloud_seeds):
    t = amrstream.trace(cloud, cloud_seeds, steps=300, point_data="dens,magx,magz",
                        backend="cpu")
    names = ("points", "offsets", "seed_ids", "directions", "steps", "reasons",
             "integration_time", "vectors")
    arrays = {name: getattr(t, name) for name in names}
    arrays.update({f"point_data[{k}]": v for k, v in t.point_data.items()})
    arrays["t[1]"], arrays["t[-1]"] = t[1], t[-1]
    copies = {name: a.copy() for name, a in arrays.items()}
    for name, a in arrays.items():
        assert isinstance(_base_owner(a), amrstream.Traces), f"{name} is not a view of Traces"

    off = t.offsets.astype(np.int64)
    assert np.shares_memory(t.points, t[0])
    assert np.shares_memory(t.points, t[1])
    assert np.array_equal(t[1], t.points[off[1]:off[2]])
    assert t[1].__array_interface__["data"][0] == t.points[off[1]:].__array_interface__["data"][0]
    assert np.shares_memory(t.points, getattr(t, "points"))
    # The channels are interleaved in one buffer: strided views of it.
    pd = t.point_data
    address = {name: a.__array_interface__["data"][0] for name, a in pd.items()}
    assert address["magx"] == address["dens"] + 4 and address["magz"] == address["dens"] + 8
    assert all(a.strides == (12,) for a in pd.values())
    assert np.array_equal(pd["magx"], t.vectors[:, 0])
    assert np.array_equal(pd["magz"], t.vectors[:, 2])

    del t, pd
    gc.collect()
    junk = [np.full(len(a) * 4 + 64, 7.0) for a in copies.values()]  # reuse freed memory
    for name, a in arrays.items():
        assert np.array_equal(a, copies[name]), f"{name} changed after the Traces was deleted"
    del junk


def test_dataset_arrays_are_views_that_outlive_the_dataset():
    ds = amrstream.load("builtin:cloud", **SMALL)
    corners, dens = ds.corners, ds.field("dens")
    assert corners.dtype == np.int32 and corners.shape == (ds.cell_count, 3)
    assert dens.dtype == np.float32 and dens.shape == (ds.cell_count,)
    assert np.shares_memory(corners, ds.corners)
    assert np.shares_memory(dens, ds.field("dens"))
    assert not np.shares_memory(dens, ds.field("magx"))
    assert isinstance(_base_owner(corners), amrstream.Dataset)
    assert isinstance(_base_owner(dens), amrstream.Dataset)
    copies = corners.copy(), dens.copy()

    del ds
    gc.collect()
    junk = np.full(4 * copies[0].size, -1, dtype=np.int32)
    assert np.array_equal(corners, copies[0])
    assert np.array_equal(dens, copies[1])
    del junk


# Views of memory the C++ side reads again are read-only: Python cannot corrupt it.
def test_writing_through_dataset_corners_cannot_crash_trace():
    result = run_python("""
        import amrstream
        ds = amrstream.load("builtin:cloud", levels=3, root_blocks=2, target_cells=50000)
        seeds = amrstream.seeds_random(ds, 4)
        try:
            ds.corners[:] = 0
        except ValueError:
            pass  # a read-only view: fine
        try:
            amrstream.trace(ds, seeds, backend="cpu")
        except ValueError:
            pass  # the corrupted cells are refused: fine
    """)
    assert result.returncode == 0, f"the interpreter died: rc {result.returncode}\n{result.stderr}"


def test_writing_through_traces_offsets_cannot_make_out_of_bounds_views(cloud, cloud_seeds):
    t = amrstream.trace(cloud, cloud_seeds, steps=50, backend="cpu")
    try:
        t.offsets[3] = 10**12
    except ValueError:
        return  # a read-only view: fine
    try:
        line = t[2]
    except (ValueError, IndexError):
        return
    assert line.shape[0] <= len(t.points), f"t[2] has {line.shape[0]} points of {len(t.points)}"


def test_offsets_are_int64_so_they_slice_as_numpy_indexes(cloud, cloud_seeds):
    t = amrstream.trace(cloud, cloud_seeds, steps=50, backend="cpu")
    assert t.offsets.dtype == np.int64
    start = t.offsets[2]
    assert isinstance(start + 1, np.integer)  # uint64 + int was float64, no slice bound
    assert np.array_equal(t.points[start:t.offsets[3]], t[2])


def test_pieces_cut_a_periodic_line_where_it_crosses_a_face():
    ds = amrstream.load("builtin:abc", levels=2, root_blocks=1, target_cells=600)
    period = np.subtract(ds.domain_right_edge, ds.domain_left_edge)
    t = amrstream.trace(ds, amrstream.seeds_random(ds, 4, seed=1), steps=500, backend="cpu")
    cut = 0
    for i in range(len(t)):
        pieces = t.pieces(i)
        assert np.array_equal(np.concatenate(pieces), t[i])
        for piece in pieces:  # within a piece no step jumps by half a period
            assert np.all(np.abs(np.diff(piece, axis=0)) <= period / 2)
        for a, b in zip(pieces, pieces[1:]):  # between pieces the line jumps across the box
            assert np.any(np.abs(b[0] - a[-1]) > period / 2)
        cut += len(pieces) - 1
    assert cut > 0  # ABC flow crosses its periodic faces within 500 steps


# ---------------------------------------------------------------- 4. both directions

def test_both_directions_forward_lines_then_backward(cloud, cloud_seeds):
    n = len(cloud_seeds)
    both = amrstream.trace(cloud, cloud_seeds, steps=300, direction="both", backend="cpu")
    assert len(both) == 2 * n
    assert both.directions.tolist() == [1.0] * n + [-1.0] * n
    assert both.seed_ids.tolist() == list(range(n)) * 2
    time_ = both.integration_time
    off = both.offsets.astype(np.int64)
    for i in range(2 * n):
        line_time = time_[off[i]:off[i + 1]]
        assert line_time[0] == 0
        if i < n:
            assert (line_time >= 0).all() and (np.diff(line_time) > 0).all()
        else:
            assert (line_time <= 0).all() and (np.diff(line_time) < 0).all()
    # Every line starts at its seed.
    assert np.array_equal(both.points[off[:-1]], cloud_seeds[both.seed_ids].astype(np.float32))

    forward = amrstream.trace(cloud, cloud_seeds, steps=300, direction="forward", backend="cpu")
    backward = amrstream.trace(cloud, cloud_seeds, steps=300, direction="backward", backend="cpu")
    for one, half in ((forward, slice(0, n)), (backward, slice(n, 2 * n))):
        assert len(one) == n
        assert one.seed_ids.tolist() == list(range(n))
        for name in ("directions", "steps", "reasons"):
            assert np.array_equal(getattr(one, name), getattr(both, name)[half]), name
        lo, hi = off[half.start], off[half.stop]
        assert np.array_equal(one.offsets.astype(np.int64), off[half.start:half.stop + 1] - lo)
        for name in ("points", "integration_time", "vectors"):
            assert np.array_equal(getattr(one, name), getattr(both, name)[lo:hi]), name
        assert np.array_equal(one.point_data["dens"], both.point_data["dens"][lo:hi])


# ---------------------------------------------------------------- 5. bad input

def _raises(exception, call, *fragments):
    with pytest.raises(exception) as info:
        call()
    for fragment in fragments:
        assert fragment in str(info.value), f"{fragment!r} not in {str(info.value)!r}"
    return info.value


@pytest.mark.parametrize("seeds,fragment", [
    (np.zeros((4, 2)), "got (4, 2)"),
    (np.full(3, 0.5), "got (3,)"),
    ([["a", "b", "c"]], "not an array of numbers"),
    (np.zeros((2, 3, 1)), "got (2, 3, 1)"),
], ids=["N-by-2", "1-D", "strings", "3-D"])
def test_seeds_of_wrong_shape_are_refused(cloud, seeds, fragment):
    _raises(ValueError, lambda: amrstream.trace(cloud, seeds, backend="cpu"),
            "seeds must be an (N, 3) array", fragment)


@pytest.mark.parametrize("bad", [[2.0, 0.5, 0.5], [0.5, -0.1, 0.5], [np.nan, 0.5, 0.5]],
                         ids=["x>1", "y<0", "nan"])
def test_seeds_outside_the_domain_are_named(cloud, bad):
    seeds = np.array([[0.5, 0.5, 0.5], [0.2, 0.2, 0.2], bad])
    error = _raises(amrstream.InputError, lambda: amrstream.trace(cloud, seeds, backend="cpu"),
                    "seeds[2]", "outside the domain")
    assert isinstance(error, ValueError)
    assert "seeds[0]" not in str(error) and "seeds[1]" not in str(error)


@pytest.mark.parametrize("kwargs,fragments", [
    (dict(vector="magx,magy,nope"), ["'nope'", "dens, magx, magy, magz"]),
    (dict(vector=("magx", "magy")), ["vector must be 'a,b,c' or three field names"]),
    (dict(point_data=["dens", "nope"]), ["'nope'", "dens, magx, magy, magz"]),
    (dict(point_data="nope"), ["'nope'"]),
    (dict(step_mode="bogus"), ["'bogus'", "cell, time or arc"]),
    (dict(direction="sideways"), ["'sideways'", "forward, backward or both"]),
    (dict(backend="quantum"), ["'quantum'", "cpu"]),
    (dict(periodic="q"), ["'q'"]),
    (dict(step_size=0.0), ["step_size: ", "0 is not > 0"]),
    (dict(integrator="rk99"), ["'rk99'", "rk4, rk45, rk2 or euler"]),
    (dict(integrator="rk45", tolerance=0.0), ["tolerance: ", "outside the range 1e-08 to 1"]),
    (dict(integrator="rk45", min_step=1.0), ["min_step: ", "max_step"]),
], ids=["vector-field", "vector-count", "point-data-list", "point-data-text", "step-mode",
        "direction", "backend", "periodic", "step-size", "integrator", "tolerance", "min-step"])
def test_bad_trace_options_are_refused_with_the_culprit(cloud, kwargs, fragments):
    _raises(ValueError, lambda: amrstream.trace(cloud, [[0.5, 0.5, 0.5]], steps=5, **kwargs),
            *fragments)


def test_integrators_rank_by_order_on_the_rotation():
    # Solid-body rotation with the linear interpolant: the exact paths are circles, one
    # revolution per unit time. A quarter revolution from radius 0.25 in steps of 2e-3: euler
    # drifts outward, rk2 and rk4 by orders of magnitude less; rk45 is as close in fewer steps.
    field = amrstream.prepare(amrstream.load("builtin:rotation", levels=3, target_cells=50000),
                              point_data="none", interpolant="linear")
    seed = np.array([[0.75, 0.5, 0.5]])
    exact = np.array([0.5, 0.75, 0.5])
    errors, steps = {}, {}
    for integrator in ("euler", "rk2", "rk4", "rk45"):
        traces = amrstream.trace(field, seed, step_mode="time", step_size=2e-3, max_time=0.25,
                                 direction="forward", integrator=integrator, tolerance=1e-5,
                                 backend="cpu")
        errors[integrator] = np.linalg.norm(traces.points[-1] - exact)
        steps[integrator] = int(traces.steps[0])
    assert errors["euler"] > 100 * errors["rk2"] > 100 * errors["rk4"]
    assert errors["rk45"] < 1e-6
    assert steps["euler"] == steps["rk4"] == 125 and steps["rk45"] < steps["rk4"]


def test_unknown_device_is_a_backend_error(cloud):
    require_backend("compute")
    _raises(amrstream.BackendError,
            lambda: amrstream.trace(cloud, [[0.5, 0.5, 0.5]], backend="compute",
                                    device="no-such-gpu-xyz"), "no-such-gpu-xyz")


def test_field_target_refuses_vector_point_data_and_periodic(cloud):
    field = amrstream.prepare(cloud)
    for kwargs in (dict(vector="magx,magy,magz"), dict(point_data="dens"), dict(periodic="x")):
        _raises(ValueError, lambda: amrstream.trace(field, [[0.5, 0.5, 0.5]], **kwargs),
                "chosen when the Field was prepared")


@pytest.mark.parametrize("target", ["builtin:cloud", None, 3, np.zeros((3, 3))],
                         ids=["str", "None", "int", "array"])
def test_wrong_target_types_are_type_errors(target):
    _raises(TypeError, lambda: amrstream.trace(target, [[0.5, 0.5, 0.5]]), "Dataset")
    _raises(TypeError, lambda: amrstream.seeds_random(target, 3), "Dataset")
    _raises(TypeError, lambda: amrstream.seeds_grid(target, (2, 2, 2)), "Dataset")
    if target is not None:  # None: see the test below
        _raises(TypeError, lambda: amrstream.seeds_densest(target, "dens", 3), "Dataset")
        _raises(TypeError, lambda: amrstream.prepare(target), "Dataset")


@pytest.mark.parametrize("call", ["prepare(None)", "seeds_densest(None, 'dens', 3)"])
def test_none_dataset_is_a_type_error_not_a_crash(call):
    result = run_python(f"""
        import amrstream
        try:
            amrstream.{call}
        except TypeError as e:
            print("TypeError:", e)
    """)
    assert result.returncode == 0, f"{call}: the interpreter died, rc {result.returncode}"
    assert "TypeError:" in result.stdout


def test_to_vtp_refuses_unknown_options_and_unwritable_paths(cloud, tmp_path):
    t = amrstream.trace(cloud, [[0.5, 0.5, 0.5]], steps=5, backend="cpu")
    _raises(ValueError, lambda: t.to_vtp(str(tmp_path / "a.vtp"), compression="gzip"),
            "zlib, lz4 or none")
    _raises(ValueError, lambda: t.to_vtp(str(tmp_path / "a.vtp"), periodic_lines="wrap"),
            "split or unwrapped")
    _raises(amrstream.InputError, lambda: t.to_vtp(str(tmp_path / "no" / "such" / "a.vtp")),
            str(tmp_path / "no" / "such" / "a.vtp"), "does not exist")
    assert not (tmp_path / "a.vtp").exists()
    _raises(IndexError, lambda: t[2], "line 2 of 2")


def _two_level_cells():
    """A 2x2x2 block of level-0 cells (2 finest cells wide) whose first is refined into eight
    level-1 cells; the vector is a uniform flow along x."""
    corners, levels = [], []
    for i, j, k in np.ndindex(2, 2, 2):
        if (i, j, k) == (0, 0, 0):
            corners += [c for c in np.ndindex(2, 2, 2)]
            levels += [1] * 8
        else:
            corners.append((2 * i, 2 * j, 2 * k))
            levels.append(0)
    n = len(levels)
    fields = {"velx": np.ones(n), "vely": np.zeros(n), "velz": np.zeros(n)}
    return np.array(corners), np.array(levels), fields


def test_from_arrays_builds_a_traceable_dataset():
    corners, levels, fields = _two_level_cells()
    ds = amrstream.from_arrays(corners, levels, fields, origin=(1, 2, 3),
                               finest_width=(0.5, 0.5, 0.5), time=2.5, time_unit="s",
                               length_unit="m", source="mine", format="test")
    assert ds.cell_count == 15 and ds.field_names == ["velx", "vely", "velz"]
    assert ds.domain_left_edge == (1, 2, 3) and ds.domain_right_edge == (3, 4, 5)
    assert (ds.source, ds.format, ds.time, ds.time_unit, ds.length_unit) == (
        "mine", "test", 2.5, "s", "m")
    assert np.array_equal(ds.levels, levels) and np.array_equal(ds.corners, corners)
    t = amrstream.trace(ds, [[1.1, 2.5, 3.5]], steps=100, direction="forward", backend="cpu")
    assert amrstream.reason_name(int(t.reasons[0])) == "out of domain"
    assert np.allclose(t[0][:, 1:], [2.5, 3.5]) and t[0][-1, 0] > 2.5


@pytest.mark.parametrize("case,exception,fragments", [
    ("short-levels", ValueError, ["levels must be an (N,) array", "15 corners"]),
    ("short-field", ValueError, ["field 'vely'", "15 values"]),
    ("corners-N-by-2", ValueError, ["corners must be an (N, 3) array"]),
    ("misaligned", amrstream.InputError, ["cell 14", "3,2,2", "not aligned", "multiples of 2"]),
    ("overlap", amrstream.InputError, ["cell 0", "2,2,2", "overlaps"]),
    ("duplicate", amrstream.InputError, ["0,0,0", "appears twice"]),
    ("nan", amrstream.InputError, ["'velx'", "non-finite", "nan", "cell 3"]),
    ("inf", amrstream.InputError, ["'velz'", "non-finite", "inf", "cell 9"]),
    ("negative-level", ValueError, ["level -1"]),
    ("no-cells", amrstream.InputError, ["no cells"]),
    ("zero-width", amrstream.InputError, ["finest cell width must be positive"]),
    ("origin-2", ValueError, ["origin must be 3 numbers"]),
])
def test_from_arrays_refuses_bad_cells(case, exception, fragments):
    corners, levels, fields = _two_level_cells()
    kwargs = {}
    if case == "short-levels":
        levels = levels[:-1]
    elif case == "short-field":
        fields["vely"] = fields["vely"][:-2]
    elif case == "corners-N-by-2":
        corners = corners[:, :2]
    elif case == "misaligned":
        corners[14] = (3, 2, 2)  # a level-0 cell is 2 wide: its corner must be even
    elif case == "overlap":
        corners[0] = (2, 2, 2)  # a level-1 cell inside the level-0 cell at (2, 2, 2)
    elif case == "duplicate":
        corners[1] = corners[0]
    elif case == "nan":
        fields["velx"][3] = np.nan
    elif case == "inf":
        fields["velz"][9] = np.inf
    elif case == "negative-level":
        levels = levels - 1
    elif case == "no-cells":
        corners, levels, fields = np.zeros((0, 3)), np.zeros(0), {}
    elif case == "zero-width":
        kwargs["finest_width"] = (0.0, 1.0, 1.0)
    elif case == "origin-2":
        kwargs["origin"] = (1.0, 2.0)
    error = _raises(exception, lambda: amrstream.from_arrays(corners, levels, fields, **kwargs),
                    *fragments)
    assert isinstance(error, ValueError)


def test_from_arrays_messages_use_the_callers_level_numbers():
    corners, levels, fields = _two_level_cells()
    corners[14] = (3, 2, 2)
    assert levels[14] == 0
    _raises(amrstream.InputError, lambda: amrstream.from_arrays(corners, levels, fields),
            "cell 14 (level 0,")


def test_from_arrays_refuses_non_integer_corners():
    corners, levels, fields = _two_level_cells()
    _raises(ValueError, lambda: amrstream.from_arrays(corners + 0.5, levels, fields), "corner")


def test_load_missing_file_names_it(tmp_path):
    path = tmp_path / "missing.exa"
    # The standard type for it, with the command line's message.
    error = _raises(FileNotFoundError, lambda: amrstream.load(str(path)), str(path),
                    "no such file")
    assert error.errno == errno.ENOENT
    assert str(error) == f"[Errno 2] {path}: no such file"
    _raises(amrstream.InputError, lambda: amrstream.load("builtin:nope"), "'nope'",
            "rotation, abc, cloud")


def test_load_garbage_and_truncated_files_names_them(tmp_path):
    garbage = tmp_path / "x.exa"
    garbage.write_bytes(b"\x00\x01\x02garbage\xff\n")
    _raises(amrstream.InputError, lambda: amrstream.load(str(garbage)), str(garbage))

    ds = _exa_from(amrstream.load("builtin:cloud", **SMALL), tmp_path)
    assert ds.cell_count > 0
    with open(tmp_path / "c.dens.scalars", "r+b") as f:
        f.truncate(1000)
    _raises(amrstream.InputError, lambda: amrstream.load(str(tmp_path / "c.exa")),
            "c.dens.scalars", "1000 bytes")
    with open(tmp_path / "c.cells", "r+b") as f:
        f.truncate(1001)
    _raises(amrstream.InputError, lambda: amrstream.load(str(tmp_path / "c.exa")),
            "c.cells", "truncated")


def test_load_truncated_gerris_dump_names_it(tmp_path):
    text = real_data("gerris-ring/ring-end.txt").read_bytes()
    cut = tmp_path / "cut.gfs"
    cut.write_bytes(text[:20000])  # ends inside a line
    _raises(amrstream.InputError, lambda: amrstream.load(str(cut)), str(cut))


def test_reason_name_names_every_code_the_vtp_holds():
    assert amrstream.reason_name(REASON_PERIODIC_WRAP) != "unknown"


def test_reason_names():
    assert [amrstream.reason_name(c) for c in (1, 3, 4, 5, 6, 7)] == [
        "out of domain", "invalid sample", "max length", "max steps", "stagnation", "max time"]


# ---------------------------------------------------------------- 6. progress

@pytest.mark.parametrize("backend", ["cpu", "compute"])
def test_progress_is_reported_up_to_done_equals_total(backend, abc):
    require_backend(backend)
    calls = []
    seeds = amrstream.seeds_random(abc, 400, seed=3)
    t = amrstream.trace(abc, seeds, steps=1000, backend=backend,
                        progress=lambda done, total: calls.append((done, total)))
    assert calls, "progress was never called"
    totals = {total for _, total in calls}
    assert len(totals) == 1 and totals.pop() > 0
    done = [d for d, _ in calls]
    assert done == sorted(done) and all(d <= calls[0][1] for d in done)
    assert calls[-1][0] == calls[-1][1]
    assert len(t) == 2 * len(seeds)


class _Stop(RuntimeError):
    pass


@pytest.mark.parametrize("backend", ["cpu", "compute"])
def test_exception_in_progress_propagates_out_of_trace(backend, abc):
    require_backend(backend)
    seeds = amrstream.seeds_random(abc, 400, seed=3)

    def progress(done, total):
        raise _Stop(f"stopped at {done} of {total}")

    with pytest.raises(_Stop, match="stopped at"):
        amrstream.trace(abc, seeds, steps=1000, backend=backend, progress=progress)
    # The module still works afterwards.
    assert len(amrstream.trace(abc, seeds[:2], steps=10, backend=backend)) == 4


# ---------------------------------------------------------------- 7. the GIL

def test_cpu_trace_releases_the_gil(abc):
    stamps = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            stamps.append(time.perf_counter())
            for _ in range(200):
                pass

    seeds = amrstream.seeds_random(abc, 1000, seed=9)
    thread = threading.Thread(target=tick)
    thread.start()
    try:
        time.sleep(0.05)
        start = time.perf_counter()
        amrstream.trace(abc, seeds, steps=1000, point_data="none", backend="cpu")
        end = time.perf_counter()
    finally:
        stop.set()
        thread.join()
    assert end - start > 0.3, f"the trace took {end - start:.3f} s: too short to tell"
    # With the GIL held through the trace the thread could run at most one switch interval
    # (5 ms) after `start`; stamps well inside the trace show it ran while the trace did.
    margin = 0.05
    inside = np.array([s for s in stamps if start + margin < s < end - margin])
    assert len(inside) > 100, f"{len(inside)} stamps during a {end - start:.2f} s trace"
    assert inside.max() - inside.min() > 0.5 * (end - start - 2 * margin)


@pytest.mark.parametrize("backend", GPU_BACKENDS)
def test_cpu_tail_finishes_the_lines_as_the_cpu_traces_them(backend, capfd):
    """cpu_tail: once a GPU round leaves that many lines or fewer, the CPU finishes them."""
    require_backend(backend)
    ds = amrstream.load("builtin:rotation", **SMALL)
    seeds = [[0.5 + r, 0.5, 0.5] for r in (0.1, 0.2, 0.3)]
    # A small budget: rounds of a few hundred steps, the 6 lines handed over after the first.
    common = dict(steps=3000, step_mode="cell", memory_budget=1 << 20)
    cpu = amrstream.trace(ds, seeds, backend="cpu", **common)
    capfd.readouterr()
    t = amrstream.trace(ds, seeds, backend=backend, cpu_tail=8, verbose=True, **common)
    assert "cpu tail   6 lines finished on the CPU" in capfd.readouterr().out
    assert np.array_equal(t.steps, cpu.steps) and np.array_equal(t.reasons, cpu.reasons)
    assert np.array_equal(t.offsets, cpu.offsets)
    # The GPU's tolerance (1e-5 finest cells and 2e-6 a step) at 3000 steps, in physical units.
    finest = 1.0 / 64
    assert np.abs(t.points - cpu.points).max() <= (1e-5 + 2e-6 * 3000) * finest


def test_a_progress_bar_where_someone_watches(monkeypatch, capsys):
    """By default trace() draws a tqdm bar on a terminal (or in Jupyter) and is quiet
    elsewhere; progress=None is quiet everywhere."""
    ds = amrstream.load("builtin:rotation", levels=2, root_blocks=1)
    seeds = amrstream.seeds_random(ds, 64)
    amrstream.trace(ds, seeds, steps=50, backend="cpu")
    assert capsys.readouterr().err == ""  # pytest's stderr is no terminal
    monkeypatch.setattr(amrstream, "_interactive", lambda: True)
    amrstream.trace(ds, seeds, steps=50, backend="cpu")
    bar = capsys.readouterr().err
    assert "tracing" in bar and "/64 " in bar and "seed" in bar, bar  # of 64 seeds
    amrstream.trace(ds, seeds, steps=50, backend="cpu", progress=None)
    assert capsys.readouterr().err == ""
