#!/usr/bin/python3
"""Writes one PolyData with VTK's own vtkXMLPolyDataWriter in every compressed layout it has.

Run with Debian's /usr/bin/python3 (python3-vtk9 and numpy):

  write_with_vtk.py OUT_DIR

The data: 30000 points on smooth curves (Points spans 11 blocks of 32768 bytes), point arrays
Pressure (Float64) and Velocity (Float32 x 3), cell array Ids (Int32), lines of 2 to 40 points,
and a FieldData array StepSizes (Float64). Files, appended data unless said otherwise:

  default.vtp             VTK's defaults: zlib, base64, header_type UInt32
  zlib_raw.vtp            zlib, raw
  zlib_raw_uint64.vtp     zlib, raw, UInt64 headers
  zlib_binary.vtp         zlib, inline base64 (format="binary")
  zlib_small_blocks.vtp   zlib, raw, blocks of 1000 bytes
  lz4_raw.vtp             LZ4, raw
  lz4_base64_big_endian.vtp  LZ4, base64, UInt64 headers, byte_order BigEndian
  none_raw.vtp            uncompressed, raw
  lzma_raw.vtp            LZMA (amrstream must refuse it, naming the compressors it reads)

For each readable file, VTK reads it back and OUT_DIR/expected/FILE/ARRAY.bin gets the values
VTK holds (float64 for floating-point arrays, int64 for integer ones, little endian; the lines'
offsets without VTK's leading 0). OUT_DIR/manifest.txt lists one array per line:
"FILE SECTION NAME COMPONENTS float|int", and "FILE refused" for the LZMA file.
"""

import os
import sys

try:
    import numpy
    import vtk
    from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy
except ImportError as error:
    sys.exit(f"write_with_vtk: cannot import vtk and numpy ({error}); "
             "run scripts/install_deps.sh (python3-vtk9) and use /usr/bin/python3")

POINTS = 30000


def named(array, name):
    array.SetName(name)
    return array


def sample():
    t = numpy.arange(POINTS, dtype=numpy.float64) * 0.01
    data = vtk.vtkPolyData()
    points = vtk.vtkPoints()
    xyz = numpy.stack([10 * numpy.cos(t), 10 * numpy.sin(1.3 * t), 0.1 * t], axis=1)
    points.SetData(numpy_to_vtk(xyz.astype(numpy.float32), deep=1))
    data.SetPoints(points)
    lines = vtk.vtkCellArray()
    begin, length = 0, 2
    while begin + 2 <= POINTS:
        end = min(POINTS, begin + length)
        lines.InsertNextCell(end - begin, list(range(begin, end)))
        begin, length = end, 2 + (length * 5) % 39
    data.SetLines(lines)
    pressure = 1e5 + 300 * numpy.sin(0.3 * t) + 1e-7 * numpy.arange(POINTS)
    data.GetPointData().AddArray(named(numpy_to_vtk(pressure, deep=1), "Pressure"))
    velocity = numpy.stack([numpy.sin(t), numpy.cos(t), t % 1.0], axis=1).astype(numpy.float32)
    data.GetPointData().AddArray(named(numpy_to_vtk(velocity, deep=1), "Velocity"))
    ids = (numpy.arange(lines.GetNumberOfCells(), dtype=numpy.int32) * 7919) - 1000
    data.GetCellData().AddArray(named(numpy_to_vtk(ids, deep=1), "Ids"))
    steps = numpy.array([0.25, 1e300, -0.0, 5e-324], dtype=numpy.float64)
    data.GetFieldData().AddArray(named(numpy_to_vtk(steps, deep=1), "StepSizes"))
    return data


LAYOUTS = {
    "default.vtp": {},
    "zlib_raw.vtp": {"encode": False},
    "zlib_raw_uint64.vtp": {"encode": False, "header64": True},
    "zlib_binary.vtp": {"mode": "binary"},
    "zlib_small_blocks.vtp": {"encode": False, "block": 1000},
    "lz4_raw.vtp": {"encode": False, "compressor": "LZ4"},
    "lz4_base64_big_endian.vtp": {"compressor": "LZ4", "header64": True, "big_endian": True},
    "none_raw.vtp": {"encode": False, "compressor": "None"},
    "lzma_raw.vtp": {"encode": False, "compressor": "LZMA"},
}


def write(data, path, mode="appended", encode=True, header64=False, big_endian=False,
          compressor="ZLib", block=None):
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetInputData(data)
    writer.SetFileName(path)
    if mode == "binary":
        writer.SetDataModeToBinary()
    writer.SetEncodeAppendedData(encode)
    if header64:
        writer.SetHeaderTypeToUInt64()
    if big_endian:
        writer.SetByteOrderToBigEndian()
    getattr(writer, f"SetCompressorTypeTo{compressor}")()
    if block:
        writer.SetBlockSize(block)
    if writer.Write() != 1:
        sys.exit(f"write_with_vtk: vtkXMLPolyDataWriter failed on {path}")


def arrays_of(output):
    """(section, name, vtk array) of every array the C++ reader is asked for."""
    point_data, cell_data = output.GetPointData(), output.GetCellData()
    yield "FieldData", "StepSizes", output.GetFieldData().GetArray("StepSizes")
    yield "PointData", "Pressure", point_data.GetArray("Pressure")
    yield "PointData", "Velocity", point_data.GetArray("Velocity")
    yield "CellData", "Ids", cell_data.GetArray("Ids")
    yield "Points", "Points", output.GetPoints().GetData()
    yield "Lines", "connectivity", output.GetLines().GetConnectivityArray()
    yield "Lines", "offsets", output.GetLines().GetOffsetsArray()


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out_dir = sys.argv[1]
    data = sample()
    manifest = []
    for name, options in LAYOUTS.items():
        path = os.path.join(out_dir, name)
        os.makedirs(out_dir, exist_ok=True)
        write(data, path, **options)
        if options.get("compressor") == "LZMA":
            manifest.append(f"{name} refused")
            continue
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(path)
        reader.Update()
        if reader.GetErrorCode() != 0:
            sys.exit(f"write_with_vtk: VTK cannot read its own {path}")
        expected_dir = os.path.join(out_dir, "expected", name)
        os.makedirs(expected_dir, exist_ok=True)
        for section, array_name, array in arrays_of(reader.GetOutput()):
            values = vtk_to_numpy(array).reshape(-1)
            if array_name == "offsets":
                values = values[1:]  # VTK XML stores no leading 0
            kind = "float" if values.dtype.kind == "f" else "int"
            values.astype("<f8" if kind == "float" else "<i8").tofile(
                os.path.join(expected_dir, array_name + ".bin"))
            manifest.append(
                f"{name} {section} {array_name} {array.GetNumberOfComponents()} {kind}")
    with open(os.path.join(out_dir, "manifest.txt"), "w") as file:
        file.write("\n".join(manifest) + "\n")
    print(f"write_with_vtk: VTK {vtk.vtkVersion.GetVTKVersion()} wrote {len(LAYOUTS)} files "
          f"in {out_dir}")


if __name__ == "__main__":
    main()
