#!/usr/bin/env python3
"""File sizes VTK's own XML writer gets on an amrstream .vtp, against amrstream's.

Reads an uncompressed .vtp (amrstream trace --compression none), writes the same polydata
with vtkXMLPolyDataWriter (appended raw, UInt64 headers) under each compressor and level, and
prints each file's size and its ratio to the uncompressed file. Files given after the first
(amrstream's own compressed outputs of the same trace) are listed beside them.

    vtk_writer_sizes.py UNCOMPRESSED.vtp [OURS.vtp ...]
"""
import os
import sys
import tempfile

import vtk


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    source = sys.argv[1]
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(source)
    reader.Update()
    lines = reader.GetOutput()
    if lines.GetNumberOfPoints() == 0:
        sys.exit(f"{source}: no points read")
    raw = os.path.getsize(source)
    print(f"VTK {vtk.vtkVersion.GetVTKVersion()}, {lines.GetNumberOfPoints():,} points, "
          f"uncompressed {raw:,} bytes")
    print(f"{'writer':<28} {'bytes':>14} {'raw / file':>10}")
    compressors = [("zlib", vtk.vtkZLibDataCompressor, level) for level in (1, 5, 9)]
    compressors += [("lz4", vtk.vtkLZ4DataCompressor, 1), ("lzma", vtk.vtkLZMADataCompressor, 5)]
    with tempfile.TemporaryDirectory() as scratch:
        for name, make, level in compressors:
            writer = vtk.vtkXMLPolyDataWriter()
            writer.SetInputData(lines)
            writer.SetDataModeToAppended()
            writer.EncodeAppendedDataOff()
            writer.SetHeaderTypeToUInt64()
            compressor = make()
            compressor.SetCompressionLevel(level)
            writer.SetCompressor(compressor)
            path = os.path.join(scratch, f"{name}{level}.vtp")
            writer.SetFileName(path)
            if writer.Write() != 1:
                sys.exit(f"{path}: VTK's writer failed")
            size = os.path.getsize(path)
            print(f"{'VTK ' + name + ' level ' + str(level):<28} {size:>14,} {raw / size:>10.3f}")
    for ours in sys.argv[2:]:
        size = os.path.getsize(ours)
        print(f"{'amrstream ' + os.path.basename(ours):<28} {size:>14,} {raw / size:>10.3f}")


if __name__ == "__main__":
    main()
