#include "output/vtp_writer.hpp"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "output/buffered_writer.hpp"
#include "output/vtk_xml_appended.hpp"

namespace amrstream::output {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the file declares byte_order=\"LittleEndian\" and its values are written as in "
              "memory");
static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "positions are written as packed Float32");

void checkConsistent(const std::filesystem::path& path, const flow::TraceSet& traces) {
  const std::size_t points = std::size_t(traces.seedCount) * traces.capacity;
  const auto fail = [&](const std::string& what) {
    throw std::invalid_argument(
        fmt::format("cannot write '{}': inconsistent traces: {}", path.string(), what));
  };
  if (traces.positions.size() != points || traces.times.size() != points ||
      traces.vectors.size() != points) {
    fail(fmt::format("{} seeds x {} points need {} values, have {} positions, {} times, {} vectors",
                     traces.seedCount, traces.capacity, points, traces.positions.size(),
                     traces.times.size(), traces.vectors.size()));
  }
  if (traces.pointCounts.size() != traces.seedCount || traces.reasons.size() != traces.seedCount) {
    fail(fmt::format("{} seeds but {} point counts and {} reasons", traces.seedCount,
                     traces.pointCounts.size(), traces.reasons.size()));
  }
  for (std::uint32_t seed = 0; seed < traces.seedCount; ++seed) {
    if (traces.pointCounts[seed] > traces.capacity) {
      fail(fmt::format("trace {} has {} points, capacity is {}", seed, traces.pointCounts[seed],
                       traces.capacity));
    }
  }
}

// Points written for a trace: a trace that ends at its seed becomes a 2-point line repeating its
// point, and a trace without points gets no line (see vtp_writer.hpp for why).
std::uint64_t writtenPoints(std::uint32_t pointCount) { return pointCount == 1 ? 2 : pointCount; }

// Point arrays need distinct names; a traced field called like one of ours gets a suffix.
std::string vectorArrayName(const flow::TraceSet& traces) {
  if (traces.vectorName.empty()) return "Vectors";
  if (traces.vectorName == "IntegrationTime" || traces.vectorName == "Speed") {
    return traces.vectorName + "_vector";
  }
  return traces.vectorName;
}

// The valid prefix of every trace's stride, trace after trace; a 1-point trace's point twice.
template <class T>
void writeValidPoints(BufferedWriter& out, const flow::TraceSet& traces,
                      const std::vector<T>& values) {
  for (std::uint32_t seed = 0; seed < traces.seedCount; ++seed) {
    const std::span<const T> valid(values.data() + traces.at(seed, 0), traces.pointCounts[seed]);
    out.write(std::as_bytes(valid));
    if (valid.size() == 1) out.write(std::as_bytes(valid));
  }
}

float speed(const glm::vec3& v) {
  const double x = v.x, y = v.y, z = v.z;
  return static_cast<float>(std::sqrt(x * x + y * y + z * z));
}

void writeSpeeds(BufferedWriter& out, const flow::TraceSet& traces) {
  for (std::uint32_t seed = 0; seed < traces.seedCount; ++seed) {
    for (std::uint32_t point = 0; point < traces.pointCounts[seed]; ++point) {
      out.put(speed(traces.vectors[traces.at(seed, point)]));
    }
    if (traces.pointCounts[seed] == 1) out.put(speed(traces.vectors[traces.at(seed, 0)]));
  }
}

// Cell arrays: one value per trace that has a line.
void writeSeedIds(BufferedWriter& out, const flow::TraceSet& traces) {
  for (std::uint32_t seed = 0; seed < traces.seedCount; ++seed) {
    if (traces.pointCounts[seed] > 0) out.put(static_cast<std::int32_t>(seed));
  }
}

void writeReasons(BufferedWriter& out, const flow::TraceSet& traces) {
  for (std::uint32_t seed = 0; seed < traces.seedCount; ++seed) {
    if (traces.pointCounts[seed] > 0) out.put(traces.reasons[seed]);
  }
}

// Lines as VTK XML stores cells: the point ids of all lines in a row ("connectivity"), and for
// each line the end of its ids ("offsets"; the first line starts at 0, which is not stored).
void writeConnectivity(BufferedWriter& out, std::uint64_t pointCount) {
  for (std::uint64_t id = 0; id < pointCount; ++id) out.put(static_cast<std::int64_t>(id));
}

void writeLineEnds(BufferedWriter& out, const flow::TraceSet& traces) {
  std::int64_t end = 0;
  for (const std::uint32_t count : traces.pointCounts) {
    if (count == 0) continue;
    end += static_cast<std::int64_t>(writtenPoints(count));
    out.put(end);
  }
}

}  // namespace

// An empty TraceSet (no seeds) is written as a valid file with 0 points and 0 lines whose
// arrays are all present and empty.
VtpCounts writeVtp(const std::filesystem::path& path, const flow::TraceSet& traces,
                   const VtpWriteOptions& options) {
  checkConsistent(path, traces);
  std::uint64_t pointCount = 0;
  std::uint64_t lineCount = 0;
  for (const std::uint32_t count : traces.pointCounts) {
    pointCount += writtenPoints(count);
    lineCount += count > 0 ? 1 : 0;
  }

  using Out = BufferedWriter&;
  const AppendedArray times{"IntegrationTime", "Float32", 1, pointCount * sizeof(float),
                            [&](Out out) { writeValidPoints(out, traces, traces.times); }};
  const AppendedArray speeds{"Speed", "Float32", 1, pointCount * sizeof(float),
                             [&](Out out) { writeSpeeds(out, traces); }};
  const AppendedArray vectors{vectorArrayName(traces), "Float32", 3, pointCount * sizeof(glm::vec3),
                              [&](Out out) { writeValidPoints(out, traces, traces.vectors); }};
  const AppendedArray seedIds{"SeedIds", "Int32", 1, lineCount * sizeof(std::int32_t),
                              [&](Out out) { writeSeedIds(out, traces); }};
  const AppendedArray reasons{"ReasonForTermination", "Int32", 1, lineCount * sizeof(std::int32_t),
                              [&](Out out) { writeReasons(out, traces); }};
  const AppendedArray points{"Points", "Float32", 3, pointCount * sizeof(glm::vec3),
                             [&](Out out) { writeValidPoints(out, traces, traces.positions); }};
  const AppendedArray connectivity{"connectivity", "Int64", 1, pointCount * sizeof(std::int64_t),
                                   [&](Out out) { writeConnectivity(out, pointCount); }};
  const AppendedArray offsets{"offsets", "Int64", 1, lineCount * sizeof(std::int64_t),
                              [&](Out out) { writeLineEnds(out, traces); }};

  struct Section {
    std::string open;
    std::string_view close;
    std::vector<const AppendedArray*> arrays;
  };
  const std::vector<Section> sections{
      {fmt::format("<PointData Scalars=\"Speed\" Vectors=\"{}\">", xmlAttribute(vectors.name)),
       "</PointData>",
       {&times, &speeds, &vectors}},
      {"<CellData>", "</CellData>", {&seedIds, &reasons}},
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
