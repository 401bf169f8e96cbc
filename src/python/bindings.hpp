#pragma once
// The parts of the amrstream Python module, each added to the module by one function.

#include <pybind11/pybind11.h>

#include "amrstream/tracing.hpp"

namespace amrstream::python {

void bindDataset(pybind11::module_& m);
void bindSeeding(pybind11::module_& m);
void bindTracing(pybind11::module_& m);

// Traces.render, on the class the tracing part makes.
void bindRendering(pybind11::class_<Traces>& traces);

}  // namespace amrstream::python
