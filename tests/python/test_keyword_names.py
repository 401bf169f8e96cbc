"""The Python keywords are the command line's options: `--step-size` is step_size=, and the seeds_*
functions' keywords are the seeding options without their `seed-` prefix (seeds_densest's
percentile= is --seed-percentile). The oracle is the CLI's own --help."""
import os
import re
import subprocess

import pytest

import amrstream
from amrstream import _amrstream

# Keywords with no option: what Python does in its own way.
PYTHON_ONLY = {"progress", "validation", "verbose", "units"}
# Options with no keyword of trace()/pathlines(): load()'s, the seeds functions', the file's.
OPTIONS_ELSEWHERE = {
    "help", "out", "compression", "pieces", "distribute", "halo_steps", "rebalance_steps",
    "levels", "root_blocks", "target_cells", "gen_seed", "time", "length_unit", "unit",
    "count", "seed", "seeds", "seeds_out", "seed_box", "seed_line", "seed_grid",
    "seed_density", "seed_percentile", "seed_weighted",
    # Output layout choices of the .vtp file, which Traces.to_vtp() and the arrays make moot.
    "endpoints_only", "periodic_lines", "trace_store",
    # The run's record as a file: a Python caller has the Traces' report and times instead.
    "json",
}


def cli_options(command):
    cli = os.environ.get("AMRSTREAM_CLI")
    if not cli:
        pytest.skip("AMRSTREAM_CLI (the command line's binary) is not set: run through ctest")
    text = subprocess.run([cli, command, "--help"], capture_output=True, text=True,
                          check=True).stdout
    return {name.replace("-", "_") for name in re.findall(r"^\s+(?:-\w,)?--([\w-]+)", text, re.M)}


def keywords(function):
    """The keyword names in a pybind11 function's signature line (positional ones included)."""
    return set(re.findall(r"(\w+): ", function.__doc__.splitlines()[0]))


@pytest.mark.parametrize("command,function,positional", [
    ("trace", _amrstream.trace, {"target", "seeds"}),
    ("pathlines", _amrstream.pathlines, {"snapshots", "seeds"}),
])
def test_tracing_keywords_are_the_commands_options(command, function, positional):
    options, names = cli_options(command), keywords(function) - positional
    assert names - PYTHON_ONLY <= options, f"{command}: keywords without an option"
    assert options - OPTIONS_ELSEWHERE <= names, f"{command}: options without a keyword"


def test_loading_keywords_are_the_options_of_a_dataset():
    options = cli_options("trace")
    assert keywords(_amrstream.load) - {"path"} - PYTHON_ONLY <= options
    assert keywords(_amrstream.prepare) - {"dataset"} <= options


def test_render_keywords_are_the_render_commands_options():
    options = cli_options("render")
    documented = re.findall(r"^(\w+)(?:=[^:]*)?: ", _amrstream.Traces.render.__doc__, re.M)
    assert len(documented) > 20
    for name in documented:
        assert name in options or "no_" + name in options, name


@pytest.mark.parametrize("function", [amrstream.seeds_random, amrstream.seeds_grid,
                                      amrstream.seeds_densest])
def test_seeding_keywords_are_the_seeding_options(function):
    options = cli_options("trace")
    keyword_only = function.__doc__.splitlines()[0].split("*,")[1]
    for name in re.findall(r"(\w+): ", keyword_only):
        assert name in options or "seed_" + name in options, f"{function.__name__}: {name}"


def test_slice_keywords_are_the_slice_commands_options():
    options = cli_options("slice")
    names = keywords(_amrstream._slice) - {"field"} - PYTHON_ONLY
    for name in names:
        assert name in options or "no_" + name in options, name
    wrapper = {"vector", "frame_velocity", "point_data", "periodic", "interpolant"}
    assert wrapper <= options
