#pragma once
// The reconstructed vector and point data on a uniform grid, written as VTK ImageData (.vti).

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "amrstream/field.hpp"
#include "amrstream/log.hpp"
#include "amrstream/trace_job.hpp"

namespace amrstream {

struct ResampleJob {
  DatasetRequest dataset;
  FieldOptions field;
  // Points per axis: one count for the longest axis of the box (the others in proportion), or
  // one per axis.
  std::vector<std::uint64_t> dims{128};
  std::vector<double> box;  // x0,y0,z0,x1,y1,z1 the grid's cells fill; empty: the domain
  std::string compression = "zlib";
  std::string out = "resample.vti";
};

// The checks made before any work: the builtin dataset's size and the grid's counts.
void checkResampleJob(const ResampleJob& job);

// Loads, builds the field, samples the grid and writes it. Says the "input", "structure", "grid"
// and "output" lines; progress: stage "resampling", rows.
void runResampleJob(const ResampleJob& job, const Reporter& reporter = {});

}  // namespace amrstream
