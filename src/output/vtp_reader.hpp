#pragma once
// Reads traces back from VTK XML PolyData (.vtp): the files vtp_writer.hpp writes, and the same
// layout written by other tools (VTK's vtkXMLPolyDataWriter, ParaView), uncompressed or
// compressed with zlib or LZ4.
//
// Mapping (one polyline of the file's <Lines> = one line of the TraceSet, in file order):
// - positions from <Points>, gathered through the lines' connectivity; Float64 points are read
//   as precise positions (precisePositions, positions and positionsLow: splitPosition of each);
// - times from the point array IntegrationTime (1 component), else 0; a line with a negative time
//   is a backward line (direction -1);
// - vectors from the point array that <PointData Vectors="..."> names (3 components), else the
//   first 3-component Float32/Float64 point array, else zero; vectorName is that array's name
//   ("" when there is none);
// - reasons and seed ids from the cell arrays ReasonForTermination and SeedIds, else 0 and the
//   line's index; steps are points - 1. Other point arrays (channels, vorticity) are not read.
// Vertex, strip and polygon cells are ignored; a file without lines gives an empty TraceSet, and
// an empty line (which VTK itself refuses) a line of 0 points, so lines and cells stay one to one.
// A periodic line that the writer split at its wraps comes back as one line per piece.
//
// A 2-point line whose two points have the same position and IntegrationTime is read as a
// 1-point trace: that is how the writer stores a trace that ends at its seed (an integration step
// always advances the time, so such a line never comes from a real step). Without
// IntegrationTime, the same position alone decides.
//
// Formats: see vtk_xml_file.hpp (appended raw or base64, inline binary, ascii; UInt32/UInt64
// headers; either byte order; any numeric type; zlib, LZ4 or none). Only single-piece files.

#include <filesystem>

#include "flow/trace_set.hpp"
#include "output/vtk_field_data.hpp"

namespace amrstream::output {

// Throws amrstream::InputError naming `path` and the problem on a missing or unreadable file,
// one that is not a regular file (a FIFO, a device), changes while it is read, is not VTK XML
// PolyData, has several pieces, is LZMA-compressed, corrupt or truncated, has an array offset
// outside the appended data, connectivity ids out of range, decreasing offsets, non-finite
// positions, or arrays or traces that would not fit in this machine's memory.
flow::TraceSet readVtpTraces(const std::filesystem::path& path);

struct VtpContents {
  flow::TraceSet lines;
  // The file's <FieldData> arrays of one component: strings, Float32/Float64 as doubles, the
  // integer types as Int64; others are skipped. Streaklines (a "streaklines" Output string, as
  // `amrstream pathlines --release-every` writes) give lines.timesAreAges.
  std::vector<FieldDataArray> fieldData;
};

// The traces and the provenance; errors as readVtpTraces.
VtpContents readVtpFile(const std::filesystem::path& path);

}  // namespace amrstream::output
