#include "polyline_writer.hpp"

#include <fmt/format.h>

#include <cstring>
#include <numeric>
#include <stdexcept>

#include "output/buffered_writer.hpp"
#include "output/vtk_xml_appended.hpp"

namespace amrstream::output {

namespace {

void check(const std::filesystem::path& path, const Polylines& lines) {
  const auto fail = [&](const std::string& problem) {
    throw std::invalid_argument(fmt::format("cannot write '{}': {}", path.string(), problem));
  };
  if (lines.offsets.empty() || lines.offsets.front() != 0 ||
      lines.offsets.back() != lines.points.size())
    fail("the offsets do not span the points");
  for (std::size_t i = 0; i + 1 < lines.offsets.size(); ++i)
    if (lines.offsets[i + 1] < lines.offsets[i] + 2) fail("a line has fewer than 2 points");
  for (const PolylineArray& array : lines.pointData)
    if (array.components < 1 || array.values.size() != lines.points.size() * array.components)
      fail(fmt::format("the array '{}' does not hold {} values per point", array.name,
                       array.components));
}

// `values` (which must outlive the write) as one appended Float32 array.
AppendedArray floatArray(std::string name, int components, const std::vector<float>& values) {
  return {std::move(name), "Float32", components, values.size() * sizeof(float),
          [&values](BufferedWriter& out) {
            for (const float v : values) out.put(v);
          }};
}

}  // namespace

void writePolylines(const std::filesystem::path& path, const Polylines& lines,
                    const PolylineWriteOptions& options) {
  check(path, lines);
  const std::uint64_t pointCount = lines.points.size(), lineCount = lines.offsets.size() - 1;
  std::vector<float> coordinates;
  coordinates.reserve(3 * pointCount);
  for (const glm::vec3& p : lines.points) coordinates.insert(coordinates.end(), {p.x, p.y, p.z});
  std::vector<AppendedArray> pointData;
  for (const PolylineArray& array : lines.pointData)
    pointData.push_back(floatArray(array.name, array.components, array.values));
  const AppendedArray points = floatArray("Points", 3, coordinates);
  using Out = BufferedWriter&;
  const AppendedArray connectivity{"connectivity", "Int64", 1, pointCount * sizeof(std::int64_t),
                                   [&](Out out) {
                                     for (std::uint64_t i = 0; i < pointCount; ++i)
                                       out.put(std::int64_t(i));
                                   }};
  // Each line's end; the first line's start, 0, is not stored.
  const AppendedArray offsets{"offsets", "Int64", 1, lineCount * sizeof(std::int64_t),
                              [&](Out out) {
                                for (std::uint64_t i = 1; i <= lineCount; ++i)
                                  out.put(std::int64_t(lines.offsets[i]));
                              }};

  AppendedFileWriter file("PolyData", options.compression);
  file.markup("  <PolyData>\n");
  file.fieldData(options.fieldData, 4);
  file.markup(
      fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"0\" NumberOfLines=\"{}\" "
                  "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n",
                  pointCount, lineCount));
  std::string attributes;
  if (!lines.scalars.empty())
    attributes += fmt::format(" Scalars=\"{}\"", xmlAttribute(lines.scalars));
  if (!lines.vectors.empty())
    attributes += fmt::format(" Vectors=\"{}\"", xmlAttribute(lines.vectors));
  file.markup(fmt::format("      <PointData{}>\n", attributes));
  for (const AppendedArray& array : pointData) file.dataArray(array, 8);
  file.markup("      </PointData>\n      <Points>\n");
  file.dataArray(points, 8);
  file.markup("      </Points>\n      <Lines>\n");
  file.dataArray(connectivity, 8);
  file.dataArray(offsets, 8);
  file.markup("      </Lines>\n    </Piece>\n  </PolyData>\n");
  file.write(path);
}

}  // namespace amrstream::output
