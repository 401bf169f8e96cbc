"""`amrstream slice --vtp` writes the field lines as PolyData that VTK opens: as many polylines as
the summary's `lines` line says, every point on the plane, the vector at each point the solid-body
rotation of builtin:rotation (which the linear interpolant reconstructs exactly across levels),
ArcLength the distance along each line; bad line options are refused before any file is written.
Usage: slice_lines_open_in_vtk.py AMRSTREAM WORK_DIR"""
import math
import os
import re
import subprocess
import sys

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

amrstream, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
vtp, png = os.path.join(work, "lines.vtp"), os.path.join(work, "lines.png")
for path in (vtp, png):
    if os.path.exists(path):
        os.remove(path)
run = subprocess.run([amrstream, "slice", "builtin:rotation", "--interpolant", "linear",
                      "--point-data", "velx", "--point", "0.5,0.5,0.4", "--width", "160", "--line-colour-by", "magnitude",
                      "--line-width-by", "velx", "--vtp", vtp, "--out", png],
                     capture_output=True, text=True, check=True)
print(run.stdout)
count = int(re.search(r"^lines\s+(\d+) evenly spaced", run.stdout, re.M).group(1))

reader = vtkXMLPolyDataReader()
reader.SetFileName(vtp)
reader.Update()
data = reader.GetOutput()
assert data.GetNumberOfLines() == count, (data.GetNumberOfLines(), count)
points = vtk_to_numpy(data.GetPoints().GetData()).astype(float)
arrays = data.GetPointData()
names = [arrays.GetArrayName(i) for i in range(arrays.GetNumberOfArrays())]
assert names == ["vel", "ArcLength", "velx"], names
assert arrays.GetVectors().GetName() == "vel" and arrays.GetScalars().GetName() == "ArcLength"
vel = vtk_to_numpy(arrays.GetArray("vel")).astype(float)
arc = vtk_to_numpy(arrays.GetArray("ArcLength")).astype(float)
velx = vtk_to_numpy(arrays.GetArray("velx")).astype(float)
assert abs(points[:, 2] - 0.4).max() < 1e-6, "points off the plane z = 0.4"
omega = 2.0 * math.pi
checked = 0
for p, v, vx in zip(points, vel, velx):
    if math.isnan(v[0]):
        continue
    expected = (-omega * (p[1] - 0.5), omega * (p[0] - 0.5), 0.0)
    assert max(abs(a - b) for a, b in zip(v, expected)) < 1e-4, (p, v, expected)
    assert abs(vx - expected[0]) < 1e-4, (p, vx, expected)
    checked += 1
assert checked > 0.9 * len(points), (checked, len(points))
offsets = vtk_to_numpy(data.GetLines().GetOffsetsArray())
for begin, end in zip(offsets[:-1], offsets[1:]):
    assert end - begin >= 2
    steps = [math.dist(points[k - 1, :2], points[k, :2]) for k in range(begin + 1, end)]
    assert arc[begin] == 0.0
    assert abs(arc[end - 1] - sum(steps)) < 1e-5 * max(1.0, sum(steps))

for bad, words in ((["--line-colour-by", "nosuch"], "--line-colour-by: 'nosuch' is not a channel"),
                   (["--line-colour-map", "nosuch"], "--line-colour-map"),
                   (["--no-lines"], "--vtp: there are no field lines")):
    out = os.path.join(work, "bad.vtp")
    refused = subprocess.run([amrstream, "slice", "builtin:rotation", "--width", "32", "--vtp", out,
                              "--out", os.path.join(work, "bad.png")] + bad,
                             capture_output=True, text=True)
    assert refused.returncode != 0 and words in refused.stderr, (bad, refused.stderr)
    assert not os.path.exists(out), f"{bad} left {out}"
print(f"{count} lines, {len(points)} points, {checked} vectors equal the rotation")
