#pragma once
// Keyword arguments and docstrings made from the library's settings (amrstream/settings.hpp):
// a keyword is the setting's name, its default the request struct's (which takes it from the
// setting), and a function's docstring lists each keyword with its default and meaning.

#include <pybind11/pybind11.h>

#include <span>
#include <string>

#include "amrstream/settings.hpp"

namespace amrstream::python {

// The keyword argument named as the setting.
inline pybind11::arg arg(const Setting& setting) { return pybind11::arg(setting.name.data()); }

// "name=default: what it means" for each setting, one a line, other settings named as keywords.
std::string settingsDoc(std::span<const Setting* const> settings);

// The settings of each call, in the order of its keywords.
namespace keywords {
namespace s = settings;
inline constexpr const Setting* kField[] = {&s::kVector, &s::kPointData, &s::kPeriodic,
                                            &s::kInterpolant};
inline constexpr const Setting* kTrace[] = {
    &s::kVector,        &s::kPointData,    &s::kPeriodic,   &s::kInterpolant, &s::kSteps,
    &s::kStepSize,      &s::kStepMode,     &s::kIntegrator, &s::kTolerance,   &s::kMinStep,
    &s::kMaxStep,       &s::kDirection,    &s::kVorticity,  &s::kMaxLength,   &s::kMaxTime,
    &s::kTerminalSpeed, &s::kMemoryBudget, &s::kCpuTail,    &s::kBackend,     &s::kDevice};
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
