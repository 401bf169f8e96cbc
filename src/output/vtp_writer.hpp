#pragma once
// Writes traces as VTK XML PolyData (.vtp), readable by VTK 9 and ParaView: one polyline per
// seed; point arrays IntegrationTime, Speed and the traced vector; cell arrays SeedIds and
// ReasonForTermination.

#include <filesystem>

#include "../flow/trace_set.hpp"

namespace amrstream::output {

// Throws std::runtime_error naming the path when the file cannot be written.
void writeVtp(const std::filesystem::path& path, const flow::TraceSet& traces);

}  // namespace amrstream::output
