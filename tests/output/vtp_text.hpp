#pragma once
// Hand-made VTK XML PolyData files for the reader tests, written by test code that shares nothing
// with the production writer or reader: any array, type, encoding, header type and byte order,
// and, since nothing is checked, broken files too (wrong counts, bad ids, several pieces).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace amrstream::testing {

struct TestArray {
  std::string section;  // "PointData", "CellData", "Points", "Verts" or "Lines"
  std::string name;
  std::string type;  // VTK type name: "Float32", "Int64", ...
  int components = 1;
  std::vector<double> values;  // converted to `type` when written (exact for the values used)
};

struct TestPiece {
  std::uint64_t points = 0;
  std::uint64_t verts = 0;
  std::uint64_t lines = 0;
  std::string pointDataAttributes;  // e.g. R"(Vectors="velocity")"
  std::vector<TestArray> arrays;    // written grouped by section, in order of first appearance
};

enum class TestEncoding { AppendedRaw, AppendedBase64, Binary, Ascii };

struct TestFileOptions {
  TestEncoding encoding = TestEncoding::AppendedRaw;
  bool uint32Header = false;  // header_type="UInt32" instead of UInt64
  bool bigEndian = false;
  int pieces = 1;  // the piece repeated
  // "zlib" or "lz4": binary and appended arrays compressed as VTK does, with zlib's compress2
  // and LZ4_compress_default, in blocks of blockBytes; the VTKFile compressor attribute says so.
  // In base64, the block header and the blocks are encoded separately, as VTK does.
  std::string compressor = "";
  std::uint64_t blockBytes = 32768;
};

std::string vtpText(const TestPiece& piece, const TestFileOptions& options = {});

// Where the data of the appended array `name` starts in `text` (the byte after "_" plus its
// offset), for tests that corrupt it.
std::size_t appendedBlockStart(const std::string& text, const std::string& name);

// A valid piece: 5 points, 2 lines (points 0 1 2 and 3 4), IntegrationTime, a Float32 vector
// "velocity" named by Vectors=, and ReasonForTermination 3 and 7.
TestPiece twoLinePiece();

// The first array called `name` in `piece`; throws std::invalid_argument when there is none.
TestArray& arrayNamed(TestPiece& piece, const std::string& name);
// Replaces the values of the array `name` in `piece`.
void setValues(TestPiece& piece, const std::string& name, std::vector<double> values);

}  // namespace amrstream::testing
