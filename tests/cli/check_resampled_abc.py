"""Checks `amrstream resample builtin:abc` with VTK: vtkXMLImageDataReader opens the .vti; the
grid fills the unit cube with points at the centres of its cells; every point is valid; and the
vector equals the analytic ABC flow (synth/abc_field.hpp) within the reconstruction's error.

Usage: check_resampled_abc.py FILE.vti NX NY NZ TOLERANCE
"""
import math
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def abc(x, y, z):
    a, b, c = math.sqrt(3.0), math.sqrt(2.0), 1.0
    X, Y, Z = (2.0 * math.pi * t for t in (x, y, z))
    return np.stack([a * np.sin(Z) + c * np.cos(Y), b * np.sin(X) + a * np.cos(Z),
                     c * np.sin(Y) + b * np.cos(X)], axis=-1)


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


def main():
    path, dims, tolerance = sys.argv[1], tuple(int(n) for n in sys.argv[2:5]), float(sys.argv[5])
    reader = vtk.vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    if grid.GetDimensions() != dims:
        fail(f"dimensions {grid.GetDimensions()}, expected {dims}")
    spacing = np.array(grid.GetSpacing())
    origin = np.array(grid.GetOrigin())
    if not np.allclose(spacing, 1.0 / np.array(dims), rtol=1e-12):
        fail(f"spacing {spacing} does not split the unit cube into {dims} cells")
    if not np.allclose(origin, 0.5 * spacing, rtol=1e-12):
        fail(f"origin {origin} is not the first cell's centre")
    data = grid.GetPointData()
    if data.GetVectors() is None or data.GetVectors().GetName() != "vel":
        fail("the point data's Vectors are not 'vel'")
    mask = vtk_to_numpy(data.GetArray("vtkValidPointMask"))
    if mask.min() != 1:
        fail(f"{int((mask == 0).sum())} points are marked invalid")
    vectors = vtk_to_numpy(data.GetArray("vel")).astype(np.float64)
    k, j, i = np.meshgrid(*(np.arange(n) for n in dims[::-1]), indexing="ij")
    points = [origin[a] + spacing[a] * index.ravel() for a, index in enumerate((i, j, k))]
    error = np.linalg.norm(vectors - abc(*points), axis=1)
    print(f"{vectors.shape[0]} points, largest error {error.max():.4g}, mean {error.mean():.4g}")
    if error.max() > tolerance:
        fail(f"largest error {error.max():.4g} above {tolerance}")


main()
