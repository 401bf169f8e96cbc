"""Leaf cells of a grid-based yt dataset, as keyword arguments for ``amrstream.from_arrays``.

Usage::

    import yt
    from amrstream.yt_cells import leaf_cells_from_yt
    cells = leaf_cells_from_yt(yt.load("DD0010/moving7_0010"), vector=("x-velocity", "y-velocity", "z-velocity"))

Conventions of the returned arrays:

* ``max_level`` is ``ds.index.max_level``, the finest level yt's index holds. Level 0 is
  yt's root level; a cell of level ``l`` spans ``2 ** (max_level - l)`` finest cells per axis.
* ``corners`` count finest cells from ``ds.domain_left_edge``.
* Field values are in the dataset's code units: fields on disk as the file writes them, derived
  fields converted with ``in_base("code")``; the units
  they ended up in are listed in ``field_units`` (a field yt cannot express in code units
  keeps the units yt gives it, and ``field_units`` says which). ``field_units`` is for
  the caller to read; pop it before ``from_arrays(**cells)`` if that does not take it.
* Cells come grid by grid in ``ds.index.grids`` order, and within a grid in C order of
  yt's (i, j, k) = (x, y, z) index.
* 2D data become a slab in z as ``amrstream.load`` makes of a 2D FLASH file: finest cells as
  deep as they are wide in x, the slab as thick as the coarsest leaf cell, each finer cell
  repeated along z to fill it; z is not periodic.

Only yt and numpy are needed; nothing from the compiled amrstream module is imported.
"""

import warnings

import numpy as np

DEFAULT_VECTOR = ("velocity_x", "velocity_y", "velocity_z")

# How far (in finest cells) a grid edge may sit from the finest lattice before we refuse it.
_LATTICE_TOLERANCE = 1e-4
# A 2D leaf cell is repeated along z at most this many times (as amrstream.load does).
_MAX_SLAB_GROWTH = 256


def leaf_cells_from_yt(ds, vector=None, fields=None):
    """Return the leaf cells of ``ds`` as keyword arguments for ``amrstream.from_arrays``.

    ``vector``: three field names or (type, name) tuples, default velocity_x/y/z.
    ``fields``: optional extra scalar fields. Raises ValueError (TypeError for datasets
    that are not made of grid patches) when the dataset cannot be traced by amrstream.
    """
    _require_cartesian_2d_or_3d(ds)
    grids = _grid_patches(ds)
    _require_refinement_by_2(ds)
    requested = _resolve_fields(ds, _as_vector(vector), list(fields or ()))

    max_level = int(ds.index.max_level)
    planar = int(ds.dimensionality) == 2
    domain_left = _code_length(ds.domain_left_edge)
    finest_width = _finest_cell_width(ds, max_level, planar)

    corner_parts, level_parts = [], []
    value_parts = {name: [] for name, _ in requested}
    field_units = {}
    for grid in grids:
        corners, level, mask = _grid_leaf_geometry(grid, max_level, domain_left, finest_width,
                                                   planar)
        if len(corners) == 0:
            continue
        corner_parts.append(corners)
        level_parts.append(np.full(len(corners), level, dtype=np.int32))
        for name, data_field in requested:
            values, units = _leaf_values_in_code_units(grid, data_field, mask)
            value_parts[name].append(values)
            field_units.setdefault(name, units)
        grid.clear_data()

    if not corner_parts:
        raise ValueError(f"yt dataset {ds} has no leaf cells (no grid has an uncovered cell)")
    corners = np.ascontiguousarray(np.concatenate(corner_parts), dtype=np.int64)
    levels = np.concatenate(level_parts)
    _check_leaf_volume(ds, levels, max_level, planar)
    values = {name: np.ascontiguousarray(np.concatenate(parts), dtype=np.float32)
              for name, parts in value_parts.items()}
    periodic = tuple(bool(p) for p in ds.periodicity)
    origin = tuple(float(x) for x in domain_left)
    if planar:
        corners, levels, values = stacked_into_a_slab(ds, corners, levels, values, max_level)
        periodic = periodic[:2] + (False,)
        origin = origin[:2] + (slab_bottom(levels, max_level, finest_width[2]),)

    return {
        "corners": corners,
        "levels": levels,
        "fields": values,
        "field_units": field_units,
        "origin": origin,
        "dimensions": 2 if planar else 3,
        "finest_width": finest_width,
        "periodic": periodic,
        "time": float(ds.current_time.to_value("code_time")),
        "time_unit": _code_unit_description(ds.time_unit, "s"),
        "length_unit": _code_unit_description(ds.length_unit, "cm"),
        "length_unit_cm": _centimetres(ds.length_unit),
        "source": _dataset_source(ds),
        "format": "yt:" + type(ds).__name__,
    }


def _require_cartesian_2d_or_3d(ds):
    if ds.dimensionality < 2:
        raise ValueError(
            f"amrstream traces 2D and 3D data; yt dataset {ds} is {ds.dimensionality}D")
    geometry = str(ds.geometry)
    if geometry != "cartesian":
        raise ValueError(
            f"amrstream traces Cartesian 2D and 3D data; yt dataset {ds} has {geometry} geometry")


def _grid_patches(ds):
    grids = getattr(ds.index, "grids", None)
    if grids is None:
        raise TypeError(
            f"yt dataset {ds} ({type(ds).__name__}) is not made of grid patches (it is an "
            "octree or particle dataset, with no ds.index.grids); amrstream reads grid-based "
            "AMR (Enzo, FLASH, AMReX/BoxLib, Athena++, Chombo...). Resample it onto a grid "
            "first, e.g. with ds.covering_grid or ds.arbitrary_grid and yt.load_uniform_grid.")
    if len(grids) == 0:
        raise ValueError(f"yt dataset {ds} has no grids")
    return grids


def _require_refinement_by_2(ds):
    ratios = np.unique(np.atleast_1d(np.asarray(ds.refine_by)))
    if ds.index.max_level > 0 and not np.array_equal(ratios, [2]):
        shown = ", ".join(str(int(r)) for r in ratios)
        raise ValueError(
            "amrstream needs refinement by 2 between levels; "
            f"this dataset refines by {shown}")


def _as_vector(vector):
    vector = DEFAULT_VECTOR if vector is None else vector
    if isinstance(vector, (str, bytes)) or len(vector) != 3:
        raise ValueError(f"vector must name three fields (x, y, z components), got {vector!r}")
    return list(vector)


def _resolve_fields(ds, vector, extras):
    """Return [(output name, field yt should read)], vector first, duplicates dropped."""
    requested = []
    seen = {}
    for field in vector + extras:
        full_name = _resolve_field(ds, field)
        name = full_name[1]
        if name in seen:
            if seen[name] != full_name:
                raise ValueError(
                    f"fields {seen[name]} and {full_name} would both be called {name!r}; "
                    "ask for only one of them")
            continue
        seen[name] = full_name
        requested.append((name, _field_to_read(ds, full_name)))
    return requested


def _resolve_field(ds, field):
    from yt.utilities.exceptions import YTFieldNotFound

    field = tuple(field) if isinstance(field, list) else field
    try:
        info = _field_info(ds, field)
    except (YTFieldNotFound, KeyError):
        raise ValueError(
            f"yt dataset {ds} has no field {field!r}. Fields on disk: "
            f"{_cell_fields_on_disk(ds)}; derived fields such as ('gas', 'velocity_x') "
            "work too") from None
    if info.sampling_type == "particle":
        raise ValueError(
            f"field {info.name} is a {info.sampling_type} field; amrstream needs cell "
            f"fields, e.g. one of {_cell_fields_on_disk(ds)}")
    return tuple(info.name)


def _field_info(ds, field):
    """yt's field for ``field``; a bare name yt finds ambiguous means the ("gas", name) one."""
    try:
        return ds._get_field_info(field)
    except ValueError:
        if isinstance(field, str) and ("gas", field) in ds.field_info:
            return ds.field_info["gas", field]
        raise


def _cell_fields_on_disk(ds):
    particle_types = set(ds.particle_types or ())
    return [field for field in ds.field_list if field[0] not in particle_types]


def _field_to_read(ds, full_name):
    """Read an alias's original field, so values skip a round trip through other units."""
    info = ds.field_info[full_name]
    if getattr(info, "is_alias", False) and info.alias_name is not None:
        return tuple(info.alias_name)
    return full_name


def _code_length(value):
    return np.asarray(value.to_value("code_length"), dtype=np.float64)


def _finest_cell_width(ds, max_level, planar):
    domain_width = _code_length(ds.domain_right_edge - ds.domain_left_edge)
    width = domain_width / (np.asarray(ds.domain_dimensions, dtype=np.float64) * 2.0**max_level)
    if planar:
        width[2] = width[0]
    return width


def _grid_leaf_geometry(grid, max_level, domain_left, finest_width, planar):
    """Return (corners of the grid's leaf cells, grid level, leaf mask); a 2D grid's at z 0."""
    level = int(grid.Level)
    if not 0 <= level <= max_level:
        raise ValueError(f"grid {grid} has level {level}, outside 0..{max_level}")
    span = 2 ** (max_level - level)
    axes = 2 if planar else 3
    _require_cell_width(grid, finest_width[:axes] * span, axes)
    offset = (_code_length(grid.LeftEdge) - domain_left) / finest_width
    if planar:
        offset[2] = 0.0
    grid_corner = _on_finest_lattice(grid, offset)
    mask = np.asarray(grid.child_mask, dtype=bool)
    cell_index = np.stack(np.nonzero(mask), axis=1).astype(np.int64)
    return grid_corner + cell_index * span, level, mask


def _require_cell_width(grid, expected, axes):
    actual = _code_length(grid.dds)[:axes]
    if not np.allclose(actual, expected, rtol=1e-6, atol=0.0):
        raise ValueError(
            f"grid {grid} at level {grid.Level} has cells {actual} wide, but refinement by 2 "
            f"from the root level gives {expected}")


def _on_finest_lattice(grid, position):
    nearest = np.rint(position)
    if np.any(np.abs(position - nearest) > _LATTICE_TOLERANCE):
        raise ValueError(
            f"grid {grid} starts at {position} finest cells from the domain edge, "
            "not on the finest cell lattice")
    return nearest.astype(np.int64)


def _leaf_values_in_code_units(grid, field, mask):
    """Return (float32 values of the leaf cells, units string).

    A field on disk keeps the units its file writes it in (yt's reader declares them, e.g.
    code_velocity**2): reducing those to code base units would scale the numbers wherever a
    code unit is not a product of the base ones (Enzo's comoving velocity unit is not
    length/time). Derived fields are expressed in code base units where yt can."""
    from unyt.exceptions import UnitConversionError, UnitsNotReducible

    values = grid[field][mask]
    if tuple(field) in grid.ds.field_list:
        return np.asarray(values.d, dtype=np.float32), str(values.units)
    try:
        values = values.in_base("code")
    except (UnitConversionError, UnitsNotReducible):
        pass
    return np.asarray(values.d, dtype=np.float32), str(values.units)


def _check_leaf_volume(ds, levels, max_level, planar):
    """Leaf cells must fill the domain once: more volume means overlapping grids."""
    counts = np.bincount(levels, minlength=max_level + 1)
    axes = 2 if planar else 3
    leaf_volume = sum(int(count) * (2**axes) ** (max_level - level)
                      for level, count in enumerate(counts))
    domain_volume = int(np.prod([int(n) << max_level for n in ds.domain_dimensions[:axes]]))
    if leaf_volume > domain_volume:
        raise ValueError(
            f"leaf cells of {ds} cover {leaf_volume} finest cells but the domain has "
            f"{domain_volume}: yt's child_mask leaves overlapping grids uncovered")
    if leaf_volume < domain_volume:
        warnings.warn(
            f"leaf cells of {ds} cover {leaf_volume} of the domain's {domain_volume} "
            "finest cells: part of the domain has no data", stacklevel=3)


def slab_bottom(levels, max_level, finest_depth):
    """The z of a slab's lower face: its middle, the data's plane, is z = 0 (as load() puts a 2D
    FLASH file's)."""
    return -0.5 * finest_depth * 2.0 ** (max_level - int(levels.min()))


def stacked_into_a_slab(ds, corners, levels, values, max_level):
    """2D cells repeated along z up to the coarsest leaf's width, as load() makes of 2D FLASH."""
    coarsest = int(levels.min())
    copies = np.left_shift(1, levels - coarsest).astype(np.int64)
    total = int(copies.sum())
    if total > _MAX_SLAB_GROWTH * len(levels):
        raise ValueError(
            f"yt dataset {ds}: {len(levels)} leaf cells become {total} cells when stacked into "
            "a slab in z: too many")
    source = np.repeat(np.arange(len(levels)), copies)
    first = np.cumsum(copies) - copies
    copy = np.arange(total, dtype=np.int64) - np.repeat(first, copies)
    stacked = corners[source]
    stacked[:, 2] = copy * np.left_shift(1, max_level - levels[source]).astype(np.int64)
    return (np.ascontiguousarray(stacked), levels[source],
            {name: np.ascontiguousarray(v[source]) for name, v in values.items()})


def _code_unit_description(unit, physical):
    from unyt.exceptions import UnitConversionError

    try:
        return f"code units (1 = {unit.to_value(physical):.4g} {physical})"  # as load() says
    except UnitConversionError:
        return f"code units (1 = {unit})"


def _centimetres(unit):
    from unyt.exceptions import UnitConversionError

    try:
        return float(unit.to_value("cm"))
    except UnitConversionError:
        return None


def _dataset_source(ds):
    filename = getattr(ds, "filename", None)
    return filename if isinstance(filename, str) and filename else str(ds)
