// amrstream.trace and amrstream.pathlines, and the Traces they return: numpy views of the traced
// lines, to_vtp and render.

#include <fmt/format.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <chrono>
#include <mutex>

#include "amrstream/field.hpp"
#include "amrstream/pathlines.hpp"
#include "amrstream/provenance.hpp"
#include "amrstream/rendering.hpp"
#include "amrstream/seeding.hpp"
#include "amrstream/trace_settings.hpp"
#include "amrstream/tracing.hpp"
#include "bindings.hpp"
#include "numpy_views.hpp"
#include "output/vtp_writer.hpp"
#include "prepared_field.hpp"

namespace amrstream::python {

namespace {

struct Traces {
  flow::TraceSet lines;
  std::vector<output::FieldDataArray> provenance;
  TraceReport report;
  std::shared_ptr<const PreparedField> field;  // what rendering the lines reads; none for paths
};

std::size_t lineIndex(const Traces& t, py::ssize_t i) {
  const py::ssize_t n = py::ssize_t(t.lines.lineCount());
  if (i < 0) i += n;
  if (i < 0 || i >= n) throw py::index_error(fmt::format("line {} of {}", i, n));
  return std::size_t(i);
}

// Points [first, first + count) as an (count, 3) array: a float32 view of the stored positions,
// or for precise positions a new float64 array of the joined ones.
py::array pointsOf(const flow::TraceSet& lines, std::uint64_t first, std::uint64_t count,
                   py::handle owner) {
  if (!lines.precisePositions) return view3(lines.positions.data() + first, count, owner);
  py::array_t<double> joined({py::ssize_t(count), py::ssize_t(3)});
  auto* out = reinterpret_cast<glm::dvec3*>(joined.mutable_data());
  static_assert(sizeof(glm::dvec3) == 3 * sizeof(double));
  for (std::uint64_t i = 0; i < count; ++i)
    out[i] = flow::joinPosition(lines.positions[first + i], lines.positionsLow[first + i]);
  return readOnly(joined);
}

// Calls a Python progress(done, total) at most ten times a second and once at the end, from
// whichever thread reports; its exceptions (KeyboardInterrupt) stop the trace. The tracer copies
// the function without the GIL, so the Python object sits behind a shared pointer; the caller's
// copy, destroyed with the GIL held, is the last.
flow::TraceProgress throttled(py::object callback) {
  if (callback.is_none()) return {};
  struct State {
    py::object callback;
    std::mutex mutex;
    std::chrono::steady_clock::time_point last{};
  };
  auto state = std::make_shared<State>();
  state->callback = std::move(callback);
  return [state](std::size_t done, std::size_t total) {
    std::lock_guard lock(state->mutex);
    const auto now = std::chrono::steady_clock::now();
    if (done < total && now - state->last < std::chrono::milliseconds(100)) return;
    state->last = now;
    py::gil_scoped_acquire locked;
    state->callback(done, total);
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  };
}

Log pythonLog(bool verbose) {
  if (!verbose) return {};
  return [](const std::string& line) {
    py::gil_scoped_acquire locked;
    py::print(line);
  };
}

flow::SeedList seedListOf(py::handle seeds) {
  const auto points = points3(seeds, "seeds");
  flow::SeedList list;
  const std::size_t n = std::size_t(points.shape(0));
  list.points.resize(n);
  std::memcpy(list.points.data(), points.data(), n * sizeof(glm::dvec3));
  list.origin = [](std::size_t i) { return fmt::format("seeds[{}]", i); };
  return list;
}

std::shared_ptr<Traces> runTrace(py::object target, py::object seeds,
                                 std::optional<std::string> vector,
                                 std::optional<std::string> pointData,
                                 std::optional<std::string> periodic,
                                 std::optional<std::string> interpolant,
                                 const TraceSettings& settings, const BackendRequest& backend,
                                 py::object progress, bool verbose) {
  std::shared_ptr<PreparedField> field;
  std::shared_ptr<Dataset> cells;
  if (py::isinstance<PreparedField>(target)) {
    if (vector || pointData || periodic || interpolant)
      throw py::value_error(
          "vector, point_data and periodic were chosen when the Field was prepared; pass the "
          "Dataset to choose them here");
    field = target.cast<std::shared_ptr<PreparedField>>();
  } else if (py::isinstance<Dataset>(target)) {
    cells = target.cast<std::shared_ptr<Dataset>>();
  } else {
    throw py::type_error("trace() needs an amrstream.Dataset or amrstream.Field, not " +
                         std::string(py::str(py::type::of(target))));
  }
  flow::SeedList seedList = seedListOf(seeds);
  const flow::TraceProgress onProgress = throttled(progress);
  const Log log = pythonLog(verbose);
  auto result = std::make_shared<Traces>();
  py::gil_scoped_release unlocked;
  if (!field)
    field = std::make_shared<PreparedField>(PreparedField{
        cells, buildField(*cells, {vector.value_or(""), pointData.value_or("all"),
                                   periodic.value_or("auto"), interpolant.value_or("tent")})});
  Field& f = field->field;
  placeSeeds(f.volume, seedList);
  const flow::TraceOptions options = traceOptions(settings, f.volume);
  flow::StoredTraces stored = trace(backend, f.volume, seedList.points, options, onProgress,
                                    &result->report, HostValues::Keep, log);
  result->provenance =
      provenanceFields({f.source, f.info, fmt::format("{} from Python", seedList.points.size()),
                        options, result->report},
                       f.volume);
  result->lines = std::move(stored).assemble();
  result->field = field;
  return result;
}

std::shared_ptr<Traces> runPathlines(const std::vector<std::string>& snapshots, py::object seeds,
                                     const FieldOptions& field, const PathlineSettings& settings,
                                     const BackendRequest& backend, py::object progress,
                                     bool verbose) {
  SeedRequest request;
  request.points = seedListOf(seeds).points;
  if (request.points.empty()) throw py::value_error("pathlines() needs at least one seed");
  const flow::TraceProgress onProgress = throttled(progress);
  const Log log = pythonLog(verbose);
  auto result = std::make_shared<Traces>();
  py::gil_scoped_release unlocked;
  const std::vector<SnapshotFile> series = listSnapshots(snapshots);
  PathlineReport report;
  const flow::PathlineTracer tracer =
      tracePathlines(series, field, request, settings, backend, report, onProgress, log);
  const bool streaks = report.options.releaseEvery > 0.0;
  result->lines = streaks ? tracer.streaklines() : tracer.pathlines();
  result->provenance = pathlineProvenance(series, report, streaks ? "streaklines" : "pathlines");
  result->report.backend = report.backend;
  result->report.device = report.device;
  result->report.setupSeconds = report.deviceSeconds;
  result->report.traceSeconds = report.traceSeconds;
  return result;
}

py::array renderTraces(const Traces& t, std::uint32_t width, std::uint32_t height,
                       std::optional<std::vector<float>> camera, std::optional<std::string> view,
                       float zoom, std::string up, float fov, std::string projection,
                       std::string frame, std::optional<std::vector<double>> lookAt,
                       std::optional<std::vector<double>> viewBox, std::optional<float> tubeRadius,
                       std::optional<double> tubeRadiusPhysical, float tubeRadiusOfView,
                       float radiusByColour, std::string colourBy, std::string colourMap,
                       std::string colourScale, std::optional<double> symlogWidth,
                       std::optional<std::vector<float>> range, std::string outline, bool axes,
                       bool triad, bool scaleBar, std::optional<std::string> background,
                       std::uint32_t aoSamples, std::optional<std::string> volume,
                       std::optional<std::vector<float>> volumeRange, float volumeOpacity,
                       bool linearVolume, std::uint32_t frames, bool colourBar, std::string backend,
                       std::string device, bool validation, py::object progress, bool verbose) {
  if (!t.field)
    throw py::value_error(
        "paths through a series have no one field to render with: write them with to_vtp() and "
        "run `amrstream render SNAPSHOT --traces FILE.vtp`");
  if (width < 16 || height < 16 || width > 16384 || height > 16384)
    throw py::value_error("width and height must be 16 to 16384 pixels");
  if (camera && camera->size() != 2 && camera->size() != 3)
    throw py::value_error("camera must be (azimuth, elevation) or (azimuth, elevation, zoom)");
  RenderOptions o;
  o.width = width;
  o.height = height;
  o.camera = camera.value_or(std::vector<float>{});
  o.view = view.value_or("");
  o.zoom = zoom;
  o.up = std::move(up);
  o.fovDegrees = fov;
  o.projection = std::move(projection);
  o.frame = std::move(frame);
  o.lookAt = lookAt.value_or(std::vector<double>{});
  o.viewBox = viewBox.value_or(std::vector<double>{});
  o.tubeRadius = tubeRadius;
  o.tubeRadiusPhysical = tubeRadiusPhysical;
  o.tubeRadiusOfView = tubeRadiusOfView;
  o.radiusByColour = radiusByColour;
  o.colourBy = std::move(colourBy);
  for (const output::FieldDataArray& f : t.provenance)  // IntegrationTime's unit by step mode
    if (const auto* text = std::get_if<std::vector<std::string>>(&f.values);
        f.name == "StepMode" && text && !text->empty())
      o.timeUnit = integrationTimeUnit(parseStepMode(text->front()), t.field->field.info);
  o.colourMap = std::move(colourMap);
  o.colourScale = std::move(colourScale);
  o.symlogWidth = symlogWidth;
  o.range = range.value_or(std::vector<float>{});
  o.outline = std::move(outline);
  o.axes = axes;
  o.triad = triad;
  o.scaleBar = scaleBar;
  o.background = background.value_or("");
  o.aoSamples = aoSamples;
  o.volume = volume.value_or("");
  o.volumeRange = volumeRange.value_or(std::vector<float>{});
  o.volumeOpacity = volumeOpacity;
  o.linearVolume = linearVolume;
  const BackendRequest request{std::move(backend), std::move(device),
                               validation || validationRequested()};
  const flow::TraceProgress onProgress = throttled(progress);
  const Log log = pythonLog(verbose);
  RenderedImage rendered;
  {
    py::gil_scoped_release unlocked;
    rendered = renderImage(
        request, o, *t.field->cells, t.field->field.volume, t.lines, frames, colourBar,
        [&](std::uint32_t done, std::uint32_t all) {
          if (onProgress) onProgress(done, all);
        },
        log);
  }
  const render::Image& image = rendered.image;
  py::array_t<std::uint8_t> rgba(
      {py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(4)});
  std::memcpy(rgba.mutable_data(), image.rgba.data(), image.rgba.size());
  return rgba;
}

void bindTraces(py::module_& m) {
  py::class_<Traces, std::shared_ptr<Traces>>(
      m, "Traces",
      "Traced lines (with both directions: the forward lines of all seeds, then the backward "
      "ones), as numpy views: line i's points are points[offsets[i]:offsets[i + 1]].")
      .def("__len__", [](const Traces& t) { return t.lines.lineCount(); })
      .def(
          "__getitem__",
          [](py::object self, py::ssize_t i) {
            const Traces& t = self.cast<const Traces&>();
            const std::size_t line = lineIndex(t, i);
            return pointsOf(t.lines, t.lines.firstPoint(line), t.lines.pointCount(line), self);
          },
          "(n_i, 3) points of line i: float32, float64 for precise positions")
      .def_property_readonly(
          "points",
          [](py::object self) {
            const Traces& t = self.cast<const Traces&>();
            return pointsOf(t.lines, 0, t.lines.pointCount(), self);
          },
          "(M, 3) points of all lines: float32, float64 for precise positions")
      .def_property_readonly("offsets",
                             [](py::object self) {
                               const Traces& t = self.cast<const Traces&>();
                               return view(t.lines.offsets.data(), t.lines.offsets.size(), self);
                             })
      .def_property_readonly("seed_ids",
                             [](py::object self) {
                               const Traces& t = self.cast<const Traces&>();
                               return view(t.lines.seedIds.data(), t.lines.lineCount(), self);
                             })
      .def_property_readonly("directions",
                             [](py::object self) {
                               const Traces& t = self.cast<const Traces&>();
                               return view(t.lines.directions.data(), t.lines.lineCount(), self);
                             })
      .def_property_readonly("steps",
                             [](py::object self) {
                               const Traces& t = self.cast<const Traces&>();
                               return view(t.lines.steps.data(), t.lines.lineCount(), self);
                             })
      .def_property_readonly("reasons",
                             [](py::object self) {
                               const Traces& t = self.cast<const Traces&>();
                               return view(t.lines.reasons.data(), t.lines.lineCount(), self);
                             })
      .def_property_readonly("integration_time",
                             [](py::object self) {
                               const Traces& t = self.cast<const Traces&>();
                               return view(t.lines.times.data(), t.lines.pointCount(), self);
                             })
      .def_property_readonly("vectors",
                             [](py::object self) {
                               const Traces& t = self.cast<const Traces&>();
                               return view3(t.lines.vectors.data(), t.lines.pointCount(), self);
                             })
      .def_property_readonly("vector_name", [](const Traces& t) { return t.lines.vectorName; })
      .def_property_readonly(
          "point_data",
          [](py::object self) {
            const Traces& t = self.cast<const Traces&>();
            const std::size_t channels = t.lines.channelCount();
            py::dict arrays;
            for (std::size_t c = 0; c < channels; ++c)
              arrays[py::str(t.lines.channelNames[c])] =
                  view(t.lines.channels.data() + c, t.lines.pointCount(), self,
                       channels * sizeof(float));
            return arrays;
          },
          "{name: (M,) float32} sampled at every point")
      .def_property_readonly("vorticity",
                             [](py::object self) -> py::object {
                               const Traces& t = self.cast<const Traces&>();
                               if (!t.lines.withVorticity) return py::none();
                               return view3(t.lines.vorticity.data(), t.lines.pointCount(), self);
                             })
      .def_property_readonly("backend", [](const Traces& t) { return t.report.backend; })
      .def_property_readonly("device", [](const Traces& t) { return t.report.device; })
      .def_property_readonly("trace_seconds", [](const Traces& t) { return t.report.traceSeconds; })
      .def_property_readonly("setup_seconds", [](const Traces& t) { return t.report.setupSeconds; })
      .def(
          "to_vtp",
          [](const Traces& t, const std::string& path, const std::string& compression,
             const std::string& periodicLines) {
            output::VtpWriteOptions options;
            const auto codec = output::compressionNamed(compression);
            if (!codec) throw py::value_error("compression must be zlib, lz4 or none");
            if (periodicLines != "split" && periodicLines != "unwrapped")
              throw py::value_error("periodic_lines must be split or unwrapped");
            options.compression = *codec;
            options.periodicLines = periodicLines == "split" ? output::PeriodicLines::Split
                                                             : output::PeriodicLines::Unwrapped;
            options.fieldData = t.provenance;
            output::VtpCounts counts;
            {
              py::gil_scoped_release unlocked;
              counts = output::writeVtp(path, t.lines, options);
            }
            return py::make_tuple(counts.lines, counts.points);
          },
          py::arg("path"), py::kw_only(), py::arg("compression") = "zlib",
          py::arg("periodic_lines") = "split",
          "Writes the lines as VTK XML PolyData, as the command line does; returns (polylines, "
          "points) written.")
      .def("render", &renderTraces, py::kw_only(), py::arg("width") = 1024, py::arg("height") = 768,
           py::arg("camera") = py::none(), py::arg("view") = py::none(), py::arg("zoom") = 1.0f,
           py::arg("up") = "+z", py::arg("fov") = 35.0f, py::arg("projection") = "perspective",
           py::arg("frame") = "traces", py::arg("look_at") = py::none(),
           py::arg("view_box") = py::none(), py::arg("tube_radius") = py::none(),
           py::arg("tube_radius_physical") = py::none(), py::arg("tube_radius_view") = 0.003f,
           py::arg("radius_by_colour") = 1.0f, py::arg("colour_by") = "speed",
           py::arg("colour_map") = "viridis", py::arg("colour_scale") = "linear",
           py::arg("symlog_width") = py::none(), py::arg("range") = py::none(),
           py::arg("outline") = "domain", py::arg("axes") = false, py::arg("triad") = true,
           py::arg("scale_bar") = false, py::arg("background") = py::none(),
           py::arg("ao_samples") = 4, py::arg("volume") = py::none(),
           py::arg("volume_range") = py::none(), py::arg("volume_opacity") = 0.05f,
           py::arg("linear_volume") = false, py::arg("frames") = 32, py::arg("colour_bar") = true,
           py::arg("backend") = "auto", py::arg("device") = "", py::arg("validation") = false,
           py::arg("progress") = py::none(), py::arg("verbose") = false,
           "Renders the lines as shaded tubes on a Vulkan device, as `amrstream render` does; "
           "returns a (height, width, 4) uint8 RGBA image.")
      .def("__repr__", [](const Traces& t) {
        return fmt::format("<amrstream.Traces {} lines, {} points, {} on {}>", t.lines.lineCount(),
                           t.lines.pointCount(), t.report.backend, t.report.device);
      });
}

}  // namespace

void bindTracing(py::module_& m) {
  bindTraces(m);
  m.def(
      "trace",
      [](py::object target, py::object seeds, std::optional<std::string> vector,
         std::optional<std::string> pointData, std::optional<std::string> periodic,
         std::optional<std::string> interpolant, std::uint32_t steps, std::optional<float> stepSize,
         std::string stepMode, std::string integrator, float tolerance,
         std::optional<float> minStep, std::optional<float> maxStep, std::string direction,
         bool vorticity, float maxLength, float maxTime, float terminalSpeed,
         std::uint64_t memoryBudget, std::uint32_t cpuTail, std::string backend, std::string device,
         bool validation, py::object progress, bool verbose) {
        TraceSettings settings;
        settings.steps = steps;
        settings.stepSize = stepSize;
        settings.stepMode = std::move(stepMode);
        settings.integrator = std::move(integrator);
        settings.tolerance = tolerance;
        settings.minStep = minStep;
        settings.maxStep = maxStep;
        settings.direction = std::move(direction);
        settings.vorticity = vorticity;
        settings.maxLength = maxLength;
        settings.maxTime = maxTime;
        settings.terminalSpeed = terminalSpeed;
        settings.memoryBudget = memoryBudget;
        settings.cpuTail = cpuTail;
        const BackendRequest request{std::move(backend), std::move(device),
                                     validation || validationRequested()};
        return runTrace(target, seeds, vector, pointData, periodic, interpolant, settings, request,
                        progress, verbose);
      },
      py::arg("target"), py::arg("seeds"), py::kw_only(), py::arg("vector") = py::none(),
      py::arg("point_data") = py::none(), py::arg("periodic") = py::none(),
      py::arg("interpolant") = py::none(), py::arg("steps") = 1000,
      py::arg("step_size") = py::none(), py::arg("step_mode") = "arc",
      py::arg("integrator") = "rk4", py::arg("tolerance") = 1e-4f, py::arg("min_step") = py::none(),
      py::arg("max_step") = py::none(), py::arg("direction") = "both", py::arg("vorticity") = false,
      py::arg("max_length") = 0.0f, py::arg("max_time") = 0.0f, py::arg("terminal_speed") = 1e-12f,
      py::arg("memory_budget") = 0, py::arg("cpu_tail") = 0, py::arg("backend") = "auto",
      py::arg("device") = "", py::arg("validation") = false, py::arg("progress") = py::none(),
      py::arg("verbose") = false,
      "Traces streamlines from seeds ((N, 3) points) through a Dataset (vector, point_data "
      "and periodic as for prepare()) or a prepared Field, as `amrstream trace` does.");
  m.def(
      "pathlines",
      [](std::vector<std::string> snapshots, py::object seeds, std::optional<std::string> vector,
         std::optional<std::string> pointData, std::optional<std::string> periodic,
         std::optional<std::string> interpolant, std::optional<double> startTime,
         std::optional<double> endTime, std::optional<double> stepSize, double releaseEvery,
         std::string backend, std::string device, bool validation, py::object progress,
         bool verbose) {
        const FieldOptions field{vector.value_or(""), pointData.value_or("all"),
                                 periodic.value_or("auto"), interpolant.value_or("tent")};
        PathlineSettings settings;
        settings.startTime = startTime;
        settings.endTime = endTime;
        settings.stepSize = stepSize;
        settings.releaseEvery = releaseEvery;
        const BackendRequest request{std::move(backend), std::move(device),
                                     validation || validationRequested()};
        return runPathlines(snapshots, seeds, field, settings, request, progress, verbose);
      },
      py::arg("snapshots"), py::arg("seeds"), py::kw_only(), py::arg("vector") = py::none(),
      py::arg("point_data") = py::none(), py::arg("periodic") = py::none(),
      py::arg("interpolant") = py::none(), py::arg("start_time") = py::none(),
      py::arg("end_time") = py::none(), py::arg("step_size") = py::none(),
      py::arg("release_every") = 0.0, py::arg("backend") = "auto", py::arg("device") = "",
      py::arg("validation") = false, py::arg("progress") = py::none(), py::arg("verbose") = false,
      "Traces pathlines from seeds ((N, 3) points, released at start_time) through a time series "
      "of snapshot files or glob patterns, ordered by the times the files state, as `amrstream "
      "pathlines` does; with release_every, streaklines. integration_time is physical time "
      "(streaklines: each particle's age); progress(done, total) counts intervals.");
  m.def("reason_name", &reasonName, py::arg("code"),
        "The name of a ReasonForTermination code, e.g. 'out of domain'.");
}

}  // namespace amrstream::python
