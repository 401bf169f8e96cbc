"""yt plot callbacks that draw amrstream's slice on yt's SlicePlots: the evenly spaced field lines
and the LIC texture that `amrstream.slice` computes for the plot's own window, on its axes in
its units.

Importing amrstream with yt installed registers them with yt::

    import yt, amrstream
    ds = yt.load("DD0010/moving7_0010")
    vector = ("x-velocity", "y-velocity", "z-velocity")
    p = yt.SlicePlot(ds, "x", ("enzo", "Density"))
    p.annotate_amrstream_lic(vector=vector)
    p.annotate_amrstream_lines(vector=vector)
    p.save()

Both read the data through `amrstream.from_yt`, once per yt dataset and vector (`dataset_for`).
"""

import functools
import typing
from typing import Any, Dict, Optional, Tuple, Union

import numpy as np
from yt.visualization import plot_modifications, plot_window

from . import DEFAULT_YT_VECTOR, _amrstream, from_yt, prepare
from . import slice as _slice

_FieldName = Union[str, Tuple[str, str]]
_Names = typing.Sequence[_FieldName]  # as from_yt takes its vector and fields

# yt's image axes across x, y and z, which amrstream's slices share: (y, z), (z, x), (x, y).
_IMAGE_AXES = ((1, 2), (2, 0), (0, 1))

_MADE = "_amrstream_made"  # the attribute of a yt dataset that keeps what was made of it


def _key(value: Any) -> Any:
    """`value` (names, numbers, lists of them) as a dictionary key."""
    if isinstance(value, (list, tuple, np.ndarray)):
        return tuple(_key(item) for item in value)
    return value


def _made(ds: Any) -> Dict[tuple, Any]:
    """The amrstream Datasets and Fields made of the yt dataset `ds`, kept on it so that they
    go with it (yt's plots hold their dataset through weak proxies, which no weak-keyed
    dictionary takes)."""
    made = getattr(ds, _MADE, None)
    if made is None:
        made = {}
        setattr(ds, _MADE, made)
    return made


def dataset_for(ds: Any, vector: _Names = DEFAULT_YT_VECTOR,
                fields: Optional[_Names] = None) -> _amrstream.Dataset:
    """`amrstream.from_yt(ds, vector, fields)`, made once per yt dataset (or yt's weak proxy of
    one), vector and fields, and kept while `ds` lives."""
    made = _made(ds)
    key = ("dataset", _key(vector), _key(fields or ()))
    if key not in made:
        made[key] = from_yt(ds, vector=vector, fields=fields)
    return made[key]


def _field_for(ds: Any, vector: _Names, frame_velocity: Any) -> _amrstream.Field:
    """The Field the callbacks slice: `dataset_for(ds, vector)`'s vector, less frame_velocity;
    made once per yt dataset, vector and frame."""
    made = _made(ds)
    key = ("field", _key(vector), _key(frame_velocity))
    if key not in made:
        dataset = dataset_for(ds, vector)
        # from_yt puts the vector's three fields first, named as the Dataset names them.
        made[key] = prepare(dataset, vector=list(dataset.field_names[:3]),
                            frame_velocity=frame_velocity, point_data="none")
    return made[key]


def _amrstream_plane(normal: np.ndarray) -> Tuple[str, np.ndarray, np.ndarray, np.ndarray]:
    """(the normal as amrstream.slice takes it, the plane's axes u and v, the north_vector that
    gives a yt cutting plane those axes) for a unit normal, as src/slice/slice_plane.cpp chooses
    them: yt's image axes across x, y or z; otherwise v is +z (+y for a normal within 0.999 of
    z) made normal to it, and u = v x normal."""
    for axis in range(3):
        if abs(normal[axis]) == 1.0:
            u, v = np.eye(3)[list(_IMAGE_AXES[axis])]
            return "xyz"[axis], u, v, v
    up = np.eye(3)[1 if abs(normal[2]) > 0.999 else 2]
    v = up - np.dot(up, normal) * normal
    v /= np.linalg.norm(v)
    return ",".join(repr(float(c)) for c in normal), np.cross(v, normal), v, up


def _shown(vector: np.ndarray) -> str:
    return "(" + ", ".join(f"{c:.4g}" for c in np.round(vector, 6) + 0.0) + ")"  # + 0.0: no -0


def _plane(data: Any, ds: Any) -> Tuple[str, np.ndarray, np.ndarray]:
    """(normal, u, v) of amrstream's slice in the plane of yt's slice `data` (a YTSlice or
    YTCuttingPlane), whose axes are the plot's image axes. Raises ValueError where amrstream
    cannot slice that plane with those axes."""
    axis = getattr(data, "axis", None)
    planar = int(ds.dimensionality) == 2
    if axis in (0, 1, 2):
        if planar and axis != 2:
            raise ValueError(
                f"{ds} is 2D, which amrstream makes a slab in z: only its z slice has field "
                f"lines, not this {'xyz'[axis]} slice")
        return _amrstream_plane(np.eye(3)[axis])[:3]
    orienter = getattr(data, "orienter", None)
    if axis != 4 or orienter is None:
        raise ValueError(f"{type(data).__name__} is not a slice of {ds}")
    if planar:
        raise ValueError(f"{ds} is 2D: amrstream draws its z slice only, not off-axis ones")
    east, north, normal = (np.asarray(orienter.unit_vectors[i], dtype=np.float64)
                           for i in range(3))
    text, u, v, up = _amrstream_plane(normal)
    if not (np.allclose(u, east, atol=1e-9) and np.allclose(v, north, atol=1e-9)):
        raise ValueError(
            f"this off-axis slice's image axes are {_shown(east)} across and {_shown(north)} "
            f"up, but amrstream's slice there has {_shown(u)} and {_shown(v)}: make the plot "
            f"OffAxisSlicePlot(ds, {_shown(np.cross(u, v))}, ..., north_vector={_shown(up)}) "
            "to draw amrstream's slice on it")
    return text, u, v


class _View(typing.NamedTuple):
    """Where a plot's window lies in amrstream's slice and on the plot's axes."""

    normal: str                                # as amrstream.slice takes it
    point: Tuple[float, float, float]          # on the plane (code_length)
    window: Tuple[float, float, float, float]  # a0, b0, a1, b1 in the plane (code_length)
    extent: Tuple[float, float, float, float]  # the axes' limits over a0..a1, then b0..b1
    swap: bool                                 # the plot shows b across and a up
    meets_domain: bool                         # the window shows part of the domain

    def on_axes(self, points: np.ndarray) -> np.ndarray:
        """(n, 2) points in the plane -> where they lie on the axes (x, y as drawn)."""
        a0, b0, a1, b1 = self.window
        x0, x1, y0, y1 = self.extent
        drawn = np.empty((len(points), 2))
        drawn[:, 0] = x0 + (points[:, 0] - a0) * ((x1 - x0) / (a1 - a0))
        drawn[:, 1] = y0 + (points[:, 1] - b0) * ((y1 - y0) / (b1 - b0))
        return drawn[:, ::-1] if self.swap else drawn

    def imshow_extent(self) -> Tuple[float, float, float, float]:
        """imshow's (left, right, bottom, top) of an image over the window."""
        x0, x1, y0, y1 = self.extent
        return (y0, y1, x0, x1) if self.swap else (x0, x1, y0, y1)


def _view(plot: Any, field: _amrstream.Field) -> _View:
    """The view of the plot being drawn (yt's CallbackWrapper) in `field`'s slice."""
    normal, u, v = _plane(plot.data, plot.ds)
    lower = np.asarray(field.domain_left_edge, dtype=np.float64)
    upper = np.asarray(field.domain_right_edge, dtype=np.float64)
    if plot.data.axis == 4:  # a cutting plane: the image's coordinates count from its centre
        point = np.asarray(plot.data.center.to_value("code_length"), dtype=np.float64)
        a, b = float(np.dot(point, u)), float(np.dot(point, v))
    else:
        point = 0.5 * (lower + upper)  # across a 2D dataset's slab: its middle
        if int(plot.ds.dimensionality) == 3:
            point[plot.data.axis] = float(plot.data.coord.to_value("code_length"))
        a = b = 0.0
    x0, x1 = (float(x.to_value("code_length")) + a for x in plot.xlim)
    y0, y1 = (float(y.to_value("code_length")) + b for y in plot.ylim)
    axes_x, axes_y = plot._axes.get_xlim(), plot._axes.get_ylim()
    if plot._swap_axes:
        axes_x, axes_y = axes_y, axes_x
    corners = np.array([[(lower, upper)[(c >> k) & 1][k] for k in range(3)] for c in range(8)])
    along_u, along_v = corners @ u, corners @ v
    meets = (x0 < along_u.max() and x1 > along_u.min() and y0 < along_v.max()
             and y1 > along_v.min())
    return _View(normal, (float(point[0]), float(point[1]), float(point[2])), (x0, y0, x1, y1),
                 (axes_x[0], axes_x[1], axes_y[0], axes_y[1]), bool(plot._swap_axes),
                 bool(meets))


class _SliceCallback(plot_modifications.PlotCallback):
    """What both callbacks share: the field they slice and the slice of the plot's window. (It
    has no __call__, so yt registers no annotate_ method for it.)"""

    _supported_geometries = None  # from_yt says which geometries it takes (ValueError)

    def __init__(self, vector: _Names, frame_velocity: Any, width: Optional[int],
                 backend: str) -> None:
        if isinstance(vector, str) or len(vector) != 3:
            raise ValueError(f"vector must name three fields (x, y, z components), as from_yt "
                             f"takes them, not {vector!r}")
        if width is not None and (isinstance(width, bool) or not isinstance(width, int)
                                  or width < 1):
            raise ValueError(f"width must be a count of pixels (int, 1 or more), not {width!r}")
        self.vector = tuple(vector)
        self.frame_velocity = frame_velocity
        self.width = width
        self.backend = backend

    def _settings(self, view: _View) -> Dict[str, Any]:
        """What amrstream.slice draws, for the view."""
        raise NotImplementedError

    def _slice(self, plot: Any) -> Tuple[_View, Optional[dict]]:
        """The plot's view and amrstream's slice of its window (None where the window misses
        the domain)."""
        field = _field_for(plot.ds, self.vector, self.frame_velocity)
        view = _view(plot, field)
        if not view.meets_domain:
            return view, None
        width = self.width if self.width is not None else int(plot.frb.buff_size[0])
        return view, _slice(field, normal=view.normal, point=view.point, window=view.window,
                            width=width, background="none", backend=self.backend,
                            progress=None, **self._settings(view))


def _middle_step(points: np.ndarray) -> Optional[Tuple[np.ndarray, np.ndarray]]:
    """The step of a polyline (of some length) nearest its half length; None: it has none."""
    steps = np.hypot(*np.diff(points, axis=0).T)
    some = np.flatnonzero(steps > 0)
    if some.size == 0:
        return None
    middles = np.cumsum(steps) - 0.5 * steps
    k = some[np.argmin(np.abs(middles[some] - 0.5 * steps.sum()))]
    return points[k], points[k + 1]


class AmrstreamLinesCallback(_SliceCallback):
    """Draws amrstream's evenly spaced field lines of the vector's part in the slice (those of
    `amrstream.slice`, computed for the plot's window) on an axis-aligned SlicePlot, or on an
    OffAxisSlicePlot whose north_vector is amrstream's (+z made normal to the slice's normal;
    +y for normals near z), with an arrow at the middle of each line in the field's direction.

    Parameters
    ----------
    vector : three field names or (type, name) tuples, default ("velocity_x", "velocity_y",
        "velocity_z"); as `amrstream.from_yt` takes them.
    frame_velocity : (vx, vy, vz) subtracted from the vector (its code units) or "auto" (its
        mean over the domain), default None: none.
    density : float, default 1.0; the lines' density: they lie 1/(30 density) of the window's
        width apart.
    line_separation : length, default None; their separation instead (a unyt quantity, or a
        number in code_length).
    width : int, default None; pixels across the window of the plane amrstream samples (None:
        the plot's buffer's, plot.buff_size).
    color, linewidth, alpha : the lines' and arrows', default "white", 1.0, 1.0.
    arrowsize : float, default 1.0; the arrows' size (10 points times it); 0: no arrows.
    backend : where amrstream computes, default "auto" (see amrstream.slice).
    **kwargs : further keywords of matplotlib's LineCollection (e.g. linestyle, zorder).
    """

    _type_name = "amrstream_lines"

    def __init__(self, vector: _Names = DEFAULT_YT_VECTOR, *,
                 frame_velocity: Any = None, density: float = 1.0,
                 line_separation: Any = None, width: Optional[int] = None,
                 color: Any = "white", linewidth: float = 1.0, alpha: float = 1.0,
                 arrowsize: float = 1.0, backend: str = "auto", **kwargs: Any) -> None:
        super().__init__(vector, frame_velocity, width, backend)
        if not density > 0:
            raise ValueError(f"density must be above 0, not {density!r}")
        self.density = density
        self.line_separation = line_separation
        self.color = color
        self.linewidth = linewidth
        self.alpha = alpha
        self.arrowsize = arrowsize
        self.kwargs = kwargs

    def _settings(self, view: _View) -> Dict[str, Any]:
        separation = self.line_separation
        if separation is None:
            separation = (view.window[2] - view.window[0]) / (30.0 * self.density)
        return {"lines": True, "lic": False, "line_separation": separation}

    def __call__(self, plot: Any) -> None:
        from matplotlib.collections import LineCollection
        from matplotlib.patches import FancyArrowPatch

        view, result = self._slice(plot)
        if result is None:
            return
        axes = plot._axes
        limits = axes.get_xlim(), axes.get_ylim()
        lines = [view.on_axes(np.asarray(line, dtype=np.float64)) for line in result["lines"]]
        collection = LineCollection(lines, colors=self.color, linewidths=self.linewidth,
                                    alpha=self.alpha, **self.kwargs)
        collection.set_gid("amrstream_lines")
        axes.add_collection(collection)
        for line in lines if self.arrowsize > 0 else []:
            step = _middle_step(line)
            if step is None:
                continue
            arrow = FancyArrowPatch(*step, arrowstyle="-|>", mutation_scale=10 * self.arrowsize,
                                    shrinkA=0, shrinkB=0, color=self.color,
                                    linewidth=self.linewidth, alpha=self.alpha,
                                    zorder=collection.get_zorder())
            arrow.set_gid("amrstream_arrow")
            axes.add_patch(arrow)
        axes.set_xlim(*limits[0])
        axes.set_ylim(*limits[1])


class AmrstreamLicCallback(_SliceCallback):
    """Draws amrstream's line integral convolution (LIC) of the vector's part in the slice (that
    of `amrstream.slice`, computed for the plot's window) over an axis-aligned SlicePlot, or an
    OffAxisSlicePlot whose north_vector is amrstream's (+z made normal to the slice's normal; +y
    for normals near z).

    Parameters
    ----------
    vector : three field names or (type, name) tuples, default ("velocity_x", "velocity_y",
        "velocity_z"); as `amrstream.from_yt` takes them.
    frame_velocity : (vx, vy, vz) subtracted from the vector (its code units) or "auto" (its
        mean over the domain), default None: none.
    lic_length : length, default None; the convolution kernel's half-length (a unyt quantity,
        or a number in code_length; None: 1/50 of the window's width).
    width : int, default None; the LIC's pixels across the window (None: the plot's buffer's,
        plot.buff_size).
    lim : (low, high), default None; the LIC values the colour map spans (amrstream's LIC lies
        in [0, 1] about 0.5; None: its 2nd to 98th percentile).
    cmap : default "binary"; the colour map.
    alpha : float, default 0.8; the LIC's opacity.
    const_alpha : bool, default False; False: the opacity grows from 0 at `low` to alpha at
        `high`, so that the dark streaks show over the plot; True: alpha everywhere.
    backend : where amrstream computes, default "auto" (see amrstream.slice).
    """

    _type_name = "amrstream_lic"

    def __init__(self, vector: _Names = DEFAULT_YT_VECTOR, *,
                 frame_velocity: Any = None, lic_length: Any = None,
                 width: Optional[int] = None, lim: Optional[Tuple[float, float]] = None,
                 cmap: Any = "binary", alpha: float = 0.8, const_alpha: bool = False,
                 backend: str = "auto") -> None:
        super().__init__(vector, frame_velocity, width, backend)
        if lim is not None and (len(lim) != 2 or not lim[1] > lim[0]):
            raise ValueError(f"lim must be (low, high) with high above low, not {lim!r}")
        self.lic_length = lic_length
        self.lim = lim
        self.cmap = cmap
        self.alpha = alpha
        self.const_alpha = const_alpha

    def _settings(self, view: _View) -> Dict[str, Any]:
        settings = {"lines": False, "lic": True}
        return settings if self.lic_length is None else {**settings, "lic_length": self.lic_length}

    def __call__(self, plot: Any) -> None:
        view, result = self._slice(plot)
        if result is None or not np.isfinite(result["lic"]).any():
            return
        lic = result["lic"]
        low, high = self.lim if self.lim is not None else np.nanpercentile(lic, (2, 98))
        alpha: Any = self.alpha
        if not self.const_alpha:
            rise = np.clip((lic - low) / ((high - low) or 1.0), 0.0, 1.0)
            alpha = np.nan_to_num(rise) * self.alpha
            alpha = alpha.T if view.swap else alpha
        axes = plot._axes
        limits = axes.get_xlim(), axes.get_ylim()
        image = axes.imshow(lic.T if view.swap else lic, extent=view.imshow_extent(),
                            origin="lower", cmap=self.cmap, vmin=low, vmax=high, alpha=alpha,
                            interpolation="nearest", aspect=axes.get_aspect())
        image.set_gid("amrstream_lic")
        axes.set_xlim(*limits[0])
        axes.set_ylim(*limits[1])


def _checking_the_plot_first(name: str) -> None:
    """Wraps the method `name` that yt registered on its plots, so that a plot amrstream cannot
    draw on or a vector the dataset lacks raises ValueError at once, not when the plot is
    drawn (where yt would report it as a YTPlotCallbackError)."""
    registered = getattr(plot_window.PWViewerMPL, name)

    @functools.wraps(registered)
    def annotate(self: Any, *args: Any, **kwargs: Any) -> Any:
        if self._plot_type not in ("Slice", "OffAxisSlice"):
            raise ValueError(
                f"{name} draws amrstream's slice on a SlicePlot (axis-aligned, or off-axis with "
                f"amrstream's north), not on a {self._plot_type} plot ({type(self).__name__})")
        _plane(self.data_source, self.ds)
        registered(self, *args, **kwargs)
        callback = self._callbacks[-1]
        try:
            _field_for(self.ds, callback.vector, callback.frame_velocity)
        except Exception:
            self._callbacks.pop()
            raise
        return self

    setattr(plot_window.PWViewerMPL, name, annotate)


_checking_the_plot_first("annotate_amrstream_lines")
_checking_the_plot_first("annotate_amrstream_lic")
