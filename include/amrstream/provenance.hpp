#pragma once
// What a trace's .vtp records about how it was made (its FieldData): the input and what the file
// says of itself, the vector and point data, the seeding, the stepping, and what ran it.

#include <vector>

#include "output/vtk_field_data.hpp"
#include "trace_job.hpp"

namespace amrstream::cli {

std::vector<output::FieldDataArray> traceProvenance(const TraceJobOptions& options,
                                                    const PreparedInput& input);

}  // namespace amrstream::cli
