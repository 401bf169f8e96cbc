#pragma once
// numpy arrays over memory that a Python object owns (no copy): the array keeps `owner` alive.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstddef>
#include <glm/glm.hpp>
#include <string>
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

// What an array holds, for messages about arrays whose items are no real numbers.
inline std::string itemsOf(const py::array& array) {
  switch (array.dtype().kind()) {
    case 'U':
    case 'S':
      return "text";
    case 'c':
      return "complex numbers";
    case 'b':
      return "bools";
    case 'O':
      return "Python objects";
    default:
      return std::string(py::str(array.dtype()));
  }
}

// Whether an array's items are real numbers: integers or floats (not bools, complex numbers, text
// or objects, which numpy would convert to numbers or refuse only while converting).
inline bool holdsRealNumbers(const py::array& array) {
  const char kind = array.dtype().kind();
  return kind == 'i' || kind == 'u' || kind == 'f';
}

// `input` as an (N, 3) array of real numbers, as given: an array is not copied, so that its rows
// can be counted before any is converted. ValueError naming `what` for anything else.
inline py::array pointsArray(py::handle input, const char* what) {
  const py::array array = py::array::ensure(input);
  std::string got;
  if (!array)
    got = "not an array of numbers";
  else if (array.ndim() != 2 || array.shape(1) != 3)
    got = py::str(
        py::tuple(py::cast(std::vector<py::ssize_t>(array.shape(), array.shape() + array.ndim()))));
  else if (!holdsRealNumbers(array))
    got = "an array of " + itemsOf(array) + ", not an array of numbers";
  if (!got.empty())
    throw py::value_error(std::string(what) + " must be an (N, 3) array of x, y, z; got " + got);
  return array;
}

}  // namespace amrstream::python
