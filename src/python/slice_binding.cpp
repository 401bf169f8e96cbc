// amrstream._slice: a prepared Field's slice figure (amrstream/slice.hpp) with the numbers it
// shows as numpy arrays; amrstream.slice (python/amrstream) prepares a Dataset first.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "amrstream/field.hpp"
#include "amrstream/slice.hpp"
#include "bindings.hpp"
#include "python_reporter.hpp"

namespace amrstream::python {

namespace py = pybind11;

namespace {

// (height, width) float32, row 0 at the window's lower edge; None for an empty layer.
py::object planeArray(const std::vector<float>& values, std::uint32_t width, std::uint32_t height) {
  if (values.empty()) return py::none();
  py::array_t<float> array({py::ssize_t(height), py::ssize_t(width)});
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}

// One float32 array per line; None when not asked for.
py::object lineArrays(const std::vector<std::vector<float>>& values) {
  if (values.empty()) return py::none();
  py::list arrays;
  for (const std::vector<float>& line : values) {
    py::array_t<float> array(py::ssize_t(line.size()));
    std::copy(line.begin(), line.end(), array.mutable_data());
    arrays.append(array);
  }
  return arrays;
}

py::dict sliceOf(const Field& field, const SliceOptions& options, py::object progress,
                 bool verbose) {
  const Reporter reporter{pythonLog(verbose), throttled(progress)};
  SliceFigure figure;
  {
    py::gil_scoped_release unlocked;
    figure = makeSlice(field, options, reporter);
  }
  py::array_t<std::uint8_t> image(
      {py::ssize_t(figure.image.height), py::ssize_t(figure.image.width), py::ssize_t(4)});
  std::copy(figure.image.rgba.begin(), figure.image.rgba.end(), image.mutable_data());
  py::list lines;
  for (const auto& line : figure.lines) {
    py::array_t<double> points({py::ssize_t(line.size()), py::ssize_t(2)});
    double* out = points.mutable_data();
    for (std::size_t k = 0; k < line.size(); ++k) {
      out[2 * k] = line[k][0];
      out[2 * k + 1] = line[k][1];
    }
    lines.append(points);
  }
  py::dict result;
  result["image"] = image;
  result["window"] =
      py::make_tuple(figure.window[0], figure.window[1], figure.window[2], figure.window[3]);
  result["axes"] = py::make_tuple(figure.axes[0], figure.axes[1]);
  result["background_name"] =
      figure.backgroundName.empty() ? py::object(py::none()) : py::str(figure.backgroundName);
  result["background"] = planeArray(figure.background, figure.width, figure.height);
  result["lic"] = planeArray(figure.lic, figure.width, figure.height);
  result["lines"] = lines;
  result["line_colour_values"] = lineArrays(figure.lineColourValues);
  result["line_width_values"] = lineArrays(figure.lineWidthValues);
  return result;
}

}  // namespace

void bindSlicing(py::module_& m) {
  const SliceOptions defaults;
  m.def(
      "_slice",
      [](const Field& field, std::string normal, std::optional<std::array<double, 3>> point,
         std::optional<std::array<double, 4>> window, std::uint32_t width, std::string background,
         std::string colourMap, std::string colourScale, std::optional<std::array<double, 2>> range,
         bool lines, double lineSeparation, float lineWidth, std::string lineColourBy,
         std::string lineColourMap, std::string lineColourScale, std::string lineWidthBy, bool lic,
         double licLength, std::string backend, std::string device, bool validation,
         py::object progress, bool verbose) {
        SliceOptions options;
        options.normal = std::move(normal);
        options.point = point;
        options.window = window;
        options.width = width;
        options.background = std::move(background);
        options.colourMap = std::move(colourMap);
        options.colourScale = std::move(colourScale);
        options.range = range;
        options.lines = lines;
        options.lineSeparation = lineSeparation;
        options.lineWidth = lineWidth;
        options.lineColourBy = std::move(lineColourBy);
        options.lineColourMap = std::move(lineColourMap);
        options.lineColourScale = std::move(lineColourScale);
        options.lineWidthBy = std::move(lineWidthBy);
        options.lic = lic;
        options.licLength = licLength;
        options.backend.backend = std::move(backend);
        options.backend.device = std::move(device);
        options.backend.validation = validation || validationRequested();
        return sliceOf(field, options, progress, verbose);
      },
      py::arg("field"), py::kw_only(), py::arg("normal") = defaults.normal,
      py::arg("point") = py::none(), py::arg("window") = py::none(),
      py::arg("width") = defaults.width, py::arg("background") = defaults.background,
      py::arg("colour_map") = defaults.colourMap, py::arg("colour_scale") = defaults.colourScale,
      py::arg("range") = py::none(), py::arg("lines") = defaults.lines,
      py::arg("line_separation") = defaults.lineSeparation,
      py::arg("line_width") = defaults.lineWidth, py::arg("line_colour_by") = defaults.lineColourBy,
      py::arg("line_colour_map") = defaults.lineColourMap,
      py::arg("line_colour_scale") = defaults.lineColourScale,
      py::arg("line_width_by") = defaults.lineWidthBy, py::arg("lic") = defaults.lic,
      py::arg("lic_length") = defaults.licLength, py::arg("backend") = defaults.backend.backend,
      py::arg("device") = defaults.backend.device, py::arg("validation") = false,
      py::arg("progress") = py::none(), py::arg("verbose") = false,
      "A prepared Field's slice figure, as `amrstream slice` draws it (amrstream.slice is the "
      "public call).");
}

}  // namespace amrstream::python
