"""Arguments the command line refuses are refused by the Python module too (issue 50).

Each public function and method is given a value of the wrong type or out of range and must
raise TypeError, or InputError (a ValueError) for a value out of its setting's range, with the
keyword's name in the message, before it does any work: sizes beyond the library's limits are
refused before anything is allocated, and no writer replaces one of the files the lines were
traced from, nor a file that is not a regular file.
"""

import os
import resource
import stat

import numpy as np
import pytest

import amrstream

from test_api import run_cli

# The library's least bytes a seed (the seed and one line of one point) and a generated cell
# take, as the command line's tests state them (tests/cli/option_values_test.cpp).
SEED_BYTES, CELL_BYTES = 140, 25


def physical_memory():
    return os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")


def refused(exception, call, *fragments):
    with pytest.raises(exception) as info:
        call()
    for fragment in fragments:
        assert fragment in str(info.value), f"{fragment!r} not in {str(info.value)!r}"
    return info.value


def peak_memory_growth(call):
    """Bytes the process's peak resident memory grew by while `call` ran."""
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    call()
    return (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before) * 1024


def two_level_cells():
    """A 2x2x2 block of level-0 cells (2 finest cells wide) whose first is refined into eight
    level-1 cells, in a uniform flow along x (lines leave the domain within a few steps)."""
    corners, levels = [], []
    for i, j, k in np.ndindex(2, 2, 2):
        if (i, j, k) == (0, 0, 0):
            corners += list(np.ndindex(2, 2, 2))
            levels += [1] * 8
        else:
            corners.append((2 * i, 2 * j, 2 * k))
            levels.append(0)
    n = len(levels)
    fields = {"velx": np.ones(n), "vely": np.zeros(n), "velz": np.zeros(n)}
    return np.array(corners), np.array(levels), fields


@pytest.fixture(scope="module")
def flow():
    return amrstream.from_arrays(*two_level_cells())


@pytest.fixture(scope="module")
def lines(flow):
    return amrstream.trace(flow, [[0.5, 0.5, 0.5]], steps=20, backend="cpu")


SEED = [[0.5, 0.5, 0.5]]


# ---------------------------------------------------------------- from_arrays

def test_from_arrays_refuses_corners_given_as_text():
    corners, levels, fields = two_level_cells()
    refused(ValueError, lambda: amrstream.from_arrays(corners.astype(str), levels, fields),
            "corners must hold real numbers, not text")


@pytest.mark.parametrize("shift,finest", [(63, 64), (29, 30)], ids=["64", "30"])
def test_from_arrays_refuses_levels_finer_than_the_library_resolves(shift, finest):
    corners, levels, fields = two_level_cells()
    refused(amrstream.InputError, lambda: amrstream.from_arrays(corners, levels + shift, fields),
            f"levels: level {finest} of cell 0 is outside the range 0 to 29")


def test_from_arrays_takes_levels_up_to_the_finest_the_library_resolves():
    corners, levels, fields = two_level_cells()
    ds = amrstream.from_arrays(corners, levels + 28, fields)
    assert np.array_equal(ds.levels, levels + 28)


def test_from_arrays_refuses_half_integer_levels():
    corners, levels, fields = two_level_cells()
    refused(ValueError, lambda: amrstream.from_arrays(corners, levels + 0.5, fields),
            "levels must be whole numbers; element 0 is 1.5")


@pytest.mark.parametrize("values,held", [
    (np.ones(15) + 1j, "complex numbers"),
    (np.ones(15).astype(str), "text"),
    (np.ones(15, dtype=bool), "bools"),
], ids=["complex", "text", "bool"])
def test_from_arrays_refuses_field_values_that_are_no_real_numbers(values, held):
    corners, levels, fields = two_level_cells()
    fields["velx"] = values
    refused(ValueError, lambda: amrstream.from_arrays(corners, levels, fields),
            f"field 'velx' must hold real numbers, not {held}")


@pytest.mark.parametrize("time", [float("nan"), float("inf")], ids=["nan", "inf"])
def test_from_arrays_refuses_a_time_that_is_not_finite(time):
    refused(amrstream.InputError, lambda: amrstream.from_arrays(*two_level_cells(), time=time),
            f"time: {time} is not a finite number")


def test_from_arrays_refuses_a_time_that_is_no_number():
    refused(TypeError, lambda: amrstream.from_arrays(*two_level_cells(), time="0.5"),
            "time must be a real number, not str")


def test_from_arrays_refuses_more_rows_than_a_dataset_may_number_before_allocating():
    rows = 2**31  # a broadcast array: no memory until it is copied (51 GB of int64 corners)
    corners = np.broadcast_to(np.zeros(3, np.int64), (rows, 3))
    levels = np.broadcast_to(np.zeros(1, np.int64), (rows,))
    growth = peak_memory_growth(lambda: refused(
        amrstream.InputError, lambda: amrstream.from_arrays(corners, levels, {}),
        "corners: 2147483648 cells are more than the 2147483647 a dataset may hold"))
    assert growth < 2**28


@pytest.mark.parametrize("rows", [2**26, 2**27, 2**31 - 1])
def test_from_arrays_refuses_more_rows_than_memory_holds_before_allocating(rows):
    if rows * CELL_BYTES <= 0.75 * physical_memory():
        pytest.skip(f"this machine could hold {rows} cells")
    corners = np.broadcast_to(np.zeros(3, np.int64), (rows, 3))
    levels = np.broadcast_to(np.zeros(1, np.int64), (rows,))
    growth = peak_memory_growth(lambda: refused(
        amrstream.InputError, lambda: amrstream.from_arrays(corners, levels, {}),
        f"corners: {rows} cells need at least"))
    assert growth < 2**28


# ---------------------------------------------------------------- trace

def test_trace_refuses_seeds_given_as_text(flow):
    refused(ValueError, lambda: amrstream.trace(flow, [["0.5", "0.5", "0.5"]], backend="cpu"),
            "seeds must be an (N, 3) array of x, y, z; got an array of text")


@pytest.mark.parametrize("kwargs,message", [
    (dict(steps=2**32 - 1), "steps: 4294967295 is outside the range 0 to 1000000000"),
    (dict(steps=10**9 + 1), "steps: 1000000001 is outside the range 0 to 1000000000"),
    (dict(steps=-1), "steps: -1 is outside the range 0 to 1000000000"),
    (dict(max_length=1e300), "max_length: 1e+300 is outside the range 0 to 3.40282e+38"),
    (dict(max_time=-1.0), "max_time: -1 is outside the range 0 to 3.40282e+38"),
    (dict(terminal_speed=float("inf")), "terminal_speed: inf is not a finite number"),
    (dict(memory_budget=2**63), "memory_budget: 9223372036854775808 is outside the range 0 to"),
    (dict(cpu_tail=2**31), "cpu_tail: 2147483648 is outside the range 0 to 2147483647"),
    (dict(tolerance=2.0), "tolerance: 2 is outside the range 1e-08 to 1"),
    (dict(step_size=float("nan")), "step_size: nan is not a finite number"),
    (dict(min_step=-1.0), "min_step: -1 is not > 0"),
], ids=["steps-2^32-1", "steps-1e9+1", "steps-negative", "max-length-1e300", "max-time",
        "terminal-speed-inf", "memory-budget-2^63", "cpu-tail", "tolerance", "step-size-nan",
        "min-step"])
def test_trace_refuses_settings_beyond_their_ranges(flow, kwargs, message):
    error = refused(amrstream.InputError,
                    lambda: amrstream.trace(flow, SEED, backend="cpu", **kwargs), message)
    assert str(error).startswith(message.split(":")[0] + ": ")


def test_trace_takes_steps_up_to_the_settings_bound(flow):
    t = amrstream.trace(flow, SEED, steps=10**9, direction="forward", backend="cpu")
    assert amrstream.reason_name(int(t.reasons[0])) == "out of domain"


@pytest.mark.parametrize("kwargs,message", [
    (dict(steps="5"), "steps must be a whole number, not str"),
    (dict(steps=5.0), "steps must be a whole number, not float"),
    (dict(steps=True), "steps must be a whole number, not bool"),
    (dict(max_length=1j), "max_length must be a real number, not complex"),
    (dict(step_size="0.1"), "step_size must be a real number, not str"),
], ids=["steps-str", "steps-float", "steps-bool", "max-length-complex", "step-size-str"])
def test_trace_refuses_settings_of_the_wrong_type(flow, kwargs, message):
    refused(TypeError, lambda: amrstream.trace(flow, SEED, backend="cpu", **kwargs), message)


def test_trace_refuses_more_seeds_than_a_run_may_trace_before_allocating(flow):
    seeds = np.broadcast_to(np.full(3, 0.5), (2**31, 3))  # 51 GB once copied
    growth = peak_memory_growth(lambda: refused(
        amrstream.InputError, lambda: amrstream.trace(flow, seeds, backend="cpu"),
        "seeds: 2147483648 seeds are more than the 2147483647 one run may trace"))
    assert growth < 2**28


@pytest.mark.parametrize("rows", [2**26, 2**27])
def test_trace_refuses_more_seeds_than_memory_holds_before_allocating(flow, rows):
    if rows * SEED_BYTES <= 0.75 * physical_memory():
        pytest.skip(f"this machine could hold {rows} seeds")
    seeds = np.broadcast_to(np.full(3, 0.5), (rows, 3))
    growth = peak_memory_growth(lambda: refused(
        amrstream.InputError, lambda: amrstream.trace(flow, seeds, backend="cpu"),
        f"seeds: {rows} seeds need at least"))
    assert growth < 2**28


# ---------------------------------------------------------------- seeds

@pytest.mark.parametrize("start,end,message", [
    ((0.1, 0.1, float("nan")), (0.9, 0.9, 0.9), "start: nan is not a finite number"),
    ((0.1, 0.1, 0.1), (float("inf"), 0.9, 0.9), "end: inf is not a finite number"),
    ((0.1, 0.1, 0.1), (0.9, 0.9, 1e39), "end: 1e+39 is outside the range"),
], ids=["nan-start", "inf-end", "end-beyond-float"])
def test_seeds_line_refuses_ends_that_are_not_finite(start, end, message):
    refused(amrstream.InputError, lambda: amrstream.seeds_line(start, end), message)


def test_seeds_line_refuses_a_count_of_0_and_ends_of_two_numbers():
    refused(amrstream.InputError, lambda: amrstream.seeds_line((0, 0, 0), (1, 1, 1), 0),
            "count: 0 is outside the range 1 to 2147483647")
    refused(ValueError, lambda: amrstream.seeds_line((0, 0), (1, 1, 1)),
            "start must be 3 numbers, not 2")


def test_seeds_random_names_count_box_and_seed(flow):
    refused(amrstream.InputError, lambda: amrstream.seeds_random(flow, 2**31),
            "count: 2147483648 is outside the range 1 to 2147483647")
    refused(ValueError, lambda: amrstream.seeds_random(flow, 4, box=(0, 0, 0, 1, 1)),
            "box must be 6 numbers, not 5")
    refused(amrstream.InputError, lambda: amrstream.seeds_random(flow, 4, box=(0, 0, 0, 9, 1, 1)),
            "box: the box reaches outside the domain")
    refused(amrstream.InputError, lambda: amrstream.seeds_random(flow, 4, seed=-1),
            "seed: -1 is outside the range 0 to")


def test_seeds_grid_names_counts(flow):
    refused(amrstream.InputError, lambda: amrstream.seeds_grid(flow, (2, 2, 0)),
            "counts: 0 is outside the range 1 to 2147483647")
    refused(amrstream.InputError, lambda: amrstream.seeds_grid(flow, (65536, 65536, 1)),
            "counts: 4294967296 seeds are more than the 2147483647")
    refused(TypeError, lambda: amrstream.seeds_grid(flow, (2, 2, 2.5)),
            "counts must be a whole number, not float")


def test_seeds_densest_names_percentile_and_count(flow):
    refused(amrstream.InputError, lambda: amrstream.seeds_densest(flow, "velx", percentile=101),
            "percentile: 101 is outside the range 0 to 100")
    refused(amrstream.InputError, lambda: amrstream.seeds_densest(flow, "velx", 0),
            "count: 0 is outside the range 1 to 2147483647")


# ---------------------------------------------------------------- render

@pytest.mark.parametrize("camera,message", [
    ((30, 200), "camera: elevation 200 is outside the range -90 to 90 degrees"),
    ((30, -90.5), "camera: elevation -90.5 is outside the range -90 to 90 degrees"),
    ((1e30, 20), "camera: azimuth 1e+30 is outside the range -360 to 360 degrees"),
], ids=["elevation-200", "elevation-below-90", "azimuth-1e30"])
def test_render_refuses_camera_angles_beyond_the_renderers(lines, camera, message):
    refused(amrstream.InputError, lambda: lines.render(width=32, height=32, camera=camera),
            message)
    refused(amrstream.InputError, lambda: amrstream.render(lines, camera=camera), message)


@pytest.mark.parametrize("kwargs,exception,message", [
    (dict(width=8), amrstream.InputError, "width: 8 is outside the range 16 to 16384"),
    (dict(frames=0), amrstream.InputError, "frames: 0 is outside the range 1 to 4096"),
    (dict(tube_radius=1e300), amrstream.InputError,
     "tube_radius: 1e+300 is outside the range 1.17549e-38 to 3.40282e+38"),
    (dict(camera=(30, float("nan"))), amrstream.InputError, "camera: nan is not a finite"),
    (dict(camera="30,20"), TypeError, "camera must be a sequence of numbers, not str"),
    (dict(ao_samples=2.0), TypeError, "ao_samples must be a whole number, not float"),
], ids=["width", "frames", "tube-radius", "camera-nan", "camera-text", "ao-samples-float"])
def test_render_refuses_settings_beyond_their_ranges(lines, kwargs, exception, message):
    refused(exception, lambda: lines.render(**kwargs), message)


def test_module_render_needs_traces():
    refused(TypeError, lambda: amrstream.render("lines.vtp"),
            "traces must be amrstream.Traces, not str")


# ---------------------------------------------------------------- load, prepare, pathlines, ...

def test_load_refuses_sizes_beyond_the_settings_before_generating():
    growth = peak_memory_growth(lambda: refused(
        amrstream.InputError, lambda: amrstream.load("builtin:cloud", target_cells=2**40),
        "target_cells: 1099511627776 is outside the range 1 to 2147483647"))
    assert growth < 2**28
    refused(amrstream.InputError, lambda: amrstream.load("builtin:rotation", levels=9),
            "levels: 9 is outside the range 1 to 8")
    refused(amrstream.InputError, lambda: amrstream.load("builtin:nest", levels=31),
            "levels: 31 is outside the range 1 to 30")
    refused(TypeError, lambda: amrstream.load("builtin:rotation", root_blocks="2"),
            "root_blocks must be a whole number, not str")


def test_load_takes_nest_levels_beyond_the_other_kinds():
    assert len(np.unique(amrstream.load("builtin:nest", levels=9).levels)) == 9


def test_load_refuses_a_builtin_this_machine_cannot_hold():
    if 2**31 * CELL_BYTES <= 0.75 * physical_memory():
        pytest.skip("this machine could hold 2^31 - 1 cells")
    refused(amrstream.InputError,
            lambda: amrstream.load("builtin:rotation", levels=8, root_blocks=255,
                                   target_cells=2**31 - 1),
            "target_cells: 2147483647 cells need at least")


def test_prepare_names_its_settings(flow):
    refused(amrstream.InputError, lambda: amrstream.prepare(flow, interpolant="cubic"),
            "interpolant: 'cubic' is not tent or linear")


def test_pathlines_names_its_settings():
    for kwargs, message in [(dict(start_time=float("nan")), "start_time: nan is not a finite"),
                            (dict(end_time=1e309), "end_time: inf is not a finite"),
                            (dict(step_size=0.0), "step_size: 0 is not > 0"),
                            (dict(release_every=-1.0), "release_every: -1 is outside the range")]:
        refused(amrstream.InputError,
                lambda: amrstream.pathlines(["no-such-*.exa"], SEED, **kwargs), message)
    refused(TypeError, lambda: amrstream.pathlines(3, SEED), "snapshots must be a file")


def test_from_yt_needs_a_yt_dataset_or_a_path():
    refused(TypeError, lambda: amrstream.from_yt(3),
            "ds must be a yt dataset (yt.load's) or a path, not int")


def test_reason_name_names_code():
    refused(TypeError, lambda: amrstream.reason_name("8"), "code must be a whole number, not str")
    refused(amrstream.InputError, lambda: amrstream.reason_name(2**40),
            "code: 1099511627776 is outside the range")


def test_dataset_field_names_name(flow):
    refused(TypeError, lambda: flow.field(3), "name must be a str, not int")


def test_field_resample_names_dims_and_box(flow):
    field = amrstream.prepare(flow)
    refused(amrstream.InputError, lambda: field.resample(0), "dims: 0 is outside 1..65535")
    refused(TypeError, lambda: field.resample("8"), "dims must be a whole number, not str")
    refused(amrstream.InputError,
            lambda: field.resample(4, box=(0, 0, 0, 1, 1, float("nan"))),
            "box: nan is not a finite number")


def test_traces_index_names_index(lines):
    refused(TypeError, lambda: lines["0"], "index must be a whole number, not str")
    refused(IndexError, lambda: lines[5], "line 5 of 2")


# ---------------------------------------------------------------- writers

def write_exa(folder):
    """two_level_cells() as an ExaBricks file set (levels 0 = finest); returns the .exa."""
    corners, levels, fields = two_level_cells()
    np.column_stack([corners, levels.max() - levels]).astype("<i4").tofile(folder / "c.cells")
    lines = ["cells c.cells"]
    for name, values in fields.items():
        values.astype("<f4").tofile(folder / f"c.{name}.scalars")
        lines.append(f"scalar {name} c.{name}.scalars")
    (folder / "c.exa").write_text("\n".join(lines) + "\n")
    return folder / "c.exa"


def test_to_vtp_refuses_the_files_the_dataset_was_read_from(tmp_path, monkeypatch):
    exa = write_exa(tmp_path)
    traced = amrstream.trace(amrstream.load(str(exa)), SEED, steps=20, backend="cpu")
    (tmp_path / "link.exa").symlink_to(exa)
    monkeypatch.chdir(tmp_path)
    inputs = [exa, tmp_path / "c.cells", tmp_path / "c.velx.scalars"]
    contents = {path: path.read_bytes() for path in inputs}
    for path in [*map(str, inputs), "link.exa", "./c.exa", tmp_path / "c.vely.scalars"]:
        refused(amrstream.InputError, lambda: traced.to_vtp(path), "path: ", "is the input")
    assert {path: path.read_bytes() for path in inputs} == contents
    assert traced.to_vtp(tmp_path / "lines.vtp")[0] == len(traced) == 2


def test_to_vtp_of_pathlines_refuses_a_snapshot(tmp_path):
    run_cli("gen", "swirl", "--levels", "2", "--root-blocks", "1", "--target-cells", "2000",
            "--series", "2", "--interval", "0.05", "--out", tmp_path / "swirl")
    snapshot = tmp_path / "swirl_0000.exa"
    before = snapshot.read_bytes()
    paths = amrstream.pathlines(str(tmp_path / "swirl_*.exa"), SEED, backend="cpu")
    refused(amrstream.InputError, lambda: paths.to_vtp(str(snapshot)), "is the input")
    refused(amrstream.InputError, lambda: paths.to_vtp(str(tmp_path / "swirl_0001.cells")),
            "is the input")
    assert snapshot.read_bytes() == before


def test_to_vtp_refuses_outputs_that_are_not_regular_files(lines, tmp_path):
    fifo = tmp_path / "fifo.vtp"
    os.mkfifo(fifo)
    refused(amrstream.InputError, lambda: lines.to_vtp(str(fifo)),
            "exists and is not a regular file")
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)
    refused(amrstream.InputError, lambda: lines.to_vtp(str(tmp_path)), "is a directory")
    refused(amrstream.InputError, lambda: lines.to_vtp(str(tmp_path / "no" / "such.vtp")),
            "the directory", "does not exist")
    refused(TypeError, lambda: lines.to_vtp(3), "path must be a str or os.PathLike")
    refused(amrstream.InputError, lambda: lines.to_vtp(str(tmp_path / "x.png")),
            "the file written is VTK XML PolyData; name it .vtp")
    assert not (tmp_path / "x.png").exists()


def test_to_vtp_does_not_replace_a_character_device(lines, tmp_path):
    if os.geteuid() != 0:
        pytest.skip("only root makes a character device (one like /dev/null, in a temporary "
                    "folder)")
    device = tmp_path / "null"
    os.mknod(device, stat.S_IFCHR | 0o666, os.makedev(1, 3))
    refused(amrstream.InputError, lambda: lines.to_vtp(str(device)),
            "exists and is not a regular file")
    assert stat.S_ISCHR(os.stat(device).st_mode)


def test_to_vtp_writes_through_a_temporary_renamed_over_the_file(lines, tmp_path):
    out, link = tmp_path / "lines.vtp", tmp_path / "old.vtp"
    out.write_text("old")
    os.link(out, link)  # a second name of the old file: writing in place would change it too
    lines.to_vtp(str(out))
    assert link.read_text() == "old" and out.read_bytes().startswith(b"<?xml")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["lines.vtp", "old.vtp"]


def test_a_mistyped_keyword_is_named_with_the_closest_one(flow, lines, tmp_path):
    """pybind11 answers an unknown keyword with every signature; the module names the keyword
    and the one meant instead."""
    refused(TypeError, lambda: amrstream.trace(flow, [[0.5, 0.5, 0.5]], stpes=3),
            "trace() got an unexpected keyword argument 'stpes' (did you mean 'steps'?)")
    refused(TypeError, lambda: amrstream.load("builtin:rotation", level=2),
            "load() got an unexpected keyword argument 'level' (did you mean 'levels'?)")
    refused(TypeError, lambda: amrstream.seeds_random(flow, 4, sed=3), "(did you mean 'seed'?)")
    refused(TypeError, lambda: amrstream.render(lines, widht=10),
            "render() got an unexpected keyword argument 'widht' (did you mean 'width'?)")
    error = refused(TypeError, lambda: amrstream.trace(flow, [[0.5, 0.5, 0.5]], frobnicate=1),
                    "trace() got an unexpected keyword argument 'frobnicate'; "
                    "help(amrstream.trace) lists them")
    assert "did you mean" not in str(error) and "incompatible" not in str(error)
    # A keyword it takes, of the wrong type, keeps its own message.
    refused(TypeError, lambda: amrstream.trace(flow, [[0.5, 0.5, 0.5]], steps="ten"), "steps")
