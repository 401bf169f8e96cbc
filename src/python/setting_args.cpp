#include "setting_args.hpp"

#include <fmt/format.h>

#include <cmath>

#include "amrstream/error.hpp"

namespace amrstream::python {

namespace {

std::string typeName(py::handle value) { return py::str(py::type::of(value).attr("__name__")); }

// numpy's kind of a numpy scalar or 0-d array ('b' bool, 'i' and 'u' integers, 'f' floats, 'c'
// complex, ...); 0 for anything else.
char numpyKind(py::handle value) {
  if (!py::hasattr(value, "dtype") || !py::hasattr(value, "ndim")) return 0;
  if (value.attr("ndim").cast<int>() != 0) return 0;
  return py::str(value.attr("dtype").attr("kind")).cast<std::string>().front();
}

bool isWholeNumber(py::handle value) {
  if (const char kind = numpyKind(value)) return kind == 'i' || kind == 'u';
  return PyLong_Check(value.ptr()) && !PyBool_Check(value.ptr());
}

bool isRealNumber(py::handle value) {
  if (const char kind = numpyKind(value)) return kind == 'i' || kind == 'u' || kind == 'f';
  return (PyLong_Check(value.ptr()) && !PyBool_Check(value.ptr())) || PyFloat_Check(value.ptr());
}

}  // namespace

DeclaredUnits declaredUnits(const std::optional<std::string>& lengthUnit,
                            const std::optional<std::map<std::string, std::string>>& units) {
  DeclaredUnits declared{lengthUnit.value_or("")};
  for (const auto& [name, unit] : units.value_or(std::map<std::string, std::string>{}))
    declared.units.push_back(name + "=" + unit);
  return declared;
}

std::string settingsDoc(std::span<const Setting* const> settings) {
  std::string doc;
  for (const Setting* s : settings) {
    const std::string shown = shownDefault(*s);
    doc += std::string(s->name) + (shown.empty() ? "" : "=" + shown) + ": " +
           spellSettings(s->help, plainName) + "\n";
  }
  return doc;
}

py::int_ wholeNumber(std::string_view name, py::handle value) {
  if (!isWholeNumber(value))
    throw py::type_error(fmt::format("{} must be a whole number, not {}", name, typeName(value)));
  return py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()));
}

void refuseOutside(std::string_view name, const std::string& shown, const std::string& least,
                   const std::string& most) {
  throw settingError(name, fmt::format("{} is outside the range {} to {}", shown, least, most));
}

double realIn(std::string_view name, py::handle value, double least, double most, bool positive) {
  if (!isRealNumber(value))
    throw py::type_error(fmt::format("{} must be a real number, not {}", name, typeName(value)));
  const double number = PyFloat_AsDouble(value.ptr());
  if (PyErr_Occurred()) {  // an int beyond double's range
    PyErr_Clear();
    refuseOutside(name, py::str(value), fmt::format("{:g}", least), fmt::format("{:g}", most));
  }
  if (!std::isfinite(number))
    throw settingError(name, fmt::format("{} is not a finite number", number));
  if (number >= least && number <= most) return number;
  if (positive && number < least)
    throw settingError(name, fmt::format("{} is not > 0 (from {:g} to {:g})", number, least, most));
  refuseOutside(name, fmt::format("{}", number), fmt::format("{:g}", least),
                fmt::format("{:g}", most));
}

std::string text(std::string_view name, py::handle value) {
  if (!PyUnicode_Check(value.ptr()))
    throw py::type_error(fmt::format("{} must be a str, not {}", name, typeName(value)));
  return value.cast<std::string>();
}

std::string outputPath(std::string_view name, py::handle value) {
  if (PyUnicode_Check(value.ptr())) return value.cast<std::string>();
  if (py::hasattr(value, "__fspath__")) {
    const py::object path = py::module_::import("os").attr("fspath")(value);
    if (PyUnicode_Check(path.ptr())) return path.cast<std::string>();
  }
  throw py::type_error(
      fmt::format("{} must be a str or os.PathLike naming a file, not {}", name, typeName(value)));
}

std::string frameVelocityText(py::handle value) {
  if (value.is_none()) return {};
  if (PyUnicode_Check(value.ptr())) return value.cast<std::string>();
  const auto v = settingValue<std::array<double, 3>>(settings::kFrameVelocity, value);
  return fmt::format("{:.17g},{:.17g},{:.17g}", v[0], v[1], v[2]);
}

namespace detail {

std::vector<py::object> items(std::string_view name, py::handle value, std::size_t count) {
  const bool sequence = py::isinstance<py::sequence>(value) || py::hasattr(value, "__array__");
  if (!sequence || PyUnicode_Check(value.ptr()) || PyBytes_Check(value.ptr()) ||
      numpyKind(value) != 0)
    throw py::type_error(
        fmt::format("{} must be a sequence of numbers, not {}", name, typeName(value)));
  std::vector<py::object> given;
  for (const py::handle item : value) given.push_back(py::reinterpret_borrow<py::object>(item));
  if (count != 0 && given.size() != count)
    throw py::value_error(fmt::format("{} must be {} numbers, not {}", name, count, given.size()));
  return given;
}

}  // namespace detail

}  // namespace amrstream::python
