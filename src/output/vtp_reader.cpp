#include "output/vtp_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "output/vtk_xml_file.hpp"
#include "util/host_memory.hpp"

namespace amrstream::output {
namespace {

struct PieceCounts {
  std::uint64_t points = 0;
  std::uint64_t verts = 0;
  std::uint64_t lines = 0;
  std::uint64_t cells = 0;  // all four kinds; cell arrays hold one tuple per cell
};

const XmlElement& onlyPiece(const VtkXmlFile& file) {
  if (file.datasetType() != "PolyData") {
    file.fail(fmt::format("a VTK XML \"{}\" file, not PolyData (.vtp)", file.datasetType()));
  }
  const std::vector<const XmlElement*> polyData = file.root().childrenNamed("PolyData");
  if (polyData.size() != 1) {
    file.fail(fmt::format("<VTKFile> has {} <PolyData> elements, expected 1", polyData.size()));
  }
  const std::vector<const XmlElement*> pieces = polyData.front()->childrenNamed("Piece");
  if (pieces.empty()) file.fail("<PolyData> has no <Piece>");
  if (pieces.size() > 1) {
    file.fail(
        fmt::format("the file has {} pieces; only single-piece files are read (merge them "
                    "first, e.g. with ParaView's Merge Blocks or vtkAppendPolyData)",
                    pieces.size()));
  }
  return *pieces.front();
}

PieceCounts countsOf(const VtkXmlFile& file, const XmlElement& piece) {
  PieceCounts counts;
  counts.points = file.count(piece, "NumberOfPoints");
  counts.verts = file.count(piece, "NumberOfVerts", 0);
  counts.lines = file.count(piece, "NumberOfLines", 0);
  const std::uint64_t strips = file.count(piece, "NumberOfStrips", 0);
  const std::uint64_t polys = file.count(piece, "NumberOfPolys", 0);
  // Each count is backed by data in the file, so real sums are far from overflowing; a sum that
  // wraps can only come from a corrupt header.
  counts.cells = counts.verts + counts.lines + strips + polys;
  if (counts.cells < counts.lines) file.fail("<Piece> cell counts overflow");
  return counts;
}

// The point array that becomes TraceSet::vectors, or nullptr.
const XmlElement* vectorArray(const VtkXmlFile& file, const XmlElement* pointData) {
  if (pointData == nullptr) return nullptr;
  if (const std::string* named = pointData->attribute("Vectors")) {
    const XmlElement* array = pointData->dataArray(*named);
    if (array == nullptr) {
      file.fail(fmt::format("<PointData Vectors=\"{}\"> names no point array", *named));
    }
    return array;
  }
  for (const XmlElement* array : pointData->childrenNamed("DataArray")) {
    const std::string* type = array->attribute("type");
    if (array->attribute("Name") != nullptr && file.components(*array) == 3 && type != nullptr &&
        (*type == "Float32" || *type == "Float64")) {
      return array;
    }
  }
  return nullptr;
}

const XmlElement& linesArray(const VtkXmlFile& file, const XmlElement* lines, const char* name) {
  const XmlElement* array = lines ? lines->dataArray(name) : nullptr;
  if (array == nullptr) file.fail(fmt::format("<Lines> has no \"{}\" array", name));
  return *array;
}

// Line i's point ids are connectivity[ends[i - 1] .. ends[i]) (ends[-1] = 0).
struct Lines {
  std::vector<std::int64_t> ends;
  std::vector<std::int64_t> connectivity;
};

Lines readLines(const VtkXmlFile& file, const XmlElement& piece, const PieceCounts& counts) {
  const XmlElement* lines = piece.child("Lines");
  Lines out;
  out.ends = file.integers(linesArray(file, lines, "offsets"), counts.lines, 1, "Lines/offsets");
  std::int64_t previous = 0;
  for (std::size_t i = 0; i < out.ends.size(); ++i) {
    if (out.ends[i] < 0) file.fail(fmt::format("Lines/offsets[{}] is {}", i, out.ends[i]));
    if (out.ends[i] < previous) {
      file.fail(
          fmt::format("Lines/offsets decrease at line {}: {} after {}", i, out.ends[i], previous));
    }
    previous = out.ends[i];
  }
  out.connectivity =
      file.integers(linesArray(file, lines, "connectivity"), std::nullopt, 1, "Lines/connectivity");
  if (static_cast<std::uint64_t>(previous) != out.connectivity.size()) {
    file.fail(fmt::format("Lines/offsets end at {} but Lines/connectivity holds {} point ids",
                          previous, out.connectivity.size()));
  }
  for (std::size_t i = 0; i < out.connectivity.size(); ++i) {
    const std::int64_t id = out.connectivity[i];
    if (id < 0 || static_cast<std::uint64_t>(id) >= counts.points) {
      file.fail(
          fmt::format("Lines/connectivity[{}] = {} is not a point id (the file has {} "
                      "points)",
                      i, id, counts.points));
    }
  }
  return out;
}

// The DataArray of <Points>, or nullptr.
const XmlElement* pointsDataArray(const XmlElement& piece) {
  const XmlElement* points = piece.child("Points");
  return points ? points->child("DataArray") : nullptr;
}

// Float64 points are precise positions (TraceSet::precisePositions).
bool holdsPrecisePositions(const XmlElement* points) {
  const std::string* type = points ? points->attribute("type") : nullptr;
  return type != nullptr && *type == "Float64";
}

// The file's points as a TraceSet keeps them: `high`, and for precise positions `low`.
struct FilePositions {
  std::vector<glm::vec3> high, low;

  bool same(std::size_t a, std::size_t b) const {
    return high[a] == high[b] && (low.empty() || low[a] == low[b]);
  }
};

FilePositions readPositions(const VtkXmlFile& file, const XmlElement* array,
                            std::uint64_t pointCount) {
  if (pointCount == 0) return {};
  if (array == nullptr) file.fail("<Points> has no DataArray");
  FilePositions positions;
  if (holdsPrecisePositions(array)) {
    const std::vector<double> xyz = file.doubles(*array, pointCount, 3, "Points");
    positions.high.resize(xyz.size() / 3);
    positions.low.resize(xyz.size() / 3);
    for (std::size_t i = 0; i < positions.high.size(); ++i) {
      const flow::SplitPosition split =
          flow::splitPosition({xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]});
      positions.high[i] = split.high;
      positions.low[i] = split.low;
    }
  } else {
    const std::vector<float> xyz = file.floats(*array, pointCount, 3, "Points");
    positions.high.resize(xyz.size() / 3);
    for (std::size_t i = 0; i < positions.high.size(); ++i)
      positions.high[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
  }
  // A finite high part has a finite low part.
  for (std::size_t i = 0; i < positions.high.size(); ++i) {
    const glm::vec3 p = positions.high[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      file.fail(fmt::format("point {} has a non-finite position ({}, {}, {})", i, p.x, p.y, p.z));
  }
  return positions;
}

std::vector<glm::vec3> readVectors(const VtkXmlFile& file, const XmlElement* array,
                                   std::uint64_t pointCount, const std::string& name) {
  if (array == nullptr) return {};
  const std::vector<float> xyz = file.floats(*array, pointCount, 3, "PointData/" + name);
  std::vector<glm::vec3> vectors(xyz.size() / 3);
  for (std::size_t i = 0; i < vectors.size(); ++i) {
    vectors[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
  }
  return vectors;
}

// An Int32 cell array of each line (cell arrays list verts first, then lines), or `fallback(i)`
// for line i when the file has no such array.
template <typename Fallback>
std::vector<std::int32_t> readLineInts(const VtkXmlFile& file, const XmlElement& piece,
                                       const PieceCounts& counts, const std::string& name,
                                       Fallback fallback) {
  const XmlElement* cellData = piece.child("CellData");
  const XmlElement* array = cellData ? cellData->dataArray(name) : nullptr;
  std::vector<std::int32_t> values(static_cast<std::size_t>(counts.lines));
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = fallback(i);
  if (array == nullptr) return values;
  const std::vector<std::int64_t> all = file.integers(*array, counts.cells, 1, "CellData/" + name);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::int64_t value = all[static_cast<std::size_t>(counts.verts) + i];
    if (!std::in_range<std::int32_t>(value))
      file.fail(fmt::format("{} of line {} is {}, not an Int32", name, i, value));
    values[i] = static_cast<std::int32_t>(value);
  }
  return values;
}

// The writer stores a trace that ends at its seed as a 2-point line repeating the point (see
// vtp_writer.hpp): such a line is one point.
std::uint32_t storedPoints(std::int64_t begin, std::int64_t end, const Lines& lines,
                           const FilePositions& positions, const std::vector<float>& times) {
  const std::int64_t count = end - begin;
  if (count != 2) return static_cast<std::uint32_t>(count);
  const auto a = static_cast<std::size_t>(lines.connectivity[static_cast<std::size_t>(begin)]);
  const auto b = static_cast<std::size_t>(lines.connectivity[static_cast<std::size_t>(begin) + 1]);
  const bool sameTime = times.empty() || times[a] == times[b];
  return positions.same(a, b) && sameTime ? 1 : 2;
}

// Like the trace command's check of --count and --steps: the traces must fit in 3/4 of memory.
void checkFitsInMemory(const VtkXmlFile& file, std::uint64_t points, bool precisePositions) {
  const double bytes =
      double(points) * double(flow::TraceSet::bytesPerPoint(0, false, precisePositions));
  const double memory = physicalMemoryBytes();
  if (memory > 0 && bytes > kTraceMemoryShare * memory)
    file.fail(
        fmt::format("its {} points need {:.1f} GiB, more than 3/4 of this machine's {:.1f} "
                    "GiB; split the file",
                    points, bytes / 0x1p30, memory / 0x1p30));
}

std::vector<FieldDataArray> readFieldData(const VtkXmlFile& file) {
  std::vector<FieldDataArray> arrays;
  const XmlElement* polyData = file.root().child("PolyData");
  const XmlElement* fieldData = polyData ? polyData->child("FieldData") : nullptr;
  if (fieldData == nullptr) return arrays;
  for (const XmlElement& array : fieldData->children) {
    const std::string* name = array.attribute("Name");
    const std::string* type = array.attribute("type");
    if (name == nullptr || type == nullptr || file.components(array) != 1) continue;
    const std::string what = "FieldData/" + *name;
    if (*type == "String") {
      arrays.push_back({*name, file.strings(array, what)});
    } else if (type->starts_with("Float")) {
      arrays.push_back({*name, file.doubles(array, std::nullopt, 1, what)});
    } else if (type->starts_with("Int") || type->starts_with("UInt")) {
      arrays.push_back({*name, file.integers(array, std::nullopt, 1, what)});
    }
  }
  return arrays;
}

bool holdsStreaklines(const std::vector<FieldDataArray>& fieldData) {
  for (const FieldDataArray& array : fieldData) {
    const auto* text = std::get_if<std::vector<std::string>>(&array.values);
    if (array.name == "Output" && text && text->size() == 1 && text->front() == "streaklines")
      return true;
  }
  return false;
}

flow::TraceSet readLinesOf(const VtkXmlFile& file) {
  const XmlElement& piece = onlyPiece(file);
  const PieceCounts counts = countsOf(file, piece);
  const XmlElement* pointData = piece.child("PointData");
  const XmlElement* vectorsArray = vectorArray(file, pointData);
  const XmlElement* positionArray = pointsDataArray(piece);

  flow::TraceSet traces;
  if (vectorsArray != nullptr) traces.vectorName = *vectorsArray->attribute("Name");
  traces.precisePositions = holdsPrecisePositions(positionArray);
  if (counts.lines == 0) return traces;

  const Lines lines = readLines(file, piece, counts);
  const FilePositions positions = readPositions(file, positionArray, counts.points);
  const XmlElement* timeArray = pointData ? pointData->dataArray("IntegrationTime") : nullptr;
  const std::vector<float> times =
      timeArray ? file.floats(*timeArray, counts.points, 1, "PointData/IntegrationTime")
                : std::vector<float>();
  const std::vector<glm::vec3> vectors =
      readVectors(file, vectorsArray, counts.points, traces.vectorName);
  const std::vector<std::int32_t> reasons =
      readLineInts(file, piece, counts, "ReasonForTermination", [](std::size_t) { return 0; });
  const std::vector<std::int32_t> seedIds = readLineInts(
      file, piece, counts, "SeedIds", [](std::size_t i) { return static_cast<std::int32_t>(i); });

  const std::size_t lineCount = lines.ends.size();
  traces.offsets.assign(lineCount + 1, 0);
  for (std::size_t line = 0; line < lineCount; ++line) {
    const std::int64_t begin = line == 0 ? 0 : lines.ends[line - 1];
    traces.offsets[line + 1] =
        traces.offsets[line] + storedPoints(begin, lines.ends[line], lines, positions, times);
  }
  checkFitsInMemory(file, traces.pointCount(), traces.precisePositions);

  const std::uint64_t points = traces.pointCount();
  traces.positions.resize(points);
  traces.positionsLow.resize(traces.precisePositions ? points : 0);
  traces.times.assign(points, 0.0f);
  traces.vectors.assign(points, glm::vec3(0.0f));
  for (std::size_t line = 0; line < lineCount; ++line) {
    const auto begin = static_cast<std::size_t>(line == 0 ? 0 : lines.ends[line - 1]);
    bool backward = false;
    for (std::uint64_t p = 0; p < traces.pointCount(line); ++p) {
      const auto id = static_cast<std::size_t>(lines.connectivity[begin + p]);
      const std::uint64_t to = traces.offsets[line] + p;
      traces.positions[to] = positions.high[id];
      if (traces.precisePositions) traces.positionsLow[to] = positions.low[id];
      if (!times.empty()) traces.times[to] = times[id];
      if (!vectors.empty()) traces.vectors[to] = vectors[id];
      backward = backward || traces.times[to] < 0.0f;
    }
    traces.seedIds.push_back(static_cast<std::uint32_t>(std::max(seedIds[line], 0)));
    traces.directions.push_back(backward ? -1.0f : 1.0f);
    traces.steps.push_back(
        traces.pointCount(line) == 0 ? 0 : static_cast<std::uint32_t>(traces.pointCount(line) - 1));
    traces.reasons.push_back(reasons[line]);
  }
  return traces;
}

}  // namespace

flow::TraceSet readVtpTraces(const std::filesystem::path& path) {
  return readLinesOf(VtkXmlFile(path));
}

VtpContents readVtpFile(const std::filesystem::path& path) {
  const VtkXmlFile file(path);
  VtpContents contents{readLinesOf(file), readFieldData(file)};
  contents.lines.timesAreAges = holdsStreaklines(contents.fieldData);
  return contents;
}

}  // namespace amrstream::output
