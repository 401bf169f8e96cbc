#pragma once
// Writes traces as VTK XML PolyData (.vtp), readable by VTK 9 and ParaView, laid out as
// vtkStreamTracer's output: one polyline per line of the TraceSet (with both directions, the
// forward lines of all seeds, then the backward ones, each starting at its seed); point arrays
// the traced vector, the point-data channels, IntegrationTime, with vorticity Vorticity, Rotation
// and AngularVelocity, and Speed; cell arrays ReasonForTermination and SeedIds. <Points> is
// Float32, or Float64 when the traces have precise positions (TraceSet::precisePositions: each
// point written as joinPosition of its two parts).
//
// Periodic domains: positions are wrapped into the domain, so a line that crosses a periodic face
// jumps by the period. By default (PeriodicLines::Split) such a line is written as several
// polylines, split where it wraps, every piece inside the domain, all with the line's SeedIds;
// every piece but the last has ReasonForTermination 8 (AMRSTREAM_REASON_PERIODIC_WRAP). With
// PeriodicLines::Unwrapped, each line is one polyline in unwrapped coordinates (continuing past
// the faces), so lengths and tangents along it are plain differences.
//
// Compressed as VTK does (zlib by default; see vtk_compression.hpp), with optional FieldData
// (provenance).
//
// Every polyline has at least 2 points. VTK rejects shorter lines when it builds its cell map
// ("Invalid cell size for lines") and VTK 9.1 then crashes in vtkPolyData::GetCellPoints, so a
// piece of one point (a line that ends at its seed) is written as a degenerate 2-point line that
// repeats the point with all its point data. readVtpTraces (vtp_reader.hpp) reads such a line
// back as one point: a real integration step always changes IntegrationTime.

#include <cstdint>
#include <filesystem>
#include <vector>

#include "flow/trace_set.hpp"
#include "flow/trace_view.hpp"
#include "output/vtk_compression.hpp"
#include "output/vtk_field_data.hpp"

namespace amrstream::output {

enum class PeriodicLines { Split, Unwrapped };

struct VtpWriteOptions {
  PeriodicLines periodicLines = PeriodicLines::Split;
  Compression compression = Compression::ZLib;
  std::vector<FieldDataArray> fieldData;  // dataset-level arrays, e.g. provenance
};

// What a file holds: its polylines and points (more points than the TraceSet's when pieces of
// one point were written as 2-point lines).
struct VtpCounts {
  std::uint64_t lines = 0;
  std::uint64_t points = 0;
};

// Throws std::invalid_argument before creating the file when the TraceSet is inconsistent or a
// field data array cannot be written; std::runtime_error naming the path when the file cannot be
// written.
VtpCounts writeVtp(const std::filesystem::path& path, const flow::TraceSet& traces,
                   const VtpWriteOptions& options = {});
// The same from any TraceView (e.g. the rounds of a tracer as they were left: no assembled copy);
// only the lines' data are checked beforehand.
VtpCounts writeVtp(const std::filesystem::path& path, const flow::TraceView& traces,
                   const VtpWriteOptions& options = {});

}  // namespace amrstream::output
