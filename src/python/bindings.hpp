#pragma once
// The parts of the amrstream Python module, each added to the module by one function.

#include <pybind11/pybind11.h>

#include <filesystem>
#include <vector>

#include "amrstream/tracing.hpp"

namespace amrstream::python {

void bindDataset(pybind11::module_& m);
void bindSeeding(pybind11::module_& m);
void bindTracing(pybind11::module_& m);
void bindSlicing(pybind11::module_& m);

// Traces as Python holds them (amrstream.Traces): with the files they were traced from, which
// their writers refuse to replace, as the command line refuses an output that is an input.
struct TracesOfFiles : Traces {
  std::vector<std::filesystem::path> inputs;  // absolute
};

// Traces.render, on the class the tracing part makes.
void bindRendering(pybind11::class_<TracesOfFiles>& traces);

}  // namespace amrstream::python
