// amrstream.trace and amrstream.pathlines, and the Traces they return: numpy views of the traced
// lines, to_vtp and render.

#include <fmt/format.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <chrono>
#include <filesystem>
#include <limits>
#include <mutex>

#include "amrstream/dataset.hpp"
#include "amrstream/error.hpp"
#include "amrstream/field.hpp"
#include "amrstream/pathlines.hpp"
#include "amrstream/rendering.hpp"
#include "amrstream/run_files.hpp"
#include "amrstream/seeding.hpp"
#include "amrstream/settings.hpp"
#include "amrstream/trace_job.hpp"
#include "amrstream/trace_settings.hpp"
#include "amrstream/tracing.hpp"
#include "api/handles.hpp"
#include "api/traces_impl.hpp"
#include "bindings.hpp"
#include "flow/trace_set.hpp"
#include "numpy_views.hpp"
#include "python_reporter.hpp"
#include "setting_args.hpp"

namespace amrstream::python {

namespace fs = std::filesystem;

namespace {

// The unit of the points' coordinates: the field's, else the one the .vtp states; "" unknown.
std::string lengthUnitOf(const Traces& t) {
  if (t.field()) return t.field()->info().lengthUnit;
  for (const output::FieldDataArray& array : t.impl().provenance) {
    const auto* text = std::get_if<std::vector<std::string>>(&array.values);
    if (array.name == "LengthUnit" && text && !text->empty()) return text->front();
  }
  return "";
}

std::size_t lineIndex(const Traces& t, py::handle index) {
  const py::ssize_t n = py::ssize_t(t.lineCount());
  py::ssize_t i =
      wholeNumberIn<py::ssize_t>("index", index, std::numeric_limits<py::ssize_t>::min(),
                                 std::numeric_limits<py::ssize_t>::max());
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

// The seeds, refused before any is converted when there are more than a run may trace (a
// broadcast array of many rows takes no memory until it is copied).
std::vector<glm::dvec3> seedPointsOf(py::handle seeds) {
  const py::array given = pointsArray(seeds, "seeds");
  checkSeedCount(double(given.shape(0)), "seeds");
  const auto points = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(given);
  std::vector<glm::dvec3> list(std::size_t(points.shape(0)));
  std::memcpy(list.data(), points.data(), list.size() * sizeof(glm::dvec3));
  return list;
}

// The files of the dataset named `source` (as load() names it), absolute: its reader's files
// where it names an input on disk; none for builtin:KIND and arrays.
std::vector<fs::path> inputFiles(const std::string& source) {
  std::error_code error;
  if (!fs::exists(source, error)) return {};
  std::vector<fs::path> files;
  try {
    files = datasetFiles(source);
  } catch (const InputError&) {  // not a dataset the library reads, but a file
    files = {source};
  }
  for (fs::path& file : files)
    if (fs::path absolute = fs::absolute(file, error); !error) file = std::move(absolute);
  return files;
}

// The field options of trace(): None leaves each as the library's default.
struct FieldKeywords {
  std::optional<std::string> vector, pointData, periodic, interpolant;
  py::object frameVelocity;

  bool any() const {
    return vector || pointData || periodic || interpolant || !frameVelocity.is_none();
  }
  FieldOptions options() const {
    const FieldOptions defaults;
    return {vector.value_or(""), pointData.value_or(defaults.pointData),
            periodic.value_or(defaults.periodic), interpolant.value_or(defaults.interpolant),
            frameVelocityText(frameVelocity)};
  }
};

TracesOfFiles runTrace(py::object target, py::object seeds, const FieldKeywords& fieldKeywords,
                       const TraceSettings& settings, const BackendRequest& backend,
                       py::object progress, bool verbose) {
  std::optional<Field> field;
  std::shared_ptr<Dataset> dataset;
  if (py::isinstance<Field>(target)) {
    if (fieldKeywords.any())
      throw py::value_error(
          "vector, frame_velocity, point_data, periodic and interpolant were chosen when the "
          "Field was prepared; pass the Dataset to choose them here");
    field = target.cast<Field>();
  } else if (py::isinstance<Dataset>(target)) {
    dataset = target.cast<std::shared_ptr<Dataset>>();
  } else {
    throw py::type_error("trace() needs an amrstream.Dataset or amrstream.Field, not " +
                         std::string(py::str(py::type::of(target))));
  }
  std::vector<glm::dvec3> points = seedPointsOf(seeds);
  const Reporter reporter{pythonLog(verbose), throttled(progress)};
  const FieldOptions options = field ? FieldOptions{} : fieldKeywords.options();
  py::gil_scoped_release unlocked;
  // frame_velocity auto: the mean over the cells that hold the seeds.
  if (!field) field = buildField(*dataset, options, KeepDataset::Yes, points);
  std::vector<fs::path> inputs = inputFiles(field->source());
  PreparedJob job = prepare(*field, std::move(points), settings, backend, "Python");
  return {trace(job, {TraceStore::Host, HostValues::Keep}, reporter).assemble(), std::move(inputs)};
}

TracesOfFiles runPathlines(const std::vector<std::string>& snapshots, py::object seeds,
                           const FieldOptions& field, const PathlineSettings& settings,
                           const DeclaredUnits& units, const BackendRequest& backend,
                           py::object progress, bool verbose) {
  PathlineJob job;
  job.units = units;
  job.seeds.points = seedPointsOf(seeds);
  if (job.seeds.points.empty()) throw py::value_error("pathlines() needs at least one seed");
  job.field = field;
  job.settings = settings;
  job.backend = backend;
  const Reporter reporter{pythonLog(verbose), throttled(progress)};
  py::gil_scoped_release unlocked;
  job.series = listSnapshots(snapshots);
  std::vector<fs::path> inputs;
  for (const SnapshotFile& snapshot : job.series) {
    const std::vector<fs::path> files = inputFiles(snapshot.path);
    inputs.insert(inputs.end(), files.begin(), files.end());
  }
  return {tracePathlines(job, reporter).lines, std::move(inputs)};
}

// Writes the lines as the command line writes --out: refused before anything is written when
// the file is one of the inputs they were traced from (or lies in an input directory), exists and
// is not a regular file, has no directory, or is not named .vtp; written through a temporary
// renamed over it.
WrittenLines writeVtp(const TracesOfFiles& t, const std::string& path, TraceOutput output) {
  RunFiles files;
  files.addInputs(t.inputs);
  files.addOutput("path", path);
  requireOutputExtension("path", path, {".vtp"}, "VTK XML PolyData");
  output.path = path;
  py::gil_scoped_release unlocked;
  return t.write(output);
}

// The lines as numpy views of the Traces' own memory, which each view keeps alive.
void bindLineArrays(py::class_<TracesOfFiles>& traces) {
  traces.def("__len__", [](const TracesOfFiles& t) { return linesOf(t).lineCount(); })
      .def(
          "__getitem__",
          [](py::object self, Given<py::ssize_t> index) {
            const flow::TraceSet& lines = linesOf(self.cast<const TracesOfFiles&>());
            const std::size_t line = lineIndex(self.cast<const TracesOfFiles&>(), index.value);
            return pointsOf(lines, lines.firstPoint(line), lines.pointCount(line), self);
          },
          py::arg("index"), "(n_i, 3) points of line i: float32, float64 for precise positions")
      .def(
          "pieces",
          [](py::object self, Given<py::ssize_t> index) {
            const flow::TraceSet& lines = linesOf(self.cast<const TracesOfFiles&>());
            const std::size_t line = lineIndex(self.cast<const TracesOfFiles&>(), index.value);
            const std::uint64_t first = lines.firstPoint(line),
                                end = first + lines.pointCount(line);
            py::list pieces;
            std::uint64_t start = first;
            for (std::uint64_t k = first + 1; k < end; ++k)
              if (lines.periodic.wraps(lines.positions[k - 1], lines.positions[k])) {
                pieces.append(pointsOf(lines, start, k - start, self));
                start = k;
              }
            if (end > start) pieces.append(pointsOf(lines, start, end - start, self));
            return pieces;
          },
          py::arg("index"),
          "line i's points cut where the line crosses a periodic face: a list of (n, 3) arrays "
          "to plot without a stroke across the box (the .vtp's periodic_lines='split')")
      .def_property_readonly(
          "points",
          [](py::object self) {
            const flow::TraceSet& lines = linesOf(self.cast<const TracesOfFiles&>());
            return pointsOf(lines, 0, lines.pointCount(), self);
          },
          "(M, 3) points of all lines: float32, float64 for precise positions");
  const auto perLine = [&](const char* name, auto member, const char* doc) {
    traces.def_property_readonly(
        name,
        [member](py::object self) {
          const flow::TraceSet& lines = linesOf(self.cast<const TracesOfFiles&>());
          const auto& values = lines.*member;
          return view(values.data(), values.size(), self);
        },
        doc);
  };
  // int64, as numpy indexes: uint64 offsets[i] + 1 would be a float64 and fail as a slice bound.
  // Offsets count points, far below 2^63, so the bytes read the same.
  traces.def_property_readonly(
      "offsets",
      [](py::object self) {
        const std::vector<std::uint64_t>& offsets =
            linesOf(self.cast<const TracesOfFiles&>()).offsets;
        return view(reinterpret_cast<const std::int64_t*>(offsets.data()), offsets.size(), self);
      },
      "(L + 1,) int64: line i is points[offsets[i]:offsets[i + 1]]");
  perLine("seed_ids", &flow::TraceSet::seedIds, "(L,) uint32: the seed each line starts at");
  perLine("directions", &flow::TraceSet::directions,
          "(L,) float32: +1 for a forward line, -1 for a backward one");
  perLine("steps", &flow::TraceSet::steps, "(L,) uint32: the integration steps each line took");
  perLine("reasons", &flow::TraceSet::reasons,
          "(L,) int32: why each line ended, a ReasonForTermination code (reason_name names it)");
  traces
      .def_property_readonly(
          "integration_time",
          [](py::object self) {
            const flow::TraceSet& lines = linesOf(self.cast<const TracesOfFiles&>());
            return view(lines.times.data(), lines.pointCount(), self);
          },
          "(M,) float32 IntegrationTime at every point: negative along "
          "backward lines; for pathlines physical time, for streaklines "
          "each particle's age")
      .def_property_readonly(
          "vectors",
          [](py::object self) {
            const flow::TraceSet& lines = linesOf(self.cast<const TracesOfFiles&>());
            return view3(lines.vectors.data(), lines.pointCount(), self);
          },
          "(M, 3) float32: the traced vector at every point")
      .def_property_readonly(
          "vector_name", [](const TracesOfFiles& t) { return linesOf(t).vectorName; },
          "the traced vector's name, e.g. 'vel' or '-grad(temp)'")
      .def_property_readonly(
          "point_data",
          [](py::object self) {
            const flow::TraceSet& lines = linesOf(self.cast<const TracesOfFiles&>());
            const std::size_t channels = lines.channelCount();
            py::dict arrays;
            for (std::size_t c = 0; c < channels; ++c)
              arrays[py::str(lines.channelNames[c])] = view(
                  lines.channels.data() + c, lines.pointCount(), self, channels * sizeof(float));
            return arrays;
          },
          "{name: (M,) float32} sampled at every point")
      .def_property_readonly(
          "vorticity",
          [](py::object self) -> py::object {
            const flow::TraceSet& lines = linesOf(self.cast<const TracesOfFiles&>());
            if (!lines.withVorticity) return py::none();
            return view3(lines.vorticity.data(), lines.pointCount(), self);
          },
          "(M, 3) float32 curl of the vector at every point (traced with vorticity=True), else "
          "None");
}

// What ran them, and writing them.
void bindReportAndOutput(py::class_<TracesOfFiles>& traces) {
  traces
      .def_property_readonly(
          "length_unit", [](const TracesOfFiles& t) { return lengthUnitOf(t); },
          "the unit of the points' coordinates, as the dataset states it (e.g. 'cm'); '' where "
          "it is unknown")
      .def_property_readonly(
          "length_unit_cm",
          [](const TracesOfFiles& t) {
            return t.field() ? t.field()->info().lengthUnitCentimetres : std::nullopt;
          },
          "the centimetres in one length_unit, where the field they were traced in states it; "
          "else None")
      .def_property_readonly(
          "backend", [](const TracesOfFiles& t) { return t.report().backend; },
          "the backend that traced them: 'cpu', 'rayquery', 'pipeline' or 'compute'")
      .def_property_readonly(
          "device", [](const TracesOfFiles& t) { return t.report().device; },
          "the Vulkan device's name, or the CPU's threads")
      .def_property_readonly(
          "trace_seconds", [](const TracesOfFiles& t) { return t.report().traceSeconds; },
          "seconds spent tracing")
      .def_property_readonly(
          "setup_seconds", [](const TracesOfFiles& t) { return t.report().setupSeconds; },
          "seconds spent before tracing: the device, its structures and uploads")
      .def(
          "to_vtp",
          [](const TracesOfFiles& t, Given<std::string> path, const std::string& compression,
             const std::string& periodicLines) {
            const WrittenLines written =
                writeVtp(t, outputPath("path", path.value), {"", compression, periodicLines});
            return py::make_tuple(written.lines, written.points);
          },
          py::arg("path"), py::kw_only(), arg(settings::kCompression) = TraceOutput{}.compression,
          arg(settings::kPeriodicLines) = TraceOutput{}.periodicLines,
          "Writes the lines as VTK XML PolyData, as the command line does (through a temporary "
          "file renamed over `path`); refuses a path that is one of the files they were traced "
          "from, or exists and is not a regular file. Returns (polylines, points) written.")
      .def("__repr__", [](const TracesOfFiles& t) {
        return fmt::format("<amrstream.Traces {} lines, {} points, {} on {}>", t.lineCount(),
                           t.pointCount(), t.report().backend, t.report().device);
      });
}

void bindTraces(py::module_& m) {
  py::class_<TracesOfFiles> traces(
      m, "Traces",
      "Traced lines (with both directions: the forward lines of all seeds, then the backward "
      "ones), as numpy views: line i's points are points[offsets[i]:offsets[i + 1]].");
  bindLineArrays(traces);
  bindReportAndOutput(traces);
  bindRendering(traces);
}

}  // namespace

void bindTracing(py::module_& m) {
  namespace s = settings;
  const TraceSettings t;
  const BackendRequest b;
  bindTraces(m);
  m.def(
      "trace",
      [](py::object target, py::object seeds, std::optional<std::string> vector,
         py::object frameVelocity, std::optional<std::string> pointData,
         std::optional<std::string> periodic, std::optional<std::string> interpolant,
         Given<std::uint32_t> steps, Given<std::optional<float>> stepSize, std::string stepMode,
         std::string integrator, Given<float> tolerance, Given<std::optional<float>> minStep,
         Given<std::optional<float>> maxStep, std::string direction, bool vorticity,
         Given<float> maxLength, Given<float> maxTime, Given<float> terminalSpeed,
         Given<std::uint64_t> memoryBudget, Given<std::uint32_t> cpuTail, std::string backend,
         std::string device, bool validation, py::object progress, bool verbose) {
        TraceSettings settings;
        settings.steps = settingValue(s::kSteps, steps);
        settings.stepSize = settingValue(s::kStepSize, stepSize);
        settings.stepMode = std::move(stepMode);
        settings.integrator = std::move(integrator);
        settings.tolerance = settingValue(s::kTolerance, tolerance);
        settings.minStep = settingValue(s::kMinStep, minStep);
        settings.maxStep = settingValue(s::kMaxStep, maxStep);
        settings.direction = std::move(direction);
        settings.vorticity = vorticity;
        settings.maxLength = settingValue(s::kMaxLength, maxLength);
        settings.maxTime = settingValue(s::kMaxTime, maxTime);
        settings.terminalSpeed = settingValue(s::kTerminalSpeed, terminalSpeed);
        // As --memory-budget: up to the machine's memory.
        settings.memoryBudget = wholeNumberIn<std::uint64_t>(
            s::kMemoryBudget.name, memoryBudget.value, 0, maxMemoryBudget());
        settings.cpuTail = settingValue(s::kCpuTail, cpuTail);
        const BackendRequest request{std::move(backend), std::move(device),
                                     validation || validationRequested()};
        return runTrace(target, seeds, {vector, pointData, periodic, interpolant, frameVelocity},
                        settings, request, progress, verbose);
      },
      py::arg("target"), py::arg("seeds"), py::kw_only(), arg(s::kVector) = py::none(),
      arg(s::kFrameVelocity) = py::none(), arg(s::kPointData) = py::none(),
      arg(s::kPeriodic) = py::none(), arg(s::kInterpolant) = py::none(), arg(s::kSteps) = t.steps,
      arg(s::kStepSize) = py::none(), arg(s::kStepMode) = t.stepMode,
      arg(s::kIntegrator) = t.integrator, arg(s::kTolerance) = s::kTolerance.fallback,
      arg(s::kMinStep) = py::none(), arg(s::kMaxStep) = py::none(),
      arg(s::kDirection) = t.direction, arg(s::kVorticity) = t.vorticity,
      arg(s::kMaxLength) = s::kMaxLength.fallback, arg(s::kMaxTime) = s::kMaxTime.fallback,
      arg(s::kTerminalSpeed) = s::kTerminalSpeed.fallback, arg(s::kMemoryBudget) = t.memoryBudget,
      arg(s::kCpuTail) = t.cpuTail, arg(s::kBackend) = b.backend, arg(s::kDevice) = b.device,
      py::arg("validation") = false, py::arg("progress") = py::none(), py::arg("verbose") = false,
      ("Traces streamlines from seeds ((N, 3) points) through a Dataset (vector, point_data "
       "and periodic as for prepare(); frame_velocity 'auto' here the vector's mean over the "
       "cells that hold the seeds) or a prepared Field, as `amrstream trace` does. "
       "progress(done, total) counts seeds; verbose prints what the command line would.\n\n" +
       settingsDoc(keywords::kTrace))
          .c_str());
  m.def(
      "pathlines",
      [](std::vector<std::string> snapshots, py::object seeds, std::optional<std::string> vector,
         std::optional<std::string> pointData, std::optional<std::string> periodic,
         std::optional<std::string> interpolant, Given<std::optional<double>> startTime,
         Given<std::optional<double>> endTime, Given<std::optional<double>> stepSize,
         Given<double> releaseEvery, std::optional<std::string> lengthUnit,
         std::optional<std::map<std::string, std::string>> units, std::string backend,
         std::string device, bool validation, py::object progress, bool verbose) {
        const FieldOptions defaults;
        const FieldOptions field{vector.value_or(""), pointData.value_or(defaults.pointData),
                                 periodic.value_or(defaults.periodic),
                                 interpolant.value_or(defaults.interpolant), ""};
        PathlineSettings settings;
        settings.startTime = settingValue(s::kStartTime, startTime);
        settings.endTime = settingValue(s::kEndTime, endTime);
        settings.stepSize = settingValue(s::kTimeStep, stepSize);
        // 0, the default, releases no more particles: streaklines need a positive interval.
        Setting releases = s::kReleaseEvery;
        releases.least = 0.0;
        releases.positive = false;
        settings.releaseEvery = settingValue(releases, releaseEvery);
        const BackendRequest request{std::move(backend), std::move(device),
                                     validation || validationRequested()};
        return runPathlines(snapshots, seeds, field, settings, declaredUnits(lengthUnit, units),
                            request, progress, verbose);
      },
      py::arg("snapshots"), py::arg("seeds"), py::kw_only(), arg(s::kVector) = py::none(),
      arg(s::kPointData) = py::none(), arg(s::kPeriodic) = py::none(),
      arg(s::kInterpolant) = py::none(), arg(s::kStartTime) = py::none(),
      arg(s::kEndTime) = py::none(), arg(s::kTimeStep) = py::none(),
      arg(s::kReleaseEvery) = PathlineSettings{}.releaseEvery, py::arg("length_unit") = py::none(),
      py::arg("units") = py::none(), arg(s::kBackend) = b.backend, arg(s::kDevice) = b.device,
      py::arg("validation") = false, py::arg("progress") = py::none(), py::arg("verbose") = false,
      ("Traces pathlines from seeds ((N, 3) points, released at start_time) through a time "
       "series of snapshot files or glob patterns, ordered by the times the files state, as "
       "`amrstream pathlines` does; with release_every, streaklines. integration_time is "
       "physical time (streaklines: each particle's age); length_unit and units ({name: "
       "unit}) declare units for snapshots that do not state them, as load() does; "
       "progress(done, total) counts intervals.\n\n" +
       settingsDoc(keywords::kPathlines))
          .c_str());
  m.def(
      "reason_name",
      [](Given<int> code) {
        return reasonName(wholeNumberIn<int>("code", code.value, std::numeric_limits<int>::min(),
                                             std::numeric_limits<int>::max()));
      },
      py::arg("code"), "The name of a ReasonForTermination code, e.g. 'out of domain'.");
}

}  // namespace amrstream::python
