#!/usr/bin/python3
"""Checks that VTK reads exactly the arrays write_sample_arrays wrote, in every compression.

Run with Debian's /usr/bin/python3 (python3-paraview and numpy):

  check_arrays_with_vtk.py DIR

For DIR/arrays_none.vtp, arrays_zlib.vtp and arrays_lz4.vtp: the file must declare the expected
compressor, vtkXMLPolyDataReader must report no error or warning, and every array (FieldData
strings and numbers, point and cell data, Points, the lines' connectivity and offsets) must have
the type and the values of DIR/expected/NAME.bin, bit for bit. Exit 1 with one line per problem.
"""

import os
import sys

try:
    import numpy
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError as error:
    sys.exit(f"check_arrays_with_vtk: cannot import vtk and numpy ({error}); "
             "run scripts/install_deps.sh (python3-paraview) and use /usr/bin/python3")

from check_vtp_with_vtk import Messages

COMPRESSORS = {"none": None, "zlib": "vtkZLibDataCompressor", "lz4": "vtkLZ4DataCompressor"}
# Array name: (where it is, the numpy type its expected file holds).
NUMERIC = {
    "StepSizes": ("field", numpy.float64),
    "Counts": ("field", numpy.int64),
    "Temperature": ("point", numpy.float64),
    "Flags": ("point", numpy.int32),
    "LineIds": ("cell", numpy.int64),
    "Points": ("points", numpy.float32),
    "connectivity": ("connectivity", numpy.int64),
    "offsets": ("offsets", numpy.int64),
}
STRINGS = ["Input", "Names"]


def declared_compressor(path):
    with open(path, "rb") as file:
        head = file.read(4096)
    start = head.find(b'compressor="')
    if start < 0:
        return None
    start += len('compressor="')
    return head[start:head.index(b'"', start)].decode()


def vtk_array(output, where, name):
    if where == "field":
        return output.GetFieldData().GetAbstractArray(name)
    if where == "point":
        return output.GetPointData().GetAbstractArray(name)
    if where == "cell":
        return output.GetCellData().GetAbstractArray(name)
    if where == "points":
        return output.GetPoints().GetData() if output.GetPoints() else None
    lines = output.GetLines()
    return lines.GetConnectivityArray() if where == "connectivity" else lines.GetOffsetsArray()


def check_file(path, compressor, expected_dir):
    problems = []
    if declared_compressor(path) != compressor:
        problems.append(f"declares compressor {declared_compressor(path)}, expected {compressor}")
    messages = Messages()
    reader = vtk.vtkXMLPolyDataReader()
    messages.observe(reader)
    reader.SetFileName(path)
    reader.Update()
    problems += [f"VTK reported: {m}" for m in messages.all()]
    output = reader.GetOutput()

    for name, (where, dtype) in NUMERIC.items():
        expected = numpy.fromfile(os.path.join(expected_dir, name + ".bin"), dtype=dtype)
        array = vtk_array(output, where, name)
        if array is None:
            problems.append(f"{name}: missing")
            continue
        values = vtk_to_numpy(array).reshape(-1)
        if where == "offsets":
            # VTK's cell array stores the leading 0 that VTK XML leaves out.
            if values.size == 0 or values[0] != 0:
                problems.append(f"{name}: does not start at 0")
            values = values[1:]
        if values.dtype != expected.dtype:
            problems.append(f"{name}: type {values.dtype}, expected {expected.dtype}")
        elif values.shape != expected.shape or values.tobytes() != expected.tobytes():
            problems.append(f"{name}: {values.size} values differ from the {expected.size} written")

    for name in STRINGS:
        with open(os.path.join(expected_dir, name + ".bin"), "rb") as file:
            expected = [s.decode("utf-8") for s in file.read().split(b"\0")[:-1]]
        array = output.GetFieldData().GetAbstractArray(name)
        if array is None or array.GetClassName() != "vtkStringArray":
            problems.append(f"{name}: no string array")
            continue
        values = [array.GetValue(i) for i in range(array.GetNumberOfValues())]
        if values != expected:
            problems.append(f"{name}: {values!r}, expected {expected!r}")
    return problems


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    directory = sys.argv[1]
    failed = False
    for name, compressor in COMPRESSORS.items():
        path = os.path.join(directory, f"arrays_{name}.vtp")
        problems = check_file(path, compressor, os.path.join(directory, "expected"))
        for problem in problems:
            print(f"check_arrays_with_vtk: {path}: {problem}")
        if not problems:
            print(f"check_arrays_with_vtk: {path}: OK (VTK {vtk.vtkVersion.GetVTKVersion()})")
        failed = failed or bool(problems)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
