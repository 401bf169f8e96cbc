"""Between amrstream's leaf cells and VTK's vtkOverlappingAMR, the AMR dataset of ParaView's FLASH,
Enzo and AMReX readers: the leaf cells of one as from_arrays() takes them, and one made of a
Dataset's leaf cells (what ParaView shows of the formats only amrstream reads). Needs VTK's
Python modules (ParaView's pvpython has them)."""

from typing import Any, Dict, List, Optional, Tuple

import numpy

from .yt_cells import slab_bottom, stacked_into_a_slab

# A cell of an overlapping AMR block that is no leaf: one covered by finer cells, one hidden, or a
# ghost copy of a neighbour's (vtkDataSetAttributes' REFINEDCELL, HIDDENCELL, DUPLICATECELL).
_NOT_LEAF = 8 | 32 | 1
_GHOSTS = "vtkGhostType"
# The leaf cells of a level are grouped into blocks of this many cells a side.
BLOCK_CELLS = 8
# FieldData arrays that carry what a vtkOverlappingAMR cannot say of itself.
SOURCE_ARRAY = "amrstream Source"
PERIODIC_ARRAY = "amrstream Periodic"
LENGTH_UNIT_ARRAY = "amrstream LengthUnit"
LENGTH_UNIT_CM_ARRAY = "amrstream LengthUnitCentimetres"
DIMENSIONS_ARRAY = "amrstream Dimensions"
COMPONENT_SUFFIXES = ("_X", "_Y", "_Z")


def leaf_cells(amr: Any) -> Dict[str, Any]:
    """from_arrays()'s arguments for the leaf cells of a vtkOverlappingAMR: the cells of every
    block not marked refined, hidden or duplicate in its vtkGhostType, with each cell array (a
    three-component array NAME becomes NAME_X, NAME_Y and NAME_Z). Raises ValueError for what
    amrstream cannot take (no blocks, refinement ratios other than 2, arrays unlike across
    blocks)."""
    blocks = [(level, amr.GetDataSet(level, index))
              for level in range(amr.GetNumberOfLevels())
              for index in range(amr.GetNumberOfDataSets(level))]
    blocks = [(level, grid) for level, grid in blocks if grid is not None]
    if not blocks:
        raise ValueError("the AMR input holds no blocks")
    finest = max(level for level, _ in blocks)
    for level in range(finest):
        if amr.GetRefinementRatio(level) != 2:
            raise ValueError(f"level {level} of the AMR input is refined by "
                             f"{amr.GetRefinementRatio(level)}; amrstream takes a ratio of 2")
    finest_width = [0.0, 0.0, 0.0]
    amr.GetSpacing(finest, finest_width)
    bounds = [0.0] * 6
    amr.GetBounds(bounds)
    origin = numpy.array(bounds[0::2])
    planar = all(grid.GetDimensions()[2] == 1 for _, grid in blocks)
    if planar:
        finest_width[2] = finest_width[0]
    corners, levels, values = [], [], []
    for level, grid in blocks:
        block_corners, leaf = _block_leaves(grid, level, finest, origin, finest_width, planar)
        corners.append(block_corners[leaf])
        levels.append(numpy.full(int(leaf.sum()), level, dtype=numpy.int32))
        values.append({name: column[leaf] for name, column in _cell_columns(grid).items()})
    names = list(values[0])
    for block in values[1:]:
        if list(block) != names:
            raise ValueError(f"the AMR input's blocks hold different cell arrays: {names} and "
                             f"{list(block)}")
    fields = {name: numpy.concatenate([block[name] for block in values]) for name in names}
    all_corners, all_levels = numpy.concatenate(corners), numpy.concatenate(levels)
    if planar:  # as load() makes a slab of a 2D FLASH file
        all_corners, all_levels, fields = stacked_into_a_slab("the 2D AMR input", all_corners,
                                                              all_levels, fields, finest)
        origin[2] = slab_bottom(all_levels, finest, finest_width[2])
    return {"corners": all_corners, "levels": all_levels, "fields": fields,
            "origin": tuple(float(x) for x in origin),
            "finest_width": tuple(float(x) for x in finest_width),
            "dimensions": 2 if planar else 3}


def _block_leaves(grid: Any, level: int, finest: int, origin: Any, finest_width: List[float],
                  planar: bool) -> Tuple[Any, Any]:
    """A block's cell corners in finest cells from `origin` (x fastest, VTK's cell order) and
    the mask of its leaves."""
    dims = [max(n - 1, 1) for n in grid.GetDimensions()]
    ratio = 2 ** (finest - level)
    start = numpy.rint((numpy.array(grid.GetOrigin()) - origin) / numpy.array(finest_width))
    if planar:
        start[2] = 0
    k, j, i = numpy.meshgrid(*(numpy.arange(n) for n in reversed(dims)), indexing="ij")
    cells = numpy.stack([i.ravel(), j.ravel(), k.ravel()], axis=1) * ratio + start
    ghosts = grid.GetCellData().GetArray(_GHOSTS)
    if ghosts is None:
        leaf = numpy.ones(len(cells), dtype=bool)
    else:
        from vtkmodules.util.numpy_support import vtk_to_numpy

        leaf = (vtk_to_numpy(ghosts) & _NOT_LEAF) == 0
    return cells.astype(numpy.int32), leaf


def _cell_columns(grid: Any) -> Dict[str, Any]:
    """A block's cell arrays as one column per component (NAME, or NAME_X/_Y/_Z)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy

    data = grid.GetCellData()
    columns = {}
    for index in range(data.GetNumberOfArrays()):
        array = data.GetArray(index)
        if array is None or array.GetName() in (None, _GHOSTS):
            continue
        values = vtk_to_numpy(array)
        if values.ndim == 1:
            columns[array.GetName()] = values
        elif values.shape[1] == 3:
            for axis, suffix in enumerate(COMPONENT_SUFFIXES):
                columns[array.GetName() + suffix] = values[:, axis]
    return columns


def overlapping_amr(dataset: Any, fields: Optional[List[str]] = None) -> Any:
    """A vtkOverlappingAMR of a Dataset's leaf cells: each level's cells in blocks of
    BLOCK_CELLS^3, the cells of a block that are no leaf of that level hidden (vtkGhostType
    HIDDENCELL, value 0), with the fields (all by default) as float32 cell arrays and the
    source, periodic axes and length unit as FieldData."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import (VTK_XYZ_GRID, vtkAMRBox, vtkOverlappingAMR,
                                               vtkUniformGrid)

    corners, levels = dataset.corners, dataset.levels
    names = dataset.field_names if fields is None else list(fields)
    columns = {name: dataset.field(name) for name in names}
    finest = int(levels.max())
    origin = numpy.array(dataset.origin)
    finest_width = numpy.array(dataset.finest_width)
    per_level = [_level_blocks(corners[levels == level] // 2 ** (finest - level))
                 for level in range(finest + 1)]
    amr = vtkOverlappingAMR()
    amr.Initialize(finest + 1, [len(blocks) for _, blocks in per_level])
    amr.SetOrigin(origin)
    amr.SetGridDescription(VTK_XYZ_GRID)
    for level, (cells, blocks) in enumerate(per_level):
        width = finest_width * 2 ** (finest - level)
        amr.SetSpacing(level, width)
        if level < finest:
            amr.SetRefinementRatio(level, 2)
        selected = numpy.flatnonzero(levels == level)
        for index, (key, members) in enumerate(blocks):
            low = key * BLOCK_CELLS
            grid = vtkUniformGrid()
            grid.SetOrigin(origin + low * width)
            grid.SetSpacing(width)
            grid.SetDimensions(*(BLOCK_CELLS + 1,) * 3)
            local = cells[members] - low
            flat = local[:, 0] + BLOCK_CELLS * (local[:, 1] + BLOCK_CELLS * local[:, 2])
            ghosts = numpy.full(BLOCK_CELLS ** 3, 32, dtype=numpy.uint8)
            ghosts[flat] = 0
            ghost_array = numpy_to_vtk(ghosts, deep=True)
            ghost_array.SetName(_GHOSTS)
            grid.GetCellData().AddArray(ghost_array)
            for name, column in columns.items():
                values = numpy.zeros(BLOCK_CELLS ** 3, dtype=numpy.float32)
                values[flat] = column[selected[members]]
                array = numpy_to_vtk(values, deep=True)
                array.SetName(name)
                grid.GetCellData().AddArray(array)
            box = vtkAMRBox([int(x) for x in low], [int(x) + BLOCK_CELLS - 1 for x in low])
            amr.SetAMRBox(level, index, box)
            amr.SetDataSet(level, index, grid)
    _describe(amr, dataset)
    return amr


def _level_blocks(cells: Any) -> Tuple[Any, List[Tuple[Any, Any]]]:
    """A level's cells (in its own cell widths) and its blocks: (block index, member rows)."""
    keys = cells // BLOCK_CELLS
    unique, inverse = numpy.unique(keys, axis=0, return_inverse=True)
    order = numpy.argsort(inverse.ravel(), kind="stable")
    splits = numpy.cumsum(numpy.bincount(inverse.ravel(), minlength=len(unique)))[:-1]
    return cells, list(zip(unique, numpy.split(order, splits)))


def _describe(amr: Any, dataset: Any) -> None:
    """FieldData: where the cells came from and what the file says of periodicity and units."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkStringArray

    def text(name: str, value: str) -> None:
        array = vtkStringArray()
        array.SetName(name)
        array.InsertNextValue(value)
        amr.GetFieldData().AddArray(array)

    text(SOURCE_ARRAY, dataset.source)
    if dataset.length_unit:
        text(LENGTH_UNIT_ARRAY, dataset.length_unit)
    if dataset.length_unit_cm:
        number = vtkDoubleArray()
        number.SetName(LENGTH_UNIT_CM_ARRAY)
        number.InsertNextValue(dataset.length_unit_cm)
        amr.GetFieldData().AddArray(number)
    if dataset.dimensions == 2:  # the slab's blocks are 3D: say that the data are not
        text(DIMENSIONS_ARRAY, "2")
    if dataset.periodic is not None:
        text(PERIODIC_ARRAY, ",".join(axis for axis, on in zip("xyz", dataset.periodic) if on)
             or "none")


def described(amr: Any) -> Dict[str, Any]:
    """What overlapping_amr() wrote into the FieldData, as from_arrays() keywords."""
    field_data = amr.GetFieldData()
    found: Dict[str, Any] = {}
    for index in range(field_data.GetNumberOfArrays()):
        array = field_data.GetAbstractArray(index)
        name = array.GetName()
        if name == SOURCE_ARRAY:
            found["source"] = array.GetValue(0)
        elif name == LENGTH_UNIT_ARRAY:
            found["length_unit"] = array.GetValue(0)
        elif name == LENGTH_UNIT_CM_ARRAY:
            found["length_unit_cm"] = array.GetValue(0)
        elif name == PERIODIC_ARRAY:
            axes = array.GetValue(0)
            found["periodic"] = tuple(axis in axes.split(",") for axis in "xyz")
        elif name == DIMENSIONS_ARRAY:
            found["dimensions"] = int(array.GetValue(0))
    return found
