#pragma once
// Where the library reports in Python: its lines printed (verbose), a progress callback called at
// most ten times a second, whose exceptions (KeyboardInterrupt) stop the work.

#include <pybind11/pybind11.h>

#include "amrstream/log.hpp"

namespace amrstream::python {

namespace py = pybind11;

// The library's lines, printed with settings named as keywords; nothing unless verbose.
Log pythonLog(bool verbose);

// progress(done, total), or nothing for None.
StageProgress throttled(py::object callback);

}  // namespace amrstream::python
