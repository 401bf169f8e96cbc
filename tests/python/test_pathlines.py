"""amrstream.pathlines against the command line and against the swirl's closed form.

A swirl series (`amrstream gen swirl --series`, refinement following a feature the flow
carries) is traced from Python and with `amrstream pathlines` from the same seeds: the .vtp files
must be the same, bit for bit but for the Seeds description; the paths must follow the closed
form; bad series must raise InputError naming the file.
"""

import math

import numpy as np
import pytest

import amrstream

from shared_data import real_data
from test_api import Vtp, assert_same_vtp, require_backend, run_cli, write_seeds

GEN = ["--levels", "3", "--root-blocks", "2", "--target-cells", "20000"]


def swirl_path(p, t0, t):
    """The closed form of synth/swirl_field.hpp: where the particle at p at time t0 is at t."""
    def turned(s):
        return 2 * math.pi * s + 0.5 * (1 - math.cos(2 * math.pi * s))

    def risen(s):
        return 0.1 * math.sin(2 * math.pi * s) / (2 * math.pi)

    a = turned(t) - turned(t0)
    x, y = p[0] - 0.5, p[1] - 0.5
    return np.array([0.5 + math.cos(a) * x - math.sin(a) * y,
                     0.5 + math.sin(a) * x + math.cos(a) * y, p[2] + risen(t) - risen(t0)])


@pytest.fixture(scope="module")
def series(tmp_path_factory):
    folder = tmp_path_factory.mktemp("swirl")
    run_cli("gen", "swirl", *GEN, "--series", "5", "--interval", "0.05", "--out",
            folder / "swirl")
    return folder


@pytest.fixture(scope="module")
def seeds():
    rng = np.random.default_rng(4)
    return rng.uniform([0.3, 0.3, 0.4], [0.7, 0.7, 0.6], size=(24, 3))


@pytest.mark.parametrize("backend", ["cpu", "compute"])
def test_pathlines_equal_the_cli_vtp(backend, series, seeds, tmp_path):
    require_backend(backend)
    pattern = str(series / "swirl_*.exa")
    write_seeds(tmp_path / "seeds.txt", seeds)
    run_cli("pathlines", pattern, "--seeds", tmp_path / "seeds.txt", "--backend", backend,
            "--interpolant", "linear", "--out", tmp_path / "cli.vtp")
    paths = amrstream.pathlines(pattern, seeds, backend=backend, interpolant="linear")
    assert len(paths) == len(seeds)
    assert paths.to_vtp(str(tmp_path / "py.vtp"))[0] == len(seeds)
    assert_same_vtp(Vtp(tmp_path / "py.vtp"), Vtp(tmp_path / "cli.vtp"),
                    ignore_field_data=("Seeds",))
    assert paths.backend == backend


def test_pathlines_follow_the_closed_form(series, seeds):
    paths = amrstream.pathlines([str(series / f"swirl_000{i}.exa") for i in (4, 0, 2, 1, 3)],
                                seeds, interpolant="linear", point_data=["temp"])
    times = paths.integration_time
    assert times[0] == 0.0 and math.isclose(times[-1], 0.2, rel_tol=1e-6)
    worst = 0.0
    for line, seed_id in enumerate(paths.seed_ids):
        first, end = paths.offsets[line], paths.offsets[line + 1]
        for k in range(first, end):
            exact = swirl_path(seeds[seed_id], 0.0, float(times[k]))
            worst = max(worst, float(np.linalg.norm(paths.points[k] - exact)))
    # Linear in time between snapshots 0.05 apart: a few 1e-3 (the C++ test measures the order).
    assert worst < 5e-3
    temp = paths.point_data["temp"]
    expected = 1.0 + 0.5 * paths.points[:, 2] + 0.25 * times
    assert np.max(np.abs(temp - expected)) < 1e-5
    assert set(paths.reasons) == {9}  # end of series


@pytest.mark.parametrize("backend", ["compute", "pipeline", "rayquery"])
def test_the_real_gerris_series_steps_on_the_device_as_on_the_cpu(backend, tmp_path_factory):
    """Streaklines through 31 Gerris snapshots whose refinement changes at every step: the
    particles stepped on the device (both snapshots of each interval resident there) take the
    CPU's steps, stop for the CPU's reasons and end where the CPU's do, to float rounding."""
    require_backend(backend)
    archive = real_data("gerris-ring-series.tar.xz")
    folder = tmp_path_factory.getbasetemp() / "gerris-ring"
    if not (folder / "gerris-ring-series").exists():
        folder.mkdir(exist_ok=True)
        import tarfile
        with tarfile.open(archive) as tar:
            tar.extractall(folder)
    pattern = str(folder / "gerris-ring-series" / "ring-*.txt")
    grid = np.stack(np.meshgrid(np.linspace(-0.2, 0.2, 5), np.linspace(-0.2, 0.2, 5),
                                [-0.35, -0.15], indexing="ij"), axis=-1).reshape(-1, 3)
    options = dict(release_every=0.1, end_time=0.5)
    cpu = amrstream.pathlines(pattern, grid, backend="cpu", **options)
    device = amrstream.pathlines(pattern, grid, backend=backend, **options)
    assert device.backend == backend
    assert len(device) == len(cpu) == len(grid)
    assert np.array_equal(device.offsets, cpu.offsets)
    assert np.array_equal(device.reasons, cpu.reasons)
    assert np.array_equal(device.integration_time, cpu.integration_time)
    assert np.max(np.abs(device.points - cpu.points)) < 1e-6  # the ring is 1 wide
    assert len(cpu.points) == 5 * len(grid)  # released at 0, 0.1, ..., 0.4


def test_streaklines_have_one_line_per_seed(series):
    streaks = amrstream.pathlines(str(series / "swirl_*.exa"), [[0.6, 0.5, 0.5], [0.7, 0.5, 0.5]],
                                  release_every=0.02, end_time=0.1)
    assert len(streaks) == 2
    assert list(streaks.seed_ids) == [0, 1]
    assert np.all(np.diff(streaks.offsets) == 5)  # released at 0, 0.02, ..., 0.08


def test_units_are_declared_for_every_snapshot(series, tmp_path):
    lines = amrstream.pathlines(str(series / "swirl_*.exa"), [[0.6, 0.5, 0.5]], end_time=0.1,
                                length_unit="km", units={"temp": "K"})
    out = tmp_path / "p.vtp"
    lines.to_vtp(out, compression="none")
    data = out.read_bytes()
    assert b'Name="LengthUnit"' in data and b"km\0" in data
    with pytest.raises(ValueError, match=r"unit: 'tmp' is no channel .*did you mean 'temp'"):
        amrstream.pathlines(str(series / "swirl_*.exa"), [[0.6, 0.5, 0.5]], units={"tmp": "K"})


def test_bad_series_raise_input_error_naming_the_file(series, tmp_path):
    with pytest.raises(amrstream.InputError, match="two snapshots or more"):
        amrstream.pathlines(str(series / "swirl_0000.exa"), [[0.5, 0.5, 0.5]])
    with pytest.raises(amrstream.InputError, match="matches no file"):
        amrstream.pathlines(str(tmp_path / "none_*.exa"), [[0.5, 0.5, 0.5]])
    with pytest.raises(amrstream.InputError, match="outside the series"):
        amrstream.pathlines(str(series / "swirl_*.exa"), [[0.5, 0.5, 0.5]], start_time=3.0)
    with pytest.raises(ValueError, match="at least one seed"):
        amrstream.pathlines(str(series / "swirl_*.exa"), np.zeros((0, 3)))
    paths = amrstream.pathlines(str(series / "swirl_*.exa"), [[0.5, 0.6, 0.5]])
    with pytest.raises(ValueError, match="to_vtp"):
        paths.render()
