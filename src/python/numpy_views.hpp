#pragma once
// numpy arrays over memory that a Python object owns (no copy): the array keeps `owner` alive.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

namespace amrstream::python {

namespace py = pybind11;

// Views are read-only: the owner's invariants (offsets within the points, cells that do not
// overlap) must hold for the C++ code that reads the same memory later.
inline py::array readOnly(py::array array) {
  py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

// An (n,) view of `data`, with `stride` bytes between elements.
template <typename T>
py::array view(const T* data, std::size_t n, py::handle owner, std::size_t stride = sizeof(T)) {
  return readOnly(py::array_t<T>({py::ssize_t(n)}, {py::ssize_t(stride)}, data, owner));
}

// An (n, 3) view of vectors (glm's vec3 and ivec3 are three packed scalars).
template <typename Vec>
py::array view3(const Vec* data, std::size_t n, py::handle owner) {
  using T = typename Vec::value_type;
  static_assert(sizeof(Vec) == 3 * sizeof(T));
  return readOnly(py::array_t<T>({py::ssize_t(n), py::ssize_t(3)},
                                 {py::ssize_t(sizeof(Vec)), py::ssize_t(sizeof(T))},
                                 reinterpret_cast<const T*>(data), owner));
}

// An (n, 3) float64 array of points, checked: ValueError naming `what` for any other shape.
inline py::array_t<double, py::array::c_style | py::array::forcecast> points3(py::handle input,
                                                                              const char* what) {
  auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(input);
  if (!array || array.ndim() != 2 || array.shape(1) != 3) {
    const std::string shape = array
                                  ? std::string(py::str(py::tuple(py::cast(std::vector<py::ssize_t>(
                                        array.shape(), array.shape() + array.ndim())))))
                                  : std::string("not an array of numbers");
    throw py::value_error(std::string(what) + " must be an (N, 3) array of x, y, z; got " + shape);
  }
  return array;
}

}  // namespace amrstream::python
