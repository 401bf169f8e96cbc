#include "output/vtp_writer.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "output/vtk_xml_appended.hpp"

namespace amrstream::output {
namespace {

using flow::PointColumn;

static_assert(std::endian::native == std::endian::little,
              "the file declares byte_order=\"LittleEndian\" and its values are written as in "
              "memory");
static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "positions are written as packed Float32");

[[noreturn]] void inconsistent(const std::filesystem::path& path, const std::string& what) {
  throw std::invalid_argument(
      fmt::format("cannot write '{}': inconsistent traces: {}", path.string(), what));
}

void checkLines(const std::filesystem::path& path, const flow::TraceSet& traces) {
  const std::size_t lines = traces.lineCount();
  if (traces.directions.size() != lines || traces.steps.size() != lines ||
      traces.reasons.size() != lines || traces.offsets.size() != lines + 1)
    inconsistent(path, fmt::format("{} lines but {} directions, {} steps, {} reasons and {} "
                                   "offsets",
                                   lines, traces.directions.size(), traces.steps.size(),
                                   traces.reasons.size(), traces.offsets.size()));
  if (traces.offsets.front() != 0) inconsistent(path, "the first line does not start at point 0");
  for (std::size_t i = 0; i < lines; ++i)
    if (traces.offsets[i + 1] < traces.offsets[i])
      inconsistent(path, fmt::format("line {} ends before it starts", i));
}

void checkPoints(const std::filesystem::path& path, const flow::TraceSet& traces) {
  const std::uint64_t points = traces.pointCount();
  if (traces.positions.size() != points || traces.times.size() != points ||
      traces.vectors.size() != points || traces.channels.size() != points * traces.channelCount() ||
      traces.vorticity.size() != (traces.withVorticity ? points : 0) ||
      traces.positionsLow.size() != (traces.precisePositions ? points : 0))
    inconsistent(path, fmt::format("{} points but {} positions, {} times, {} vectors, {} channel "
                                   "values, {} vorticity values, {} low parts of positions",
                                   points, traces.positions.size(), traces.times.size(),
                                   traces.vectors.size(), traces.channels.size(),
                                   traces.vorticity.size(), traces.positionsLow.size()));
}

// One polyline of the file: points [first, first + count) of line `line` (counted along it).
struct Piece {
  std::uint32_t line = 0;
  std::uint64_t first = 0;
  std::uint64_t count = 0;
  bool last = true;  // the line's last piece
};

std::uint64_t writtenPoints(const Piece& piece) { return piece.count == 1 ? 2 : piece.count; }

// The file's polylines: one per line with points, split where periodic lines wrap.
std::vector<Piece> piecesOf(const flow::TraceView& traces, PeriodicLines periodicLines) {
  const flow::TraceSet& lines = traces.lines();
  const bool split = periodicLines == PeriodicLines::Split && lines.periodic.any();
  if (!split) {
    std::vector<Piece> pieces(lines.lineCount());
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, lines.lineCount(), 1 << 14),
                      [&](const tbb::blocked_range<std::uint32_t>& range) {
                        for (std::uint32_t line = range.begin(); line < range.end(); ++line)
                          pieces[line] = {line, 0, lines.pointCount(line), true};
                      });
    std::erase_if(pieces, [](const Piece& piece) { return piece.count == 0; });
    return pieces;
  }
  std::vector<Piece> pieces;
  std::vector<double> scratch;
  for (std::uint32_t line = 0; line < lines.lineCount(); ++line) {
    const std::uint64_t count = lines.pointCount(line);
    if (count == 0) continue;
    std::uint64_t first = 0;
    const std::span<const double> p = flow::exactPositions(traces, line, scratch);
    const auto at = [&](std::uint64_t k) {
      return glm::dvec3(p[3 * k], p[3 * k + 1], p[3 * k + 2]);
    };
    for (std::uint64_t k = 1; k < count; ++k)
      if (lines.periodic.wraps(at(k - 1), at(k))) {
        pieces.push_back({line, first, k - first, false});
        first = k;
      }
    pieces.push_back({line, first, count - first, true});
  }
  return pieces;
}

// The file's polylines and where each starts among the written points.
struct PieceTable {
  std::vector<Piece> pieces;
  std::vector<std::uint64_t> firstWritten;  // per piece, then the total
  std::uint64_t points() const { return firstWritten.back(); }
};

PieceTable pieceTable(std::vector<Piece> pieces) {
  PieceTable table{std::move(pieces), {0}};
  for (const Piece& piece : table.pieces)
    table.firstWritten.push_back(table.firstWritten.back() + writtenPoints(piece));
  return table;
}

// The buffers a column's values along a line are made in, reused from line to line: `values`
// holds what a column returns when it is not a view of the stored points, the others the columns
// it is made from.
template <typename T>
struct LineScratch {
  std::vector<T> values;
  std::vector<float> vectors, channels, vorticity, times, omega;
  std::vector<double> exact;
};

// Bytes [first, first + out.size()) of the point array `name`, `width` values of type T (float or
// double) per written point, whose values along a line `lineValues(line, scratch)` gives; each
// piece takes its part of its line (a 1-point piece its values twice). Thread-safe when
// lineValues is. Throws std::runtime_error naming the array and the point for a value that is not
// finite: no inf or NaN is ever written (the file is then not made).
template <typename T, typename LineValues>
void fillPoints(const PieceTable& table, std::size_t width, const LineValues& lineValues,
                const std::string& name, std::uint64_t first, std::span<std::byte> out) {
  const std::uint64_t pointBytes = width * sizeof(T);
  const std::uint64_t begin = first / pointBytes;
  const std::uint64_t end = (first + out.size() + pointBytes - 1) / pointBytes;
  std::vector<T> values((end - begin) * width);
  LineScratch<T> scratch;
  std::size_t k = std::upper_bound(table.firstWritten.begin(), table.firstWritten.end(), begin) -
                  table.firstWritten.begin() - 1;
  T* to = values.data();
  for (std::uint64_t w = begin; w < end; ++k) {
    const Piece& piece = table.pieces[k];
    const std::span<const T> line = lineValues(piece.line, scratch);
    const std::uint64_t stop = std::min(end, table.firstWritten[k + 1]);
    if (piece.count == 1) {  // its one point, written twice
      for (; w < stop; ++w) to = std::copy_n(line.data() + piece.first * width, width, to);
    } else {
      const std::uint64_t point = piece.first + (w - table.firstWritten[k]);
      to = std::copy_n(line.data() + point * width, (stop - w) * width, to);
      w = stop;
    }
  }
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw std::runtime_error(
          fmt::format("the point array '{}' has a non-finite value ({}) at "
                      "written point {}: nothing was written",
                      name, values[i], begin + i / width));
  std::memcpy(out.data(),
              reinterpret_cast<const std::byte*>(values.data()) + (first - begin * pointBytes),
              out.size());
}

// A Float32 (T = float) or Float64 (T = double) point array of `components` values per point,
// made in parallel by fillPoints.
template <typename T = float, typename LineValues>
AppendedArray pointArray(std::string name, int components, const PieceTable& table,
                         LineValues lineValues) {
  static_assert(std::is_same_v<T, float> || std::is_same_v<T, double>);
  const std::string_view type = std::is_same_v<T, float> ? "Float32" : "Float64";
  const std::size_t width = static_cast<std::size_t>(components);
  return {name,
          type,
          components,
          table.points() * width * sizeof(T),
          {},
          [&table, width, lineValues, name](std::uint64_t first, std::span<std::byte> out) {
            fillPoints<T>(table, width, lineValues, name, first, out);
          }};
}

// A column as it is stored.
auto storedColumn(const flow::TraceView& traces, PointColumn column) {
  return [&traces, column](std::uint32_t line, LineScratch<float>& scratch) {
    return traces.column(column, line, scratch.values);
  };
}

// One channel of the interleaved channel values.
auto channelColumn(const flow::TraceView& traces, std::size_t channel) {
  return [&traces, channel](std::uint32_t line, LineScratch<float>& scratch) {
    const std::size_t width = traces.lines().channelCount();
    const std::span<const float> values =
        traces.column(PointColumn::Channels, line, scratch.channels);
    std::vector<float>& out = scratch.values;
    out.resize(values.size() / width);
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = values[k * width + channel];
    return std::span<const float>(out);
  };
}

float speedOf(const float* v) {
  const double x = v[0], y = v[1], z = v[2];
  return static_cast<float>(std::sqrt(x * x + y * y + z * z));
}

auto speedColumn(const flow::TraceView& traces) {
  return [&traces](std::uint32_t line, LineScratch<float>& scratch) {
    const std::span<const float> v = traces.column(PointColumn::Vectors, line, scratch.vectors);
    std::vector<float>& out = scratch.values;
    out.resize(v.size() / 3);
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = speedOf(&v[3 * k]);
    return std::span<const float>(out);
  };
}

// vtkStreamTracer's AngularVelocity: the vorticity's component along the unit tangent.
void angularVelocities(const flow::TraceView& traces, std::uint32_t line, std::vector<float>& out,
                       LineScratch<float>& scratch) {
  const std::span<const float> v = traces.column(PointColumn::Vectors, line, scratch.vectors);
  const std::span<const float> w = traces.column(PointColumn::Vorticity, line, scratch.vorticity);
  out.resize(v.size() / 3);
  for (std::size_t k = 0; k < out.size(); ++k) {
    const glm::dvec3 velocity(v[3 * k], v[3 * k + 1], v[3 * k + 2]);
    const glm::dvec3 vorticity(w[3 * k], w[3 * k + 1], w[3 * k + 2]);
    const double speed = glm::length(velocity);
    out[k] = speed > 0.0 ? static_cast<float>(glm::dot(vorticity, velocity) / speed) : 0.0f;
  }
}

auto angularVelocityColumn(const flow::TraceView& traces) {
  return [&traces](std::uint32_t line, LineScratch<float>& scratch) {
    angularVelocities(traces, line, scratch.values, scratch);
    return std::span<const float>(scratch.values);
  };
}

// vtkStreamTracer's Rotation: the angular velocity integrated along each line with the trapezoid
// rule over IntegrationTime, from 0 at the seed.
auto rotationColumn(const flow::TraceView& traces) {
  return [&traces](std::uint32_t line, LineScratch<float>& scratch) {
    std::vector<float>& omega = scratch.omega;
    angularVelocities(traces, line, omega, scratch);
    const std::span<const float> t = traces.column(PointColumn::Times, line, scratch.times);
    std::vector<float>& out = scratch.values;
    out.assign(omega.size(), 0.0f);
    double total = 0.0;
    for (std::size_t k = 1; k < omega.size(); ++k) {
      total += 0.5 * (double(omega[k - 1]) + omega[k]) * (double(t[k]) - t[k - 1]);
      out[k] = static_cast<float>(total);
    }
    return std::span<const float>(out);
  };
}

// Precise positions, joined.
auto exactPositionColumn(const flow::TraceView& traces) {
  return [&traces](std::uint32_t line, LineScratch<double>& scratch) {
    return flow::exactPositions(traces, line, scratch.values);
  };
}

// Positions continued across periodic faces: each wrap adds or removes one period. Found from the
// exact positions, written as T.
template <typename T>
auto unwrappedPositionColumn(const flow::TraceView& traces) {
  return [&traces](std::uint32_t line, LineScratch<T>& scratch) {
    const flow::PeriodicBox& box = traces.lines().periodic;
    const std::span<const double> p = flow::exactPositions(traces, line, scratch.exact);
    std::vector<T>& out = scratch.values;
    out.assign(p.begin(), p.end());
    const glm::dvec3 period = box.upper - box.lower;
    glm::dvec3 shift(0.0);
    for (std::size_t k = 1; k < p.size() / 3; ++k) {
      for (int a = 0; a < 3; ++a) {
        if (!box.axes[a]) continue;
        const double jump = p[3 * k + a] - p[3 * (k - 1) + a];
        if (jump > 0.5 * period[a]) shift[a] -= period[a];
        if (jump < -0.5 * period[a]) shift[a] += period[a];
        out[3 * k + a] = static_cast<T>(p[3 * k + a] + shift[a]);
      }
    }
    return std::span<const T>(out);
  };
}

// <Points>: Float64 for precise positions, else Float32 as stored.
AppendedArray pointsArray(const flow::TraceView& traces, const PieceTable& table, bool unwrap) {
  if (traces.lines().precisePositions)
    return unwrap ? pointArray<double>("Points", 3, table, unwrappedPositionColumn<double>(traces))
                  : pointArray<double>("Points", 3, table, exactPositionColumn(traces));
  return unwrap ? pointArray("Points", 3, table, unwrappedPositionColumn<float>(traces))
                : pointArray("Points", 3, table, storedColumn(traces, PointColumn::Positions));
}

// Array names must differ; a traced vector or channel named like one of ours gets a suffix.
std::string distinctName(std::string name, const std::vector<std::string>& taken,
                         std::string_view suffix) {
  while (std::find(taken.begin(), taken.end(), name) != taken.end()) name += suffix;
  return name;
}

// The point data: the vectors, the channels, the integration time, the vorticity's arrays when
// traced, and the speed; `vectorName` is the vectors' name, distinct from the others.
std::vector<AppendedArray> pointDataArrays(const flow::TraceView& traces, const PieceTable& table,
                                           std::string& vectorName) {
  const flow::TraceSet& lines = traces.lines();
  std::vector<std::string> ours{"IntegrationTime", "Speed", "Vorticity", "Rotation",
                                "AngularVelocity"};
  std::vector<AppendedArray> arrays;
  vectorName =
      distinctName(lines.vectorName.empty() ? "Vectors" : lines.vectorName, ours, "_vector");
  ours.push_back(vectorName);
  arrays.push_back(pointArray(vectorName, 3, table, storedColumn(traces, PointColumn::Vectors)));
  for (std::size_t c = 0; c < lines.channelCount(); ++c) {
    const std::string name = distinctName(lines.channelNames[c], ours, "_channel");
    ours.push_back(name);
    arrays.push_back(pointArray(name, 1, table, channelColumn(traces, c)));
  }
  arrays.push_back(
      pointArray("IntegrationTime", 1, table, storedColumn(traces, PointColumn::Times)));
  if (lines.withVorticity) {
    arrays.push_back(
        pointArray("Vorticity", 3, table, storedColumn(traces, PointColumn::Vorticity)));
    arrays.push_back(pointArray("Rotation", 1, table, rotationColumn(traces)));
    arrays.push_back(pointArray("AngularVelocity", 1, table, angularVelocityColumn(traces)));
  }
  arrays.push_back(pointArray("Speed", 1, table, speedColumn(traces)));
  return arrays;
}

// An array of `count` values of type T (VTK type `type`), value i being valueAt(i); made in
// parallel. valueAt must be thread-safe.
template <typename T, typename ValueAt>
AppendedArray indexedArray(std::string name, std::string_view type, std::uint64_t count,
                           ValueAt valueAt) {
  return {std::move(name),
          type,
          1,
          count * sizeof(T),
          {},
          [valueAt](std::uint64_t first, std::span<std::byte> out) {
            const std::uint64_t begin = first / sizeof(T);
            std::vector<T> values((first + out.size() + sizeof(T) - 1) / sizeof(T) - begin);
            for (std::size_t i = 0; i < values.size(); ++i) values[i] = valueAt(begin + i);
            std::memcpy(out.data(),
                        reinterpret_cast<const std::byte*>(values.data()) + first % sizeof(T),
                        out.size());
          }};
}

}  // namespace

VtpCounts writeVtp(const std::filesystem::path& path, const flow::TraceSet& traces,
                   const VtpWriteOptions& options) {
  checkLines(path, traces);
  checkPoints(path, traces);
  return writeVtp(path, flow::TraceSetView(traces), options);
}

// An empty trace (no lines) is written as a valid file with 0 points and 0 lines whose arrays
// are all present and empty.
VtpCounts writeVtp(const std::filesystem::path& path, const flow::TraceView& traces,
                   const VtpWriteOptions& options) {
  const flow::TraceSet& lines = traces.lines();
  checkLines(path, lines);
  const PieceTable table = pieceTable(piecesOf(traces, options.periodicLines));
  const std::vector<Piece>& pieces = table.pieces;
  const std::uint64_t pointCount = table.points();
  const std::uint64_t lineCount = pieces.size();
  const bool unwrap = options.periodicLines == PeriodicLines::Unwrapped && lines.periodic.any();

  std::string vectorName;
  const std::vector<AppendedArray> pointArrays = pointDataArrays(traces, table, vectorName);
  const AppendedArray reasons =
      indexedArray<std::int32_t>("ReasonForTermination", "Int32", lineCount, [&](std::uint64_t i) {
        return pieces[i].last ? lines.reasons[pieces[i].line]
                              : std::int32_t(AMRSTREAM_REASON_PERIODIC_WRAP);
      });
  const AppendedArray seedIds = indexedArray<std::int32_t>(
      "SeedIds", "Int32", lineCount,
      [&](std::uint64_t i) { return static_cast<std::int32_t>(lines.seedIds[pieces[i].line]); });
  const AppendedArray points = pointsArray(traces, table, unwrap);
  // Lines as VTK XML stores cells: the point ids of all lines in a row ("connectivity"), and for
  // each line the end of its ids ("offsets"; the first line starts at 0, which is not stored).
  const AppendedArray connectivity =
      indexedArray<std::int64_t>("connectivity", "Int64", pointCount,
                                 [](std::uint64_t i) { return static_cast<std::int64_t>(i); });
  const AppendedArray offsets = indexedArray<std::int64_t>(
      "offsets", "Int64", lineCount,
      [&](std::uint64_t i) { return static_cast<std::int64_t>(table.firstWritten[i + 1]); });

  struct Section {
    std::string open;
    std::string_view close;
    std::vector<const AppendedArray*> arrays;
  };
  std::vector<const AppendedArray*> pointData;
  for (const AppendedArray& array : pointArrays) pointData.push_back(&array);
  const std::vector<Section> sections{
      {fmt::format("<PointData Scalars=\"IntegrationTime\" Vectors=\"{}\">",
                   xmlAttribute(vectorName)),
       "</PointData>", pointData},
      {"<CellData>", "</CellData>", {&reasons, &seedIds}},
      {"<Points>", "</Points>", {&points}},
      {"<Lines>", "</Lines>", {&connectivity, &offsets}},
  };
  AppendedFileWriter file("PolyData", options.compression);
  file.markup("  <PolyData>\n");
  file.fieldData(options.fieldData, 4);
  file.markup(
      fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"0\" NumberOfLines=\"{}\" "
                  "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n",
                  pointCount, lineCount));
  for (const Section& section : sections) {
    file.markup(fmt::format("      {}\n", section.open));
    for (const AppendedArray* array : section.arrays) file.dataArray(*array, 8);
    file.markup(fmt::format("      {}\n", section.close));
  }
  file.markup("    </Piece>\n  </PolyData>\n");
  file.write(path);
  return {lineCount, pointCount};
}

}  // namespace amrstream::output
