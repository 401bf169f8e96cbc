"""VTK's vtkStreamTracer on the block hierarchy of amr_blocks.

`trace_amr`: a vtkOverlappingAMR of one vtkUniformGrid per 8^3 block with the vector as cell
data (constant per cell), covered cells blanked. `trace_image`: the leaf cells painted onto one
vtkImageData at the finest resolution with the vector as point data at the finest cell centres
(trilinear between them).
"""

import time

import numpy as np
import vtk
from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy

VECTOR_NAME = "vector"


def _vector_array(columns):
    array = numpy_to_vtk(np.ascontiguousarray(np.stack(columns, axis=1)), deep=1)
    array.SetName(VECTOR_NAME)
    return array


def to_overlapping_amr(blocks, vector):
    amr = vtk.vtkOverlappingAMR()
    vtk_levels = list(reversed(blocks.levels))  # VTK's level 0 is the coarsest
    amr.Initialize(len(vtk_levels), [len(level.corners) for level in vtk_levels])
    amr.SetOrigin(blocks.to_physical(blocks.lower))
    amr.SetGridDescription(vtk.VTK_XYZ_GRID)
    for vtk_level, level in enumerate(vtk_levels):
        spacing = blocks.spacing * level.width
        amr.SetSpacing(vtk_level, spacing)
        amr.SetRefinementRatio(vtk_level, 2)
        for i, corner in enumerate(level.corners):
            low = [int(v) for v in (corner - blocks.lower) // level.width]
            amr.SetAMRBox(vtk_level, i, vtk.vtkAMRBox(low, [v + 7 for v in low]))
            grid = vtk.vtkUniformGrid()
            grid.SetOrigin(blocks.to_physical(corner))
            grid.SetSpacing(spacing)
            grid.SetDimensions(9, 9, 9)
            # VTK's cell order is x fastest: Fortran order of our [x, y, z] arrays
            grid.GetCellData().SetVectors(
                _vector_array([level.values[name][i].ravel(order="F") for name in vector]))
            amr.SetDataSet(vtk_level, i, grid)
    vtk.vtkAMRUtilities.BlankCells(amr)
    return amr


def finest_cell_count(blocks):
    return int(np.prod(blocks.upper - blocks.lower))


def to_finest_image(blocks, vector):
    shape = tuple(int(n) for n in blocks.upper - blocks.lower)
    painted = np.empty(shape + (3,), dtype=np.float32)
    for level in blocks.levels:
        for i in np.flatnonzero(~level.refined):
            x, y, z = (level.corners[i] - blocks.lower)
            side = level.block_width
            for c, name in enumerate(vector):
                cells = level.values[name][i]
                for axis in range(3):
                    cells = np.repeat(cells, level.width, axis=axis)
                painted[x:x + side, y:y + side, z:z + side, c] = cells
    image = vtk.vtkImageData()
    image.SetDimensions(*shape)
    image.SetOrigin(blocks.to_physical(blocks.lower + 0.5))
    image.SetSpacing(blocks.spacing)
    image.GetPointData().SetVectors(
        _vector_array([painted[..., c].ravel(order="F") for c in range(3)]))
    return image


def polylines(polydata):
    """Seed index -> (n, 3) points of each line, from the cell array SeedIds.

    Reads the connectivity arrays directly: VTK 9.1 crashes building its cell map when a
    line has a single point (a trace that ended at its seed).
    """
    coordinates = vtk_to_numpy(polydata.GetPoints().GetData()).astype(np.float64)
    seed_ids = vtk_to_numpy(polydata.GetCellData().GetArray("SeedIds"))
    cells = polydata.GetLines()
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    connectivity = vtk_to_numpy(cells.GetConnectivityArray())
    return {int(seed): coordinates[connectivity[begin:end]]
            for seed, begin, end in zip(seed_ids, offsets[:-1], offsets[1:])}


def _trace(data, association, seeds, step, steps, repeat):
    points = vtk.vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(seeds, dtype=np.float64), deep=1))
    source = vtk.vtkPolyData()
    source.SetPoints(points)

    tracer = vtk.vtkStreamTracer()
    tracer.SetInputData(data)
    tracer.SetSourceData(source)
    tracer.SetInputArrayToProcess(0, 0, 0, association, VECTOR_NAME)
    tracer.SetIntegratorTypeToRungeKutta4()
    tracer.SetIntegrationDirectionToForward()
    tracer.SetIntegrationStepUnit(vtk.vtkStreamTracer.LENGTH_UNIT)
    tracer.SetInitialIntegrationStep(step)
    tracer.SetMaximumNumberOfSteps(steps)
    tracer.SetMaximumPropagation(1e300)
    tracer.SetTerminalSpeed(1e-12)
    tracer.SetComputeVorticity(False)

    best = float("inf")
    for _ in range(repeat):
        tracer.Modified()
        started = time.perf_counter()
        tracer.Update()
        best = min(best, time.perf_counter() - started)

    lines = polylines(tracer.GetOutput())
    return {
        "seconds": best,
        "steps": sum(len(line) - 1 for line in lines.values()),
        "lines": lines,
    }


def trace_amr(blocks, seeds, step, steps, vector, repeat=1):
    started = time.perf_counter()
    amr = to_overlapping_amr(blocks, vector)
    setup = time.perf_counter() - started
    result = _trace(amr, vtk.vtkDataObject.FIELD_ASSOCIATION_CELLS, seeds, step, steps, repeat)
    return {"method": "VTK StreamTracer AMR", "setup_seconds": setup, **result}


def trace_image(blocks, seeds, step, steps, vector, repeat=1):
    started = time.perf_counter()
    image = to_finest_image(blocks, vector)
    setup = time.perf_counter() - started
    result = _trace(image, vtk.vtkDataObject.FIELD_ASSOCIATION_POINTS, seeds, step, steps, repeat)
    return {"method": "VTK StreamTracer image", "setup_seconds": setup, **result}


def version():
    return vtk.vtkVersion.GetVTKVersion()
