#!/usr/bin/python3
"""Rewrites a .vtp with VTK's own vtkXMLPolyDataWriter in every layout readVtpTraces reads.

Run with Debian's /usr/bin/python3 (python3-paraview):

  rewrite_with_vtk.py IN.vtp OUT_DIR

Reads IN.vtp with vtkXMLPolyDataReader and writes, uncompressed unless said otherwise:
  appended_raw.vtp          appended raw, header_type UInt64
  appended_raw_uint32.vtp   appended raw, header_type UInt32
  appended_base64.vtp       appended, base64 encoded
  binary.vtp                inline base64 (format="binary")
  ascii.vtp                 format="ascii"
  big_endian.vtp            appended raw, byte_order BigEndian
  float64_int32.vtp         appended raw; Points and point arrays Float64, Lines Int32
  zlib_default.vtp          VTK's defaults: zlib, appended base64, header_type UInt32
  zlib_raw.vtp              zlib, appended raw
  zlib_binary.vtp           zlib, inline base64
  lz4_raw.vtp               LZ4, appended raw
  lzma.vtp                  LZMA, appended raw (the reader must refuse it)
"""

import os
import sys

try:
    import vtk
except ImportError as error:
    sys.exit(f"rewrite_with_vtk: cannot import vtk ({error}); "
             "run scripts/install_deps.sh (python3-paraview) and use /usr/bin/python3")


def as_double(array):
    copy = vtk.vtkDoubleArray()
    copy.DeepCopy(array)
    copy.SetName(array.GetName())
    return copy


def widened(source):
    """A copy with Float64 points and point arrays and 32-bit line ids."""
    data = vtk.vtkPolyData()
    data.DeepCopy(source)
    points = vtk.vtkPoints()
    points.SetData(as_double(data.GetPoints().GetData()))
    data.SetPoints(points)
    point_data = data.GetPointData()
    vectors = point_data.GetVectors().GetName()
    for name in [point_data.GetArrayName(i) for i in range(point_data.GetNumberOfArrays())]:
        point_data.AddArray(as_double(point_data.GetArray(name)))  # replaces the array of that name
    point_data.SetActiveVectors(vectors)
    if not data.GetLines().ConvertTo32BitStorage():
        sys.exit("rewrite_with_vtk: cannot convert the lines to 32-bit ids")
    return data


def write(data, path, mode="appended", encode=False, header64=True, big_endian=False,
          compressor="None"):
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetInputData(data)
    writer.SetFileName(path)
    {"appended": writer.SetDataModeToAppended, "binary": writer.SetDataModeToBinary,
     "ascii": writer.SetDataModeToAscii}[mode]()
    writer.SetEncodeAppendedData(encode)
    (writer.SetHeaderTypeToUInt64 if header64 else writer.SetHeaderTypeToUInt32)()
    (writer.SetByteOrderToBigEndian if big_endian else writer.SetByteOrderToLittleEndian)()
    getattr(writer, f"SetCompressorTypeTo{compressor}")()
    if writer.Write() != 1:
        sys.exit(f"rewrite_with_vtk: vtkXMLPolyDataWriter failed on {path}")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    source, out_dir = sys.argv[1:]
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(source)
    reader.Update()
    if reader.GetErrorCode() != 0:
        sys.exit(f"rewrite_with_vtk: cannot read {source}")
    data = reader.GetOutput()
    os.makedirs(out_dir, exist_ok=True)
    out = lambda name: os.path.join(out_dir, name)
    write(data, out("appended_raw.vtp"))
    write(data, out("appended_raw_uint32.vtp"), header64=False)
    write(data, out("appended_base64.vtp"), encode=True)
    write(data, out("binary.vtp"), mode="binary")
    write(data, out("ascii.vtp"), mode="ascii")
    write(data, out("big_endian.vtp"), big_endian=True)
    write(widened(data), out("float64_int32.vtp"))
    write(data, out("zlib_default.vtp"), encode=True, header64=False, compressor="ZLib")
    write(data, out("zlib_raw.vtp"), compressor="ZLib")
    write(data, out("zlib_binary.vtp"), mode="binary", compressor="ZLib")
    write(data, out("lz4_raw.vtp"), compressor="LZ4")
    write(data, out("lzma.vtp"), compressor="LZMA")
    print(f"rewrite_with_vtk: VTK {vtk.vtkVersion.GetVTKVersion()} wrote 12 files in {out_dir}")


if __name__ == "__main__":
    main()
