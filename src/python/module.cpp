// The compiled part of the `amrstream` Python package (python/amrstream/__init__.py).

#include "amrstream/error.hpp"
#include "amrstream/settings.hpp"
#include "amrstream/version.hpp"
#include "bindings.hpp"
#include "vk/context_error.hpp"

PYBIND11_MODULE(_amrstream, m) {
  namespace py = pybind11;
  m.doc() = "amrstream: streamlines through AMR vector fields on the CPU and on any Vulkan GPU";
  m.attr("__version__") = AMRSTREAM_VERSION;
  static py::exception<amrstream::InputError> inputError(m, "InputError", PyExc_ValueError);
  static py::exception<amrstream::vk::ContextError> backendError(m, "BackendError",
                                                                 PyExc_RuntimeError);
  inputError.doc() =
      "Bad input (a ValueError): a file, a dataset or a keyword's value that cannot be used. The "
      "message names the file or keyword and says what is wrong, as the command line's does.";
  backendError.doc() =
      "A Vulkan device lacks what the backend asked for needs (a RuntimeError); `amrstream "
      "devices` lists what each device supports.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const amrstream::InputError& e) {
      // Settings by their keywords, which are their neutral names.
      const std::string message = e.spelled(amrstream::plainName);
      if (e.systemError() != 0) {
        // OSError(errno, message) is the subclass for errno (FileNotFoundError, ...), shown as
        // "[Errno 2] " and the command line's message.
        py::object error = py::reinterpret_steal<py::object>(
            PyObject_CallFunction(PyExc_OSError, "is", e.systemError(), message.c_str()));
        PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(error.ptr())), error.ptr());
        return;
      }
      PyErr_SetString(inputError.ptr(), message.c_str());
    } catch (const amrstream::vk::ContextError& e) {
      PyErr_SetString(backendError.ptr(), e.what());
    }
  });
  amrstream::python::bindDataset(m);
  amrstream::python::bindSeeding(m);
  amrstream::python::bindTracing(m);
  amrstream::python::bindSlicing(m);
}
