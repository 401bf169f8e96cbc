#pragma once
// What a trace's .vtp records about how it was made (its FieldData): the input and what the file
// says of itself, the vector and point data, the seeding, the stepping, and what ran it.

#include <string>
#include <vector>

#include "amrstream/dataset_info.hpp"
#include "amrstream/tracing.hpp"
#include "flow/trace_options.hpp"
#include "flow/vector_volume.hpp"
#include "output/vtk_field_data.hpp"

namespace amrstream {

struct TraceProvenance {
  std::string source;  // the input's name
  DatasetInfo info;    // what it says of itself
  std::string seeds;   // e.g. "256 from random (seed 1) in a box"
  flow::TraceOptions options;
  TraceReport report;
};

std::vector<output::FieldDataArray> provenanceFields(const TraceProvenance& provenance,
                                                     const flow::VectorVolume& volume);

// What any output made from a dataset records: the amrstream version, the input and its format,
// the vector, the point-data channels, the periodic axes and the interpolant, then the
// simulation time and units where the input has them.
std::vector<output::FieldDataArray> datasetProvenance(const std::string& source,
                                                      const DatasetInfo& info,
                                                      const flow::VectorVolume& volume);

}  // namespace amrstream
