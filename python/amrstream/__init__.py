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
    seeds_grid,
    seeds_line,
    seeds_random,
)
from . import _amrstream

__all__ = [
    "BackendError", "Dataset", "Field", "InputError", "Traces", "__version__", "from_arrays",
    "from_yt", "load", "pathlines", "prepare", "reason_name", "render", "seeds_densest",
    "seeds_grid", "seeds_line", "seeds_random", "trace",
]

DEFAULT_YT_VECTOR = ("velocity_x", "velocity_y", "velocity_z")


def _vector_text(vector):
    """None, 'a,b,c' or three names -> None or 'a,b,c'."""
    if vector is None or isinstance(vector, str):
        return vector
    names = [name[-1] if isinstance(name, tuple) else name for name in vector]
    if len(names) != 3 or not all(isinstance(name, str) for name in names):
        raise ValueError(f"vector must be 'a,b,c' or three field names, not {vector!r}")
    return ",".join(names)


def prepare(dataset, vector=None, point_data="all", periodic="auto", interpolant="tent"):
    """A Field ready for tracing: the vector ('a,b,c' or three names; default the velocity,
    else the magnetic field), the point data ('all', 'none' or names), periodic axes ('auto' as
    the file says, 'none', or e.g. 'x,y,z'), the interpolant ('tent', the paper's, or 'linear',
    exact for linear fields across level jumps); bricks and regions built once for many
    traces."""
    if isinstance(point_data, (list, tuple)):
        point_data = ",".join(point_data) if point_data else "none"
    return _amrstream.prepare(dataset, vector=_vector_text(vector), point_data=point_data,
                              periodic=periodic, interpolant=interpolant)


def trace(target, seeds, *, vector=None, point_data=None, periodic=None, interpolant=None,
          **settings):
    """Traces streamlines from seeds ((N, 3) points) through a Dataset or a prepared Field.

    Settings, as `amrstream trace` names them: steps=1000, step_size (default 0.25 cell
    widths), step_mode='cell'|'time'|'arc', direction='both'|'forward'|'backward',
    vorticity=False, max_length=0, max_time=0, terminal_speed=1e-12, memory_budget=0 (bytes),
    backend='auto'|'cpu'|'compute'|'pipeline'|'rayquery', device='' (a device name part),
    progress=callable(done, total), verbose=False. vector, point_data, periodic and interpolant
    are those of prepare() (only with a Dataset). Returns Traces.
    """
    if isinstance(point_data, (list, tuple)):
        point_data = ",".join(point_data) if point_data else "none"
    return _amrstream.trace(target, seeds, vector=_vector_text(vector), point_data=point_data,
                            periodic=periodic, interpolant=interpolant, **settings)


def pathlines(snapshots, seeds, *, vector=None, point_data=None, **settings):
    """Traces pathlines from seeds ((N, 3) points) through a time series of snapshots: a list of
    files, folders (AMReX plotfiles) or glob patterns (a single string is one pattern), ordered
    by the times the files state.

    Settings, as `amrstream pathlines` names them: start_time (default: the first snapshot's),
    end_time (default: the last's), step_size (default: a tenth of the shortest interval),
    release_every (streaklines: new particles from every seed at this interval), periodic,
    interpolant, backend, device, progress=callable(done, total) over the intervals,
    verbose=False. vector and point_data as for prepare(). Returns Traces (one line per
    particle; integration_time is physical time), which to_vtp() writes.
    """
    if isinstance(snapshots, str):
        snapshots = [snapshots]
    if isinstance(point_data, (list, tuple)):
        point_data = ",".join(point_data) if point_data else "none"
    return _amrstream.pathlines([str(s) for s in snapshots], seeds, vector=_vector_text(vector),
                                point_data=point_data, **settings)


def render(traces, **look):
    """Renders Traces as shaded tubes on a Vulkan device; returns a (height, width, 4) uint8
    RGBA image. Options as `amrstream render` names them: width=1024, height=768,
    camera=(azimuth, elevation[, zoom]) or view='iso'|'+x'|'-x'|..., zoom=1, up='+z', fov=35,
    projection='perspective'|'orthographic', frame='traces'|'domain', look_at=(x, y, z),
    view_box=(x0, y0, z0, x1, y1, z1) the camera frames (default: the traces),
    tube_radius (finest cells) or tube_radius_physical or tube_radius_view=0.003 (of the
    view's height), colour_by='speed'|'time'|a field, colour_map='viridis'|'magma'|'inferno'|
    'plasma'|'cividis'|'coolwarm'|'rdbu'|'twilight', colour_scale='linear'|'log'|'symlog',
    symlog_width, range=(min, max), outline='domain'|'bricks'|'none', axes=False, triad=True,
    scale_bar=False, background='white'|'transparent'|'#rrggbb'|'r,g,b', ao_samples=4,
    volume=<a field shown behind the tubes>, volume_range, volume_opacity=0.05,
    linear_volume=False, frames=32, colour_bar=True, backend, device, progress, verbose."""
    return traces.render(**look)


def from_yt(ds, vector=DEFAULT_YT_VECTOR, fields=None):
    """A Dataset of the leaf cells of a grid-based yt dataset (Enzo, FLASH, AMReX/BoxLib,
    Athena++, Chombo, ...): the vector's three fields first, then `fields`, in code units;
    positions in code_length. Trace it with vector=<the same three names> unless they are
    velocity_x/y/z."""
    from .yt_cells import leaf_cells_from_yt

    cells = leaf_cells_from_yt(ds, vector=vector, fields=fields)
    cells.pop("field_units", None)
    return from_arrays(**cells)
