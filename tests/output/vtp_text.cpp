#include "vtp_text.hpp"

#include <lz4.h>
#include <zlib.h>

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

void appendHeaderValue(std::string& out, std::uint64_t value, const TestFileOptions& options) {
  if (options.uint32Header) {
    appendValue(out, static_cast<std::uint32_t>(value), options.bigEndian);
  } else {
    appendValue(out, value, options.bigEndian);
  }
}

std::string compressed(const std::string& bytes, const std::string& compressor) {
  std::string out;
  if (compressor == "zlib") {
    uLongf size = compressBound(bytes.size());
    out.resize(size);
    if (compress2(reinterpret_cast<Bytef*>(out.data()), &size,
                  reinterpret_cast<const Bytef*>(bytes.data()), bytes.size(), 6) != Z_OK) {
      throw std::runtime_error("vtpText: compress2 failed");
    }
    out.resize(size);
  } else if (compressor == "lz4") {
    out.resize(static_cast<std::size_t>(LZ4_compressBound(static_cast<int>(bytes.size()))));
    const int size = LZ4_compress_default(bytes.data(), out.data(), static_cast<int>(bytes.size()),
                                          static_cast<int>(out.size()));
    if (size <= 0) throw std::runtime_error("vtpText: LZ4_compress_default failed");
    out.resize(static_cast<std::size_t>(size));
  } else {
    throw std::invalid_argument("vtpText: unknown compressor " + compressor);
  }
  return out;
}

// The array's data as it goes into the file before any base64: VTK's block header and blocks.
struct CompressedData {
  std::string header;
  std::string blocks;
};
CompressedData compressedData(const std::string& bytes, const TestFileOptions& options) {
  const std::uint64_t size = bytes.size();
  const std::uint64_t count = (size + options.blockBytes - 1) / options.blockBytes;
  CompressedData out;
  appendHeaderValue(out.header, count, options);
  appendHeaderValue(out.header, options.blockBytes, options);
  appendHeaderValue(out.header, size % options.blockBytes, options);
  for (std::uint64_t block = 0; block < count; ++block) {
    const std::string part = compressed(
        bytes.substr(block * options.blockBytes, options.blockBytes), options.compressor);
    appendHeaderValue(out.header, part.size(), options);
    out.blocks += part;
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
        // Raw and base64 forms of the array's data.
        std::string block, encoded;
        if (options.compressor.empty()) {
          appendHeaderValue(block, bytes.size(), options);
          block += bytes;
          encoded = base64(block);
        } else {
          const CompressedData data = compressedData(bytes, options);
          block = data.header + data.blocks;
          encoded = base64(data.header) + base64(data.blocks);
        }
        xml += "        <DataArray type=\"" + a.type + "\" Name=\"" + a.name +
               "\" NumberOfComponents=\"" + std::to_string(a.components) + "\" format=\"";
        switch (options.encoding) {
          case TestEncoding::AppendedRaw:
          case TestEncoding::AppendedBase64:
            xml += "appended\" offset=\"" + std::to_string(blocks.size()) + "\"/>\n";
            blocks += options.encoding == TestEncoding::AppendedRaw ? block : encoded;
            break;
          case TestEncoding::Binary:
            xml += "binary\">\n          " + encoded + "\n        </DataArray>\n";
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
  if (options.compressor == "zlib") text += "\" compressor=\"vtkZLibDataCompressor";
  if (options.compressor == "lz4") text += "\" compressor=\"vtkLZ4DataCompressor";
  text += "\">\n  <PolyData>\n" + xml + "  </PolyData>\n";
  if (appended) {
    text += "  <AppendedData encoding=\"";
    text += options.encoding == TestEncoding::AppendedRaw ? "raw" : "base64";
    text += "\">\n   _" + blocks + "\n  </AppendedData>\n";
  }
  return text + "</VTKFile>\n";
}

std::size_t appendedBlockStart(const std::string& text, const std::string& name) {
  const std::size_t tag = text.find("Name=\"" + name + "\"");
  const std::size_t value = text.find("offset=\"", tag) + 8;
  const std::size_t base = text.find('_', text.find("<AppendedData")) + 1;
  if (tag == std::string::npos || value < 8 || base == 0) {
    throw std::invalid_argument("appendedBlockStart: no appended array " + name);
  }
  return base + std::stoull(text.substr(value, text.find('"', value) - value));
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
