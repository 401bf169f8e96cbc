#pragma once
// Keyword arguments made from the library's settings (amrstream/settings.hpp): a keyword is the
// setting's name, its default the request struct's (which takes it from the setting), a
// function's docstring lists each keyword with its default and meaning, and a value is read as
// the command line reads the option's text (src/cli/setting_options.hpp): of the right type,
// finite, and within the setting's range and the type it is stored as.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "amrstream/dataset_info.hpp"
#include "amrstream/settings.hpp"

namespace amrstream::python {

namespace py = pybind11;

// The keyword argument named as the setting.
inline pybind11::arg arg(const Setting& setting) { return pybind11::arg(setting.name.data()); }

// The units length_unit and units ({name: unit}) declare, as DeclaredUnits.
DeclaredUnits declaredUnits(const std::optional<std::string>& lengthUnit,
                            const std::optional<std::map<std::string, std::string>>& units);

// "name=default: what it means" for each setting, one a line, other settings named as keywords.
std::string settingsDoc(std::span<const Setting* const> settings);

// A keyword's value as the caller gave it: a binding reads it (settingValue) once the call runs,
// so that a value of the wrong type or out of range is told by the keyword's name rather than by
// pybind11's list of signatures. Signatures show it as the T it is read as.
template <typename T>
struct Given {
  py::object value;
};

// A whole number: an int or a numpy integer (not a bool, not a float). TypeError naming `name`
// for a value of another type.
py::int_ wholeNumber(std::string_view name, py::handle value);

// InputError naming `name`: `shown` is outside the range `least` to `most`.
[[noreturn]] void refuseOutside(std::string_view name, const std::string& shown,
                                const std::string& least, const std::string& most);

// A whole number from `least` to `most` (InputError naming `name` outside them).
template <typename Int>
Int wholeNumberIn(std::string_view name, py::handle value, Int least, Int most) {
  const py::int_ number = wholeNumber(name, value);
  if (number < py::int_(least) || number > py::int_(most))
    refuseOutside(name, py::repr(number).cast<std::string>(), std::to_string(least),
                  std::to_string(most));
  return number.cast<Int>();
}

// A real number: an int or a float, numpy's too (not a bool, a complex number or text), finite
// and within [least, most]; `positive` says so where `least` is the smallest positive value.
// TypeError or InputError naming `name`, as wholeNumber.
double realIn(std::string_view name, py::handle value, double least, double most,
              bool positive = false);

// Text: a str. TypeError naming `name` for anything else.
std::string text(std::string_view name, py::handle value);

// A path to write: a str or an os.PathLike naming one. TypeError naming `name` otherwise.
std::string outputPath(std::string_view name, py::handle value);

// frame_velocity as a keyword takes it, as FieldOptions::frameVelocity's text: None (none, ""),
// a str ("auto" or "VX,VY,VZ", checked where the field is built) or three real numbers.
std::string frameVelocityText(py::handle value);

namespace detail {
template <typename T>
struct IsOptional : std::false_type {};
template <typename T>
struct IsOptional<std::optional<T>> : std::true_type {};
template <typename T>
struct IsVector : std::false_type {};
template <typename T>
struct IsVector<std::vector<T>> : std::true_type {};
template <typename T>
struct IsArray : std::false_type {};
template <typename T, std::size_t N>
struct IsArray<std::array<T, N>> : std::true_type {};

// The items of a sequence (a list, a tuple, an array; not text), `count` of them unless 0.
std::vector<py::object> items(std::string_view name, py::handle value, std::size_t count);
}  // namespace detail

// The value of keyword `name` (the setting's own name if empty) for `setting` stored as T, as
// the command line takes it: a count (integral T) within the setting's range and T's; a real
// number (floating T) finite, within the setting's range and T's, and at least T's smallest
// normal value for a positive setting; std::optional: None leaves it unset; std::vector and
// std::array: a sequence of such values (an array of its length).
template <typename T>
T settingValue(const Setting& setting, py::handle value, std::string_view name = {}) {
  const std::string_view keyword = name.empty() ? setting.name : name;
  if constexpr (detail::IsOptional<T>::value) {
    if (value.is_none()) return std::nullopt;
    return settingValue<typename T::value_type>(setting, value, keyword);
  } else if constexpr (detail::IsVector<T>::value || detail::IsArray<T>::value) {
    T values{};
    const std::size_t count = detail::IsArray<T>::value ? values.size() : 0;
    const std::vector<py::object> given = detail::items(keyword, value, count);
    if constexpr (detail::IsVector<T>::value) values.resize(given.size());
    for (std::size_t i = 0; i < given.size(); ++i)
      values[i] = settingValue<typename T::value_type>(setting, given[i], keyword);
    return values;
  } else if constexpr (std::is_integral_v<T>) {
    // double(max) of a 64-bit type rounds up past max, so compare before converting.
    const auto typeMost = std::uint64_t(std::numeric_limits<T>::max());
    const std::uint64_t most =
        setting.most >= double(typeMost) ? typeMost : std::uint64_t(setting.most);
    return T(wholeNumberIn<std::uint64_t>(keyword, value,
                                          std::uint64_t(std::max(0.0, setting.least)), most));
  } else {
    static_assert(std::is_floating_point_v<T>);
    const double limit = double(std::numeric_limits<T>::max());
    if (setting.positive)
      return T(realIn(keyword, value, double(std::numeric_limits<T>::min()),
                      std::min(setting.most, limit), true));
    return T(
        realIn(keyword, value, std::max(setting.least, -limit), std::min(setting.most, limit)));
  }
}

template <typename T>
T settingValue(const Setting& setting, const Given<T>& given, std::string_view name = {}) {
  return settingValue<T>(setting, given.value, name);
}

// The settings of each call, in the order of its keywords.
namespace keywords {
namespace s = settings;
inline constexpr const Setting* kField[] = {&s::kVector, &s::kFrameVelocity, &s::kPointData,
                                            &s::kPeriodic, &s::kInterpolant};
inline constexpr const Setting* kTrace[] = {
    &s::kVector,  &s::kFrameVelocity, &s::kPointData,    &s::kPeriodic,   &s::kInterpolant,
    &s::kSteps,   &s::kStepSize,      &s::kStepMode,     &s::kIntegrator, &s::kTolerance,
    &s::kMinStep, &s::kMaxStep,       &s::kDirection,    &s::kVorticity,  &s::kMaxLength,
    &s::kMaxTime, &s::kTerminalSpeed, &s::kMemoryBudget, &s::kCpuTail,    &s::kBackend,
    &s::kDevice};
inline constexpr const Setting* kPathlines[] = {
    &s::kVector,  &s::kPointData, &s::kPeriodic,     &s::kInterpolant, &s::kStartTime,
    &s::kEndTime, &s::kTimeStep,  &s::kReleaseEvery, &s::kBackend,     &s::kDevice};
inline constexpr const Setting* kRender[] = {&s::kWidth,
                                             &s::kHeight,
                                             &s::kCamera,
                                             &s::kView,
                                             &s::kZoom,
                                             &s::kUp,
                                             &s::kFov,
                                             &s::kProjection,
                                             &s::kFrame,
                                             &s::kLookAt,
                                             &s::kViewBox,
                                             &s::kTubeRadius,
                                             &s::kTubeRadiusPhysical,
                                             &s::kTubeRadiusView,
                                             &s::kRadiusByColour,
                                             &s::kColourBy,
                                             &s::kColourMap,
                                             &s::kColourScale,
                                             &s::kSymlogWidth,
                                             &s::kRange,
                                             &s::kOutline,
                                             &s::kAxes,
                                             &s::kTriad,
                                             &s::kScaleBar,
                                             &s::kBackground,
                                             &s::kAoSamples,
                                             &s::kVolume,
                                             &s::kVolumeRange,
                                             &s::kVolumeOpacity,
                                             &s::kLinearVolume,
                                             &s::kFrames,
                                             &s::kColourBar};
}  // namespace keywords

}  // namespace amrstream::python

namespace pybind11::detail {

// Given<T> takes any value, to be read by the binding; signatures name it as T.
template <typename T>
struct type_caster<amrstream::python::Given<T>> {
  PYBIND11_TYPE_CASTER(amrstream::python::Given<T>, make_caster<T>::name);
  bool load(handle source, bool) {
    value.value = reinterpret_borrow<object>(source);
    return true;
  }
  static handle cast(const amrstream::python::Given<T>& given, return_value_policy, handle) {
    return given.value.inc_ref();
  }
};

}  // namespace pybind11::detail
