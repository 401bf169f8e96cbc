#pragma once
// What Traces hold (include/amrstream/tracing.hpp), for the library and the Python module.

#include <optional>
#include <vector>

#include "amrstream/field.hpp"
#include "amrstream/tracing.hpp"
#include "flow/trace_options.hpp"
#include "flow/trace_set.hpp"
#include "output/vtk_field_data.hpp"

namespace amrstream {

struct Traces::Impl {
  flow::TraceSet lines;
  std::vector<output::FieldDataArray> provenance;  // the .vtp's FieldData
  TraceReport report;
  std::optional<Field> field;              // the field they were traced in, where one was
  std::optional<flow::StepMode> stepMode;  // how they were traced, where it is known
};

inline Traces tracesOf(Traces::Impl impl) {
  return Traces(std::make_shared<const Traces::Impl>(std::move(impl)));
}

// The lines of traces.
inline const flow::TraceSet& linesOf(const Traces& traces) { return traces.impl().lines; }

}  // namespace amrstream
