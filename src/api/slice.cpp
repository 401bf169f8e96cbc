#include "amrstream/slice.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "amrstream/builtin.hpp"
#include "amrstream/error.hpp"
#include "api/device.hpp"
#include "api/handles.hpp"
#include "api/provenance.hpp"
#include "api/render_scene.hpp"
#include "flow/uniform_resample.hpp"
#include "flow/vector_selection.hpp"
#include "gpu/plane_lic.hpp"
#include "output/polyline_writer.hpp"
#include "output/vti_writer.hpp"
#include "render/image/colour_map.hpp"
#include "render/image/png_io.hpp"
#include "slice/even_lines.hpp"
#include "slice/lic.hpp"
#include "slice/line_samples.hpp"
#include "slice/plane_field.hpp"
#include "slice/slice_figure.hpp"
#include "slice/slice_plane.hpp"
#include "util/stopwatch.hpp"

namespace amrstream {

namespace {

constexpr std::string_view kMagnitude = "magnitude";

std::string lowered(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

// The index of the channel `name` names in the point data, or -1 for "magnitude" (the vector's
// length); InputError naming `option` for any other name, offering `others` beside the channels.
int channelIndexOf(const std::string& name, const flow::VectorVolume& volume,
                   std::string_view option, std::string_view others = "magnitude") {
  if (name == kMagnitude) return -1;
  const auto found = std::find(volume.channelNames.begin(), volume.channelNames.end(), name);
  if (found == volume.channelNames.end())
    throw settingError(option, fmt::format("'{}' is not a channel of the point data ({}); give "
                                           "one, {}",
                                           name, fmt::join(volume.channelNames, ", "), others));
  return int(found - volume.channelNames.begin());
}

// The channel the background shows ("magnitude" for the vector's), or empty for none.
std::string chosenBackground(const SliceOptions& options, const flow::VectorVolume& volume) {
  if (options.background == "none") return {};
  if (options.background == "auto") {
    for (const std::string& name : volume.channelNames)
      if (const std::string l = lowered(name); l == "dens" || l == "density" || l == "rho")
        return name;
    return std::string(kMagnitude);
  }
  channelIndexOf(options.background, volume, "background", "magnitude, auto or none");
  return options.background;
}

// Per pixel, channel `channel` of the samples (or the vector's length where it is negative);
// NaN where the sample is not valid.
std::vector<float> backgroundValues(int channel, const flow::VectorVolume& volume,
                                    const flow::GridSamples& samples) {
  const std::size_t points = samples.valid.size(), count = volume.channelCount();
  std::vector<float> values(points, std::numeric_limits<float>::quiet_NaN());
  for (std::size_t n = 0; n < points; ++n) {
    if (!samples.valid[n]) continue;
    values[n] = channel < 0 ? glm::length(samples.vectors[n])
                            : samples.channels[n * count + std::size_t(channel)];
  }
  return values;
}

render::ColourScale backgroundScale(const SliceOptions& options, const std::vector<float>& values) {
  const render::ScaleKind kind = *render::parseScaleKind(options.colourScale);
  std::optional<render::ValueRange> range;
  if (options.range)
    range = render::ValueRange{float((*options.range)[0]), float((*options.range)[1])};
  return colourScaleOver(kind, range, widenSeen(nothingSeen(), kind, values), std::nullopt);
}

void writeSliceVti(const SliceJob& job, const Field& field, const slice::SlicePlane& plane,
                   const flow::GridSamples& samples, const std::vector<float>& lic) {
  const flow::VectorVolume& volume = volumeOf(field);
  output::VtiWriteOptions options;
  if (plane.axis < 0) {
    // The image's i and j run along the plane's u and v: its Direction.
    output::VtiFrame frame;
    frame.origin = plane.physical(plane.pixelCentre(0, 0));
    frame.spacing = glm::dvec3(plane.pixelSize(), 1.0);
    frame.axes = {plane.u, plane.v, plane.normal};
    options.frame = frame;
  }
  // Across an axis, ImageData's point (i, j, k) runs along x, y, z and the plane's pixels along
  // its (u, v); any other plane's image runs along (u, v, normal).
  const int uAxis = plane.axis < 0 ? 0 : plane.axis == 0 ? 1 : plane.axis == 1 ? 2 : 0;
  const int vAxis = plane.axis < 0 ? 1 : plane.axis == 0 ? 2 : plane.axis == 1 ? 0 : 1;
  flow::UniformGrid grid;
  glm::dvec3 lower = plane.point, upper = plane.point;
  lower[uAxis] = plane.lower.x;
  upper[uAxis] = plane.upper.x;
  lower[vAxis] = plane.lower.y;
  upper[vAxis] = plane.upper.y;
  grid.spec.lower = lower;
  grid.spec.upper = upper;
  grid.spec.dims = {1, 1, 1};
  grid.spec.dims[uAxis] = plane.width;
  grid.spec.dims[vAxis] = plane.height;
  const std::size_t count = volume.channelCount(), channels = count + (lic.empty() ? 0 : 1);
  const std::size_t points = samples.valid.size();
  grid.vectors.resize(points);
  grid.valid.resize(points);
  grid.channels.resize(points * channels);
  for (std::uint32_t j = 0; j < plane.height; ++j) {
    for (std::uint32_t i = 0; i < plane.width; ++i) {
      const std::size_t from = i + std::size_t(plane.width) * j;
      std::array<std::size_t, 3> at{0, 0, 0};
      at[std::size_t(uAxis)] = i;
      at[std::size_t(vAxis)] = j;
      const std::size_t to =
          at[0] + grid.spec.dims[0] * (at[1] + std::size_t(grid.spec.dims[1]) * at[2]);
      grid.vectors[to] = samples.vectors[from];
      grid.valid[to] = samples.valid[from];
      for (std::size_t c = 0; c < count; ++c)
        grid.channels[to * channels + c] = samples.channels[from * count + c];
      if (!lic.empty()) grid.channels[to * channels + count] = lic[from];
    }
  }
  options.vectorName = volume.vectorName;
  options.channelNames = volume.channelNames;
  if (!lic.empty()) options.channelNames.push_back("LIC");
  options.fieldData = datasetProvenance(field.source(), field.info(), volume);
  output::writeVti(job.vti, grid, options);
}

// The lines of at least 2 points as polylines with the samples along them and their arc length.
void writeLinesVtp(const SliceJob& job, const Field& field, const slice::SliceLayers& layers,
                   const slice::LineSamples& samples) {
  const flow::VectorVolume& volume = volumeOf(field);
  const std::size_t count = volume.channelCount();
  output::Polylines lines;
  output::PolylineArray vector{volume.vectorName, 3, {}}, arc{"ArcLength", 1, {}};
  std::vector<output::PolylineArray> channels;
  for (const std::string& name : volume.channelNames) channels.push_back({name, 1, {}});
  for (std::size_t line = 0; line < layers.lines.size(); ++line) {
    const std::vector<glm::dvec2>& points = layers.lines[line].points;
    if (points.size() < 2) continue;
    double length = 0.0;
    for (std::size_t k = 0; k < points.size(); ++k) {
      const std::uint64_t n = samples.offsets[line] + k;
      if (k > 0) length += glm::distance(points[k - 1], points[k]);
      lines.points.push_back(glm::vec3(samples.positions[n]));
      const glm::vec3 v = samples.vectors[n];
      vector.values.insert(vector.values.end(), {v.x, v.y, v.z});
      arc.values.push_back(float(length));
      for (std::size_t c = 0; c < count; ++c)
        channels[c].values.push_back(samples.channels[n * count + c]);
    }
    lines.offsets.push_back(lines.points.size());
  }
  lines.pointData = {std::move(vector), std::move(arc)};
  for (output::PolylineArray& channel : channels) lines.pointData.push_back(std::move(channel));
  lines.scalars = "ArcLength";
  lines.vectors = volume.vectorName;
  output::PolylineWriteOptions options;
  options.fieldData = datasetProvenance(field.source(), field.info(), volume);
  output::writePolylines(job.vtp, lines, options);
}

// The LIC of the plane's in-plane vector on the device of `choice`, sampled there.
std::vector<float> deviceLic(const flow::VectorVolume& volume, const slice::SlicePlane& plane,
                             const slice::LicOptions& options, const BackendRequest& request,
                             const BackendChoice& choice, const Log& log) {
  Stopwatch clock;
  const vk::Context ctx = createContext(request, choice);
  gpu::PlaneLic lic(ctx, choice.backend, volume);
  const double setup = clock.seconds();
  std::vector<float> intensity =
      lic.convolve(slice::pixelGrid(volume, plane), slice::licParams(plane, options));
  checkValidation(ctx);
  const gpu::PlaneLic::Times& t = lic.times();
  say(log, fmt::format("lic device backend {} on {} [device setup {:.2f} s: upload {:.2f} s, "
                       "structure {:.2f} s, kernels {:.2f} s; sampling and convolving {:.3f} s, "
                       "read {:.3f} s]",
                       gpu::backendName(choice.backend), ctx.deviceName(), setup,
                       lic.setup().uploadSeconds, lic.setup().structureSeconds,
                       lic.setup().pipelineSeconds, t.deviceSeconds, t.readSeconds));
  return intensity;
}

// A slice's plane, samples and layers, before they are drawn or written.
struct Sliced {
  slice::SlicePlane plane;
  flow::GridSamples samples;
  slice::SliceLayers layers;
  slice::LineSamples lineSamples;
  std::string background;
};

// The lines' colours and widths by the channels `options` name, from the samples along them.
void styleLines(const Field& field, const SliceOptions& options, Sliced& sliced) {
  const flow::VectorVolume& volume = volumeOf(field);
  slice::SliceLayers& layers = sliced.layers;
  const std::size_t count = volume.channelCount();
  if (!options.lineColourBy.empty()) {
    const int channel = channelIndexOf(options.lineColourBy, volume, "line_colour_by");
    layers.lineColourValues = slice::valuesAlongLines(sliced.lineSamples, count, channel);
    std::vector<float> all;
    for (const std::vector<float>& line : layers.lineColourValues)
      all.insert(all.end(), line.begin(), line.end());
    const render::ScaleKind kind = *render::parseScaleKind(options.lineColourScale);
    render::ColourBar& bar = layers.lineColours;
    bar.map = *render::parseColourMap(options.lineColourMap);
    bar.scale =
        colourScaleOver(kind, std::nullopt, widenSeen(nothingSeen(), kind, all), std::nullopt);
    bar.label = channel < 0 ? "|" + volume.vectorName + "|" : options.lineColourBy;
    bar.unit = unitOf(field.info(), channel < 0 ? volume.vectorName : options.lineColourBy);
  }
  if (!options.lineWidthBy.empty()) {
    const int channel = channelIndexOf(options.lineWidthBy, volume, "line_width_by");
    layers.lineWidthValues = slice::valuesAlongLines(sliced.lineSamples, count, channel);
    float low = std::numeric_limits<float>::infinity(), high = -low;
    for (const std::vector<float>& line : layers.lineWidthValues)
      for (const float v : line)
        if (std::isfinite(v)) low = std::min(low, v), high = std::max(high, v);
    layers.lineWidthRange = {low, high};
  }
}

// The field's options, with no vector where the figure needs none (no lines, no LIC) and the
// data have none of the known ones: a channel alone on the plane.
FieldOptions sliceFieldOptions(const SliceJob& job, const Dataset& cells) {
  FieldOptions options = job.field;
  if (job.slice.lines || job.slice.lic || !options.vector.empty()) return options;
  try {
    flow::chooseVectorChannels(cellsOf(cells), "");
  } catch (const InputError&) {
    options.vector = std::string(flow::kNoVector);
  }
  return options;
}

slice::SlicePlane planeOf(const flow::VectorVolume& volume, const SliceOptions& options) {
  if (volume.planar && options.normal != "z")
    throw settingError("normal", fmt::format("'{}': 2D data are sliced across z only, through "
                                             "their plane",
                                             options.normal));
  slice::SliceRequest request;
  request.normal = options.normal;
  if (options.point)
    request.point = glm::dvec3((*options.point)[0], (*options.point)[1], (*options.point)[2]);
  request.window = options.window;
  request.width = options.width;
  return slice::slicePlane(request, volume.transform.toPhysical(glm::dvec3(volume.domain.lower)),
                           volume.transform.toPhysical(glm::dvec3(volume.domain.upper)));
}

Sliced sliceOnPlane(const Field& field, const slice::SlicePlane& plane, const SliceOptions& options,
                    const Reporter& reporter) {
  const Log& log = reporter.log;
  const flow::VectorVolume& volume = volumeOf(field);
  Sliced sliced;
  sliced.plane = plane;
  sliced.background = chosenBackground(options, volume);
  Stopwatch clock;
  sliced.samples = slice::samplePixels(
      volume, slice::pixelGrid(volume, plane),
      [&](std::size_t done) { reporter.advance("slicing", done, plane.height); });
  say(log,
      fmt::format("plane      {} x {} pixels across {}, {} with data, background {} "
                  "[{:.2f} s]",
                  plane.width, plane.height, options.normal, withCommas(sliced.samples.validCount),
                  sliced.background.empty() ? "none" : sliced.background, clock.seconds()));
  slice::SliceLayers& layers = sliced.layers;
  layers.lengthUnit = shortLengthUnit(field.info());
  layers.lineWidthPixels = options.lineWidth;
  if (!sliced.background.empty()) {
    layers.background = backgroundValues(channelIndexOf(sliced.background, volume, "background"),
                                         volume, sliced.samples);
    layers.colours.map = *render::parseColourMap(options.colourMap);
    layers.colours.scale = backgroundScale(options, layers.background);
    const bool magnitude = sliced.background == kMagnitude;
    layers.colours.label = magnitude ? "|" + volume.vectorName + "|" : sliced.background;
    layers.colours.unit = unitOf(field.info(), magnitude ? volume.vectorName : sliced.background);
  }
  const double windowWidth = plane.upper.x - plane.lower.x;
  if (options.lic) {
    clock.restart();
    slice::LicOptions lic;
    const double length = options.licLength > 0.0 ? options.licLength : windowWidth / 50.0;
    lic.halfLengthPixels = float(length / plane.pixelSize().x);
    if (!(lic.halfLengthPixels / lic.stepPixels <= float(slice::kMaxLicStepsEachWay)))
      throw settingError(
          "lic_length",
          fmt::format("{:g} is {:g} pixels each way, more than the {:g} the LIC "
                      "reaches",
                      length, lic.halfLengthPixels, slice::kMaxLicStepsEachWay * lic.stepPixels));
    const BackendChoice choice = chooseBackend(options.backend, BackendUse::Slice, log);
    layers.lic =
        choice.backend == gpu::Backend::Cpu
            ? slice::lineIntegralConvolution(slice::inPlaneImage(plane, sliced.samples), lic)
            : deviceLic(volume, plane, lic, options.backend, choice, log);
    say(log, fmt::format("lic        kernel {:g} each way ({:.1f} pixels), {} [{:.2f} s]", length,
                         lic.halfLengthPixels, gpu::backendName(choice.backend), clock.seconds()));
  }
  if (options.lines) {
    clock.restart();
    slice::EvenLinesOptions even;
    even.lower = plane.lower;
    even.upper = plane.upper;
    even.separation = options.lineSeparation > 0.0 ? options.lineSeparation : windowWidth / 30.0;
    layers.lines = slice::evenlySpacedLines(slice::exactInPlane(volume, plane), even);
    sliced.lineSamples = slice::sampleAlongLines(volume, plane, layers.lines);
    styleLines(field, options, sliced);
    std::size_t points = 0;
    for (const slice::PlaneLine& line : layers.lines) points += line.points.size();
    say(log,
        fmt::format("lines      {} evenly spaced {:g} apart, {} points [{:.2f} s]",
                    layers.lines.size(), even.separation, withCommas(points), clock.seconds()));
  }
  return sliced;
}

}  // namespace

void checkSliceOptions(const SliceOptions& options) {
  if (!render::parseColourMap(options.colourMap))
    throw settingError("colour_map", fmt::format("'{}' is not one of {}", options.colourMap,
                                                 render::colourMapNames()));
  if (!render::parseScaleKind(options.colourScale))
    throw settingError("colour_scale",
                       fmt::format("'{}' is not linear, log or symlog", options.colourScale));
  if (!render::parseColourMap(options.lineColourMap))
    throw settingError(
        "line_colour_map",
        fmt::format("'{}' is not one of {}", options.lineColourMap, render::colourMapNames()));
  if (!render::parseScaleKind(options.lineColourScale))
    throw settingError("line_colour_scale",
                       fmt::format("'{}' is not linear, log or symlog", options.lineColourScale));
  if (options.range) {
    const auto [low, high] = *options.range;
    if (!std::isfinite(low) || !std::isfinite(high) || !(low < high))
      throw settingError("range", "give MIN,MAX, finite, with MIN below MAX");
    if (options.colourScale == "log" && !(low > 0.0))
      throw settingError("range", "a log scale needs a positive MIN");
  }
  if (options.width < 1 || options.width > 16384)
    throw settingError("width", fmt::format("{} is outside 1..16384", options.width));
  if (!std::isfinite(options.lineSeparation) || options.lineSeparation < 0.0)
    throw settingError("line_separation", "give a positive length (0: the default)");
  if (!std::isfinite(options.lineWidth) || !(options.lineWidth > 0.0f) || options.lineWidth > 64.0f)
    throw settingError("line_width", "give a width in pixels above 0, at most 64");
  if (!std::isfinite(options.licLength) || options.licLength < 0.0)
    throw settingError("lic_length", "give a positive length (0: the default)");
}

void checkSliceJob(const SliceJob& job) {
  if (job.dataset.input.starts_with("builtin:")) checkBuiltinSize(job.dataset.builtin);
  checkSliceOptions(job.slice);
  if (!job.vtp.empty() && !job.slice.lines)
    throw settingError("vtp", "there are no field lines to write without lines (--no-lines)");
}

SliceFigure makeSlice(const Field& field, const SliceOptions& options, const Reporter& reporter) {
  checkSliceOptions(options);
  const Sliced sliced = sliceOnPlane(field, planeOf(volumeOf(field), options), options, reporter);
  SliceFigure figure;
  figure.image = publicImage(slice::drawSliceFigure(sliced.plane, sliced.layers));
  figure.width = sliced.plane.width;
  figure.height = sliced.plane.height;
  figure.window = {sliced.plane.lower.x, sliced.plane.lower.y, sliced.plane.upper.x,
                   sliced.plane.upper.y};
  figure.axes = sliced.plane.axisNames();
  figure.backgroundName = sliced.background;
  figure.background = sliced.layers.background;
  figure.lic = sliced.layers.lic;
  figure.lineColourValues = sliced.layers.lineColourValues;
  figure.lineWidthValues = sliced.layers.lineWidthValues;
  for (const slice::PlaneLine& line : sliced.layers.lines) {
    std::vector<std::array<double, 2>>& points = figure.lines.emplace_back();
    for (const glm::dvec2& p : line.points) points.push_back({p.x, p.y});
  }
  return figure;
}

void runSliceJob(const SliceJob& job, const Reporter& reporter) {
  checkSliceJob(job);
  const Log& log = reporter.log;
  Stopwatch clock;
  const Dataset cells = load(job.dataset.input, job.dataset.builtin, job.dataset.units);
  say(log, fmt::format("input      {}: {} cells [{:.2f} s]", cells.source(),
                       withCommas(cells.cellCount()), clock.seconds()));
  const auto [cellChecks, overlapCheck] = cells.checkSeconds();
  reporter.lap("input", {{"cell checks", cellChecks}, {"overlap check", overlapCheck}});
  clock.restart();
  const Field field = buildField(cells, sliceFieldOptions(job, cells), KeepDataset::No);
  const flow::VectorVolume& volume = volumeOf(field);
  say(log,
      fmt::format("structure  {} bricks, {} regions, vector {} [{:.2f} s]",
                  withCommas(volume.originalBrickCount), withCommas(volume.regions.regions.size()),
                  volume.vectorName, clock.seconds()));
  reporter.lap("structure");
  const slice::SlicePlane plane = planeOf(volume, job.slice);
  const Sliced sliced = sliceOnPlane(field, plane, job.slice, reporter);
  reporter.lap("slicing");
  clock.restart();
  render::writePng(job.out, slice::drawSliceFigure(plane, sliced.layers));
  if (!job.vti.empty()) writeSliceVti(job, field, plane, sliced.samples, sliced.layers.lic);
  if (!job.vtp.empty()) writeLinesVtp(job, field, sliced.layers, sliced.lineSamples);
  say(log,
      fmt::format("output     {}{}{} [{:.2f} s]", job.out, job.vti.empty() ? "" : ", " + job.vti,
                  job.vtp.empty() ? "" : ", " + job.vtp, clock.seconds()));
  reporter.lap("output");
}

}  // namespace amrstream
