// Traces.render: the look of the tubes as keyword arguments named as the library's settings
// (amrstream/settings.hpp), each written into RenderOptions, whose defaults are the settings'.

#include <fmt/format.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <cstring>
#include <functional>
#include <map>
#include <string>

#include "amrstream/rendering.hpp"
#include "amrstream/settings.hpp"
#include "api/traces_impl.hpp"
#include "bindings.hpp"
#include "numpy_views.hpp"
#include "python_reporter.hpp"
#include "setting_args.hpp"

namespace amrstream::python {

namespace {

// What one render call asks for.
struct RenderRequest {
  RenderOptions look;
  BackendRequest backend;
  py::object progress = py::none();
  bool verbose = false;
};

using Setter = std::function<void(RenderRequest&, py::handle)>;

// Writes a keyword's value into a member of the request: a number read as its setting says
// (settingValue), text and flags as they are (None into an optional or a list: unset).
template <typename T>
Setter into(const Setting& setting, T RenderOptions::*member) {
  return [&setting, member](RenderRequest& r, py::handle value) {
    if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, std::string>)
      r.look.*member = value.cast<T>();
    else if constexpr (std::is_same_v<T, std::vector<float>> ||
                       std::is_same_v<T, std::vector<double>>)
      r.look.*member = value.is_none() ? T{} : settingValue<T>(setting, value);
    else
      r.look.*member = settingValue<T>(setting, value);
  };
}

template <typename T>
Setter intoRequest(T RenderRequest::*member) {
  return [member](RenderRequest& r, py::handle value) { r.*member = value.cast<T>(); };
}

// Every keyword render() takes, by the setting it sets.
const std::map<std::string, Setter>& setters() {
  namespace s = settings;
  static const std::map<std::string, Setter> table{
      {"width", into(s::kWidth, &RenderOptions::width)},
      {"height", into(s::kHeight, &RenderOptions::height)},
      {"camera", into(s::kCamera, &RenderOptions::camera)},
      {"view", [](RenderRequest& r,
                  py::handle v) { r.look.view = v.is_none() ? "" : v.cast<std::string>(); }},
      {"zoom", into(s::kZoom, &RenderOptions::zoom)},
      {"up", into(s::kUp, &RenderOptions::up)},
      {"fov", into(s::kFov, &RenderOptions::fovDegrees)},
      {"projection", into(s::kProjection, &RenderOptions::projection)},
      {"frame", into(s::kFrame, &RenderOptions::frame)},
      {"look_at", into(s::kLookAt, &RenderOptions::lookAt)},
      {"view_box", into(s::kViewBox, &RenderOptions::viewBox)},
      {"tube_radius", into(s::kTubeRadius, &RenderOptions::tubeRadius)},
      {"tube_radius_physical", into(s::kTubeRadiusPhysical, &RenderOptions::tubeRadiusPhysical)},
      {"tube_radius_view", into(s::kTubeRadiusView, &RenderOptions::tubeRadiusOfView)},
      {"radius_by_colour", into(s::kRadiusByColour, &RenderOptions::radiusByColour)},
      {"colour_by", into(s::kColourBy, &RenderOptions::colourBy)},
      {"colour_map", into(s::kColourMap, &RenderOptions::colourMap)},
      {"colour_scale", into(s::kColourScale, &RenderOptions::colourScale)},
      {"symlog_width", into(s::kSymlogWidth, &RenderOptions::symlogWidth)},
      {"range", into(s::kRange, &RenderOptions::range)},
      {"outline", into(s::kOutline, &RenderOptions::outline)},
      {"axes", into(s::kAxes, &RenderOptions::axes)},
      {"triad", into(s::kTriad, &RenderOptions::triad)},
      {"scale_bar", into(s::kScaleBar, &RenderOptions::scaleBar)},
      {"background",
       [](RenderRequest& r, py::handle v) {
         r.look.background = v.is_none() ? "" : v.cast<std::string>();
       }},
      {"ao_samples", into(s::kAoSamples, &RenderOptions::aoSamples)},
      {"volume", [](RenderRequest& r,
                    py::handle v) { r.look.volume = v.is_none() ? "" : v.cast<std::string>(); }},
      {"volume_range", into(s::kVolumeRange, &RenderOptions::volumeRange)},
      {"volume_opacity", into(s::kVolumeOpacity, &RenderOptions::volumeOpacity)},
      {"linear_volume", into(s::kLinearVolume, &RenderOptions::linearVolume)},
      {"frames", into(s::kFrames, &RenderOptions::frames)},
      {"colour_bar", into(s::kColourBar, &RenderOptions::colourBar)},
      {"backend",
       [](RenderRequest& r, py::handle v) { r.backend.backend = v.cast<std::string>(); }},
      {"device", [](RenderRequest& r, py::handle v) { r.backend.device = v.cast<std::string>(); }},
      {"validation", [](RenderRequest& r, py::handle v) { r.backend.validation = v.cast<bool>(); }},
      {"progress",
       [](RenderRequest& r, py::handle v) { r.progress = py::reinterpret_borrow<py::object>(v); }},
      {"verbose", intoRequest(&RenderRequest::verbose)},
  };
  return table;
}

RenderRequest requestOf(const py::kwargs& look) {
  RenderRequest request;
  for (const auto& [key, value] : look) {
    const std::string name = py::str(key);
    const auto setter = setters().find(name);
    if (setter == setters().end())
      throw py::type_error(fmt::format("render() got an unexpected keyword argument '{}'", name));
    try {
      setter->second(request, value);
    } catch (const py::cast_error&) {
      throw py::type_error(fmt::format("render(): {} cannot be {}", name,
                                       std::string(py::str(py::type::of(value)))));
    }
  }
  if (!request.look.camera.empty() && request.look.camera.size() != 2 &&
      request.look.camera.size() != 3)
    throw py::value_error("camera must be (azimuth, elevation) or (azimuth, elevation, zoom)");
  request.backend.validation = request.backend.validation || validationRequested();
  return request;
}

py::array renderTraces(const TracesOfFiles& t, const py::kwargs& look) {
  if (!t.field())
    throw py::value_error(
        "paths through a series have no one field to render with: write them with to_vtp() and "
        "run `amrstream render SNAPSHOT --traces FILE.vtp`");
  const RenderRequest r = requestOf(look);
  const Reporter reporter{pythonLog(r.verbose), throttled(r.progress)};
  RenderedImage rendered;
  {
    py::gil_scoped_release unlocked;
    rendered = renderImage(r.backend, r.look, *t.field(), t, reporter);
  }
  const Image& image = rendered.image;
  py::array_t<std::uint8_t> rgba(
      {py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(4)});
  std::memcpy(rgba.mutable_data(), image.rgba.data(), image.rgba.size());
  return rgba;
}

}  // namespace

void bindRendering(py::class_<TracesOfFiles>& traces) {
  namespace s = settings;
  traces.def("render", &renderTraces,
             ("render(**look): renders the lines as shaded tubes on a Vulkan device, as "
              "`amrstream render` does; returns a (height, width, 4) uint8 RGBA image. "
              "Keywords, with their defaults (also backend, device, validation=False, "
              "progress(done, total) over the frames, verbose=False):\n\n" +
              settingsDoc(keywords::kRender))
                 .c_str());
}

}  // namespace amrstream::python
