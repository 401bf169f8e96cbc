#pragma once
// Writes traces as VTK XML PolyData (.vtp), readable by VTK 9 and ParaView: one polyline per
// seed; point arrays IntegrationTime, Speed and the traced vector; cell arrays SeedIds and
// ReasonForTermination; optional FieldData. Compressed as VTK does (zlib by default; see
// vtk_compression.hpp).
//
// Every polyline has at least 2 points. VTK rejects shorter lines when it builds its cell map
// ("Invalid cell size for lines") and VTK 9.1 then crashes in vtkPolyData::GetCellPoints, so a
// trace that ends at its seed (1 point) is written as a degenerate 2-point line that repeats the
// point with all its point data (same position, IntegrationTime and vector). The file then has
// one point more than the TraceSet for each such trace, and still one cell per trace, so the
// cell arrays stay aligned with the seeds. readVtpTraces (vtp_reader.hpp) reads such a line back
// as one point: a real integration step always advances IntegrationTime.
//
// A trace without points (TraceSet promises at least the seed; only the viewer's export of
// progressive traces before their first step has them) has nothing to draw and gets no line:
// cells then skip it, and the cell array SeedIds says which seed each line traces.

#include <cstdint>
#include <filesystem>
#include <vector>

#include "../flow/trace_set.hpp"
#include "output/vtk_compression.hpp"
#include "output/vtk_field_data.hpp"

namespace amrstream::output {

// What a file holds: its polylines and points (more points than the TraceSet's when traces of
// one point were written as 2-point lines).
struct VtpCounts {
  std::uint64_t lines = 0;
  std::uint64_t points = 0;
};

struct VtpWriteOptions {
  Compression compression = Compression::ZLib;
  std::vector<FieldDataArray> fieldData;  // dataset-level arrays, e.g. provenance
};

// Throws std::invalid_argument before creating the file when the TraceSet is inconsistent or a
// field data array cannot be written; std::runtime_error naming the path when the file cannot be
// written.
VtpCounts writeVtp(const std::filesystem::path& path, const flow::TraceSet& traces,
                   const VtpWriteOptions& options = {});

}  // namespace amrstream::output
