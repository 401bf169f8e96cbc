// Writes one PolyData with known arrays once per compression, for check_arrays_with_vtk.py:
//
//   write_sample_arrays DIR
//
// DIR/arrays_none.vtp, DIR/arrays_zlib.vtp and DIR/arrays_lz4.vtp hold the same data through
// AppendedFileWriter: 40000 points on smooth curves (Points spans 15 blocks of 32768 bytes, the
// last one partial), point, cell and line arrays of several types, and FieldData strings and
// numbers with awkward values. DIR/expected/NAME.bin holds each array's values as this program
// made them (raw little-endian bytes of the array's type; a string array as every string followed
// by a NUL), written with plain file writes, not through the code under test.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "output/vtk_compression.hpp"
#include "output/vtk_field_data.hpp"
#include "output/vtk_xml_appended.hpp"

namespace {

namespace fs = std::filesystem;
using namespace amrstream::output;

template <class T>
void writeExpected(const fs::path& dir, const std::string& name, const std::vector<T>& values) {
  std::ofstream(dir / (name + ".bin"), std::ios::binary)
      .write(reinterpret_cast<const char*>(values.data()),
             static_cast<std::streamsize>(values.size() * sizeof(T)));
}

void writeExpected(const fs::path& dir, const std::string& name,
                   const std::vector<std::string>& strings) {
  std::ofstream out(dir / (name + ".bin"), std::ios::binary);
  for (const std::string& s : strings) out << s << '\0';
}

template <class T>
AppendedArray arrayOf(const std::string& name, std::string_view type, int components,
                      const std::vector<T>& values) {
  return {name, type, components, values.size() * sizeof(T), [&values](BufferedWriter& out) {
            // Many small writes, as the trace writer's producers make them.
            for (const T& v : values) out.put(v);
          }};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s DIR\n", argv[0]);
    return 2;
  }
  try {
    const fs::path dir = argv[1];
    fs::create_directories(dir / "expected");

    constexpr std::size_t kPoints = 40000;
    std::vector<float> points;
    std::vector<double> temperature;
    std::vector<std::int32_t> flags;
    for (std::size_t i = 0; i < kPoints; ++i) {
      const double t = 0.01 * double(i);
      points.insert(points.end(),
                    {float(10 * std::cos(t)), float(10 * std::sin(1.3 * t)), float(0.1 * t)});
      temperature.push_back(300 + 20 * std::sin(0.7 * t) + 1e-9 * double(i));
      flags.push_back(std::int32_t(i % 7) - 3);
    }
    // Lines of 2 to 50 points covering all points in order.
    std::vector<std::int64_t> connectivity, offsets, lineIds;
    for (std::size_t begin = 0, length = 2; begin < kPoints; length = 2 + (length * 7) % 49) {
      const std::size_t end = std::min(kPoints, begin + length);
      if (end - begin < 2) break;  // the last few points stay out of any line
      for (std::size_t id = begin; id < end; ++id) connectivity.push_back(std::int64_t(id));
      offsets.push_back(std::int64_t(connectivity.size()));
      lineIds.push_back(std::int64_t(lineIds.size()) * 1000003 - 5);
      begin = end;
    }

    const std::vector<FieldDataArray> fieldData{
        textField("Input", "builtin:cloud <1> & \"2\" 'three'"),
        {"Names", std::vector<std::string>{"", "caf\xC3\xA9", "two words", "tab\there", ""}},
        {"StepSizes", std::vector<double>{0.25, 1e300, -0.0, 5e-324, -1.5}},
        {"Counts", std::vector<std::int64_t>{std::numeric_limits<std::int64_t>::min(), -1, 0,
                                             std::numeric_limits<std::int64_t>::max()}},
    };
    const fs::path expected = dir / "expected";
    writeExpected(expected, "Points", points);
    writeExpected(expected, "Temperature", temperature);
    writeExpected(expected, "Flags", flags);
    writeExpected(expected, "LineIds", lineIds);
    writeExpected(expected, "connectivity", connectivity);
    writeExpected(expected, "offsets", offsets);
    for (const FieldDataArray& array : fieldData) {
      std::visit([&](const auto& values) { writeExpected(expected, array.name, values); },
                 array.values);
    }

    const AppendedArray pointArray = arrayOf("Points", "Float32", 3, points);
    const AppendedArray temperatureArray = arrayOf("Temperature", "Float64", 1, temperature);
    const AppendedArray flagsArray = arrayOf("Flags", "Int32", 1, flags);
    const AppendedArray lineIdsArray = arrayOf("LineIds", "Int64", 1, lineIds);
    const AppendedArray connectivityArray = arrayOf("connectivity", "Int64", 1, connectivity);
    const AppendedArray offsetsArray = arrayOf("offsets", "Int64", 1, offsets);
    for (const Compression compression : {Compression::None, Compression::ZLib, Compression::LZ4}) {
      AppendedFileWriter file("PolyData", compression);
      file.markup("  <PolyData>\n");
      file.fieldData(fieldData, 4);
      file.markup("    <Piece NumberOfPoints=\"" + std::to_string(kPoints) + "\" NumberOfLines=\"" +
                  std::to_string(offsets.size()) + "\">\n");
      file.markup("      <PointData>\n");
      file.dataArray(temperatureArray, 8);
      file.dataArray(flagsArray, 8);
      file.markup("      </PointData>\n      <CellData>\n");
      file.dataArray(lineIdsArray, 8);
      file.markup("      </CellData>\n      <Points>\n");
      file.dataArray(pointArray, 8);
      file.markup("      </Points>\n      <Lines>\n");
      file.dataArray(connectivityArray, 8);
      file.dataArray(offsetsArray, 8);
      file.markup("      </Lines>\n    </Piece>\n  </PolyData>\n");
      file.write(dir / ("arrays_" + std::string(compressionName(compression)) + ".vtp"));
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "write_sample_arrays: %s\n", e.what());
    return 1;
  }
  return 0;
}
