#pragma once
// What the public handles hold (include/amrstream: Dataset, Field), for the library's own code
// and the front ends built with it (the Python module, the viewer).

#include <memory>
#include <optional>
#include <string>

#include "amrstream/dataset.hpp"
#include "amrstream/field.hpp"
#include "bricks/amr_field.hpp"
#include "flow/vector_selection.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream {

struct Dataset::Impl {
  bricks::AmrField cells;
};

struct Field::Impl {
  flow::VectorVolume volume;
  flow::VectorChannels vector;
  std::string source;  // the dataset's name
  DatasetInfo info;    // what the dataset says of itself
  FieldBuildTimes times;
  std::optional<Dataset> dataset;  // when kept
};

// The cells of a dataset.
inline const bricks::AmrField& cellsOf(const Dataset& dataset) { return dataset.impl().cells; }
// A dataset of these cells.
Dataset datasetOf(bricks::AmrField cells);

// The field's volume, which tracing reads (and a GPU trace may release the host values of).
inline flow::VectorVolume& volumeOf(const Field& field) { return field.impl().volume; }
// A field of a volume built from `vector` of a dataset named `source`.
Field fieldOf(flow::VectorVolume volume, flow::VectorChannels vector, std::string source,
              DatasetInfo info, const flow::VolumeBuildTimes& times,
              std::optional<Dataset> dataset = std::nullopt);

}  // namespace amrstream
