#include "vtp_text.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

namespace amrstream::testing {
namespace {

template <class T>
void appendValue(std::string& out, T value, bool bigEndian) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (bigEndian) std::reverse(raw, raw + sizeof(T));  // the tests run on little-endian hosts
  out.append(raw, sizeof(T));
}

template <class T>
void appendAll(std::string& out, const std::vector<double>& values, bool bigEndian) {
  for (const double v : values) appendValue(out, static_cast<T>(v), bigEndian);
}

std::string packed(const TestArray& array, bool bigEndian) {
  using Packer = void (*)(std::string&, const std::vector<double>&, bool);
  static const std::map<std::string, Packer> packers{
      {"Float32", appendAll<float>},      {"Float64", appendAll<double>},
      {"Int8", appendAll<std::int8_t>},   {"UInt8", appendAll<std::uint8_t>},
      {"Int16", appendAll<std::int16_t>}, {"UInt16", appendAll<std::uint16_t>},
      {"Int32", appendAll<std::int32_t>}, {"UInt32", appendAll<std::uint32_t>},
      {"Int64", appendAll<std::int64_t>}, {"UInt64", appendAll<std::uint64_t>}};
  const auto packer = packers.find(array.type);
  if (packer == packers.end()) throw std::invalid_argument("vtpText: cannot pack " + array.type);
  std::string out;
  packer->second(out, array.values, bigEndian);
  return out;
}

std::string base64(const std::string& bytes) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t group = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      group = (group << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    }
    for (std::size_t k = 0; k < 4; ++k) {
      out += k <= n ? alphabet[(group >> (18 - 6 * k)) & 63] : '=';
    }
  }
  return out;
}

std::string asciiValues(const TestArray& array) {
  std::ostringstream out;
  out.precision(std::numeric_limits<double>::max_digits10);
  for (std::size_t i = 0; i < array.values.size(); ++i) {
    out << (i % 6 == 0 ? "\n          " : " ") << array.values[i];
  }
  out << "\n        ";
  return out.str();
}

}  // namespace

std::string vtpText(const TestPiece& piece, const TestFileOptions& options) {
  std::vector<std::string> sections;
  for (const TestArray& a : piece.arrays) {
    if (std::find(sections.begin(), sections.end(), a.section) == sections.end()) {
      sections.push_back(a.section);
    }
  }
  const bool appended = options.encoding == TestEncoding::AppendedRaw ||
                        options.encoding == TestEncoding::AppendedBase64;
  std::string xml, blocks;
  for (int p = 0; p < options.pieces; ++p) {
    xml += "    <Piece NumberOfPoints=\"" + std::to_string(piece.points) + "\" NumberOfVerts=\"" +
           std::to_string(piece.verts) + "\" NumberOfLines=\"" + std::to_string(piece.lines) +
           "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";
    for (const std::string& section : sections) {
      xml += "      <" + section +
             (section == "PointData" && !piece.pointDataAttributes.empty()
                  ? " " + piece.pointDataAttributes
                  : "") +
             ">\n";
      for (const TestArray& a : piece.arrays) {
        if (a.section != section) continue;
        const std::string bytes = packed(a, options.bigEndian);
        std::string block;
        if (options.uint32Header) {
          appendValue(block, static_cast<std::uint32_t>(bytes.size()), options.bigEndian);
        } else {
          appendValue(block, static_cast<std::uint64_t>(bytes.size()), options.bigEndian);
        }
        block += bytes;
        xml += "        <DataArray type=\"" + a.type + "\" Name=\"" + a.name +
               "\" NumberOfComponents=\"" + std::to_string(a.components) + "\" format=\"";
        switch (options.encoding) {
          case TestEncoding::AppendedRaw:
          case TestEncoding::AppendedBase64:
            xml += "appended\" offset=\"" + std::to_string(blocks.size()) + "\"/>\n";
            blocks += options.encoding == TestEncoding::AppendedRaw ? block : base64(block);
            break;
          case TestEncoding::Binary:
            xml += "binary\">\n          " + base64(block) + "\n        </DataArray>\n";
            break;
          case TestEncoding::Ascii:
            xml += "ascii\">" + asciiValues(a) + "</DataArray>\n";
            break;
        }
      }
      xml += "      </" + section + ">\n";
    }
    xml += "    </Piece>\n";
  }
  std::string text =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"";
  text += options.bigEndian ? "BigEndian" : "LittleEndian";
  text += "\" header_type=\"";
  text += options.uint32Header ? "UInt32" : "UInt64";
  text += "\">\n  <PolyData>\n" + xml + "  </PolyData>\n";
  if (appended) {
    text += "  <AppendedData encoding=\"";
    text += options.encoding == TestEncoding::AppendedRaw ? "raw" : "base64";
    text += "\">\n   _" + blocks + "\n  </AppendedData>\n";
  }
  return text + "</VTKFile>\n";
}

TestPiece twoLinePiece() {
  TestPiece piece;
  piece.points = 5;
  piece.lines = 2;
  piece.pointDataAttributes = R"(Scalars="IntegrationTime" Vectors="velocity")";
  piece.arrays = {
      {"PointData", "IntegrationTime", "Float32", 1, {0, 0.5, 1, 0, 0.25}},
      {"PointData", "velocity", "Float32", 3, {1, 0, 0, 2, 0, 0, 3, 0, 0, 0, 1, 0, 0, 2, 0}},
      {"CellData", "ReasonForTermination", "Int32", 1, {3, 7}},
      {"Points", "Points", "Float32", 3, {0, 0, 0, 1, 0, 0, 2, 0, 0, 5, 5, 5, 5, 6, 5}},
      {"Lines", "connectivity", "Int64", 1, {0, 1, 2, 3, 4}},
      {"Lines", "offsets", "Int64", 1, {3, 5}},
  };
  return piece;
}

TestArray& arrayNamed(TestPiece& piece, const std::string& name) {
  for (TestArray& a : piece.arrays) {
    if (a.name == name) return a;
  }
  throw std::invalid_argument("vtpText: no array " + name);
}

void setValues(TestPiece& piece, const std::string& name, std::vector<double> values) {
  arrayNamed(piece, name).values = std::move(values);
}

}  // namespace amrstream::testing
