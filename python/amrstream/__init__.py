"""amrstream: streamlines through adaptive-mesh-refinement vector fields, on the CPU and on any
Vulkan GPU, with the data along them.

    import amrstream
    ds = amrstream.load("DD0010/moving7_0010")          # or amrstream.from_yt(yt_ds)
    seeds = amrstream.seeds_densest(ds, "Density", 256)
    lines = amrstream.trace(ds, seeds, steps=2000)       # both directions, every field along them
    for points in lines: ...                             # (n_i, 3) arrays
    lines.to_vtp("lines.vtp")

docs/python.md in the amrstream sources is the reference.
"""

import difflib
import functools
import glob
import os
import re
import sys
from collections.abc import Sequence as _Sequence
from typing import Any, Callable, List, Optional, Tuple, TypeVar, Union

from ._amrstream import (
    BackendError,
    Dataset,
    Field,
    InputError,
    Traces,
    __version__,
    from_arrays,
    load,
    reason_name,
    seeds_densest,
)
from . import _amrstream
from .lengths import first_unit, has_units, in_coordinates, in_unit, with_unit

__all__ = [
    "BackendError", "Dataset", "Field", "InputError", "Traces", "__version__", "from_arrays",
    "from_yt", "load", "pathlines", "prepare", "reason_name", "render", "seeds_densest",
    "seeds_grid", "seeds_line", "seeds_random", "slice", "trace",
]

DEFAULT_YT_VECTOR = ("velocity_x", "velocity_y", "velocity_z")


_Function = TypeVar("_Function", bound=Callable[..., Any])


def _keyword_names(text):
    """The keywords a compiled function takes, from its signatures ("name: type") and its
    settings' lines ("name=default: meaning") in `text` (its docstring or pybind11's error)."""
    names = set(re.findall(r"(?:\(|, )\*?(\w+): ", text))
    names.update(re.findall(r"^(\w+)=", text, flags=re.MULTILINE))
    return names


def _with_keyword_hints(compiled: _Function, name: Optional[str] = None) -> _Function:
    """`compiled`, whose TypeError for a keyword it does not take names that keyword and the
    closest one it takes, instead of pybind11's list of signatures."""
    @functools.wraps(compiled)
    def call(*args, **kwargs):
        try:
            return compiled(*args, **kwargs)
        except TypeError as error:
            message = str(error)
            if "incompatible function arguments" not in message and \
                    "unexpected keyword argument" not in message:
                raise
            names = _keyword_names(message) | _keyword_names(compiled.__doc__ or "")
            unknown = [k for k in kwargs if k not in names]
            if not unknown:
                raise
            hints = []
            for keyword in unknown:
                close = difflib.get_close_matches(keyword, sorted(names), n=1)
                hints.append(f"'{keyword}'" + (f" (did you mean '{close[0]}'?)" if close else ""))
            called = name or compiled.__name__
            raise TypeError(f"{called}() got an unexpected keyword argument {', '.join(hints)}; "
                            f"help(amrstream.{called}) lists them") from None
    return call  # type: ignore[return-value]


from_arrays = _with_keyword_hints(from_arrays)
load = _with_keyword_hints(load)
seeds_densest = _with_keyword_hints(seeds_densest)
_compiled_seeds_grid = _with_keyword_hints(_amrstream.seeds_grid)
_compiled_seeds_line = _with_keyword_hints(_amrstream.seeds_line)
_compiled_seeds_random = _with_keyword_hints(_amrstream.seeds_random)
_compiled_resample = _with_keyword_hints(Field.resample)
_compiled_prepare = _with_keyword_hints(_amrstream.prepare)
_compiled_trace = _with_keyword_hints(_amrstream.trace)
_compiled_pathlines = _with_keyword_hints(_amrstream.pathlines)
_compiled_render = _with_keyword_hints(Traces.render)
_compiled_slice = _with_keyword_hints(_amrstream._slice, "slice")


_VectorRequest = Union[None, str, _Sequence[Union[str, Tuple[str, str]]]]
_PointDataRequest = Union[None, str, _Sequence[str]]


def _interactive() -> bool:
    """Whether a person is watching: a terminal on stderr, or a Jupyter kernel."""
    if "ipykernel" in sys.modules:
        return True
    return sys.stderr is not None and hasattr(sys.stderr, "isatty") and sys.stderr.isatty()


def _progress_bar(what: str, unit: str) -> Optional[Callable[[int, int], None]]:
    """A progress(done, total) that draws a tqdm bar where someone watches and tqdm is
    installed; None (quiet) otherwise."""
    if not _interactive():
        return None
    try:
        from tqdm.auto import tqdm
    except ImportError:
        return None
    bar = None

    def progress(done: int, total: int) -> None:
        nonlocal bar
        if bar is None:
            bar = tqdm(total=total, desc=what, unit=unit, leave=False)
        bar.total = total
        bar.update(done - bar.n)
        if done >= total:
            bar.close()

    return progress


def _with_default_progress(settings: dict, what: str, unit: str) -> dict:
    """`settings` with progress set to a bar (see _progress_bar) unless the caller chose."""
    if "progress" not in settings:
        settings["progress"] = _progress_bar(what, unit)
    return settings


def _point_data_text(point_data: _PointDataRequest) -> Optional[str]:
    """None, 'all', 'none', 'a,b' or names -> None or the text the module takes."""
    if point_data is None or isinstance(point_data, str):
        return point_data
    return ",".join(point_data) if point_data else "none"


def _vector_text(vector):
    """None, 'a,b,c' or three names -> None or 'a,b,c'."""
    if vector is None or isinstance(vector, str):
        return vector
    names = [name[-1] if isinstance(name, tuple) else name for name in vector]
    if len(names) != 3 or not all(isinstance(name, str) for name in names):
        raise ValueError(f"vector must be 'a,b,c' or three field names, not {vector!r}")
    return ",".join(names)


def prepare(dataset: Dataset, vector: _VectorRequest = None, point_data: _PointDataRequest = None,
            **settings: Any) -> Field:
    """A Field ready for tracing: the vector ('a,b,c' or three names, 'grad(NAME)' or
    '-grad(NAME)'), the frame velocity subtracted from it ((vx, vy, vz) or 'auto'), the point
    data ('all', 'none' or names), the periodic axes and the interpolant; bricks and regions
    built once for many traces. The settings, with their defaults, are those of
    amrstream._amrstream.prepare (below)."""
    if point_data is not None:
        settings["point_data"] = _point_data_text(point_data)
    return _compiled_prepare(dataset, vector=_vector_text(vector), **settings)


def seeds_random(target: Union[Dataset, Field], count: int = 256, **settings: Any) -> Any:
    return _compiled_seeds_random(target, count, **_box_in_coordinates(settings, target))


def seeds_grid(target: Union[Dataset, Field], counts: _Sequence[int], **settings: Any) -> Any:
    return _compiled_seeds_grid(target, counts, **_box_in_coordinates(settings, target))


def _box_in_coordinates(settings: dict, target: Any) -> dict:
    """`settings` with a box of quantities in the coordinates of `target`."""
    if "box" in settings:
        settings["box"] = in_coordinates(settings["box"], target, "box")
    return settings


def seeds_line(start: Any, end: Any, count: int = 256) -> Any:
    if not has_units((start, end)):
        return _compiled_seeds_line(start, end, count)
    unit = first_unit((start, end))
    return with_unit(_compiled_seeds_line(in_unit(start, unit, "start"), in_unit(end, unit, "end"),
                                          count), unit)


for _wrapper, _compiled in ((seeds_random, _amrstream.seeds_random),
                            (seeds_grid, _amrstream.seeds_grid),
                            (seeds_line, _amrstream.seeds_line)):
    _wrapper.__doc__ = _compiled.__doc__


def _resample_method(self: Field, dims: Any = 128, **settings: Any) -> Any:
    return _compiled_resample(self, dims, **_box_in_coordinates(settings, self))


_resample_method.__doc__ = Field.resample.__doc__
Field.resample = _resample_method  # type: ignore  # the method, taking quantities for the box

_LENGTH_SETTINGS = ("max_length", "look_at", "view_box", "tube_radius_physical")


def _lengths_in_coordinates(settings: dict, target: Any) -> dict:
    """`settings` with its lengths and positions (quantities) in the dataset's coordinates."""
    for name in _LENGTH_SETTINGS:
        if name in settings:
            settings[name] = in_coordinates(settings[name], target, name)
    return settings


def trace(target: Union[Dataset, Field], seeds: Any, *, vector: _VectorRequest = None,
          point_data: _PointDataRequest = None, periodic: Optional[str] = None,
          interpolant: Optional[str] = None, **settings: Any) -> Traces:
    """Traces streamlines from seeds ((N, 3) points) through a Dataset or a prepared Field
    (vector, frame_velocity, point_data, periodic and interpolant only with a Dataset). Returns
    Traces. The settings, as `amrstream trace` names them, with their defaults, are those of
    amrstream._amrstream.trace (below).
    """
    seeds = in_coordinates(seeds, target, "seeds")
    _lengths_in_coordinates(settings, target)
    return _compiled_trace(target, seeds, vector=_vector_text(vector),
                           point_data=_point_data_text(point_data), periodic=periodic,
                           interpolant=interpolant,
                           **_with_default_progress(settings, "tracing", "seed"))


_SnapshotRequest = Union[str, "os.PathLike[str]", _Sequence[Union[str, "os.PathLike[str]"]]]


def pathlines(snapshots: _SnapshotRequest, seeds: Any, *, vector: _VectorRequest = None,
              point_data: _PointDataRequest = None, **settings: Any) -> Traces:
    """Traces pathlines from seeds ((N, 3) points) through a time series of snapshots: a list of
    files, folders (AMReX plotfiles) or glob patterns (a single string is one pattern), ordered
    by the times the files state.

    Returns Traces (one line per particle; integration_time is physical time), which to_vtp()
    writes. The settings, as `amrstream pathlines` names them, with their defaults, are those of
    amrstream._amrstream.pathlines (below).
    """
    paths = _snapshot_paths(snapshots)
    if has_units(seeds):
        seeds = in_coordinates(seeds, _first_snapshot(paths, settings), "seeds")
    return _compiled_pathlines(paths, seeds, vector=_vector_text(vector),
                               point_data=_point_data_text(point_data),
                               **_with_default_progress(settings, "pathlines", "interval"))


_SLICE_LENGTHS = ("line_separation", "lic_length")


def slice(target: Union[Dataset, Field], *, vector: _VectorRequest = None,
          frame_velocity: Any = None, point_data: _PointDataRequest = None,
          periodic: Optional[str] = None, interpolant: Optional[str] = None,
          **settings: Any) -> dict:
    """A slice figure, as `amrstream slice` draws it: a plane through a Dataset (prepared with
    vector, frame_velocity, point_data, periodic and interpolant, as prepare() takes them) or a
    prepared Field, with a channel reconstructed at every pixel's centre, the evenly spaced field
    lines of the vector's part in the plane and optionally a LIC texture.

    Keywords, with their defaults (the command line's options of the same names; `lines=False`
    is --no-lines; point, window, line_separation and lic_length also as unyt quantities):
    normal='z' (x, y, z or 'NX,NY,NZ'), point=None (x, y, z; default the domain's centre),
    window=None (a0, b0, a1, b1 in the plane; default the domain), width=1024 (pixels across),
    background='auto' (a channel, 'magnitude', 'none' or 'auto'), colour_map='viridis',
    colour_scale='linear', range=None (min, max), lines=True, line_separation=0.0 (0: 1/30 of
    the window's width), line_width=1.5 (pixels; with line_width_by the widest),
    line_colour_by='' (a channel or 'magnitude' colouring the lines, with a colour bar),
    line_colour_map='plasma', line_colour_scale='linear', line_width_by='' (a channel or
    'magnitude' the lines' width follows), lic=False, lic_length=0.0 (0: 1/50 of the
    window's width), backend='auto' (where the LIC runs: rayquery, pipeline or compute sample
    the plane and convolve on that Vulkan device; cpu; auto as for tracing), device='' (a
    substring of the Vulkan device's name), validation=False, progress=None (progress(done,
    total) over the rows; a bar where someone watches), verbose=False.

    Returns a dict: 'image' ((H, W, 4) uint8, the figure), 'window' (a0, b0, a1, b1), 'axes'
    (the plane's axes' names), 'background_name', 'background' and 'lic' ((height, width)
    float32 over the window, row 0 at b0, NaN without data; None when not drawn), 'lines'
    ((n, 2) arrays in the plane's coordinates), and 'line_colour_values' and
    'line_width_values' (one float32 array per line, the values at its points; None when not
    asked for).
    """
    if isinstance(target, Field):
        if any(v is not None for v in (vector, frame_velocity, point_data, periodic,
                                       interpolant)):
            raise ValueError("vector, frame_velocity, point_data, periodic and interpolant were "
                             "chosen when the Field was prepared; pass the Dataset to choose "
                             "them here")
        field = target
    elif isinstance(target, Dataset):
        field_settings = {name: value for name, value in
                          (("frame_velocity", frame_velocity), ("periodic", periodic),
                           ("interpolant", interpolant)) if value is not None}
        field = prepare(target, vector=vector, point_data=point_data, **field_settings)
    else:
        raise TypeError(f"slice() needs an amrstream.Dataset or amrstream.Field, not "
                        f"{type(target).__name__}")
    if "point" in settings:
        settings["point"] = in_coordinates(settings["point"], field, "point")
    for name in ("window",) + _SLICE_LENGTHS:
        if name in settings:
            settings[name] = in_coordinates(settings[name], field, name)
    return _compiled_slice(field, **_with_default_progress(settings, "slicing", "row"))


def _snapshot_paths(snapshots: Any) -> List[str]:
    """A file, folder or pattern (str or os.PathLike), or a list of them -> a list of str."""
    if isinstance(snapshots, (str, os.PathLike)):
        snapshots = [snapshots]
    try:
        paths = [os.fspath(s) for s in snapshots]
    except TypeError:
        paths = None
    if paths is None or not all(isinstance(path, str) for path in paths):
        raise TypeError("snapshots must be a file, folder or glob pattern (str or os.PathLike) "
                        f"or a list of them, not {snapshots!r}")
    return paths


def _first_snapshot(paths: List[str], settings: dict) -> Any:
    """What states the series' coordinates: its first snapshot, loaded (with the length_unit=
    given)."""
    matches = sorted(glob.glob(paths[0])) if paths and glob.has_magic(paths[0]) else paths[:1]
    if not matches:  # the pathlines call names the pattern that matches nothing
        return None
    return load(matches[0], length_unit=settings.get("length_unit"), units=settings.get("units"))


def render(traces: Traces, **look: Any) -> Any:
    """Renders Traces as shaded tubes on a Vulkan device; returns a (height, width, 4) uint8
    RGBA image. The options, as `amrstream render` names them, with their defaults, are those of
    Traces.render (below)."""
    if not isinstance(traces, Traces):
        raise TypeError(f"traces must be amrstream.Traces, not {type(traces).__name__}")
    _lengths_in_coordinates(look, traces)
    return _compiled_render(traces, **_with_default_progress(look, "rendering", "frame"))


def _render_method(self: Traces, **look: Any) -> Any:
    return render(self, **look)


_render_method.__doc__ = Traces.render.__doc__
Traces.render = _render_method  # type: ignore  # the method, with the default progress bar


# The compiled functions' signatures and settings (defaults and meanings, from the library's one
# list of settings) complete the wrappers' docstrings.
for _wrapper, _compiled in ((prepare, _amrstream.prepare), (trace, _amrstream.trace),
                            (pathlines, _amrstream.pathlines), (render, Traces.render)):
    _wrapper.__doc__ = (_wrapper.__doc__ or "") + "\n" + (_compiled.__doc__ or "")


def from_yt(ds: Any, vector: _Sequence[Union[str, Tuple[str, str]]] = DEFAULT_YT_VECTOR,
            fields: Optional[_Sequence[Union[str, Tuple[str, str]]]] = None) -> Dataset:
    """A Dataset of the leaf cells of a grid-based yt dataset (Enzo, FLASH, AMReX/BoxLib,
    Athena++, Chombo, ...): the vector's three fields first, then `fields`, in code units;
    positions in code_length. Trace it with vector=<the same three names> unless they are
    velocity_x/y/z. `ds` may also be a path, which yt.load opens."""
    from .yt_cells import leaf_cells_from_yt

    if isinstance(ds, (str, os.PathLike)):
        try:
            import yt
        except ImportError:
            raise TypeError(f"from_yt({os.fspath(ds)!r}): a path needs yt to open it, and yt is "
                            "not installed; amrstream.load(path) reads Enzo, FLASH, AMReX, "
                            "Gerris and .exa files without yt") from None
        ds = yt.load(os.fspath(ds))
    if not hasattr(ds, "index") or not hasattr(ds, "dimensionality"):
        raise TypeError(f"ds must be a yt dataset (yt.load's) or a path, not {type(ds).__name__}")
    cells = leaf_cells_from_yt(ds, vector=vector, fields=fields)
    cells["units"] = {name: unit for name, unit in cells.pop("field_units", {}).items()
                      if unit not in ("", "dimensionless")}
    return from_arrays(**cells)


# yt's annotate_amrstream_lines and _lic, registered once yt's plots are imported.
from . import _yt_hook

_yt_hook.install()
