#include "output/vtp_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "output/buffered_writer.hpp"
#include "output/vtk_xml_appended.hpp"

namespace amrstream::output {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the file declares byte_order=\"LittleEndian\" and its values are written as in "
              "memory");
static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "positions are written as packed Float32");

void checkConsistent(const std::filesystem::path& path, const flow::TraceSet& traces) {
  const auto fail = [&](const std::string& what) {
    throw std::invalid_argument(
        fmt::format("cannot write '{}': inconsistent traces: {}", path.string(), what));
  };
  const std::size_t lines = traces.lineCount();
  if (traces.directions.size() != lines || traces.steps.size() != lines ||
      traces.reasons.size() != lines || traces.offsets.size() != lines + 1)
    fail(fmt::format("{} lines but {} directions, {} steps, {} reasons and {} offsets", lines,
                     traces.directions.size(), traces.steps.size(), traces.reasons.size(),
                     traces.offsets.size()));
  if (traces.offsets.front() != 0) fail("the first line does not start at point 0");
  for (std::size_t i = 0; i < lines; ++i)
    if (traces.offsets[i + 1] < traces.offsets[i]) fail(fmt::format("line {} ends before it starts", i));
  const std::uint64_t points = traces.pointCount();
  if (traces.positions.size() != points || traces.times.size() != points ||
      traces.vectors.size() != points ||
      traces.channels.size() != points * traces.channelCount() ||
      traces.vorticity.size() != (traces.withVorticity ? points : 0))
    fail(fmt::format("{} points but {} positions, {} times, {} vectors, {} channel values, {} "
                     "vorticity values",
                     points, traces.positions.size(), traces.times.size(), traces.vectors.size(),
                     traces.channels.size(), traces.vorticity.size()));
}

// One polyline of the file: points [first, first + count) of the TraceSet, of line `line`.
struct Piece {
  std::uint64_t first = 0;
  std::uint64_t count = 0;
  std::uint32_t line = 0;
  bool last = true;  // the line's last piece
};

// The file's polylines: one per line with points, split where periodic lines wrap.
std::vector<Piece> piecesOf(const flow::TraceSet& traces, PeriodicLines periodicLines) {
  std::vector<Piece> pieces;
  const bool split = periodicLines == PeriodicLines::Split && traces.periodic.any();
  for (std::size_t line = 0; line < traces.lineCount(); ++line) {
    const std::uint64_t begin = traces.offsets[line], end = traces.offsets[line + 1];
    if (begin == end) continue;
    std::uint64_t first = begin;
    if (split)
      for (std::uint64_t p = begin + 1; p < end; ++p)
        if (traces.periodic.wraps(traces.positions[p - 1], traces.positions[p])) {
          pieces.push_back({first, p - first, std::uint32_t(line), false});
          first = p;
        }
    pieces.push_back({first, end - first, std::uint32_t(line), true});
  }
  return pieces;
}

std::uint64_t writtenPoints(const Piece& piece) { return piece.count == 1 ? 2 : piece.count; }

// Point values of every piece, `width` values per point; a 1-point piece's values twice.
template <class Values>
void writePerPoint(BufferedWriter& out, const std::vector<Piece>& pieces, const Values& values,
                   std::size_t width = 1) {
  using T = typename Values::value_type;
  for (const Piece& piece : pieces) {
    const std::span<const T> valid(values.data() + piece.first * width, piece.count * width);
    out.write(std::as_bytes(valid));
    if (piece.count == 1) out.write(std::as_bytes(valid));
  }
}

// One channel of the interleaved channel values.
void writeChannel(BufferedWriter& out, const std::vector<Piece>& pieces,
                  const flow::TraceSet& traces, std::size_t channel) {
  const std::size_t width = traces.channelCount();
  for (const Piece& piece : pieces)
    for (std::uint64_t k = 0; k < writtenPoints(piece); ++k)
      out.put(traces.channels[(piece.first + std::min(k, piece.count - 1)) * width + channel]);
}

// A value computed from each point index, for every written point.
template <class Value>
void writeDerived(BufferedWriter& out, const std::vector<Piece>& pieces, Value&& value) {
  for (const Piece& piece : pieces)
    for (std::uint64_t k = 0; k < writtenPoints(piece); ++k)
      out.put(value(piece.first + std::min(k, piece.count - 1)));
}

float speedAt(const flow::TraceSet& traces, std::uint64_t i) {
  const glm::dvec3 v(traces.vectors[i]);
  return static_cast<float>(glm::length(v));
}

// vtkStreamTracer's AngularVelocity: the vorticity's component along the unit tangent.
float angularVelocityAt(const flow::TraceSet& traces, std::uint64_t i) {
  const glm::dvec3 v(traces.vectors[i]), w(traces.vorticity[i]);
  const double speed = glm::length(v);
  return speed > 0.0 ? static_cast<float>(glm::dot(w, v) / speed) : 0.0f;
}

// vtkStreamTracer's Rotation: the angular velocity integrated along each line with the trapezoid
// rule over IntegrationTime, from 0 at the seed.
flow::Column<float> rotationOf(const flow::TraceSet& traces) {
  flow::Column<float> rotation(traces.pointCount(), 0.0f);
  for (std::size_t line = 0; line < traces.lineCount(); ++line) {
    double total = 0.0;
    for (std::uint64_t i = traces.offsets[line] + 1; i < traces.offsets[line + 1]; ++i) {
      total += 0.5 * (double(angularVelocityAt(traces, i - 1)) + angularVelocityAt(traces, i)) *
               (double(traces.times[i]) - traces.times[i - 1]);
      rotation[i] = static_cast<float>(total);
    }
  }
  return rotation;
}

// Positions continued across periodic faces: each wrap adds or removes one period.
flow::Column<glm::vec3> unwrappedPositions(const flow::TraceSet& traces) {
  flow::Column<glm::vec3> positions = traces.positions;
  const glm::dvec3 period = traces.periodic.upper - traces.periodic.lower;
  for (std::size_t line = 0; line < traces.lineCount(); ++line) {
    glm::dvec3 shift(0.0);
    for (std::uint64_t i = traces.offsets[line] + 1; i < traces.offsets[line + 1]; ++i) {
      for (int a = 0; a < 3; ++a) {
        if (!traces.periodic.axes[a]) continue;
        const double jump = double(traces.positions[i][a]) - traces.positions[i - 1][a];
        if (jump > 0.5 * period[a]) shift[a] -= period[a];
        if (jump < -0.5 * period[a]) shift[a] += period[a];
      }
      positions[i] = glm::vec3(glm::dvec3(traces.positions[i]) + shift);
    }
  }
  return positions;
}

// Array names must differ; a traced vector or channel named like one of ours gets a suffix.
std::string distinctName(std::string name, const std::vector<std::string>& taken,
                         std::string_view suffix) {
  while (std::find(taken.begin(), taken.end(), name) != taken.end()) name += suffix;
  return name;
}

}  // namespace

// An empty TraceSet (no lines) is written as a valid file with 0 points and 0 lines whose arrays
// are all present and empty.
VtpCounts writeVtp(const std::filesystem::path& path, const flow::TraceSet& traces,
                   const VtpWriteOptions& options) {
  checkConsistent(path, traces);
  const std::vector<Piece> pieces = piecesOf(traces, options.periodicLines);
  std::uint64_t pointCount = 0;
  for (const Piece& piece : pieces) pointCount += writtenPoints(piece);
  const std::uint64_t lineCount = pieces.size();
  const bool unwrap = options.periodicLines == PeriodicLines::Unwrapped && traces.periodic.any();
  const flow::Column<glm::vec3> unwrapped =
      unwrap ? unwrappedPositions(traces) : flow::Column<glm::vec3>{};
  const flow::Column<glm::vec3>& positions = unwrap ? unwrapped : traces.positions;
  const flow::Column<float> rotation =
      traces.withVorticity ? rotationOf(traces) : flow::Column<float>{};

  using Out = BufferedWriter&;
  const std::uint64_t floats = pointCount * sizeof(float), vec3s = pointCount * sizeof(glm::vec3);
  std::vector<std::string> ours{"IntegrationTime", "Speed", "Vorticity", "Rotation",
                                "AngularVelocity"};
  std::vector<AppendedArray> pointArrays;
  const std::string vectorName =
      distinctName(traces.vectorName.empty() ? "Vectors" : traces.vectorName, ours, "_vector");
  pointArrays.push_back({vectorName, "Float32", 3, vec3s,
                         [&](Out out) { writePerPoint(out, pieces, traces.vectors); }});
  ours.push_back(vectorName);
  for (std::size_t c = 0; c < traces.channelCount(); ++c) {
    const std::string name = distinctName(traces.channelNames[c], ours, "_channel");
    ours.push_back(name);
    pointArrays.push_back(
        {name, "Float32", 1, floats, [&, c](Out out) { writeChannel(out, pieces, traces, c); }});
  }
  pointArrays.push_back({"IntegrationTime", "Float32", 1, floats,
                         [&](Out out) { writePerPoint(out, pieces, traces.times); }});
  if (traces.withVorticity) {
    pointArrays.push_back({"Vorticity", "Float32", 3, vec3s,
                           [&](Out out) { writePerPoint(out, pieces, traces.vorticity); }});
    pointArrays.push_back({"Rotation", "Float32", 1, floats,
                           [&](Out out) { writePerPoint(out, pieces, rotation); }});
    pointArrays.push_back({"AngularVelocity", "Float32", 1, floats, [&](Out out) {
                             writeDerived(out, pieces, [&](std::uint64_t i) {
                               return angularVelocityAt(traces, i);
                             });
                           }});
  }
  pointArrays.push_back({"Speed", "Float32", 1, floats, [&](Out out) {
                           writeDerived(out, pieces,
                                        [&](std::uint64_t i) { return speedAt(traces, i); });
                         }});

  const AppendedArray reasons{"ReasonForTermination", "Int32", 1, lineCount * sizeof(std::int32_t),
                              [&](Out out) {
                                for (const Piece& piece : pieces)
                                  out.put(piece.last ? traces.reasons[piece.line]
                                                     : std::int32_t(AMRSTREAM_REASON_PERIODIC_WRAP));
                              }};
  const AppendedArray seedIds{"SeedIds", "Int32", 1, lineCount * sizeof(std::int32_t),
                              [&](Out out) {
                                for (const Piece& piece : pieces)
                                  out.put(static_cast<std::int32_t>(traces.seedIds[piece.line]));
                              }};
  const AppendedArray points{"Points", "Float32", 3, vec3s,
                             [&](Out out) { writePerPoint(out, pieces, positions); }};
  // Lines as VTK XML stores cells: the point ids of all lines in a row ("connectivity"), and for
  // each line the end of its ids ("offsets"; the first line starts at 0, which is not stored).
  const AppendedArray connectivity{"connectivity", "Int64", 1, pointCount * sizeof(std::int64_t),
                                   [&](Out out) {
                                     for (std::uint64_t id = 0; id < pointCount; ++id)
                                       out.put(static_cast<std::int64_t>(id));
                                   }};
  const AppendedArray offsets{"offsets", "Int64", 1, lineCount * sizeof(std::int64_t),
                              [&](Out out) {
                                std::int64_t end = 0;
                                for (const Piece& piece : pieces) {
                                  end += static_cast<std::int64_t>(writtenPoints(piece));
                                  out.put(end);
                                }
                              }};

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
