// The compiled part of the `amrstream` Python package (python/amrstream/__init__.py).

#include "bindings.hpp"
#include "util/input_error.hpp"
#include "vk/context_error.hpp"

PYBIND11_MODULE(_amrstream, m) {
  namespace py = pybind11;
  m.doc() = "amrstream: streamlines through AMR vector fields on the CPU and on any Vulkan GPU";
  m.attr("__version__") = AMRSTREAM_VERSION;
  static py::exception<amrstream::InputError> inputError(m, "InputError", PyExc_ValueError);
  static py::exception<amrstream::vk::ContextError> backendError(m, "BackendError",
                                                                 PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const amrstream::InputError& e) {
      PyErr_SetString(inputError.ptr(), e.what());
    } catch (const amrstream::vk::ContextError& e) {
      PyErr_SetString(backendError.ptr(), e.what());
    }
  });
  amrstream::python::bindDataset(m);
  amrstream::python::bindSeeding(m);
  amrstream::python::bindTracing(m);
}
