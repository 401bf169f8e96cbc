#pragma once
// The parts of the amrstream Python module, each added to the module by one function.

#include <pybind11/pybind11.h>

namespace amrstream::python {

void bindDataset(pybind11::module_& m);
void bindSeeding(pybind11::module_& m);
void bindTracing(pybind11::module_& m);

}  // namespace amrstream::python
